from turtletui.compat.parameter import (  # noqa: F401
    Parameter,
    get_parameter_value,
    parameter_dict_from_yaml_file,
    parameter_value_to_python,
)
