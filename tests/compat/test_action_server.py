"""rclpy.action.ActionServer under both hosts, and between two sandboxed controllers.

The expectations are rclpy 9's (tests/fidelity/programs/action_server.py
checks the same against the real rclpy).
"""

from __future__ import annotations

import textwrap
from pathlib import Path

from support.hosts import node_logs

from turtletui.api import run

FIBONACCI_SERVER = """
import time

import rclpy
from rclpy.action import ActionServer
from rclpy.node import Node
from example_interfaces.action import Fibonacci


class FibonacciActionServer(Node):
    def __init__(self):
        super().__init__("fibonacci_action_server")
        self._action_server = ActionServer(self, Fibonacci, "fibonacci", self.execute_callback)

    def execute_callback(self, goal_handle):
        self.get_logger().info("Executing goal...")
        feedback_msg = Fibonacci.Feedback()
        feedback_msg.sequence = [0, 1]
        for i in range(1, goal_handle.request.order):
            feedback_msg.sequence.append(feedback_msg.sequence[i] + feedback_msg.sequence[i - 1])
            self.get_logger().info(f"Feedback: {feedback_msg.sequence}")
            goal_handle.publish_feedback(feedback_msg)
            time.sleep(1)
        goal_handle.succeed()
        result = Fibonacci.Result()
        result.sequence = feedback_msg.sequence
        return result
"""

FIBONACCI_CLIENT = """
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from example_interfaces.action import Fibonacci


class FibonacciActionClient(Node):
    def __init__(self):
        super().__init__("fibonacci_action_client")
        self._action_client = ActionClient(self, Fibonacci, "fibonacci")

    def send_goal(self, order):
        self._action_client.wait_for_server()
        self._send_goal_future = self._action_client.send_goal_async(
            Fibonacci.Goal(order=order), feedback_callback=self.feedback_callback
        )
        self._send_goal_future.add_done_callback(self.goal_response_callback)

    def goal_response_callback(self, future):
        goal_handle = future.result()
        if not goal_handle.accepted:
            self.get_logger().info("Goal rejected :(")
            return
        self.get_logger().info("Goal accepted :)")
        goal_handle.get_result_async().add_done_callback(self.get_result_callback)

    def get_result_callback(self, future):
        self.get_logger().info(f"Result: {list(future.result().result.sequence)}")
        rclpy.shutdown()

    def feedback_callback(self, feedback_msg):
        self.get_logger().info(f"Received feedback: {list(feedback_msg.feedback.sequence)}")
"""


def test_the_official_action_server_tutorial_with_its_client_in_the_same_file(controller_host):
    result = controller_host.run(
        FIBONACCI_SERVER
        + FIBONACCI_CLIENT
        + """
def main():
    rclpy.init()
    server = FibonacciActionServer()
    client = FibonacciActionClient()
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(server)
    executor.add_node(client)
    client.send_goal(4)
    executor.spin()
""",
        duration=10.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "fibonacci_action_server") == [  # int32[] is an array, as in rclpy
        "Executing goal...",
        "Feedback: array('i', [0, 1, 1])",
        "Feedback: array('i', [0, 1, 1, 2])",
        "Feedback: array('i', [0, 1, 1, 2, 3])",
    ]
    # A single-threaded executor runs the blocking execute callback to its end
    # before the client hears that its goal was accepted. The real rclpy (Kilted,
    # measured) then logs the first feedback before "Goal accepted": its client
    # takes the goal response and one feedback together, and the goal future's done
    # callback runs two spins later, as a task. turtletui takes them one at a time,
    # so where "Goal accepted" falls among the feedback is not compared here.
    client_logs = node_logs(result, "fibonacci_action_client")
    assert [line for line in client_logs if line != "Goal accepted :)"] == [
        "Received feedback: [0, 1, 1]",
        "Received feedback: [0, 1, 1, 2]",
        "Received feedback: [0, 1, 1, 2, 3]",
        "Result: [0, 1, 1, 2, 3]",
    ]
    assert client_logs.count("Goal accepted :)") == 1
    ended = [r.t for r in result.logs if r.msg.startswith("Result:")]
    assert ended == [3.0]  # three 1 s sleeps of simulated time


