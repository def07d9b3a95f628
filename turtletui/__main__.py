"""``python -m turtletui``: the same as the ``turtletui`` command."""

from turtletui.cli import main

if __name__ == "__main__":
    main()
