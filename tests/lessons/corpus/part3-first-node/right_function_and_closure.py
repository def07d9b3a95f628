import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("counter_node")
    state = {"count": 0}

    def tick():
        node.get_logger().info(f"count: {state['count']}")
        state["count"] += 1

    node.create_timer(0.5, tick)
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
