"""Controller threads take turns in simulated time (sandboxed): the same file
gives the same run every time, and waits in threads behave as in rclpy.

The expected lines of the rclpy programs below are what the real rclpy 9.1.2
(Fast DDS) printed for them, with times from ``time.monotonic()``.
"""

from __future__ import annotations

import sys
import textwrap
import threading
from pathlib import Path

import pytest
from support.controllers import spin_in_a_thread

from turtletui.api import RunResult, run
from turtletui.runtime.sandbox import Limits

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="the sandbox needs POSIX processes")

AVOIDER = """
if pose is not None and not (2.0 < pose.x < 9.0 and 2.0 < pose.y < 9.0):
    cmd.linear.x, cmd.angular.z = 1.0, 1.7
else:
    cmd.linear.x = 3.0
"""

WAITS = {
    "time.sleep": "time.sleep(0.05)",
    "rate.sleep": "rate.sleep()",
    "Event.wait": "threading.Event().wait(0.05)",
}

RATE_IN_MAIN = """
import threading, time
import rclpy
from rclpy.node import Node


class Counter(Node):
    def __init__(self):
        super().__init__("counter")
        self.ticks = 0
        self.create_timer(0.1, self.tick)

    def tick(self):
        self.ticks += 1


def main():
    rclpy.init()
    node = Counter()
    spinner = threading.Thread(target=rclpy.spin, args=(node,), daemon=True)
    spinner.start()
    rate = node.create_rate(5)
    start = time.monotonic()
    for i in range(5):
        rate.sleep()
        print(f"loop {i} after {time.monotonic() - start:.1f} s: {node.ticks} timer ticks", flush=True)
    threading.Event().wait(0.3)
    print(f"after the wait: {node.ticks} timer ticks", flush=True)
    rclpy.shutdown()
    spinner.join()
    print("done", flush=True)


if __name__ == "__main__":
    main()
"""
RATE_IN_MAIN_RCLPY = [
    "loop 0 after 0.2 s: 2 timer ticks",
    "loop 1 after 0.4 s: 4 timer ticks",
    "loop 2 after 0.6 s: 6 timer ticks",
    "loop 3 after 0.8 s: 8 timer ticks",
    "loop 4 after 1.0 s: 10 timer ticks",
    "after the wait: 13 timer ticks",
    "done",
]

QUEUE_FROM_A_CALLBACK = """
import queue, threading, time
import rclpy
from rclpy.node import Node


class Counter(Node):
    def __init__(self):
        super().__init__("counter")
        self.ticks = 0
        self.jobs = queue.Queue()
        self.create_timer(0.1, self.tick)

    def tick(self):
        self.ticks += 1
        if self.ticks % 3 == 0:
            self.jobs.put(self.ticks)


def main():
    rclpy.init()
    node = Counter()
    threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
    start = time.monotonic()
    got = []
    while len(got) < 4:
        try:
            got.append(node.jobs.get(timeout=0.25))
        except queue.Empty:
            got.append(None)
    print(f"got {got} after {time.monotonic() - start:.1f} s", flush=True)
    time.sleep(0.45)
    print(f"after sleeping: {node.ticks} ticks at {time.monotonic() - start:.2f} s", flush=True)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
"""
QUEUE_FROM_A_CALLBACK_RCLPY = ["got [None, 3, None, 6] after 0.6 s", "after sleeping: 10 ticks at 1.05 s"]


def write(folder: Path, text: str, name: str = "node.py") -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / name
    path.write_text(textwrap.dedent(text))
    return path


def printed(result: RunResult) -> list[str]:
    return [r.msg for r in result.logs if r.node.endswith(":stdout")]


def poses(result: RunResult) -> list[tuple[float, float, float, float]]:
    return result.poses["turtle1"]


@pytest.mark.parametrize("wait", sorted(WAITS))
def test_spin_in_a_thread_and_a_loop_in_main_repeat_bit_for_bit(tmp_path: Path, wait: str) -> None:
    path = write(tmp_path, spin_in_a_thread(AVOIDER, WAITS[wait]))
    runs = [run([path], duration=15.0, seed=3, keep_poses=True) for _ in range(3)]
    for result in runs:
        assert result.crashes == [], result.crashes[0].details()
    assert poses(runs[0]) == poses(runs[1]) == poses(runs[2])
    # it drives, and turns back from the walls it meets
    assert runs[0].distance > 30.0
    assert runs[0].wall_hits == 0


