"""Canceling a goal while it executes, as the official action tutorial's server does it: a
MultiThreadedExecutor, the server in a Reentrant group, an execute callback that loops
(publishing feedback, sleeping) and checks is_cancel_requested; the client cancels after the
first feedback. The cancel response, the statuses the goal goes through on both sides, the
result of the canceled goal, and a second goal that runs to its end.

Sandboxed only: the execute callback sleeps while other threads spin."""
import threading
import time

import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient, ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from turtlesim_msgs.action import RotateAbsolute


class Server(Node):
    def __init__(self):
        super().__init__("rotate_server")
        self.server = ActionServer(
            self,
            RotateAbsolute,
            "slow_rotate",
            execute_callback=self.execute,
            callback_group=ReentrantCallbackGroup(),
            goal_callback=lambda goal: GoalResponse.ACCEPT,
            cancel_callback=self.on_cancel,
        )

    def on_cancel(self, goal_handle):
        self.get_logger().info(f"cancel requested, status {goal_handle.status}")
        return CancelResponse.ACCEPT

    def execute(self, goal_handle):
        self.get_logger().info(f"executing theta={goal_handle.request.theta}")
        remaining = goal_handle.request.theta
        while remaining > 0:
            if goal_handle.is_cancel_requested:
                goal_handle.canceled()
                self.get_logger().info(f"canceled, status {goal_handle.status}")
                return RotateAbsolute.Result(delta=-1.0)
            goal_handle.publish_feedback(RotateAbsolute.Feedback(remaining=remaining))
            remaining -= 1.0
            time.sleep(0.2)
        goal_handle.succeed()
        self.get_logger().info(f"succeeded, status {goal_handle.status}")
        return RotateAbsolute.Result(delta=goal_handle.request.theta)


class Client(Node):
    def __init__(self):
        super().__init__("rotate_client")
        self.client = ActionClient(self, RotateAbsolute, "slow_rotate")
        self.first_feedback = threading.Event()

    def on_feedback(self, message):
        self.first_feedback.set()


def wait(future):
    for _ in range(200):
        if future.done():
            return future.result()
        time.sleep(0.05)
    raise RuntimeError("no answer")


def main():
    rclpy.init()
    server, client = Server(), Client()
    executor = MultiThreadedExecutor()
    executor.add_node(server)
    executor.add_node(client)
    spinner = threading.Thread(target=executor.spin, daemon=True)
    spinner.start()
    print("server ready:", client.client.wait_for_server(timeout_sec=5.0))

    handle = wait(client.client.send_goal_async(RotateAbsolute.Goal(theta=50.0), feedback_callback=client.on_feedback))
    print(f"accepted={handle.accepted}")
    print("feedback came:", client.first_feedback.wait(timeout=10.0))
    cancel = wait(handle.cancel_goal_async())
    print(f"cancel: return_code={cancel.return_code} goals={len(cancel.goals_canceling)}"
          f" same goal={cancel.goals_canceling[0].goal_id == handle.goal_id}")
    result = wait(handle.get_result_async())
    print(f"result: status={result.status} canceled={result.status == GoalStatus.STATUS_CANCELED}"
          f" delta={result.result.delta} handle status={handle.status}")

    handle = wait(client.client.send_goal_async(RotateAbsolute.Goal(theta=2.0)))
    result = wait(handle.get_result_async())
    print(f"second goal: status={result.status} delta={result.result.delta}")
    cancel = wait(handle.cancel_goal_async())
    print(f"cancel after the end: return_code={cancel.return_code} goals={len(cancel.goals_canceling)}")

    executor.shutdown()
    rclpy.shutdown()
    spinner.join(timeout=5.0)


if __name__ == "__main__":
    main()
