"""An action server and its client in one node (the official action tutorials' shape): a goal
callback that rejects, feedback and a succeeded goal, an aborted one, an ``async def`` execute
callback, a goal canceled before it executes, a cancel request for a goal that has ended, and
publish_feedback with the wrong type."""
import rclpy
from rclpy.action import ActionClient, ActionServer, CancelResponse, GoalResponse
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


class Rotator(Node):
    def __init__(self):
        super().__init__("rotator")
        self.server = ActionServer(
            self,
            RotateAbsolute,
            "rotate",
            self.execute,
            goal_callback=self.on_goal,
        )
        self.async_server = ActionServer(self, RotateAbsolute, "rotate_async", self.execute_async)
        self.stored = []
        self.later_server = ActionServer(
            self,
            RotateAbsolute,
            "rotate_later",
            self.execute,
            handle_accepted_callback=self.stored.append,
            cancel_callback=lambda goal_handle: CancelResponse.ACCEPT,
        )
        self.client = ActionClient(self, RotateAbsolute, "rotate")
        self.async_client = ActionClient(self, RotateAbsolute, "rotate_async")
        self.later_client = ActionClient(self, RotateAbsolute, "rotate_later")

    def on_goal(self, goal):
        self.get_logger().info(f"goal request theta={goal.theta}")
        return GoalResponse.ACCEPT if goal.theta >= 0 else GoalResponse.REJECT

    def execute(self, goal_handle):
        theta = goal_handle.request.theta
        self.get_logger().info(f"executing theta={theta} status={goal_handle.status}")
        if goal_handle.is_cancel_requested:
            goal_handle.canceled()
            return RotateAbsolute.Result(delta=0.0)
        for remaining in (theta, theta / 2):
            goal_handle.publish_feedback(RotateAbsolute.Feedback(remaining=remaining))
        try:
            goal_handle.publish_feedback(RotateAbsolute.Result())
        except TypeError:
            self.get_logger().warning("publish_feedback refused a Result")
        if theta > 3:
            goal_handle.abort()
        else:
            goal_handle.succeed()
        self.get_logger().info(f"active={goal_handle.is_active} status={goal_handle.status}")
        return RotateAbsolute.Result(delta=theta)

    async def execute_async(self, goal_handle):
        goal_handle.publish_feedback(RotateAbsolute.Feedback(remaining=1.0))
        goal_handle.succeed()
        return RotateAbsolute.Result(delta=-goal_handle.request.theta)


def wait(node, future):
    rclpy.spin_until_future_complete(node, future)
    return future.result()


def run_goal(node, client, theta):
    feedback = []  # printed with the result: rclpy may take one before the goal's acceptance
    handle = wait(node, client.send_goal_async(RotateAbsolute.Goal(theta=theta), feedback_callback=feedback.append))
    print(f"theta={theta}: accepted={handle.accepted}")
    if not handle.accepted:
        return None
    response = wait(node, handle.get_result_async())
    print(f"  result status={response.status} delta={response.result.delta} handle status={handle.status}")
    print(f"  feedback {[message.feedback.remaining for message in feedback]}")
    return handle


def main():
    rclpy.init()
    node = Rotator()
    for client in (node.client, node.async_client, node.later_client):
        client.wait_for_server(timeout_sec=5.0)
    run_goal(node, node.client, -1.0)
    done = run_goal(node, node.client, 2.0)
    run_goal(node, node.client, 4.0)
    run_goal(node, node.async_client, 1.5)
    cancel = wait(node, done.cancel_goal_async())
    print(f"cancel an ended goal: return_code={cancel.return_code} canceling={len(cancel.goals_canceling)}")

    handle = wait(node, node.later_client.send_goal_async(RotateAbsolute.Goal(theta=1.0)))
    print(f"later: accepted={handle.accepted} stored={len(node.stored)}")
    cancel = wait(node, handle.cancel_goal_async())
    print(f"cancel before executing: return_code={cancel.return_code} canceling={len(cancel.goals_canceling)}")
    node.stored[0].execute()
    response = wait(node, handle.get_result_async())
    print(f"later: result status={response.status} handle status={handle.status}")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
