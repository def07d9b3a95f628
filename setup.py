"""Package layout that pyproject.toml cannot express on its own: the reference
nodes live at the top of the repository (plugins/reference), where students
find them, and install as the package turtletui.reference."""

from setuptools import find_namespace_packages, setup

setup(
    # Namespace-aware search: compat/ros/ (the rclpy shims) has no __init__.py.
    packages=[
        *find_namespace_packages(include=["turtletui", "turtletui.*"], exclude=["*.__pycache__"]),
        "turtletui.reference",
    ],
    package_dir={"turtletui.reference": "plugins/reference"},
)
