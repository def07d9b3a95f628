"""Lesson files of the course series (installed with turtletui as turtletui.lessons_data)."""
