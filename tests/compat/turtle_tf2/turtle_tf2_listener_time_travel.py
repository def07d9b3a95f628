"""The "Traveling in time" tutorial: turtle2 goes where turtle1 was 5 s ago."""

import rclpy
from turtle_tf2_listener import FrameListener


class TimeTravelListener(FrameListener):
    def lookup(self, to_frame_rel, from_frame_rel):
        when = self.get_clock().now() - rclpy.time.Duration(seconds=5.0)
        return self.tf_buffer.lookup_transform_full(
            target_frame=to_frame_rel,
            target_time=rclpy.time.Time(),
            source_frame=from_frame_rel,
            source_time=when,
            fixed_frame='world',
            timeout=rclpy.duration.Duration(seconds=0.05))


def main():
    rclpy.init()
    rclpy.spin(TimeTravelListener())
