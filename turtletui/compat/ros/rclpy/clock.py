from turtletui.compat.time import (  # noqa: F401
    Clock,
    ClockChange,
    ClockType,
    JumpHandle,
    JumpThreshold,
    ROSClock,
    TimeJump,
)
