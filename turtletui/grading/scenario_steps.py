"""The steps that set a scenario's run up (a turtle's start, a scripted drive).

They run in the grader and again in a sandboxed child's own copy of the
simulation (turtletui.runtime.replica), so this module stays light: the
child imports it.
"""

from __future__ import annotations

from collections.abc import Callable

from turtletui.graph.logs import INFO
from turtletui.runtime.simulation import Simulation


class ScenarioDriver:
    """Drives turtle1 for a scenario with a ``drive`` (linear, angular): the
    same Twist every 16 ms, as a person holding a teleop key would, so that a
    node that only watches sees the turtle move.

    It is that person's turtle_teleop_key, as on a real system: a
    ``teleop_turtle`` node (turtletui.graph.teleop_node) whose cmd_vel
    publisher counts, shows in ``ros2 node list`` and is discovered like
    any other, so its first messages reach turtlesim only once turtlesim
    has discovered it."""

    PERIOD_NS = 16_000_000

    def __init__(self, sim: Simulation, drive: tuple[float, float]) -> None:
        from turtletui.graph.teleop_node import TeleopNode
        from turtletui.interfaces.geometry_msgs import Twist, Vector3

        teleop = TeleopNode(sim.graph, "scenario", sim.distro)
        self.msg = Twist(linear=Vector3(x=drive[0]), angular=Vector3(z=drive[1]))
        """The one message it publishes (the trace tells it from the controller's)."""
        sim.graph.add_timer(teleop.node, self.PERIOD_NS, lambda: teleop.publish(self.msg))


class ScenarioTeleport:
    """Teleports turtle1 once, at a scenario's ``teleport`` (at, x, y, theta), as
    ``ros2 service call /turtle1/teleport_absolute`` from a terminal would (the
    jump shows at turtlesim's next step); ``on_jump`` hears of it (the trace)."""

    def __init__(self, sim: Simulation, teleport: tuple[float, float, float, float], label: str) -> None:
        at, x, y, theta = teleport
        self.on_jump: list[Callable[[str], None]] = []

        def jump() -> None:
            if "turtle1" not in sim.world.turtles:
                return
            sim.world.teleport_absolute("turtle1", x, y, theta)
            sim.graph.log("turtletui", INFO, f"scenario {label}: turtle1 teleported to x=[{x:f}], y=[{y:f}], theta=[{theta:f}]")
            for listener in self.on_jump:
                listener("turtle1")

        sim.graph.call_later(sim.turtlesim.node, round(at * 1e9) - sim.graph.now_ns, jump)


def place_turtle(sim: Simulation, start: tuple[float, float, float], label: str) -> None:
    """Put turtle1 at a scenario's start before anything has run (nothing drawn)."""
    sim.world.place("turtle1", *start)
    turtle = sim.world.turtles["turtle1"]
    sim.graph.log(
        "turtletui",
        INFO,
        f"scenario {label}: turtle1 starts at x=[{turtle.x:f}], y=[{turtle.y:f}], theta=[{turtle.theta:f}]",
    )
