"""Recordings the ROS ecosystem opens: MCAP files and rosbag2 folders (profile
ros2, CDR messages, ros2msg schemas), and the same channels served live to
Foxglove. Plain Python over the graph; the ``mcap`` package is imported only
when an MCAP file is written or read, ``foxglove`` only for a live view.
"""
