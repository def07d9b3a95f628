"""Tools for testing controllers: :func:`check_controller` and the pytest plugin.

    from turtletui.testing import check_controller

    report = check_controller("my_node.py", seconds=10)
    print(report.summary())

Like Gymnasium's ``check_env``: it raises :class:`ControllerCheckError` naming
what differs and where, or returns a :class:`ControllerCheck` report. The
pytest fixtures live in :mod:`turtletui.testing.pytest_plugin` (loaded by
pytest through the ``pytest11`` entry point); importing this package needs
neither pytest nor Textual.
"""

from turtletui.testing.checker import ControllerCheck, ControllerCheckError, check_controller

__all__ = ["ControllerCheck", "ControllerCheckError", "check_controller"]
