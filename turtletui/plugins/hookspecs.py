"""Hook specifications: everything a turtletui plugin can provide.

Every hook is a *registration* hook: it receives a ``register`` callback and
calls it once per thing it provides (the pattern of llm's
``register_models``), so plugin code stays short::

    @hookimpl
    def turtletui_register_lessons(register):
        register(Path(__file__).parent / "lessons")

Hooks are called when turtletui collects what plugins provide (at start-up of
``turtletui run``, ``turtletui grade``, ``turtletui plugins``, ...), once per
command and plugin, in the order plugins were loaded: built-in plugins (among
them the grading engine's own checks), then installed packages (entry
points), then files named with ``--plugin``. When two plugins register the
same name, the one loaded later wins. A hook's return value is ignored.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, Protocol

from turtletui.plugins import hookspec

NodeFactory = Callable[[], Sequence[type]]
"""A zero-argument callable returning the rclpy ``Node`` classes to instantiate.

It is called only when the controller is loaded, in the process that runs
controller code, so it may import ``rclpy`` and message packages (which exist
only there) inside its body.
"""


class RegisterController(Protocol):
    """The ``register`` callback of :func:`turtletui_register_controllers`."""

    def __call__(self, name: str, controller: NodeFactory | Path, description: str = "") -> None:
        """Offer a controller called ``name``: a node factory, or the path of an
        rclpy ``.py`` file with a ``main()``; ``description`` is one line."""


class RegisterLesson(Protocol):
    """The ``register`` callback of :func:`turtletui_register_lessons`."""

    def __call__(self, path: Path) -> None:
        """Offer a lesson file, or a folder of lesson files."""


class RegisterWorld(Protocol):
    """The ``register`` callback of :func:`turtletui_register_worlds`."""

    def __call__(self, name: str, factory: Callable[[], Any], description: str = "") -> None:
        """Offer a world called ``name``; ``factory()`` returns its description."""


class RegisterCheck(Protocol):
    """The ``register`` callback of :func:`turtletui_register_checks`."""

    def __call__(self, name: str, function: Callable[..., Any], description: str = "") -> None:
        """Offer a grading check called ``name``; ``description`` is one line."""


@hookspec
def turtletui_register_controllers(register: RegisterController) -> None:
    """Register controllers (rclpy programs that drive turtles).

    Called when turtletui collects the controllers it can run by name (the
    course's reference nodes are registered this way by the built-in plugin).
    Call ``register(name, controller, description="")`` for each, where
    ``controller`` is either a :data:`NodeFactory` (a zero-argument callable
    returning a list of rclpy Node classes, imported lazily) or a
    :class:`pathlib.Path` to an rclpy ``.py`` file with a ``main()``.
    Returns nothing.
    """


@hookspec
def turtletui_register_lessons(register: RegisterLesson) -> None:
    """Register lessons.

    Called when turtletui collects the lessons it can show and grade. Call
    ``register(path)`` with a :class:`pathlib.Path` to a lesson file or to a
    folder of lesson files. Returns nothing.
    """


@hookspec
def turtletui_register_worlds(register: RegisterWorld) -> None:
    """Register worlds (arenas with obstacles, start poses, ...).

    Called when turtletui collects the worlds a scenario can name. Call
    ``register(name, factory, description="")`` where ``factory()`` returns a
    world description object (called only when the world is used).
    Returns nothing.
    """


@hookspec
def turtletui_register_checks(register: RegisterCheck) -> None:
    """Register grading checks.

    Called when turtletui collects the checks a lesson can name. Call
    ``register(name, function, description="")`` where ``function`` turns a
    recorded run into a scored result. Returns nothing.
    """
