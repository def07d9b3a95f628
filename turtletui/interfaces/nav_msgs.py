"""nav_msgs: Odometry, Path, OccupancyGrid and the map and plan services.

Import paths in ROS 2: nav_msgs.msg, nav_msgs.srv.
Definitions copied from the ROS 2 interface packages (Apache-2.0) by
scripts/interfaces_from_ros.py: the text of each is its file's, byte for byte.
"""

from turtletui.interfaces import builtin_interfaces as _builtin_interfaces  # noqa: F401  (nested types)
from turtletui.interfaces import geometry_msgs as _geometry_msgs  # noqa: F401  (nested types)
from turtletui.interfaces import std_msgs as _std_msgs  # noqa: F401  (nested types)
from turtletui.interfaces._message import define_message as _msg
from turtletui.interfaces._message import define_service as _srv

__all__ = [
    'GetMap',
    'GetPlan',
    'Goals',
    'GridCells',
    'LoadMap',
    'MapMetaData',
    'OccupancyGrid',
    'Odometry',
    'Path',
    'SetMap',
]

Goals = _msg('nav_msgs/msg/Goals', '''\
# An array of navigation goals


# This header will store the time at which the poses were computed (not to be confused \
with the stamps of the poses themselves)
# In the case that individual poses do not have their frame_id set or their timetamp set \
they will use the default value here.
std_msgs/Header header

# An array of goals to for navigation to achieve.
# The goals should be executed in the order of the array.
# The header and stamp are intended to be used for computing the position of the goals.
# They may vary to support cases of goals that are moving with respect to the robot.
geometry_msgs/PoseStamped[] goals
''', globals())

GridCells = _msg('nav_msgs/msg/GridCells', '''\
# An array of cells in a 2D grid

std_msgs/Header header

# Width of each cell
float32 cell_width

# Height of each cell
float32 cell_height

# Each cell is represented by the Point at the center of the cell
geometry_msgs/Point[] cells
''', globals())

MapMetaData = _msg('nav_msgs/msg/MapMetaData', '''\
# This hold basic information about the characteristics of the OccupancyGrid

# The time at which the map was loaded
builtin_interfaces/Time map_load_time

# The map resolution [m/cell]
float32 resolution

# Map width [cells]
uint32 width

# Map height [cells]
uint32 height

# The origin of the map [m, m, rad].  This is the real-world pose of the
# bottom left corner of cell (0,0) in the map.
geometry_msgs/Pose origin
''', globals())

OccupancyGrid = _msg('nav_msgs/msg/OccupancyGrid', '''\
# This represents a 2-D grid map
std_msgs/Header header

# MetaData for the map
MapMetaData info

# The map data, in row-major order, starting with (0,0).\x20
# Cell (1, 0) will be listed second, representing the next cell in the x direction.\x20
# Cell (0, 1) will be at the index equal to info.width, followed by (1, 1).
# The values inside are application dependent, but frequently,\x20
# 0 represents unoccupied, 1 represents definitely occupied, and
# -1 represents unknown.\x20
int8[] data
''', globals())

Odometry = _msg('nav_msgs/msg/Odometry', '''\
# This represents an estimate of a position and velocity in free space.
# The pose in this message should be specified in the coordinate frame given by header.frame_id
# The twist in this message should be specified in the coordinate frame given by the child_frame_id

# Includes the frame id of the pose parent.
std_msgs/Header header

# Frame id the pose points to. The twist is in this coordinate frame.
string child_frame_id

# Estimated pose that is typically relative to a fixed world frame.
geometry_msgs/PoseWithCovariance pose

# Estimated linear and angular velocity relative to child_frame_id.
geometry_msgs/TwistWithCovariance twist
''', globals())

Path = _msg('nav_msgs/msg/Path', '''\
# An array of poses that represents a Path for a robot to follow.

# Indicates the frame_id of the path.
std_msgs/Header header

# Array of poses to follow.
geometry_msgs/PoseStamped[] poses
''', globals())

GetMap = _srv('nav_msgs/srv/GetMap', '''\
# Get the map as a nav_msgs/OccupancyGrid
---
# The current map hosted by this map service.
OccupancyGrid map
''', globals())

GetPlan = _srv('nav_msgs/srv/GetPlan', '''\
# Get a plan from the current position to the goal Pose

# The start pose for the plan
geometry_msgs/PoseStamped start

# The final pose of the goal position
geometry_msgs/PoseStamped goal

# If the goal is obstructed, how many meters the planner can
# relax the constraint in x and y before failing.
float32 tolerance
---
# Array of poses from start to goal if one was successfully found.
Path plan
''', globals())

LoadMap = _srv('nav_msgs/srv/LoadMap', '''\
# URL of map resource
# Can be an absolute path to a file: file:///path/to/maps/floor1.yaml
# Or, relative to a ROS package: package://my_ros_package/maps/floor2.yaml
string map_url
---
# Result code definitions
uint8 RESULT_SUCCESS=0
uint8 RESULT_MAP_DOES_NOT_EXIST=1
uint8 RESULT_INVALID_MAP_DATA=2
uint8 RESULT_INVALID_MAP_METADATA=3
uint8 RESULT_UNDEFINED_FAILURE=255

# Returned map is only valid if result equals RESULT_SUCCESS
nav_msgs/OccupancyGrid map
uint8 result
''', globals())

SetMap = _srv('nav_msgs/srv/SetMap', '''\
# Set a new map together with an initial pose

# Requested 2D map to be set.
nav_msgs/OccupancyGrid map

# Estimated initial pose when setting new map.
geometry_msgs/PoseWithCovarianceStamped initial_pose
---

# True if the map was successfully set, false otherwise.
bool success
''', globals())
