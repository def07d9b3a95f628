"""What the app shows and drives, without Textual: a live simulation in real
time, its sandboxed controllers, teleop, and the controls (pause, step,
speed, reset, clear, restart, hot reload). The app calls ``advance()`` from
its ticker thread every 16 ms and reads the rest as plain data, holding
``lock`` (the public methods take it themselves).
"""

from __future__ import annotations

import functools
import os
import threading
from collections import Counter, deque
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from turtletui.graph.logs import ERROR, INFO, LogRecord
from turtletui.graph.teleop_node import HEADINGS, TeleopNode
from turtletui.interfaces.std_srvs import Empty
from turtletui.interfaces.turtlesim import RotateAbsolute
from turtletui.runtime.loader import ControllerError, ControllerSpec, check_source
from turtletui.runtime.sandbox import Limits, SandboxHost
from turtletui.runtime.simulation import Simulation
from turtletui.runtime.turtlesim_args import TurtlesimArgs
from turtletui.sim import DT
from turtletui.tui.marks import HitMarks
from turtletui.worlds import WorldSpec

if TYPE_CHECKING:
    from turtletui.bridge.host import RosBridge
    from turtletui.bridge.run import RosConnection

SPEEDS = (0.25, 0.5, 1.0, 2.0, 4.0, 8.0)
"""Simulation speeds the app offers, in simulated seconds per wall second."""

MAX_CATCH_UP = 0.25
"""Wall seconds of simulation at most per advance: after a stall (a
suspended laptop, a slow terminal) the world does not race to catch up."""

_OWNER = "app"

UNCAPPED = 1 << 62
"""A line or byte count no controller reaches."""

LINES_PER_SECOND = 2000
"""print() lines, and log records, of one controller the app shows a second:
taking in more would starve the simulation and the screen, which share the
process (and nobody reads 2,000 lines a second)."""

APP_LIMITS = Limits(
    start_timeout=3.0,
    cpu_seconds=None,
    output_lines=UNCAPPED,
    output_bytes=UNCAPPED,
    output_lines_per_second=LINES_PER_SECOND,
    log_lines=UNCAPPED,
    log_bytes=UNCAPPED,
    log_lines_per_second=LINES_PER_SECOND,
)
"""Controllers in the app live as long as the app: no CPU cap and no cap per
run on what they log or print (the log panel keeps a window of its own), only
LINES_PER_SECOND of each a second; memory, files and the per-step deadline
stay limited as when grading."""

RATE_SECONDS = 1.0
"""Wall seconds over which log rates are measured."""


def _locked(method):
    """Run a method holding its object's ``lock``: the app's ticker thread
    advances the simulation while the screen's thread sends requests."""

    @functools.wraps(method)
    def locked(self, *args, **kwargs):
        with self.lock:
            return method(self, *args, **kwargs)

    return locked


@dataclass
class ControllerSlot:
    """One controller the app runs, and the file it watches for changes."""

    spec: ControllerSpec
    host: SandboxHost | None = None
    mtime: float | None = None
    status: str = "starting"
    """starting, running, stopped (ended normally, or by the user) or failed."""
    detail: str = ""
    held: bool = False
    """Stopped by the user: a change to its file does not start it again."""


@dataclass
class Teleop:
    """turtle_teleop_key as a node of the app (turtletui.graph.teleop_node):
    arrows publish a Twist each, g/t/r/e/d/c/v/b send rotate_absolute goals,
    f cancels."""

    sim: Simulation
    turtle: str = "turtle1"
    goal: Any = None
    ros: TeleopNode = field(init=False)
    node: Any = field(init=False)
    lock: Any = field(default_factory=threading.RLock)

    def __post_init__(self) -> None:
        self.ros = TeleopNode(self.sim.graph, _OWNER, self.sim.distro, turtle=self.turtle)
        self.node = self.ros.node

    @_locked
    def drive(self, linear: float = 0.0, angular: float = 0.0) -> None:
        self.ros.publish(self.ros.key_twist(linear, angular))

    @_locked
    def rotate(self, key: str) -> None:
        self.sim.graph.send_goal(
            f"/{self.turtle}/rotate_absolute",
            RotateAbsolute.Goal(theta=HEADINGS[key]),
            _OWNER,
            self._accepted,
            lambda feedback: None,
            self._finished,
        )

    @_locked
    def cancel(self) -> None:
        if self.goal is not None:
            self.sim.graph.cancel_goal(self.goal)

    def _accepted(self, handle: Any) -> None:
        self.goal = handle

    def _finished(self, status: str, result: Any) -> None:
        self.goal = None
        self.sim.graph.log("teleop_turtle", INFO, f"Rotation goal {status}, turned {result.delta:.4f} rad")