def test_async_goal_and_execute_callbacks_reject_and_abort(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.action import ActionClient, ActionServer, GoalResponse
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


class Server(Node):
    def __init__(self):
        super().__init__("server")
        ActionServer(self, RotateAbsolute, "turn", self.execute, goal_callback=self.decide)
        self.client = ActionClient(self, RotateAbsolute, "turn")

    async def decide(self, goal):
        return GoalResponse.ACCEPT if goal.theta > 0 else GoalResponse.REJECT

    async def execute(self, goal_handle):
        if goal_handle.request.theta > 2:
            goal_handle.abort()
        else:
            goal_handle.succeed()
        return RotateAbsolute.Result(delta=goal_handle.request.theta)


def main():
    rclpy.init()
    node = Server()
    node.client.wait_for_server()
    for theta in (-1.0, 1.0, 3.0):
        future = node.client.send_goal_async(RotateAbsolute.Goal(theta=theta))
        rclpy.spin_until_future_complete(node, future)
        handle = future.result()
        if not handle.accepted:
            node.get_logger().info(f"{theta}: rejected")
            continue
        response = handle.get_result_async()
        rclpy.spin_until_future_complete(node, response)
        node.get_logger().info(f"{theta}: status {response.result().status} delta {response.result().result.delta}")
""",
        duration=5.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "server") == ["-1.0: rejected", "1.0: status 4 delta 1.0", "3.0: status 6 delta 3.0"]


def test_an_execute_callback_that_raises_aborts_its_goal_and_says_why(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.action import ActionClient, ActionServer
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


def main():
    rclpy.init()
    node = Node("server")

    def execute(goal_handle):
        goal_handle.canceled()  # not canceling: rcl refuses the transition

    ActionServer(node, RotateAbsolute, "turn", execute)
    client = ActionClient(node, RotateAbsolute, "turn")
    client.wait_for_server()
    future = client.send_goal_async(RotateAbsolute.Goal(theta=1.0))
    rclpy.spin_until_future_complete(node, future)
    response = future.result().get_result_async()
    rclpy.spin_until_future_complete(node, response)
    node.get_logger().info(f"status {response.result().status}")
""",
        duration=5.0,
    )
    assert result.ok, result.crashes
    logs = node_logs(result, "server.action_server")
    assert logs[0] == (
        "Error raised in execute callback: Failed to update goal state: goal_handle attempted invalid "
        "transition from state EXECUTING with event CANCELED"
    )
    assert logs[1].startswith("Goal state not set, assuming aborted. Goal ID: ")
    assert node_logs(result, "server") == ["status 6"]
    output = "\n".join(r.msg for r in result.logs if r.node.endswith(":stderr"))
    if controller_host.sandboxed:  # what rclpy prints on stderr: the student's frames only
        assert "in execute" in output and "turtletui" not in output


