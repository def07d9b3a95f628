"""An action server whose goal and cancel callbacks return the wrong thing, as first attempts
do: a goal callback that returns True, one that returns None (forgot the return), an
``async def`` goal callback that returns GoalResponse.ACCEPT, a cancel callback that returns
True instead of CancelResponse.ACCEPT; what rclpy logs and what the client gets back."""
import rclpy
from rclpy.action import ActionClient, ActionServer, CancelResponse, GoalResponse
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


def execute(goal_handle):
    if goal_handle.is_cancel_requested:
        goal_handle.canceled()
    else:
        goal_handle.succeed()
    return RotateAbsolute.Result(delta=goal_handle.request.theta)


async def accept_later(goal):
    return GoalResponse.ACCEPT


class Server(Node):
    def __init__(self):
        super().__init__("returns")
        self.held = []
        ActionServer(self, RotateAbsolute, "returns_true", execute, goal_callback=lambda goal: True)
        ActionServer(self, RotateAbsolute, "returns_none", execute, goal_callback=lambda goal: None)
        ActionServer(self, RotateAbsolute, "async_accept", execute, goal_callback=accept_later)
        ActionServer(
            self,
            RotateAbsolute,
            "cancel_true",
            execute,
            handle_accepted_callback=self.held.append,
            cancel_callback=lambda goal_handle: True,
        )
        ActionServer(
            self,
            RotateAbsolute,
            "cancel_accept",
            execute,
            handle_accepted_callback=self.held.append,
            cancel_callback=lambda goal_handle: CancelResponse.ACCEPT,
        )


def send(node, name, theta):
    client = ActionClient(node, RotateAbsolute, name)
    client.wait_for_server(timeout_sec=5.0)
    future = client.send_goal_async(RotateAbsolute.Goal(theta=theta))
    rclpy.spin_until_future_complete(node, future, timeout_sec=5.0)
    handle = future.result()
    print(name, "accepted:", handle.accepted)
    return handle


def main():
    rclpy.init()
    node = Server()
    for name in ("returns_true", "returns_none", "async_accept"):
        handle = send(node, name, 0.5)
        if handle.accepted:
            result = handle.get_result_async()
            rclpy.spin_until_future_complete(node, result, timeout_sec=5.0)
            print(name, "result:", result.result().status, result.result().result.delta)
    for name in ("cancel_true", "cancel_accept"):
        handle = send(node, name, 1.0)
        cancel = handle.cancel_goal_async()
        rclpy.spin_until_future_complete(node, cancel, timeout_sec=5.0)
        response = cancel.result()
        print(name, "cancel:", response.return_code, len(response.goals_canceling))
        goal_handle = node.held.pop()
        print(name, "cancel requested:", goal_handle.is_cancel_requested, "status:", goal_handle.status)
        goal_handle.execute()
        result = handle.get_result_async()
        rclpy.spin_until_future_complete(node, result, timeout_sec=5.0)
        print(name, "result:", result.result().status, result.result().result.delta)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
