"""Helpers shared by several test folders (``tests`` is on pytest's pythonpath:
``from support.grading import ...``), so that the suite runs against the
installed turtletui, not the source tree."""
