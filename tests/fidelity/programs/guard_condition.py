"""Guard conditions: create_guard_condition, trigger() from the program wakes spin_once and runs
the callback once per trigger, node.guards lists them, destroy_guard_condition."""
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("guarded")
    fired = []
    guard = node.create_guard_condition(lambda: fired.append("guard"))
    print("guards:", len(list(node.guards)), type(guard).__name__)
    rclpy.spin_once(node, timeout_sec=0.1)
    print("without trigger:", fired)
    guard.trigger()
    rclpy.spin_once(node, timeout_sec=1.0)
    print("after a trigger:", fired)
    guard.trigger()
    guard.trigger()
    rclpy.spin_once(node, timeout_sec=1.0)
    rclpy.spin_once(node, timeout_sec=0.1)
    print("after two triggers:", fired)
    print("destroyed:", node.destroy_guard_condition(guard))
    print("guards left:", len(list(node.guards)))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
