"""Reference nodes of the ROS 2 crash-course series, as the course gives them.

Each file is an ordinary rclpy program: it runs unchanged under turtletui and
on a real ROS 2 turtlesim. Installed with turtletui as turtletui.reference.
"""
