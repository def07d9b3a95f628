from turtletui.compat.parameter_client import AsyncParameterClient  # noqa: F401
