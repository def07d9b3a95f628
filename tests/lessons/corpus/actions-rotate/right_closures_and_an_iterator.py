"""Right, written differently: no class, closures as callbacks, the headings as an iterator
of (name, theta), a relative action name."""
import math

import rclpy
from rclpy.action import ActionClient
from turtlesim.action import RotateAbsolute


def main():
    rclpy.init()
    node = rclpy.create_node("compass")
    client = ActionClient(node, RotateAbsolute, "turtle1/rotate_absolute")
    headings = iter([("north", math.pi / 2), ("west", math.pi), ("south", -math.pi / 2), ("east", 0.0)])
    log = node.get_logger()

    def on_feedback(fb):
        log.info(f"remaining={fb.feedback.remaining:+.3f}")

    def on_result(future):
        log.info(f"turned {future.result().result.delta:.2f} rad")
        go()

    def on_goal(future):
        handle = future.result()
        if handle.accepted:
            handle.get_result_async().add_done_callback(on_result)

    def go():
        item = next(headings, None)
        if item is None:
            log.info("finished")
            return
        name, theta = item
        log.info(f"facing {name}")
        client.send_goal_async(RotateAbsolute.Goal(theta=theta), feedback_callback=on_feedback).add_done_callback(on_goal)

    client.wait_for_server()
    go()
    rclpy.spin(node)


if __name__ == "__main__":
    main()