class LiveSession:
    """A real-time simulation with its controllers, for the app."""

    def __init__(
        self,
        controllers: Sequence[ControllerSpec] = (),
        *,
        ros_args: Sequence[str] = (),
        seed: int = 0,
        limits: Limits | None = None,
        log_capacity: int = 2000,
        world: WorldSpec | None = None,
        start: bool = True,
        record: str | None = None,
        foxglove: str | None = None,
        turtlesim: TurtlesimArgs | None = None,
        distro: str | None = None,
        ros: RosConnection | None = None,
    ) -> None:
        """``start``: start the controllers now (else with start_controllers()).
        ``distro``: the ROS 2 distro nodes run as (None: the default).
        ``ros``: on a real ROS 2 graph (``--ros``), the controllers then ROS 2
        processes, and the distro the graph's own."""
        self.lock = threading.RLock()
        """Held by whoever reads or changes the simulation: the app advances it
        from a ticker thread while the screen's thread reads it and sends requests."""
        self.logs: deque[LogRecord] = deque(maxlen=log_capacity)
        """The latest log lines (bounded, so memory stays flat)."""
        self.log_count = 0
        """Log lines seen since the start (the app compares it to know what is new)."""
        self.node_log_counts: Counter[str] = Counter()
        """Log lines per node since the start."""
        self._rate_sample: tuple[float, Counter[str]] | None = None
        self._rates: dict[str, float] = {}
        self._seed = seed
        self._turtlesim = turtlesim or TurtlesimArgs()
        self._distro = distro
        if ros is not None:
            from turtletui.bridge.run import distro_of

            self._distro = distro_of(ros)  # the real graph's, as its turtlesim names its types
        self.hits = HitMarks()
        """Where turtles ran into walls and obstacles lately (the arena marks them)."""
        self._build(world)
        self.paused = False
        self.hold_at_ns: int | None = None
        """Simulated instant (ns) at which the clock pauses once it gets there
        (a replay's end, so that its last frame is held exactly); then None."""
        self.speed = 1.0
        self._ros_args = list(ros_args)
        if self._ros_args and self._ros_args[0] != "--ros-args":
            self._ros_args.insert(0, "--ros-args")
        self._limits = limits or APP_LIMITS
        self._last_wall: float | None = None
        self._outputs: dict[str, Any] = {}
        """The recording and the Foxglove view of this session (``--record``,
        ``--foxglove``), by what they are, for messages."""
        self._open_outputs(record, foxglove)
        self.ros: RosBridge | None = None
        """The bridge onto the real ROS 2 graph (``--ros``), else None."""
        if ros is not None:
            from turtletui.bridge.run import attach

            self.ros = attach(self.sim, ros, earlier_logs=list(self.logs), log_filter=self._turtlesim.log_filter)
        self.slots = [ControllerSlot(spec) for spec in controllers]
        self._started = False
        if start:
            self.start_controllers()

    def _build(self, world: WorldSpec | None) -> None:
        """A new simulation in ``world``, at t = 0, with turtlesim's arguments and teleop."""
        self.world_spec = world
        """The world the simulation runs in (obstacles, LiDAR); None: turtlesim's empty arena."""
        self.sim = Simulation(
            world=None if world is None else world.build(self._seed),
            realtime=True,
            paced=False,
            log_sinks=[self._turtlesim.log_filter(self._on_log)],
            turtlesim_name=self._turtlesim.name,
            distro=self._distro,
        )
        self._turtlesim.apply(self.sim)
        self.teleop = Teleop(self.sim, lock=self.lock)
        self.sim.turtlesim.event_sinks.append(lambda event: self.hits.record(event, self.sim.world.time))
        self._target_ns = 0

    def world_fixed_by(self) -> str | None:
        """What keeps this session in its world (a recording, the Foxglove
        view: each follows one simulation from its start; the real ROS 2
        graph of ``--ros``), or None."""
        fixed = [*self._outputs, *(["the ROS 2 graph (--ros)"] if self.ros is not None else [])]
        return " and ".join(fixed) or None

    @_locked
    def change_world(self, world: WorldSpec | None) -> None:
        """Start the simulation again in ``world`` (None: turtlesim's empty
        arena): a new simulation at t = 0 with that world's turtles and no
        drawing, the controllers restarted in it (those stopped with ``s``
        stay stopped). Callers stop what they run on the old graph (ros2
        commands) and take the new ``sim``. ValueError while
        ``world_fixed_by()`` says what keeps the world."""
        fixed = self.world_fixed_by()
        if fixed is not None:
            raise ValueError(f"{fixed} keeps this session in its world")
        for slot in self.slots:
            self._stop(slot)
        self.hits.clear()
        self._build(world)
        self._log(INFO, f"the simulation starts again in the world {world.name if world else 'empty'}")
        if self._started:
            for slot in self.slots:
                if not slot.held:
                    self._start(slot)

    @_locked
    def start_controllers(self) -> None:
        """Start the controllers (each in its sandbox). A session made with
        ``start=False`` keeps simulated time still until then, so its
        controllers see the run from t = 0."""
        if self._started:
            return
        self._started = True
        for slot in self.slots:
            self._start(slot)

    # -- time ---------------------------------------------------------------
    @property
    def t(self) -> float:
        return self.sim.t

    @_locked
    def advance(self, now: float) -> None:
        """Run the simulation up to wall time ``now`` (time.monotonic())."""
        last, self._last_wall = self._last_wall, now
        if last is None or self.paused or not self._started:
            return
        elapsed = min(max(now - last, 0.0), MAX_CATCH_UP)
        self._run_to(self._target_ns + round(elapsed * self.speed * 1e9))

    @_locked
    def toggle_pause(self) -> bool:
        self.paused = not self.paused
        return self.paused

    @_locked
    def step(self) -> None:
        """One 16 ms step (pauses first)."""
        self.paused = True
        self._run_to(self.sim.graph.now_ns + round(DT * 1e9))

    def _run_to(self, target_ns: int) -> None:
        hold = self.hold_at_ns
        if hold is not None and target_ns >= hold:
            target_ns, self.hold_at_ns, self.paused = hold, None, True
        self._target_ns = target_ns
        self.sim.run_until(target_ns)
        self._watch_controllers()

    @_locked
    def faster(self) -> float:
        self.speed = next((s for s in SPEEDS if s > self.speed), SPEEDS[-1])
        return self.speed

    @_locked
    def slower(self) -> float:
        self.speed = next((s for s in reversed(SPEEDS) if s < self.speed), SPEEDS[0])
        return self.speed

    # -- turtlesim's services -------------------------------------------------
    @_locked
    def reset(self) -> None:
        """Call /reset, as `ros2 service call /reset std_srvs/srv/Empty` would."""
        self.sim.graph.call("/reset", Empty.Request(), lambda response: None, _OWNER)

    @_locked
    def clear(self) -> None:
        self.sim.graph.call("/clear", Empty.Request(), lambda response: None, _OWNER)

    # -- controllers --------------------------------------------------------------
    @_locked
    def restart_controllers(self) -> None:
        for slot in self.slots:
            self._stop(slot)
            self._log(INFO, f"restarting {slot.spec.label}")
            self._start(slot)

    @property
    def controllers_held(self) -> bool:
        """True when the user stopped the controllers (``toggle_controllers``)."""
        return bool(self.slots) and all(slot.held for slot in self.slots)

    @_locked
    def toggle_controllers(self) -> bool:
        """Stop the controller nodes (teleop and ``topic pub`` then drive alone),
        or start them again; returns True when they now run."""
        start = self.controllers_held
        for slot in self.slots:
            if start:
                self._log(INFO, f"starting {slot.spec.label}")
                self._start(slot)
            else:
                self._stop(slot)
                slot.held, slot.status, slot.detail = True, "stopped", "by you"
                self._log(INFO, f"stopped {slot.spec.label} (turtlesim stops the turtle 1 s after its last command)")
        return start

    @_locked
    def check_for_changes(self) -> list[str]:
        """Reload controllers whose file changed; returns what was reloaded.
        A file that no longer compiles is reported and the running one kept."""
        reloaded = []
        if not self._started:
            return reloaded
        for slot in self.slots:
            path = slot.spec.path
            if path is None:
                continue
            mtime = _mtime(path)
            if mtime is None or mtime == slot.mtime:
                continue
            slot.mtime = mtime
            if slot.held:
                continue  # stopped by the user: it starts from the new file when started
            try:
                check_source(path)
            except ControllerError as err:
                self._log(ERROR, f"{err} (the previous version keeps running)")
                continue
            self._stop(slot)
            self._log(INFO, f"{path.name} changed: reloading its node")
            self._start(slot)
            reloaded.append(slot.spec.label)
        return reloaded

    @_locked
    def close(self) -> None:
        for slot in self.slots:
            self._stop(slot)
        if self.ros is not None:
            self.ros.close()
        for output in self._outputs.values():
            try:
                output.close()
            except OSError as err:
                self._log(ERROR, str(err))
        self._outputs = {}

    def _open_outputs(self, record: str | None, foxglove: str | None) -> None:
        if record is not None:
            from turtletui.runtime.recorder import open_recorder

            try:
                recorder = open_recorder(self.sim, record, earlier_logs=list(self.logs))
                self._outputs[f"the recording to {record} (--record)"] = recorder
            except OSError as err:
                self._log(ERROR, f"not recording: {err}")
        if foxglove is not None:
            from turtletui.recording.foxglove import FoxgloveBridge

            try:
                self._outputs["the Foxglove view (--foxglove)"] = FoxgloveBridge(self.sim, foxglove)
            except (OSError, ValueError) as err:
                self._log(ERROR, f"no Foxglove view: {err}")

    def _start(self, slot: ControllerSlot) -> None:
        if slot.spec.path is not None:
            slot.mtime = _mtime(slot.spec.path)
        if self.ros is not None:
            from turtletui.bridge.run import RosController

            slot.host = RosController(
                self.ros.twin.python, slot.spec, self._ros_args, self._controller_output, lambda: self.sim.t
            )
            slot.status, slot.detail, slot.held = "running", "", False
            return
        try:
            slot.host = SandboxHost.start(
                self.sim, slot.spec, ros_args=self._ros_args, seed=self._seed, limits=self._limits
            )
        except ControllerError as err:
            slot.host, slot.status, slot.detail, slot.held = None, "failed", str(err), False
            self._log(ERROR, str(err))
            return
        slot.status, slot.detail, slot.held = "running", "", False
        self._watch_controllers()

    def _stop(self, slot: ControllerSlot) -> None:
        if slot.host is not None:
            slot.host.close()
            slot.host = None

    def _watch_controllers(self) -> None:
        for slot in self.slots:
            host = slot.host
            if host is None or not host.finished:
                continue
            slot.host = None
            if host.crash is not None:
                slot.status, slot.detail = "failed", host.crash.summary()
            else:
                slot.status, slot.detail = "stopped", "its main() returned"

    def _controller_output(self, label: str, line: str) -> None:
        """A line a ROS 2 controller process printed (from its reader thread):
        its log lines arrive through /rosout, the rest goes to the log as its own."""
        from turtletui.bridge.run import is_console_log

        if line.strip() and not is_console_log(line):
            with self.lock:
                self.sim.graph.log(Path(label).stem, INFO, line)

    # -- logs -------------------------------------------------------------------------
    def _on_log(self, record: LogRecord) -> None:
        self.logs.append(record)
        self.log_count += 1
        self.node_log_counts[record.node] += 1

    @_locked
    def log_rates(self, now: float) -> dict[str, float]:
        """Log lines per wall second of each node that logged in the last
        ``RATE_SECONDS`` (measured once per period; ``now`` is time.monotonic())."""
        sample = self._rate_sample
        if sample is None:
            self._rate_sample = (now, self.node_log_counts.copy())
        elif now - sample[0] >= RATE_SECONDS:
            then, counts = sample
            self._rates = {node: (count - counts[node]) / (now - then)
                           for node, count in self.node_log_counts.items() if count > counts[node]}
            self._rate_sample = (now, self.node_log_counts.copy())
        return self._rates

    def _log(self, level: int, msg: str) -> None:
        self.sim.graph.log("turtletui", level, msg)


def _mtime(path: Path) -> float | None:
    try:
        return os.stat(path).st_mtime
    except OSError:
        return None

