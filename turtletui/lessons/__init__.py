"""Lessons: Markdown files with a TOML front matter block between ``+++`` lines.

:mod:`turtletui.lessons.model` holds the data (:class:`~turtletui.lessons.model.Lesson`,
its scenarios and checks); :mod:`turtletui.lessons.loader` parses and validates
lesson files and finds them (the bundled lessons/ folder, ``--folder`` and
plugins through the ``turtletui_register_lessons`` hook). The format is
documented in lessons/README.md. Nothing here imports a front end.
"""
