from turtletui.compat.service_introspection import ServiceIntrospectionState  # noqa: F401