def test_rate_and_waits_in_main_wake_after_the_timers_due_then_as_in_rclpy(tmp_path: Path) -> None:
    result = run([write(tmp_path, RATE_IN_MAIN)], duration=3.0)
    assert result.crashes == []
    assert printed(result) == RATE_IN_MAIN_RCLPY


def test_a_queue_fed_by_a_callback_times_out_in_simulated_time_as_in_rclpy(tmp_path: Path) -> None:
    result = run([write(tmp_path, QUEUE_FROM_A_CALLBACK)], duration=3.0)
    assert result.crashes == []
    assert printed(result) == QUEUE_FROM_A_CALLBACK_RCLPY


BLOCKING_IN_A_CALLBACK = """
import queue, select, threading, time
import rclpy
from rclpy.node import Node


class Waiter(Node):
    def __init__(self):
        super().__init__("waiter")
        self.done = False
        self.held = threading.Lock()
        self.held.acquire()
        self.create_timer(0.1, self.tick)

    def tick(self):
        if self.done:
            return
        self.done = True
        start = time.monotonic()
        self.get_logger().info("waiting")
        WAIT
        self.get_logger().info(f"waited {time.monotonic() - start:.3f} s")


def main():
    rclpy.init()
    rclpy.spin(Waiter())
"""

BLOCKING = {
    "Event.wait": "threading.Event().wait(0.5)",
    "Condition.wait": "c = threading.Condition()\n        with c:\n            c.wait(0.5)",
    "Semaphore.acquire": "threading.Semaphore(0).acquire(timeout=0.5)",
    "Lock.acquire": "self.held.acquire(timeout=0.5)",
    "queue.get": "try:\n            queue.Queue().get(timeout=0.5)\n        except queue.Empty:\n            pass",
    "SimpleQueue.get": "try:\n            queue.SimpleQueue().get(timeout=0.5)\n        except queue.Empty:\n            pass",
    "select": "select.select([], [], [], 0.5)",
    "select on a pipe": "import os\n        r, w = os.pipe()\n        select.select([r], [], [], 0.5)",
    "poll": "p = select.poll()\n        p.poll(500)",
    "Barrier.wait": (
        "try:\n            threading.Barrier(2).wait(0.5)\n        except threading.BrokenBarrierError:\n            pass"
    ),
}


@pytest.mark.parametrize("wait", sorted(BLOCKING))
def test_a_blocking_wait_in_a_callback_passes_in_simulated_time(tmp_path: Path, wait: str) -> None:
    """As ``time.sleep`` does: the node is blocked for half a simulated second,
    the world goes on, and no wall time is spent waiting (a 0.5 s wait per
    callback used to cost 0.5 s of wall time each)."""
    path = write(tmp_path, BLOCKING_IN_A_CALLBACK.replace("WAIT", BLOCKING[wait]))
    result = run([path], duration=2.0, limits=Limits(realtime_lag=0.3))
    assert result.crashes == [], result.crashes[0].details()
    lines = {r.msg: r.t for r in result.logs if r.node == "waiter"}
    assert lines == {"waiting": pytest.approx(0.1), "waited 0.500 s": pytest.approx(0.6)}


TURNS = """
import queue, threading, time
from concurrent.futures import ThreadPoolExecutor
import rclpy
from rclpy.node import Node

log = []
lock = threading.Lock()
ready = threading.Condition(lock)
items = queue.Queue(maxsize=2)


def producer(name):
    for i in range(4):
        items.put(f"{name}{i}")
        with lock:
            log.append(f"put {name}{i} at {time.monotonic() - 1700000000:.2f}")
            ready.notify_all()
        time.sleep(0.01)


def consumer():
    for _ in range(8):
        item = items.get()
        log.append(f"got {item} at {time.monotonic() - 1700000000:.2f}")
        time.sleep(0.015)


def square(x):
    time.sleep(0.001 * x)
    return x * x


def main():
    rclpy.init()
    node = Node("turns")
    threads = [threading.Thread(target=producer, args=(n,)) for n in "ab"] + [threading.Thread(target=consumer)]
    for thread in threads:
        thread.start()
    with ThreadPoolExecutor(max_workers=3) as pool:
        squares = list(pool.map(square, range(6)))
    for thread in threads:
        thread.join()
    timer = threading.Timer(0.2, lambda: log.append(f"timer at {time.monotonic() - 1700000000:.2f}"))
    timer.start()
    timer.join()
    print("|".join(log), squares, [t.is_alive() for t in threads], flush=True)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
"""


