"""The ROS-named interface modules (``geometry_msgs.msg``, ``turtlesim_msgs.srv``
...) of turtletui.compat.ros, filled as rosidl_generator_py fills them.

A real ``geometry_msgs.msg`` re-exports each class from a module of its own
(``geometry_msgs.msg._twist``), which is the class's ``__module__``: what
``type(msg)`` prints, and where ``import geometry_msgs.msg._twist`` and
``sys.modules[type(msg).__module__]`` find it. Those modules exist here too,
made as the package is imported.
"""

from __future__ import annotations

import sys
from types import ModuleType
from typing import Any

from turtletui.interfaces import ros_module_members, ros_submodules


def fill(namespace: dict[str, Any]) -> None:
    """Fill the shim module whose ``globals()`` is ``namespace`` (its name is
    ``package.kind``) with the interfaces' classes and their modules."""
    package, kind = namespace["__name__"].split(".")
    namespace.update(ros_module_members(package, kind))
    for short, members in ros_submodules(package, kind).items():
        module = ModuleType(f"{namespace['__name__']}.{short}")
        module.__file__ = namespace["__file__"]  # where it is made (turtletui.compat.install keeps it)
        module.__package__ = namespace["__name__"]
        vars(module).update(members)
        sys.modules[module.__name__] = module
        namespace[short] = module
