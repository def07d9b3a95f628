"""Run one controller file as an ordinary ROS 2 process: run by a ROS 2 python.

``python3 run_file.py FILE [ARGS...]`` runs FILE as ``python3 FILE`` would
(as ``__main__``: an ``if __name__ == "__main__":`` block runs, and so does
code at its top level); then, if the file never calls its ``main()`` and
started no rclpy context, it does what ``ros2 run`` does with a package's
entry point: calls ``main()``, or creates and spins every Node subclass the
file defines. These are the rules turtletui applies to the files it runs
itself (turtletui.runtime.loader), with the real rclpy.

``sys.argv`` is ``[FILE, ARGS...]`` (``rclpy.init()`` reads the
``--ros-args`` there) and the file's folder comes first on the path. Nothing
of turtletui is imported here, and turtletui's rclpy-shaped modules are
nowhere on the path. Ctrl-C (how turtletui ends a run, as ros2 launch does)
ends it quietly; an exception is printed without this launcher's lines.
"""

from __future__ import annotations

import ast
import os
import sys
import traceback
import types


# calls_main and spin_nodes repeat turtletui.runtime.loader's on purpose: this
# file runs in ROS 2's python, where turtletui is not importable.
def calls_main(source: str) -> bool:
    """Whether the file's top-level code calls ``main`` (also under
    ``if __name__ == "__main__":`` or in ``sys.exit(main())``)."""
    pending = list(ast.parse(source).body)
    while pending:
        node = pending.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)):
            continue
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "main":
            return True
        pending.extend(ast.iter_child_nodes(node))
    return False


def spin_nodes(classes: list) -> None:
    """What a ROS main() does with Node classes: init, create, spin, shut down."""
    import rclpy
    from rclpy.executors import SingleThreadedExecutor

    rclpy.init()
    nodes = [cls() for cls in classes]
    executor = SingleThreadedExecutor()
    for node in nodes:
        executor.add_node(node)
    try:
        executor.spin()
    finally:
        for node in nodes:
            node.destroy_node()
        rclpy.try_shutdown()


def run(path: str) -> int:
    with open(path, encoding="utf-8") as f:
        source = f.read()
    code = compile(source, path, "exec", dont_inherit=True)  # not this module's __future__ imports
    inits = _count_inits()
    module = types.ModuleType("__main__")
    module.__file__ = path
    sys.modules["__main__"] = module
    exec(code, module.__dict__)
    if calls_main(source):
        return 0  # it ran itself
    entry = module.__dict__.get("main")
    if callable(entry):
        if inits[0]:
            return 0  # a script that used rclpy and ended
        result = entry()
        return result if isinstance(result, int) else 0
    if inits[0]:
        return 0
    try:
        from rclpy.node import Node
    except ImportError:
        return 0
    classes = [
        value for value in module.__dict__.values()
        if isinstance(value, type) and issubclass(value, Node) and value is not Node
        and value.__module__ == "__main__"
    ]
    if not classes:
        sys.stderr.write(f"{path}: found no main() function and no rclpy Node subclass to run\n")
        return 1
    spin_nodes(classes)
    return 0


def _count_inits() -> list:
    """A counter of rclpy.init() calls (to tell a script that used rclpy from a module)."""
    count = [0]
    try:
        import rclpy
    except ImportError:
        return count
    real_init = rclpy.init

    def init(*args, **kwargs):
        count[0] += 1
        return real_init(*args, **kwargs)

    init.__doc__ = real_init.__doc__
    rclpy.init = init
    return count


def main() -> int:
    if len(sys.argv) < 2:
        sys.stderr.write("usage: run_file.py FILE [ARGS...]\n")
        return 2
    path = os.path.abspath(sys.argv[1])
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path[:] = [os.path.dirname(path)] + [p for p in sys.path[1:] if os.path.abspath(p or ".") != here]
    sys.argv = [path, *sys.argv[2:]]
    try:
        return run(path)
    except KeyboardInterrupt:
        return 0
    except SystemExit:
        raise
    except BaseException as err:
        if type(err).__name__ == "ExternalShutdownException":  # rclpy, after Ctrl-C
            return 0
        _print_own_traceback(err)
        return 1


def _print_own_traceback(err: BaseException) -> None:
    """The traceback as ``python3 FILE`` prints it: without this launcher's frames."""
    tb = err.__traceback__
    while tb is not None and tb.tb_frame.f_code.co_filename == __file__:
        tb = tb.tb_next
    traceback.print_exception(type(err), err, tb)


if __name__ == "__main__":
    sys.exit(main())
