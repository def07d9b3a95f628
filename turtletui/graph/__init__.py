"""A small deterministic ROS-like middleware (see core.py) and the /turtlesim node."""
