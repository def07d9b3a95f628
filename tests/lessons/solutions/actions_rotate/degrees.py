"""Wrong: headings in degrees. turtlesim reads goal.theta in radians, so
90.0 is 90 rad = 14 turns and 2.04 rad: the turtle waits for every result
but stops facing the wrong ways."""
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute

HEADINGS = [90.0, 180.0, -90.0, 0.0]  # north, west, south, east


class RotateClientNode(Node):
    def __init__(self):
        super().__init__("rotate_client")
        self.rotate_client_ = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
        self.index_ = 0
        self.rotate_client_.wait_for_server()
        self.send_next_goal()

    def send_next_goal(self):
        if self.index_ >= len(HEADINGS):
            return
        goal = RotateAbsolute.Goal()
        goal.theta = HEADINGS[self.index_]
        future = self.rotate_client_.send_goal_async(goal, feedback_callback=self.feedback_callback)
        future.add_done_callback(self.goal_response_callback)

    def goal_response_callback(self, future):
        future.result().get_result_async().add_done_callback(self.result_callback)

    def feedback_callback(self, feedback_msg):
        self.get_logger().info(f"Remaining: {feedback_msg.feedback.remaining:.2f} rad")

    def result_callback(self, future):
        self.get_logger().info(f"Done, delta {future.result().result.delta:.2f}")
        self.index_ += 1
        self.send_next_goal()


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(RotateClientNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
