from turtletui.compat.qos_overriding_options import InvalidQosOverridesError, QoSOverridingOptions  # noqa: F401
