"""The sandboxed child's own copy of the trusted side, for the fast path.

A run with one sandboxed controller, in lockstep and with nothing
interactive, need not stop at every exchange to ask the parent: the child
runs the controller against a copy of the simulation, built from a
:class:`Recipe` (the world as it was before the run, the distro, the steps
that set the run up), and the parent replays what the controller did
through its own simulation (turtletui.runtime.fastpath). The recipe holds
only what the controller could observe anyway: never the grader's memory.

:func:`recipe_for` decides, in one place, whether a run may take the fast
path; :func:`build_copy` builds the child's copy; :func:`digest` is what the
two sides compare to find a copy the controller tampered with.
"""

from __future__ import annotations

import base64
import importlib
import json
import os
import pickle
import zlib
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from turtletui.runtime.loader import ControllerSpec
    from turtletui.runtime.simulation import Simulation
    from turtletui.sim import World

LOCKSTEP_VAR = "TURTLETUI_LOCKSTEP"
"""Set to 1: every sandboxed run keeps the lockstep path (tests and bench compare both)."""


@dataclass(frozen=True)
class Step:
    """One step of a run's set-up a child can redo on its copy:
    ``function(sim, *args)``, ``function`` named ``"module:qualname"``,
    ``args`` plain data."""

    function: str
    args: tuple = ()

    def __call__(self, sim: Simulation) -> Any:
        return _resolve(self.function)(sim, *self.args)


@dataclass
class ReplicableSetup:
    """A run's set-up (api.run's ``setup``) in two parts: ``steps`` change the
    simulation in ways the child's copy redoes from data (a turtle's start, a
    scripted drive); ``observe`` adds what stays with the trusted process
    (taps, recorders, collectors) and must change neither the graph nor the
    world (a graph it changed keeps the run in lockstep)."""

    steps: Sequence[Step] = ()
    observe: Callable[[Simulation], None] | None = None
    graph_version: int | None = field(default=None, init=False)
    """The graph's version once the steps were done (None: not run yet)."""
    results: list[Any] = field(default_factory=list, init=False)
    """What each step returned, for ``observe``."""

    def __call__(self, sim: Simulation) -> None:
        self.results = [step(sim) for step in self.steps]
        self.graph_version = sim.graph.version
        if self.observe is not None:
            self.observe(sim)


@dataclass(frozen=True)
class Recipe:
    """How the child builds its copy of the simulation: a plain-data config entry."""

    world: str
    """The world before the run, pickled, compressed and in base64."""
    distro: str
    discovery_ns: int
    end_ns: int
    steps: tuple[Step, ...] = ()

    def to_config(self) -> dict[str, Any]:
        return {
            "world": self.world,
            "distro": self.distro,
            "discovery_ns": self.discovery_ns,
            "end_ns": self.end_ns,
            "steps": [[step.function, list(step.args)] for step in self.steps],
        }

    @classmethod
    def from_config(cls, data: dict[str, Any]) -> Recipe:
        steps = tuple(Step(function, tuple(_tuples(args))) for function, args in data["steps"])
        return cls(data["world"], data["distro"], data["discovery_ns"], data["end_ns"], steps)


def _tuples(value: Any) -> Any:
    """JSON's lists back as tuples (a start pose was a tuple)."""
    return tuple(_tuples(v) for v in value) if isinstance(value, list) else value


def snapshot_world(world: World | None) -> str | None:
    """The world as the copy starts from it (None: turtlesim's own empty arena);
    "" if it cannot be copied (the run then keeps the lockstep path)."""
    if world is None:
        return None
    try:
        return base64.b64encode(zlib.compress(pickle.dumps(world, protocol=5), 1)).decode()
    except Exception:  # noqa: BLE001 - a plugin's world may hold anything
        return ""


FAST_PATH_MIN_NS = 120_000_000_000
"""Simulated time from which the fast path pays for itself in a child started
afresh: its copy of the simulation costs it about 0.1 s to import (numpy, the
simulator) and saves about 12 us of a 35 us exchange (bench/bench_ratios.py).
A child forked from a fork server (grading) has imported it already."""


