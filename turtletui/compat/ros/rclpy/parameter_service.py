from turtletui.compat.parameter_service import ParameterService  # noqa: F401
