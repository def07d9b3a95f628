"""turtletui's message packages against the real ones (ros-* wheels of Kilted).

probe_messages.py describes every message class of a package as a program
sees it; it runs once under the real rclpy and once under turtletui's shims,
and the two descriptions must agree: fields and their types, constants and
defaults, default instances and their repr, and for every field what happens
when a program sets it to each of thirty values (stored as what, or refused
with which exception and sentence). The interface files must be turtletui's
definitions byte for byte.

Deliberate differences, normalised away here and listed in the README:
fixed-size numeric arrays (``float64[36] covariance``) are lists in
turtletui, numpy arrays in ROS; ROS's classes carry a ``_check_fields`` slot.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from support.real_ros import run_real

import turtletui.interfaces as I

pytestmark = pytest.mark.realros

PACKAGES = ["std_msgs", "geometry_msgs", "sensor_msgs", "nav_msgs", "std_srvs", "rcl_interfaces", "lifecycle_msgs",
            "rosgraph_msgs", "service_msgs", "type_description_interfaces", "action_msgs"]
PROBE = Path(__file__).with_name("probe_messages.py")
EXPECTED_COUNTS = {"std_msgs": 30, "geometry_msgs": 32, "sensor_msgs": 28, "nav_msgs": 10, "std_srvs": 3,
                   "rcl_interfaces": 21, "lifecycle_msgs": 8, "rosgraph_msgs": 1,
                   "service_msgs": 1, "type_description_interfaces": 7, "action_msgs": 4}


IDENTITY_PACKAGES = [*PACKAGES, "builtin_interfaces", "unique_identifier_msgs", "turtlesim_msgs"]
"""Every package of turtletui's that the real ROS 2 of the tests has (turtlesim_msgs: Kilted's name)."""


def _ours(args: list[str], cwd) -> dict:
    code = (
        "import runpy, sys; import turtletui.compat as c; c.install('kilted'); "
        f"sys.argv = ['probe', *{args!r}]; runpy.run_path({str(PROBE)!r}, run_name='__main__')"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=cwd, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def real(tmp_path_factory) -> dict:
    done = run_real([str(PROBE), *PACKAGES, "--files"], cwd=tmp_path_factory.mktemp("real"))
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def ours(tmp_path_factory) -> dict:
    return _ours(PACKAGES, tmp_path_factory.mktemp("ours"))


def _normalised(value):
    """ROS's numpy fixed arrays as lists (turtletui keeps lists)."""
    if isinstance(value, dict):
        return {k: _normalised(v) for k, v in value.items()}
    if isinstance(value, list):
        if len(value) == 2 and value[0] == "fixed":
            return _normalised(value[1])
        return [_normalised(v) for v in value]
    return value


def test_every_interface_file_is_turtletuis_definition_byte_for_byte(real):
    files = real["files"]
    for package, count in EXPECTED_COUNTS.items():
        assert sum(name.startswith(f"{package}/") for name in files) == count, package
    different = [name for name, text in files.items() if I.get_interface(name)._DEFINITION != text]
    assert different == []
    ours_listed = {n for n in I.all_interfaces() if n.split("/")[0] in EXPECTED_COUNTS}
    assert ours_listed == set(files)


def test_the_same_classes_exist(real, ours):
    assert set(ours["classes"]) == set(real["classes"])
    assert len(real["classes"]) > 100


@pytest.mark.parametrize("package", PACKAGES)
def test_fields_constants_and_defaults_are_ros_s(real, ours, package):
    for name, r in real["classes"].items():
        if not name.startswith(package + "/"):
            continue
        o = ours["classes"][name]
        assert o["fields"] == r["fields"], name
        assert o["slots"] == [s for s in r["slots"] if s != "_check_fields"], name
        assert o["constants"] == r["constants"], name
        assert _normalised(o["default"]) == _normalised(r["default"]), name
        if "fixed" not in json.dumps(r["default"]):
            assert o["repr"] == r["repr"], name
        assert (o["unknown_keyword"], o["equal_defaults"]) == (r["unknown_keyword"], r["equal_defaults"]), name


@pytest.mark.parametrize("package", PACKAGES)
def test_setting_any_field_to_anything_does_what_ros_does(real, ours, package):
    compared = 0
    for name, r in real["classes"].items():
        if not name.startswith(package + "/"):
            continue
        for field, outcomes in r["sets"].items():
            theirs = [_normalised(x) for x in outcomes]
            mine = [_normalised(x) for x in ours["classes"][name]["sets"][field]]
            assert mine == theirs, f"{name}.{field}"
            compared += len(outcomes)
    assert compared > 0


def test_every_class_is_named_printed_imported_and_pickled_as_ros_s(tmp_path):
    """``type(msg)`` prints ``<class 'geometry_msgs.msg._twist.Twist'>``, its
    metaclass ``Metaclass_Twist``, ``import geometry_msgs.msg._twist`` finds
    it, and so on for every class, services' and actions' parts included."""
    real_run = run_real([str(PROBE), "--identities", *IDENTITY_PACKAGES], cwd=tmp_path)
    assert real_run.returncode == 0, real_run.stderr
    theirs = json.loads(real_run.stdout)
    mine = _ours(["--identities", *IDENTITY_PACKAGES], tmp_path)
    assert mine["modules"] == theirs["modules"]
    assert set(mine["classes"]) == set(theirs["classes"])
    assert len(theirs["classes"]) > 300
    for label, identity in theirs["classes"].items():
        assert mine["classes"][label] == identity, label
