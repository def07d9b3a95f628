"""ros2/examples' trigger_guard_condition, as a student copies it: inside `with rclpy.init():`,
a timer triggers a guard condition whose callback calls rclpy.shutdown() and then logs, a
`while rclpy.ok(): executor.spin_once()` loop that ends by itself, log lines with a newline
in them, and what the executor and rclpy say afterwards."""
import rclpy
from rclpy.executors import ExternalShutdownException


def main(args=None):
    try:
        with rclpy.init(args=args):
            node = rclpy.create_node("demo_guard_condition")
            executor = rclpy.executors.SingleThreadedExecutor()
            executor.add_node(node)

            def guard_condition_callback():
                rclpy.shutdown()
                node.get_logger().info("guard callback called shutdown")

            def timer_callback():
                guard_condition.trigger()
                node.get_logger().info("timer callback triggered guard condition")

            node.create_timer(timer_period_sec=0.2, callback=timer_callback)
            guard_condition = node.create_guard_condition(guard_condition_callback)

            loops = 0
            while rclpy.ok():
                node.get_logger().info("waiting for 'spin_once' to finish...")
                executor.spin_once()
                node.get_logger().info("...'spin_once' finished!\n")
                loops += 1
            print("loops:", loops, "ok:", rclpy.ok())
            try:
                executor.spin_once(timeout_sec=0.1)
                print("spin_once after shutdown returned")
            except Exception as err:
                print("spin_once after shutdown:", type(err).__name__, err)
            try:
                print("node still named:", node.get_name())
            except Exception as err:  # rclpy destroyed the node at shutdown
                print("get_name after shutdown:", type(err).__name__, err)
        print("after with:", rclpy.ok())
    except (KeyboardInterrupt, ExternalShutdownException) as err:
        print("caught", type(err).__name__)


if __name__ == "__main__":
    main()