def forced_lockstep() -> bool:
    return os.environ.get(LOCKSTEP_VAR, "") not in ("", "0")


def _fast_path_pays(end_ns: int) -> bool:
    from turtletui.runtime import forkserver

    return end_ns >= FAST_PATH_MIN_NS or forkserver.servers() is not None


def recipe_for(
    sim: Simulation,
    specs: Sequence[ControllerSpec],
    *,
    world: str | None,
    setup: Callable[[Simulation], None] | None,
    graph_version: int,
    end_ns: int,
    lockstep: bool | None = None,
) -> Recipe | None:
    """The recipe of the child's copy if this run may take the fast path, else
    None. ``world`` is :func:`snapshot_world` of the world before the
    simulation was built; ``graph_version`` the graph's version right after
    it was built (before ``setup``).

    Fast: exactly one controller, sandboxed; lockstep time (on Linux); a set-up the
    child can redo (none, or a ReplicableSetup whose observers left the graph
    as its steps made it); nothing else on the graph (a bag's player or
    recorder, teleop, the app). Anything else keeps the lockstep path.
    ``lockstep`` as Limits.lockstep: None takes the fast path only where it
    pays (a long run, or a child from a fork server).
    """
    if lockstep or forced_lockstep() or sim.realtime or len(specs) != 1 or specs[0].trusted:
        return None
    if lockstep is None and not _fast_path_pays(end_ns):
        return None
    if not hasattr(os, "memfd_create"):  # the shared journal (Linux)
        return None
    if world == "":
        return None
    steps: tuple[Step, ...] = ()
    if setup is not None:
        if not isinstance(setup, ReplicableSetup) or setup.graph_version is None:
            return None
        steps = tuple(setup.steps)
        graph_version = setup.graph_version
    if sim.graph.version != graph_version:
        return None
    world_data = world if world is not None else ""
    return Recipe(world_data, sim.distro, sim.graph.discovery_ns, end_ns, steps)


def build_copy(recipe: Recipe) -> Simulation:
    """The child's copy of the simulation the parent built from the same recipe."""
    from turtletui.runtime.simulation import Simulation

    world = pickle.loads(zlib.decompress(base64.b64decode(recipe.world))) if recipe.world else None
    sim = Simulation(world=world, distro=recipe.distro)
    sim.graph.discovery_ns = recipe.discovery_ns
    for step in recipe.steps:
        step(sim)
    return sim


def digest(sim: Simulation) -> bytes:
    """What the two sides compare: the time and every turtle's pose, exactly."""
    turtles = [[name, t.x, t.y, t.theta] for name, t in sim.world.turtles.items()]
    return json.dumps([sim.graph.now_ns, turtles], separators=(",", ":")).encode()


def describe_difference(theirs: bytes, ours: bytes) -> str:
    """A line saying how the child's copy differs from the trusted simulation."""
    try:
        now, turtles = json.loads(theirs)
        claimed = {str(t[0]): (float(t[1]), float(t[2])) for t in turtles}
    except Exception:  # noqa: BLE001 - untrusted bytes
        return "its copy of the simulator sent a state turtletui cannot read"
    _, actual = json.loads(ours)
    for name, x, y, _theta in actual:
        if name not in claimed:
            return f"{name} was missing from its copy of the simulator"
        cx, cy = claimed[name]
        if (cx, cy) != (x, y):
            return f"its copy had {name} at ({cx:.3f}, {cy:.3f}), the simulator at ({x:.3f}, {y:.3f})"
    extra = sorted(set(claimed) - {t[0] for t in actual})
    if extra:
        return f"its copy of the simulator had a turtle the simulator has not: {extra[0][:60]}"
    return "its copy of the simulator was in another state than the simulator"


def _resolve(reference: str) -> Callable[..., Any]:
    module, _, qualname = reference.partition(":")
    target: Any = importlib.import_module(module)
    for part in qualname.split("."):
        target = getattr(target, part)
    return target
