"""Message hot paths: building, copying and importing ROS messages (no asserts: a table to read).

Run from the repository root:  python bench/bench_messages.py [--repeats N]
Each figure is the best of N repeats (the least disturbed by other work), in
microseconds per operation, with its ratio to a baseline measured in the same
process: building a plain two-slot Python object.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import timeit
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from turtletui.interfaces import copier  # noqa: E402
from turtletui.interfaces.geometry_msgs import Twist  # noqa: E402
from turtletui.interfaces.turtlesim import Pose  # noqa: E402


class _Plain:
    __slots__ = ("a", "b")

    def __init__(self) -> None:
        self.a = 0.0
        self.b = 0.0


def best_us(fn, number: int, repeats: int) -> float:
    return min(timeit.repeat(fn, number=number, repeat=repeats)) / number * 1e6


def import_ms(repeats: int) -> float:
    code = "import time; t = time.perf_counter(); import turtletui.interfaces; print(time.perf_counter() - t)"
    times = [
        float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT).stdout)
        for _ in range(repeats)
    ]
    return min(times) * 1e3


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    number = 50_000
    twist = Twist()
    twist.linear.x = 2.0
    pose = Pose(x=1.0, y=2.0)
    copy_twist, copy_pose = copier(Twist), copier(Pose)
    baseline = best_us(_Plain, number, args.repeats)
    figures = [
        ("Twist()", best_us(Twist, number, args.repeats)),
        ("Pose._trusted(5 floats)", best_us(lambda: Pose._trusted(1.0, 2.0, 3.0, 0.0, 0.0), number, args.repeats)),
        ("copy of a Twist (publish)", best_us(lambda: copy_twist(twist), number, args.repeats)),
        ("copy of a Pose (a subscription's own)", best_us(lambda: copy_pose(pose), number, args.repeats)),
    ]
    print(f"python:  {sys.version.split()[0]}, best of {args.repeats}")
    print(f"\n  {'figure':<40}{'us/op':>10}{'x baseline':>12}")
    print(f"  {'baseline: a plain 2-slot object':<40}{baseline:>10.3f}{1:>12.1f}")
    for name, us in figures:
        print(f"  {name:<40}{us:>10.3f}{us / baseline:>12.1f}")
    print(f"  {'import turtletui.interfaces (ms)':<40}{import_ms(args.repeats):>10.1f}")


if __name__ == "__main__":
    main()
