from turtletui.compat.tf2.listener import (  # noqa: F401
    DEFAULT_STATIC_TF_TOPIC,
    DEFAULT_TF_TOPIC,
    TransformListener,
)
