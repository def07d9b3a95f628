"""A ROS 2 ament_python package as ``ros2 pkg create --build-type ament_python``
lays it out, with the course's ``my_robot_controller`` node, to submit the way
students do: the package folder, or a colcon workspace with it under ``src/``."""

from __future__ import annotations

from pathlib import Path

from support.grading import HONEST

PACKAGE = "my_robot_controller"
EXECUTABLE = "turtle_controller"

SETUP_PY = f'''from setuptools import find_packages, setup

package_name = '{PACKAGE}'

setup(
    name=package_name,
    version='0.0.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages',
            ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='student',
    maintainer_email='student@example.org',
    description='TODO: Package description',
    license='TODO: License declaration',
    tests_require=['pytest'],
    entry_points={{
        'console_scripts': [
            "test_node = {PACKAGE}.my_first_node:main",
            "{EXECUTABLE} = {PACKAGE}.{EXECUTABLE}:main",
        ],
    }},
)
'''

PACKAGE_XML = f"""<?xml version="1.0"?>
<package format="3">
  <name>{PACKAGE}</name>
  <version>0.0.0</version>
  <description>TODO: Package description</description>
  <maintainer email="student@example.org">student</maintainer>
  <license>TODO: License declaration</license>
  <depend>rclpy</depend>
  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
"""

FIRST_NODE = '''import rclpy
from rclpy.node import Node


class MyNode(Node):
    def __init__(self):
        super().__init__("first_node")
        self.create_timer(1.0, lambda: self.get_logger().info("Hello"))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(MyNode())
    rclpy.shutdown()
'''

# the controller keeps its thresholds in a module of its own package, imported
# both ways students write it
UTILS = "SAFE_LOW = 2.0\nSAFE_HIGH = 9.0\n"


def controller_source() -> str:
    return (
        HONEST.replace(
            "from turtlesim.msg import Pose\n",
            f"from turtlesim.msg import Pose\n\nfrom {PACKAGE}.utils import SAFE_LOW\nfrom .utils import SAFE_HIGH\n",
        )
        .replace("pose.x > 9.0", "pose.x > SAFE_HIGH")
        .replace("pose.x < 2.0", "pose.x < SAFE_LOW")
    )


def write_package(folder: Path, controller: str | None = None) -> Path:
    """The package in ``folder``/my_robot_controller; returns that folder."""
    root = folder / PACKAGE
    code = root / PACKAGE
    code.mkdir(parents=True)
    (root / "setup.py").write_text(SETUP_PY)
    (root / "setup.cfg").write_text(
        f"[develop]\nscript_dir=$base/lib/{PACKAGE}\n[install]\ninstall_scripts=$base/lib/{PACKAGE}\n"
    )
    (root / "package.xml").write_text(PACKAGE_XML)
    (root / "resource").mkdir()
    (root / "resource" / PACKAGE).write_text("")
    (root / "test").mkdir()
    (root / "test" / "test_flake8.py").write_text("def test_flake8():\n    assert True\n")
    (code / "__init__.py").write_text("")
    (code / "utils.py").write_text(UTILS)
    (code / "my_first_node.py").write_text(FIRST_NODE)
    (code / f"{EXECUTABLE}.py").write_text(controller or controller_source())
    return root


def write_workspace(folder: Path) -> Path:
    """A colcon workspace ``folder``/ros2_ws with the package under src/ (and the
    build, install and log folders colcon leaves)."""
    workspace = folder / "ros2_ws"
    write_package(workspace / "src")
    for leftover in ("build", "install", "log"):
        (workspace / leftover / PACKAGE).mkdir(parents=True)
    (workspace / "install" / PACKAGE / "setup.py").write_text("raise SystemExit('not this one')\n")
    return workspace
