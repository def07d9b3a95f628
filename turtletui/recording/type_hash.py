"""ROS 2's type hashes (``RIHS01_<sha256>``), which rosbag2 stores for each topic
(computed by turtletui.interfaces.type_descriptions, as rosidl does)."""

from __future__ import annotations

import functools

from turtletui.interfaces.type_descriptions import type_hash as _class_hash
from turtletui.recording.schema import interface_of


@functools.cache
def type_hash(type_name: str) -> str:
    """The RIHS01 hash of a recorded message type (``turtlesim/msg/Pose``);
    a request recorded as ``turtlesim/msg/SetPen_Request`` is hashed under that
    name, as readers that check hashes (rosbags) hash the type they are given."""
    cls = interface_of(type_name)
    # a type recorded under another package's name (turtlesim_msgs/... from
    # Kilted on) names the types of its own package it uses that way too
    defined, recorded = cls._TYPE_NAME.split("/", 1)[0], type_name.split("/", 1)[0]
    return _class_hash(cls, type_name, ((defined, recorded),) if recorded != defined else ())
