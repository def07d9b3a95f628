"""Several action goals sent at once, as a node sends a goal per waypoint before it spins:
the server's goal callback sees each request, a single-threaded executor runs each execute
callback to its end (feedback, then succeed, abort or canceled), and every client handle gets
its own feedback and result; GoalStatus's constants and the statuses the handles report."""
import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient, ActionServer, CancelResponse, GoalResponse
from rclpy.node import Node
from turtlesim_msgs.action import RotateAbsolute


class Turner(Node):
    def __init__(self):
        super().__init__("turner")
        self.server = ActionServer(
            self,
            RotateAbsolute,
            "turn",
            self.execute,
            goal_callback=self.on_goal,
            cancel_callback=lambda goal_handle: CancelResponse.ACCEPT,
        )
        self.client = ActionClient(self, RotateAbsolute, "turn")

    def on_goal(self, goal):
        self.get_logger().info(f"goal theta={goal.theta}")
        return GoalResponse.REJECT if goal.theta > 3.0 else GoalResponse.ACCEPT

    def execute(self, goal_handle):
        theta = goal_handle.request.theta
        self.get_logger().info(f"execute theta={theta}")
        for step in range(3):
            goal_handle.publish_feedback(RotateAbsolute.Feedback(remaining=theta - step))
        if theta < 0:
            goal_handle.abort()
        elif goal_handle.is_cancel_requested:
            goal_handle.canceled()
        else:
            goal_handle.succeed()
        return RotateAbsolute.Result(delta=theta)


def spin_until_all(node, futures):
    while not all(future.done() for future in futures):
        rclpy.spin_once(node, timeout_sec=1.0)


def main():
    rclpy.init()
    node = Turner()
    node.client.wait_for_server(timeout_sec=5.0)
    names = {value: name for name, value in vars(GoalStatus).items() if name.startswith("STATUS_")}
    print(sorted(names.items()))
    thetas = (1.0, 4.0, -1.0, 2.0)
    feedback = {theta: [] for theta in thetas}
    sent = [
        node.client.send_goal_async(
            RotateAbsolute.Goal(theta=theta),
            feedback_callback=lambda message, theta=theta: feedback[theta].append(message.feedback.remaining),
        )
        for theta in thetas
    ]
    spin_until_all(node, sent)
    handles = [future.result() for future in sent]
    for theta, handle in zip(thetas, handles, strict=True):
        print(f"theta={theta}: accepted={handle.accepted} status={names.get(handle.status, handle.status)}")
    accepted = [(theta, handle) for theta, handle in zip(thetas, handles, strict=True) if handle.accepted]
    # all feedback heard before the results are asked for: rclpy drops a goal's
    # feedback that its executor takes after the goal's result
    for _ in range(100):
        if all(len(feedback[theta]) == 3 for theta, _ in accepted):
            break
        rclpy.spin_once(node, timeout_sec=0.05)
    results = [handle.get_result_async() for _, handle in accepted]
    spin_until_all(node, results)
    for (theta, handle), future in zip(accepted, results, strict=True):
        response = future.result()
        print(
            f"theta={theta}: result {names[response.status]} delta={response.result.delta}"
            f" handle={names[handle.status]} feedback={feedback[theta]}"
        )
    again = accepted[0][1].get_result_async()
    spin_until_all(node, [again])
    print(f"asked again: {names[again.result().status]} {again.result().result}")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
