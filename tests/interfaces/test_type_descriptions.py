"""Type descriptions and RIHS01 hashes against ROS's own (rosidl's JSON files).

The constants were read from the share/<package>/*/*.json files of the Kilted
wheels; the realros test compares every type turtletui ships with those files
in the real ROS 2 itself, description (default values included) and hashes.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from support.real_ros import run_real

from turtletui.interfaces import get_interface
from turtletui.interfaces.type_descriptions import type_description, type_hash, type_sources

TURTLESIM_MSGS = (("turtlesim", "turtlesim_msgs"),)
KILTED = {
    "geometry_msgs/msg/Twist": "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a",
    "geometry_msgs/msg/Quaternion": "RIHS01_8a765f66778c8ff7c8ab94afcc590a2ed5325a1d9a076ffff38fbce36f458684",
    "sensor_msgs/msg/LaserScan": "RIHS01_64c191398013af96509d518dac71d5164f9382553fce5c1f8cca5be7924bd828",
    "rcl_interfaces/msg/Log": "RIHS01_e28ce254ca8abc06abf92773b74602cdbf116ed34fbaf294fb9f81da9f318eac",
    "std_srvs/srv/SetBool": "RIHS01_abe9e4bb6b41b40e6789712c00ec8871923e089af3f667a79992a428cff2da0a",
    "action_msgs/srv/CancelGoal": "RIHS01_573d8b0a534451d7bc2ac8c5ffde8ac14b8593b7001175d0cd6516dcbeb8689a",
    "type_description_interfaces/srv/GetTypeDescription":
        "RIHS01_69b9c19c1021405984cc60dbbb1edceb147a6538b411d812ba6afabeed962cd5",
    "turtlesim/msg/Pose": "RIHS01_739beba26bcba6920404ba722b7b8321348512f92ea5be235c47251940dd8aa9",
    "turtlesim/srv/Kill": "RIHS01_81c7c9131a0802f384e515fbd04867f8da57abaa83ee3a0ec76e39091e54bbc3",
    "turtlesim/action/RotateAbsolute": "RIHS01_08ba6dd83d976f1cb548edd1f75f16cf30cca624ce1410b6ce77f44b8a3c2895",
}
KILTED_TURTLESIM_MSGS = {
    "turtlesim/msg/Pose": "RIHS01_37b07ace09a0ed2c5b774b1410dec972dfd1d292de5656ebc2b075ac646e09c8",
    "turtlesim/action/RotateAbsolute": "RIHS01_18617e6b742158766b7a9a14938f06be93e499368904e91955b75e8bcc1b0fcf",
}


@pytest.mark.parametrize("name", KILTED)
def test_hashes_are_ros_2s(name):
    assert type_hash(get_interface(name)) == KILTED[name]


@pytest.mark.parametrize("name", KILTED_TURTLESIM_MSGS)
def test_turtlesim_msgs_hashes_rename_every_type(name):
    cls = get_interface(name)
    assert type_hash(cls, None, TURTLESIM_MSGS) == KILTED_TURTLESIM_MSGS[name]
    names = [t["type_name"] for t in type_description(cls, None, TURTLESIM_MSGS)["referenced_type_descriptions"]]
    assert names == sorted(names)
    assert not any(n.startswith("turtlesim/") for n in names)


def test_a_service_is_its_request_response_and_event():
    full = type_description(get_interface("std_srvs/srv/SetBool"))
    assert [(f["name"], f["type"]["nested_type_name"]) for f in full["type_description"]["fields"]] == [
        ("request_message", "std_srvs/srv/SetBool_Request"),
        ("response_message", "std_srvs/srv/SetBool_Response"),
        ("event_message", "std_srvs/srv/SetBool_Event"),
    ]
    event = next(t for t in full["referenced_type_descriptions"] if t["type_name"] == "std_srvs/srv/SetBool_Event")
    assert [(f["name"], f["type"]["type_id"], f["type"]["capacity"]) for f in event["fields"]] == [
        ("info", 1, 0), ("request", 97, 1), ("response", 97, 1)]


def test_defaults_are_in_the_description_but_not_in_the_hash():
    fields = type_description(get_interface("geometry_msgs/msg/Quaternion"))["type_description"]["fields"]
    assert [f["default_value"] for f in fields] == ["0.0", "0.0", "0.0", "1.0"]
    request = type_description(get_interface("type_description_interfaces/srv/GetTypeDescription_Request"))
    assert request["type_description"]["fields"][2]["default_value"] == "True"


def test_sources_are_the_files_and_implicit_parts():
    sources = type_sources(get_interface("std_srvs/srv/SetBool"))
    assert [(s["type_name"], s["encoding"]) for s in sources] == [
        ("std_srvs/srv/SetBool", "srv"),
        ("builtin_interfaces/msg/Time", "msg"),
        ("service_msgs/msg/ServiceEventInfo", "msg"),
        ("std_srvs/srv/SetBool_Event", "implicit"),
        ("std_srvs/srv/SetBool_Request", "implicit"),
        ("std_srvs/srv/SetBool_Response", "implicit"),
    ]
    assert sources[0]["raw_file_contents"].endswith("string message # informational, e.g. for error messages")
    assert sources[3]["raw_file_contents"] == ""


PROBE = """
import glob, json, os, sys
from ament_index_python.packages import get_package_share_directory
found = {}
for package in sys.argv[1:]:
    try:
        share = get_package_share_directory(package)
    except Exception:
        continue
    for path in sorted(glob.glob(os.path.join(share, '*', '*.json'))):
        with open(path) as f:
            found[package + '/' + os.path.relpath(path, share)] = json.load(f)
print(json.dumps(found))
"""
SHIPPED = ("action_msgs", "builtin_interfaces", "example_interfaces", "geometry_msgs", "lifecycle_msgs", "nav_msgs",
           "rcl_interfaces", "rosgraph_msgs", "sensor_msgs", "service_msgs", "std_msgs", "std_srvs", "tf2_msgs",
           "turtlesim", "turtlesim_msgs", "type_description_interfaces", "unique_identifier_msgs",
           "visualization_msgs")
"""turtletui's interface packages (turtlesim_msgs: the same classes under Kilted's name)."""


@pytest.mark.realros
def test_every_shipped_type_is_described_and_hashed_as_rosidl_does(tmp_path: Path):
    done = run_real(["-c", PROBE, *SHIPPED], cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    files = json.loads(done.stdout)
    assert len(files) > 100, "the real ROS 2 has too few type description files"
    compared = 0
    for path, data in files.items():
        if path.endswith(".schema.json"):
            continue
        real = data["type_description_msg"]
        name = real["type_description"]["type_name"]
        names = TURTLESIM_MSGS if name.startswith("turtlesim_msgs/") else ()
        cls = get_interface(name)
        assert type_description(cls, None, names) == real, path
        hashes = {h["type_name"]: h["hash_string"] for h in data["type_hashes"]}
        assert type_hash(cls, None, names) == hashes[name], path
        for referenced in real["referenced_type_descriptions"]:
            if not referenced["type_name"].endswith("_Event"):  # no class of its own: in its service's hash
                assert type_hash(get_interface(referenced["type_name"]), None, names) == hashes[referenced["type_name"]]
        compared += 1
    assert compared == len([p for p in files if not p.endswith(".schema.json")])