def test_threads_take_turns_the_same_way_every_time(tmp_path: Path) -> None:
    path = write(tmp_path, TURNS)
    first, second = (run([path], duration=2.0) for _ in range(2))
    assert first.crashes == [] and second.crashes == []
    [line] = printed(first)
    assert printed(second) == [line]
    events, squares, alive = line.rsplit(" [", 2)
    assert squares == "0, 1, 4, 9, 16, 25]" and alive == "False, False, False]"
    events = events.split("|")
    assert sorted(e.split()[1] for e in events if e.startswith("put")) == [f"{n}{i}" for n in "ab" for i in range(4)]
    got = [e.split()[1] for e in events if e.startswith("got")]
    assert sorted(got) == [f"{n}{i}" for n in "ab" for i in range(4)]
    # each producer's items come out in its own order (one FIFO queue)
    for name in "ab":
        assert [g for g in got if g.startswith(name)] == [f"{name}{i}" for i in range(4)]
    # the consumer takes 15 ms per item: eight items take at least 0.105 s of simulated time
    assert float(events[-2].split()[-1]) >= 0.105
    assert events[-1].startswith("timer at ")


OTHER_THREADS = """
import threading, time
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


def drive(node, pub):
    start = time.time()
    while time.time() - start < 2.0:
        msg = Twist()
        msg.linear.x = 1.0
        pub.publish(msg)
        time.sleep(0.1)
    pub.publish(Twist())
    node.get_logger().info("stopped")


def fail():
    raise ValueError("a thread fails")


def main():
    rclpy.init()
    node = Node("driver")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    threading.Thread(target=fail).start()
    threading.Thread(target=drive, args=(node, pub)).start()
    # main() returns at once: as in Python, the program goes on while a thread that is not a daemon runs
"""


def test_a_program_lives_as_long_as_its_threads_and_a_failing_thread_does_not_end_it(tmp_path: Path) -> None:
    result = run([write(tmp_path, OTHER_THREADS)], duration=4.0)
    assert result.crashes == []
    assert result.turtles["turtle1"].distance == pytest.approx(2.0, abs=0.1)
    [stopped] = [r.t for r in result.logs if r.msg == "stopped"]
    assert stopped == pytest.approx(2.0, abs=0.11)
    # Python's report of the failed thread, with the student's line, on stderr
    output = "\n".join(r.msg for r in result.logs if r.node.endswith(":stderr"))
    assert "ValueError: a thread fails" in output and 'raise ValueError("a thread fails")' in output


def test_threads_in_an_in_process_controller_are_refused_with_a_clear_message(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    failures: list[BaseException] = []
    monkeypatch.setattr(threading, "excepthook", lambda args: failures.append(args.exc_value))
    path = write(tmp_path, spin_in_a_thread(AVOIDER, "time.sleep(0.05)"))
    result = run([path], duration=1.0, sandbox=False)
    # the spinning thread stops at once with the reason; the main loop goes on
    [failure] = failures
    assert "run it sandboxed (without --in-process) to use threads" in str(failure)
    assert result.crashes == [] and result.sim_time == pytest.approx(1.0)


def test_threads_waiting_for_ever_on_each_other_are_a_deadlock_at_once(tmp_path: Path) -> None:
    """A thread waits for an event nobody sets, main() joins it: a hung
    program on a robot. In simulated time nothing else can happen, so it is
    reported then, as a deadlock at main()'s line (the waiting thread runs no
    line of the student's), instead of ending the waits when the run ends as
    if the program had gone on (it printed "joined")."""
    path = write(tmp_path, """
        import threading
        import rclpy
        from rclpy.node import Node

        def main():
            rclpy.init()
            node = Node("stuck")
            never = threading.Event()
            waiter = threading.Thread(target=never.wait)
            waiter.start()
            waiter.join()
            print("joined", flush=True)
    """)
    result = run([path], duration=1.0)
    [crash] = result.crashes
    assert crash.kind == "deadlock" and crash.t == 0.0
    assert [frame.splitlines()[1].strip() for frame in crash.frames] == ["waiter.join()"]
    assert printed(result) == []
