"""rclpy.lifecycle under both hosts: a managed node driven from another file
through its services, and turtletui's notes where rclpy stays silent.

tests/fidelity/programs/lifecycle_node.py checks the same API against the
real rclpy (Kilted).
"""

from __future__ import annotations

from support.hosts import node_logs, write_controller

from turtletui.api import run

MANAGED = """
import rclpy
from rclpy.lifecycle import LifecycleNode, TransitionCallbackReturn
from geometry_msgs.msg import Twist


class Driver(LifecycleNode):
    def __init__(self):
        super().__init__("driver")
        self.pub = None
        self.create_timer(0.1, self.tick)

    def on_configure(self, state):
        self.pub = self.create_lifecycle_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.get_logger().info(f"configured from {state.label}")
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state):
        self.get_logger().info("activated")
        return super().on_activate(state)

    def tick(self):
        if self.pub is not None:
            msg = Twist()
            msg.linear.x = 1.0
            self.pub.publish(msg)
"""

MANAGER = """
import rclpy
from rclpy.node import Node
from lifecycle_msgs.msg import Transition, TransitionEvent
from lifecycle_msgs.srv import ChangeState, GetState


class Manager(Node):
    def __init__(self):
        super().__init__("manager")
        self.create_subscription(TransitionEvent, "/driver/transition_event", self.seen, 10)
        self.change = self.create_client(ChangeState, "/driver/change_state")
        self.get = self.create_client(GetState, "/driver/get_state")
        self.steps = [Transition.TRANSITION_CONFIGURE, Transition.TRANSITION_ACTIVATE]
        self.create_timer(0.5, self.step)

    def step(self):
        if self.steps:
            request = ChangeState.Request()
            request.transition.id = self.steps.pop(0)
            self.change.call_async(request).add_done_callback(
                lambda f: self.get_logger().info(f"changed {f.result().success}"))
        else:
            self.get.call_async(GetState.Request()).add_done_callback(
                lambda f: self.get_logger().info(f"state {f.result().current_state.label}"))

    def seen(self, event):
        self.get_logger().info(f"event {event.start_state.label} -> {event.goal_state.label}")
"""


def test_a_lifecycle_node_driven_from_another_file_drives_only_once_active(tmp_path):
    # two files run sandboxed only (in-process runs one file)
    result = run([write_controller(tmp_path, MANAGED, "driver.py"), write_controller(tmp_path, MANAGER, "manager.py")], duration=2.0)
    assert result.ok, result.crashes
    assert node_logs(result, "driver") == ["configured from unconfigured", "activated"]
    assert node_logs(result, "manager") == [
        "event unconfigured -> configuring", "event configuring -> inactive", "changed True",
        "event inactive -> activating", "event activating -> active", "changed True",
        "state active", "state active",
    ]
    # driving from the activation at t=1.0 s on: 1 m/s for about a second
    assert 0.8 < result.turtles["turtle1"].distance < 1.1


SELF_MANAGED = """
import rclpy
from rclpy.lifecycle import LifecycleNode, TransitionCallbackReturn
from std_msgs.msg import String


class Steps(LifecycleNode):
    def __init__(self):
        super().__init__("steps")
        self.pub = self.create_lifecycle_publisher(String, "out", 10)
        self.pub.publish(String(data="too early"))
        self.pub.publish(String(data="too early again"))
        self.get_logger().info(f"{self.trigger_activate()}")
        self.get_logger().info(f"{self.trigger_configure()} {self.trigger_activate()}")
        self.get_logger().info(f"{self.trigger_deactivate()} {self._state_machine.current_state}")

    def on_deactivate(self, state):
        raise ValueError("no way")
"""


def test_mistakes_rclpy_hides_are_told_once(controller_host):
    result = controller_host.run(SELF_MANAGED, duration=0.2)
    assert result.ok, result.crashes
    assert node_logs(result, "steps") == [
        "Unable to start transition 3 from current state (1, 'unconfigured')",
        "TransitionCallbackReturnType.ERROR",
        "TransitionCallbackReturnType.SUCCESS TransitionCallbackReturnType.SUCCESS",
        "TransitionCallbackReturnType.ERROR (1, 'unconfigured')",
    ]
    assert node_logs(result, "rcl_lifecycle") == ["No transition matching 3 found for current state unconfigured"]
    notes = node_logs(result, "turtletui")
    assert [n.split(" ", 1)[0] for n in notes] == ["/steps", "/steps's"]
    assert notes[0].startswith("/steps published on /out while its lifecycle publisher is not activated")
    assert notes[1].startswith("/steps's on_deactivate() raised ValueError: no way")


def test_a_transition_callback_returning_nothing_is_a_clear_error(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.lifecycle import LifecycleNode


class Forgetful(LifecycleNode):
    def __init__(self):
        super().__init__("forgetful")
        self.trigger_configure()

    def on_configure(self, state):
        self.get_logger().info("configuring")
""",
        duration=0.2,
    )
    assert not result.ok
    [crash] = result.crashes
    assert crash.message == (
        "TypeError: on_configure() must return TransitionCallbackReturn.SUCCESS, FAILURE or ERROR, got None"
    )
