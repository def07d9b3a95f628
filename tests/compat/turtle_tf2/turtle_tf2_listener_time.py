"""The "Using time" tutorial: look the transform up at now(), waiting up to 1 s for it.

Spun by one thread, nothing fills the buffer while the timer callback waits,
so the lookup fails after its second (tf2_ros's wait spins nothing); with
`--ros-args -p threads:=true` a MultiThreadedExecutor runs the listener meanwhile."""

import rclpy
from rclpy.executors import MultiThreadedExecutor
from turtle_tf2_listener import FrameListener


class TimeListener(FrameListener):
    def lookup(self, to_frame_rel, from_frame_rel):
        now = self.get_clock().now()
        return self.tf_buffer.lookup_transform(
            to_frame_rel, from_frame_rel, now, timeout=rclpy.duration.Duration(seconds=1.0))


def main():
    rclpy.init()
    node = TimeListener()
    if node.declare_parameter('threads', False).value:
        executor = MultiThreadedExecutor()
        executor.add_node(node)
        executor.spin()
    else:
        rclpy.spin(node)
