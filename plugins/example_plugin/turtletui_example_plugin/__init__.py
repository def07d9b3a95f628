"""An example turtletui plugin: registers the controller ``example_square``.

This module is imported whenever turtletui loads its plugins (``turtletui
plugins``, ``turtletui run``, ...), in processes that have no ``rclpy``. So it
imports nothing from ROS: the node lives in :mod:`turtletui_example_plugin.square`,
which is imported only when the controller is loaded, where turtletui provides
``rclpy`` and the message packages.
"""

from __future__ import annotations

from turtletui.plugins import hookimpl


def square_nodes() -> list[type]:
    """The node factory: the Node classes to instantiate for ``example_square``."""
    from turtletui_example_plugin.square import SquareDriver

    return [SquareDriver]


@hookimpl
def turtletui_register_controllers(register):
    register(
        "example_square",
        square_nodes,
        "Drives turtle1 in a square with a timer (parameters side_length, speed)",
    )
