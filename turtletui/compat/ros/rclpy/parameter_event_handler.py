from turtletui.compat.parameter_event_handler import (  # noqa: F401
    ParameterCallbackHandle,
    ParameterEventCallbackHandle,
    ParameterEventHandler,
)
