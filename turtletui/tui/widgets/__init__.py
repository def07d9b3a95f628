"""Textual widgets of the turtletui app (``arena.ArenaView``: the turtlesim window)."""
