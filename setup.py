"""Package layout that pyproject.toml cannot express on its own: the reference
nodes (plugins/reference) and the lesson files (lessons/) live at the top of
the repository, where students find them, and install as the packages
turtletui.reference and turtletui.lessons_data."""

from setuptools import find_namespace_packages, setup

setup(
    # Namespace-aware search: compat/ros/ (the rclpy shims) has no __init__.py.
    packages=[
        *find_namespace_packages(include=["turtletui", "turtletui.*"], exclude=["*.__pycache__"]),
        "turtletui.reference",
        "turtletui.lessons_data",
        "turtletui.lessons_data.worlds",  # world files (lessons/worlds/*.toml)
    ],
    package_dir={"turtletui.reference": "plugins/reference", "turtletui.lessons_data": "lessons"},
)
