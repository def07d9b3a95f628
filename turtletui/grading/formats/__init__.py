"""Report formats of the platforms and gradebooks instructors use, one module
each; :mod:`turtletui.grading.reports` renders them by name."""
