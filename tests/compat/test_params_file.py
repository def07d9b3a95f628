"""--ros-args --params-file: ROS 2 parameter files, applied as rclpy applies them.

The expected values were observed with the real rclpy (Kilted 9.1): a file's
``/**`` section and ``-p`` are for every node, a section naming the node wins
over both, and nested keys become dotted names."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from turtletui.api import RosArgsError, run
from turtletui.runtime.turtlesim_args import parse_turtlesim_args

HOSTS = [True, False]  # sandboxed, in-process

NODES = """
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    for name in ("param_node", "other"):
        node = Node(name, automatically_declare_parameters_from_overrides=True)
        values = {p: node.get_parameter(p).value for p in ("speed", "pid.kp", "pid.gains") if node.has_parameter(p)}
        node.get_logger().info(repr(values))
    rclpy.shutdown()
"""

PARAMS = """
/**:
  ros__parameters:
    speed: 1.5
    pid: {kp: 2.0, gains: [1.0, 2.5]}
param_node:
  ros__parameters:
    speed: 3.0
/turtlesim:
  ros__parameters:
    background_r: 0
"""


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text).lstrip())
    return path


def logged(result, node: str) -> dict:
    (line,) = [r.msg for r in result.logs if r.node == node]
    return eval(line)  # the node logged a dict's repr


@pytest.mark.parametrize("sandbox", HOSTS, ids=["sandboxed", "in-process"])
def test_a_parameter_file_reaches_the_nodes_it_names(tmp_path, sandbox):
    nodes, params = write(tmp_path, "nodes.py", NODES), write(tmp_path, "params.yaml", PARAMS)
    result = run([nodes], duration=0.5, sandbox=sandbox, ros_args=["--params-file", str(params)])
    assert result.ok, result.crashes
    assert logged(result, "param_node") == {"speed": 3.0, "pid.kp": 2.0, "pid.gains": [1.0, 2.5]}
    assert logged(result, "other") == {"speed": 1.5, "pid.kp": 2.0, "pid.gains": [1.0, 2.5]}
    # -p is for every node: over the file's /** section, under a section naming the node
    result = run([nodes], duration=0.5, sandbox=sandbox, ros_args=["--params-file", str(params), "-p", "speed:=9.0"])
    assert logged(result, "param_node")["speed"] == 3.0 and logged(result, "other")["speed"] == 9.0


def test_turtlesim_takes_its_own_parameters_from_a_file_and_leaves_the_rest(tmp_path):
    params = write(tmp_path, "params.yaml", PARAMS)
    assert parse_turtlesim_args(["--params-file", str(params)]).parameters == {"background_r": 0}
    wrong = write(tmp_path, "wrong.yaml", "/turtlesim:\n  ros__parameters:\n    background_r: 300\n")
    with pytest.raises(RosArgsError, match=r"^--params-file: background_r:=300: .*0\.\.255"):
        parse_turtlesim_args(["--params-file", str(wrong)])


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (None, "no such file"),
        ("key: [\n", "not valid YAML at line 2"),
        ("- 1\n- 2\n", "expected node names at the top"),
        ("/node:\n  speed: 1\n", "node '/node' needs a 'ros__parameters:' mapping under it"),
        ("/node:\n  ros__parameters:\n    gains: [1, 'a']\n", "/node: gains: the list mixes types"),
        ("/node:\n  ros__parameters:\n    when: 2024-01-01\n", "/node: when: datetime.date(2024, 1, 1) is not a value"),
    ],
)
def test_a_bad_parameter_file_is_one_line_naming_it(tmp_path, text, message):
    path = tmp_path / "params.yaml"
    if text is not None:
        path.write_text(text)
    with pytest.raises(RosArgsError) as caught:
        run([write(tmp_path, "nodes.py", NODES)], duration=0.5, ros_args=["--params-file", str(path)])
    assert str(caught.value).startswith(f"--params-file {path}: ") and message in str(caught.value)
    assert "\n" not in str(caught.value)
