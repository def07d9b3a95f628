"""Run one controller file as ``ros2 run`` runs a node: run by a ROS 2 python.

``python3 run_file.py FILE [ARGS...]``: FILE is imported as a module (not as
``__main__``), then its ``main()`` is called, as the console script of a ROS
2 package calls its entry point; a file without ``main()`` is a plain script
and has already run. ``sys.argv`` is ``[FILE, ARGS...]`` (``rclpy.init()``
reads the ``--ros-args`` there) and the file's folder comes first on the
path, as for ``python3 FILE``. Nothing of turtletui is imported here, and
turtletui's rclpy-shaped modules are nowhere on the path: the file gets the
real rclpy. Ctrl-C (how turtletui ends a run, as ros2 launch does) ends it
quietly.
"""

from __future__ import annotations

import os
import runpy
import sys
import traceback


def main() -> int:
    if len(sys.argv) < 2:
        sys.stderr.write("usage: run_file.py FILE [ARGS...]\n")
        return 2
    path = os.path.abspath(sys.argv[1])
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path[:] = [os.path.dirname(path)] + [p for p in sys.path[1:] if os.path.abspath(p or ".") != here]
    sys.argv = [path, *sys.argv[2:]]
    try:
        namespace = runpy.run_path(path, run_name="__turtletui_ros__")
        entry = namespace.get("main")
        if callable(entry):
            result = entry()
            return result if isinstance(result, int) else 0
    except KeyboardInterrupt:
        return 0
    except SystemExit:
        raise
    except BaseException as err:
        if type(err).__name__ == "ExternalShutdownException":  # rclpy, after Ctrl-C
            return 0
        _print_own_traceback(err)
        return 1
    return 0


def _print_own_traceback(err: BaseException) -> None:
    """The traceback as ``python3 FILE`` prints it: without this launcher's frames."""
    tb = err.__traceback__
    while tb is not None and tb.tb_frame.f_code.co_filename in (__file__, runpy.__file__):
        tb = tb.tb_next
    traceback.print_exception(type(err), err, tb)


if __name__ == "__main__":
    sys.exit(main())
