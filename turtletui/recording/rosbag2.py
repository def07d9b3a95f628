"""rosbag2's bag metadata (``metadata.yaml``), as ``ros2 bag record`` writes it
with the mcap storage plugin in Jazzy and Kilted (version 9).

yaml-cpp's emitter sets the layout: two-space indents, block sequences
indented under their key, ``""`` for empty strings, ``~`` for an empty map,
no newline after the last line.
"""

from __future__ import annotations

from dataclasses import dataclass

from turtletui.recording.qos import OfferedQos

VERSION = 9
STORAGE = "mcap"
ROS_DISTRO = "jazzy"
"""The distro a bag says it was recorded with when the run's is not known."""


@dataclass
class TopicInfo:
    name: str
    type: str
    qos: list[OfferedQos]
    message_count: int
    type_hash: str = ""


@dataclass
class BagInfo:
    """What metadata.yaml tells: times in ns (ROS time), one file per bag here."""

    files: list[str]
    start_ns: int
    duration_ns: int
    message_count: int
    topics: list[TopicInfo]
    ros_distro: str = ROS_DISTRO
    """The distro of the run (its type names: turtlesim_msgs/msg/Pose from Kilted on)."""


def metadata_yaml(info: BagInfo) -> str:
    """The file ``metadata.yaml`` of a bag folder."""
    body = _bag_lines(info)
    return "\n".join(["rosbag2_bagfile_information:", *("  " + line for line in body)])


def serialized_metadata(info: BagInfo) -> str:
    """The same, as the mcap plugin stores it in the file's "rosbag2" metadata record."""
    return "\n".join(_bag_lines(info))


def _bag_lines(info: BagInfo) -> list[str]:
    lines = [
        f"version: {VERSION}",
        f"storage_identifier: {STORAGE}",
        "duration:",
        f"  nanoseconds: {info.duration_ns}",
        "starting_time:",
        f"  nanoseconds_since_epoch: {info.start_ns}",
        f"message_count: {info.message_count}",
        "topics_with_message_count:",
    ]
    if not info.topics:
        lines.append("  []")
    for topic in info.topics:
        lines += [
            "  - topic_metadata:",
            f"      name: {_scalar(topic.name)}",
            f"      type: {_scalar(topic.type)}",
            "      serialization_format: cdr",
            "      offered_qos_profiles:",
            *("        " + line for profile in topic.qos for line in profile.yaml_lines()),
            f"      type_description_hash: {_scalar(topic.type_hash)}",
            f"    message_count: {topic.message_count}",
        ]
    lines += [
        'compression_format: ""',
        'compression_mode: ""',
        "relative_file_paths:",
        *(f"  - {_scalar(name)}" for name in info.files),
        "files:",
    ]
    for name in info.files:
        lines += [
            f"  - path: {_scalar(name)}",
            "    starting_time:",
            f"      nanoseconds_since_epoch: {info.start_ns}",
            "    duration:",
            f"      nanoseconds: {info.duration_ns}",
            f"    message_count: {info.message_count}",
        ]
    lines += ["custom_data: ~", f"ros_distro: {info.ros_distro}"]
    return lines


def _scalar(text: str) -> str:
    """A YAML scalar as yaml-cpp writes it: plain when it can be, else quoted."""
    if text == "":
        return '""'
    plain_safe = all(c.isalnum() or c in "/_.-" for c in text) and text[0] not in "-."
    if plain_safe and text.lower() not in ("~", "null", "true", "false", "yes", "no", "on", "off"):
        return text
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'
