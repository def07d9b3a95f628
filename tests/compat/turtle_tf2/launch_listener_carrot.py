"""The fixed/dynamic frame launch files' listener entry: turtle2 chases carrot1."""

import rclpy
from turtle_tf2_listener import FrameListener


def main():
    rclpy.init(args=['--ros-args', '-p', 'target_frame:=carrot1'])
    rclpy.spin(FrameListener())
