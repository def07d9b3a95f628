"""The grading engine's own checks, registered through
``turtletui_register_checks`` like any plugin's (a built-in plugin: see
turtletui.plugins.manager.BUILTIN_PLUGINS)."""

from __future__ import annotations

from turtletui.grading.checks import BUILTIN_CHECKS
from turtletui.plugins import hookimpl
from turtletui.plugins.hookspecs import RegisterCheck


@hookimpl
def turtletui_register_checks(register: RegisterCheck) -> None:
    for check in BUILTIN_CHECKS.values():
        register(check.name, check, check.description)
