from turtletui.compat.serialization import deserialize_message, serialize_message  # noqa: F401
