"""A controller file runs as ``python3 FILE`` runs it (as ``__main__``), in
both hosts; one that never starts itself is started as ``ros2 run`` would.
Whichever way it starts, it runs once, and no crash is made up at the end."""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

import pytest

from turtletui.api import run
from turtletui.runtime.loader import ControllerError

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="the sandbox needs POSIX processes")

HOSTS = {"sandboxed": True, "in-process": False}

NODE = """\
import sys
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.1, self.tick)
        self.ticks = 0
        self.get_logger().info(f"started as {__name__}")

    def tick(self):
        self.ticks += 1
        if self.ticks == FAIL_AT:
            raise RuntimeError("tick failed")  # <- fails here
        msg = Twist()
        msg.linear.x = 1.0
        self.pub.publish(msg)
"""

MAIN = """

def main():
    rclpy.init()
    node = Driver()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.try_shutdown()
"""

VARIANTS = {
    # main() called at the top level, without the __name__ guard
    "unguarded main()": NODE + MAIN + "\n\nmain()\n",
    "guarded main()": NODE + MAIN + '\n\nif __name__ == "__main__":\n    main()\n',
    "sys.exit(main())": NODE + MAIN + '\n\nif __name__ == "__main__":\n    sys.exit(main())\n',
    # what ros2 run calls (console_scripts): never called in the file
    "main() never called": NODE + MAIN,
    "only a Node subclass": NODE,
    "a script": NODE + "\n\nrclpy.init()\nrclpy.spin(Driver())\n",
}


def write(folder: Path, text: str, fail_at: int = 0) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "student.py"
    path.write_text(text.replace("FAIL_AT", str(fail_at)))
    return path


@pytest.mark.parametrize("host", sorted(HOSTS))
@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_a_file_runs_once_whichever_way_it_starts(tmp_path: Path, variant: str, host: str) -> None:
    result = run([write(tmp_path, VARIANTS[variant])], duration=3.0, sandbox=HOSTS[host])
    assert result.crashes == [], result.crashes[0].details()
    starts = [r.msg for r in result.logs if r.node == "driver"]
    assert starts == ["started as __main__"]
    # 1 m/s from the first tick at 0.1 s to the end
    assert result.turtles["turtle1"].distance == pytest.approx(2.9, abs=0.05)


@pytest.mark.parametrize("host", sorted(HOSTS))
@pytest.mark.parametrize("variant", ["unguarded main()", "a script", "main() never called"])
def test_a_crash_shows_the_student_s_own_lines(tmp_path: Path, variant: str, host: str) -> None:
    path = write(tmp_path, VARIANTS[variant], fail_at=5)
    result = run([path], duration=3.0, sandbox=HOSTS[host])
    [crash] = result.crashes
    assert crash.kind == "exception" and crash.message == "RuntimeError: tick failed"
    assert crash.t == pytest.approx(0.5)
    line = next(i for i, text in enumerate(path.read_text().splitlines(), 1) if "<- fails here" in text)
    assert f'File "{path.resolve()}", line {line}, in tick' in crash.frames[-1]
    assert all(str(path.resolve()) in frame for frame in crash.frames)


@pytest.mark.parametrize("host", sorted(HOSTS))
def test_a_script_that_uses_rclpy_and_ends_at_once_is_not_an_error(tmp_path: Path, host: str) -> None:
    path = write(tmp_path, textwrap.dedent("""
        import rclpy
        from geometry_msgs.msg import Twist

        rclpy.init()
        node = rclpy.create_node("once")
        node.get_logger().info("hello")
        node.destroy_node()
        rclpy.shutdown()
    """))
    result = run([path], duration=1.0, sandbox=HOSTS[host])
    assert result.crashes == []
    assert [r.msg for r in result.logs if r.node == "once"] == ["hello"]


def test_a_file_with_nothing_to_run_is_still_a_one_line_error(tmp_path: Path) -> None:
    path = write(tmp_path, "x = 1\n")
    with pytest.raises(ControllerError, match="found no main\\(\\) function and no rclpy Node subclass"):
        run([path], duration=1.0, sandbox=False)
    [crash] = run([path], duration=1.0).crashes
    assert crash.kind == "load" and "found no main() function" in crash.message
