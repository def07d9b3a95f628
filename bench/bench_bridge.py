"""turtletui on a real ROS 2 graph: the tick, the closed loop, the trajectory.

    python bench/bench_bridge.py [--seconds 30] [--ros-python PATH]

Runs the bridged turtlesim (real time) with the unchanged course Part 6
controller as a real rclpy process, then the same controller in lockstep in
this process (the baseline), and prints:

- the update period (mean, p99 of |period - 16 ms|) and this process's CPU
  (and the twin's) as a share of one core;
- the round trip of the closed loop: a pose leaving turtletui to the
  controller's command arriving back (through the twin and DDS);
- how far the bridged trajectory strays from the lockstep one, aligned at
  the first move, over the ticks before the first command that missed its
  update (a late command shifts the rest, as on a real turtlesim).

The ROS 2 python is ``--ros-python``, ``$TURTLETUI_ROS_PYTHON`` or the
environment scripts/real_ros_env.py built. Discovery stays on this machine.
"""

from __future__ import annotations

import argparse
import os
import platform
import random
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
PART6 = REPO / "plugins" / "reference" / "turtle_controller.py"
TICK = 0.016


def ros_python(explicit: str | None) -> str:
    if explicit or os.environ.get("TURTLETUI_ROS_PYTHON"):
        return explicit or os.environ["TURTLETUI_ROS_PYTHON"]
    found = subprocess.run([sys.executable, str(REPO / "scripts" / "real_ros_env.py"), "--existing"],
                           capture_output=True, text=True)
    if found.returncode != 0:
        sys.exit("no ROS 2: build one with python3 scripts/real_ros_env.py, or give --ros-python")
    return str(Path(found.stdout.strip()) / "ros-python")


class StampedReplies:
    """The twin's replies, each noted with the monotonic time it arrived."""

    def __init__(self, inner, arrivals: list) -> None:
        self._inner = inner
        self._arrivals = arrivals

    def put(self, item) -> None:
        if item and item.get("op") == "message" and item.get("topic") == "/turtle1/cmd_vel":
            self._arrivals.append(time.monotonic())
        self._inner.put(item)

    def __getattr__(self, name):
        return getattr(self._inner, name)


def cpu_seconds(pid: int) -> float:
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rpartition(")")[2].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def bridged(python: str, seconds: float):
    from turtletui.bridge.host import RosBridge
    from turtletui.bridge.run import RosController, connect
    from turtletui.runtime.loader import ControllerSpec
    from turtletui.runtime.simulation import Simulation

    connection = connect(python)
    arrivals: list[float] = []
    proc = connection.twin._proc
    connection.twin.replies = StampedReplies(connection.twin.replies, arrivals)
    sim = Simulation(realtime=True)
    bridge = RosBridge(sim, connection.twin, connection.info)
    sim.remotes.append(bridge)
    ticks: list[float] = []
    poses: list[tuple[float, float]] = []

    def tap(kind, payload):
        if kind == "topic" and payload[0].name == "/turtle1/pose":
            ticks.append(time.monotonic())
            poses.append((payload[1].x, payload[1].y))

    sim.graph.taps.append(tap)
    controller = RosController(connection.twin.python, ControllerSpec(name="part6", path=PART6), output=lambda *_: None)
    # the controller starts; measure once it drives
    deadline = time.monotonic() + 60
    while not arrivals and time.monotonic() < deadline:
        sim.run_until(sim.graph.now_ns + 16_000_000)
    ticks.clear()
    first_arrival = len(arrivals)
    cpu0, twin0, wall0 = resource.getrusage(resource.RUSAGE_SELF), cpu_seconds(proc.pid), time.monotonic()
    sim.run_until(sim.graph.now_ns + round(seconds * 1e9))
    cpu1, twin1, wall1 = resource.getrusage(resource.RUSAGE_SELF), cpu_seconds(proc.pid), time.monotonic()
    controller.stop()
    bridge.close()
    wall = wall1 - wall0
    own_cpu = (cpu1.ru_utime + cpu1.ru_stime - cpu0.ru_utime - cpu0.ru_stime) / wall
    round_trips = []
    j = 0
    measured = arrivals[first_arrival:]
    for tick in ticks:  # the first command after each pose
        while j < len(measured) and measured[j] < tick:
            j += 1
        if j < len(measured):
            round_trips.append(measured[j] - tick)
    return ticks, poses, round_trips, own_cpu, (twin1 - twin0) / wall, sim.world.turtles["turtle1"]


def lockstep(seconds: float):
    from turtletui.api import run

    result = run([PART6], duration=seconds, keep_poses=True, sandbox=False)
    return [(x, y) for _, x, y, _ in result.poses["turtle1"]]


def first_move(poses: list[tuple[float, float]]) -> int:
    x0, y0 = poses[0]
    return next(i for i, (x, y) in enumerate(poses) if (x, y) != (x0, y0))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=30.0)
    parser.add_argument("--ros-python")
    args = parser.parse_args()
    python = ros_python(args.ros_python)
    os.environ.setdefault("ROS_DOMAIN_ID", str(random.SystemRandom().randrange(1, 100)))
    os.environ.setdefault("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")
    load = os.getloadavg()
    ticks, poses, trips, own_cpu, twin_cpu, turtle = bridged(python, args.seconds)
    baseline = lockstep(args.seconds + 10)
    gaps = [later - earlier for earlier, later in zip(ticks, ticks[1:])]  # noqa: B905
    late = [i for i, trip in enumerate(trips) if trip > TICK]
    a, b = first_move(poses), first_move(baseline)
    span = min(len(poses) - a, len(baseline) - b, (late[0] if late else len(poses)))
    deviation = max(
        ((poses[a + i][0] - baseline[b + i][0]) ** 2 + (poses[a + i][1] - baseline[b + i][1]) ** 2) ** 0.5
        for i in range(span)
    ) if span > 0 else float("nan")
    print(f"machine: {platform.platform()}, {os.cpu_count()} CPUs, load {load[0]:.1f} before,"
          f" {os.getloadavg()[0]:.1f} after; python {platform.python_version()}; ROS 2 python {python}")
    print(f"  bridged run                                {args.seconds:.0f} s, {len(ticks)} updates")
    print(f"  update period mean                         {statistics.fmean(gaps) * 1e3:.3f} ms   (16.000)")
    print(f"  update period p99 |period - 16 ms|         "
          f"{sorted(abs(g - TICK) for g in gaps)[int(len(gaps) * 0.99)] * 1e3:.2f} ms")
    print(f"  turtletui CPU / twin CPU (one core)        {own_cpu * 100:.1f} % / {twin_cpu * 100:.1f} %")
    print(f"  closed-loop round trip median / p99        {statistics.median(trips) * 1e3:.2f} ms /"
          f" {sorted(trips)[int(len(trips) * 0.99)] * 1e3:.2f} ms")
    print(f"  commands that missed their update          {len(late)} of {len(trips)}")
    print(f"  trajectory vs lockstep (aligned, {span} ticks) {deviation:.2e} m")
    print(f"  wall hits                                  {turtle.wall_hits}")


if __name__ == "__main__":
    main()
