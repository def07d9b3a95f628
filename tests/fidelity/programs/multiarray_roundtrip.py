"""std_msgs MultiArrays with a layout, published and received by the same node."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Float64MultiArray, Int32MultiArray, MultiArrayDimension


class Matrix(Node):
    def __init__(self):
        super().__init__("matrix")
        self.pub = self.create_publisher(Float64MultiArray, "matrix", 10)
        self.ints = self.create_publisher(Int32MultiArray, "ints", 10)
        self.create_subscription(Float64MultiArray, "matrix", self.on_matrix, 10)
        self.create_subscription(Int32MultiArray, "ints", self.on_ints, 10)
        self.received = 0

    def send(self):
        msg = Float64MultiArray()
        msg.layout.dim = [
            MultiArrayDimension(label="rows", size=2, stride=6),
            MultiArrayDimension(label="cols", size=3, stride=3),
        ]
        msg.data = [1.0, 2.0, 3.0, 4.0, 5.5, 6.25]
        self.pub.publish(msg)
        self.ints.publish(Int32MultiArray(data=[-2, 0, 2**31 - 1]))

    def on_matrix(self, msg):
        dims = [(d.label, d.size, d.stride) for d in msg.layout.dim]
        self.get_logger().info(f"matrix {dims} offset {msg.layout.data_offset}: {list(msg.data)}")
        self.received += 1

    def on_ints(self, msg):
        self.get_logger().info(f"ints {list(msg.data)} stored as {type(msg.data).__name__}")
        self.received += 1


def main():
    rclpy.init()
    node = Matrix()
    while node.pub.get_subscription_count() == 0 or node.ints.get_subscription_count() == 0:
        rclpy.spin_once(node, timeout_sec=0.1)
    node.send()
    while node.received < 2:
        rclpy.spin_once(node, timeout_sec=1.0)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