def test_an_execute_callback_must_return_a_result(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.action import ActionClient, ActionServer
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


def main():
    rclpy.init()
    node = Node("server")

    def execute(goal_handle):
        goal_handle.succeed()

    ActionServer(node, RotateAbsolute, "turn", execute)
    client = ActionClient(node, RotateAbsolute, "turn")
    client.wait_for_server()
    future = client.send_goal_async(RotateAbsolute.Goal(theta=1.0))
    rclpy.spin_until_future_complete(node, future)
    rclpy.spin_until_future_complete(node, future.result().get_result_async())
""",
        duration=5.0,
    )
    [crash] = result.crashes
    assert "the execute callback of action /turn must return a turtlesim/action/RotateAbsolute.Result, got None" in (
        crash.message
    )


SERVER_FILE = """
import time

import rclpy
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


class Server(Node):
    def __init__(self):
        super().__init__("server")
        self.server = ActionServer(
            self, RotateAbsolute, "turn", self.execute,
            goal_callback=lambda goal: GoalResponse.ACCEPT if goal.theta > 0 else GoalResponse.REJECT,
            cancel_callback=lambda goal_handle: CancelResponse.ACCEPT,
            callback_group=ReentrantCallbackGroup(),
        )

    def execute(self, goal_handle):
        for step in range(10):
            if goal_handle.is_cancel_requested:
                goal_handle.canceled()
                self.get_logger().info(f"canceled at step {step}")
                return RotateAbsolute.Result(delta=float(step))
            goal_handle.publish_feedback(RotateAbsolute.Feedback(remaining=float(10 - step)))
            time.sleep(0.2)
        goal_handle.succeed()
        return RotateAbsolute.Result(delta=goal_handle.request.theta)


def main():
    rclpy.init()
    executor = MultiThreadedExecutor()
    executor.add_node(Server())
    executor.spin()
"""

CLIENT_FILE = """
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


def main():
    rclpy.init()
    node = Node("client")
    client = ActionClient(node, RotateAbsolute, "turn")
    client.wait_for_server()
    log = node.get_logger().info

    def send(theta, feedback=None):
        future = client.send_goal_async(RotateAbsolute.Goal(theta=theta), feedback_callback=feedback)
        rclpy.spin_until_future_complete(node, future)
        return future.result()

    log(f"rejected: {not send(-1.0).accepted}")
    remaining = []
    handle = send(2.0, lambda message: remaining.append(message.feedback.remaining))
    response = handle.get_result_async()
    rclpy.spin_until_future_complete(node, response)
    log(f"succeeded: {response.result().status} {response.result().result.delta} feedback {len(remaining)}")
    handle = send(3.0)
    rclpy.spin_until_future_complete(node, rclpy.task.Future(), timeout_sec=0.5)
    cancel = handle.cancel_goal_async()
    rclpy.spin_until_future_complete(node, cancel)
    log(f"cancel: {cancel.result().return_code} {len(cancel.result().goals_canceling)}")
    response = handle.get_result_async()
    rclpy.spin_until_future_complete(node, response)
    log(f"canceled: {response.result().status} {response.result().result.delta} {handle.status}")
"""


def test_a_sandboxed_action_server_serves_a_client_in_another_controller(tmp_path: Path):
    server = tmp_path / "server.py"
    client = tmp_path / "client.py"
    server.write_text(textwrap.dedent(SERVER_FILE).lstrip())
    client.write_text(textwrap.dedent(CLIENT_FILE).lstrip())
    result = run([server, client], duration=6.0, sandbox=True)
    assert result.ok, result.crashes
    assert node_logs(result, "client") == [
        "rejected: True",
        "succeeded: 4 2.0 feedback 10",
        "cancel: 0 1",
        "canceled: 5 3.0 5",
    ]
    assert node_logs(result, "server") == ["canceled at step 3"]
    again = run([server, client], duration=6.0, sandbox=True)
    assert [(r.t, r.node, r.msg) for r in again.logs] == [(r.t, r.node, r.msg) for r in result.logs]


def test_turtlesims_rotate_absolute_answers_cancel_requests(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


def main():
    rclpy.init()
    node = Node("client")
    client = ActionClient(node, RotateAbsolute, "/turtle1/rotate_absolute")
    client.wait_for_server()
    future = client.send_goal_async(RotateAbsolute.Goal(theta=3.0))
    rclpy.spin_until_future_complete(node, future)
    handle = future.result()
    cancel = handle.cancel_goal_async()
    rclpy.spin_until_future_complete(node, cancel)
    response = handle.get_result_async()
    rclpy.spin_until_future_complete(node, response)
    again = handle.cancel_goal_async()
    rclpy.spin_until_future_complete(node, again)
    node.get_logger().info(
        f"{cancel.result().return_code} {len(cancel.result().goals_canceling)} "
        f"{response.result().status} {again.result().return_code}"
    )
""",
        duration=5.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "client") == ["0 1 5 3"]
