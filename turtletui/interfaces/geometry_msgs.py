"""geometry_msgs: points, vectors, poses, twists, wrenches and the rest.

Import path in ROS 2: geometry_msgs.msg.
Definitions copied from the ROS 2 interface packages (Apache-2.0) by
scripts/interfaces_from_ros.py: the text of each is its file's, byte for byte.
"""

from turtletui.interfaces import std_msgs as _std_msgs  # noqa: F401  (nested types)
from turtletui.interfaces._message import define_message as _msg

__all__ = [
    'Accel',
    'AccelStamped',
    'AccelWithCovariance',
    'AccelWithCovarianceStamped',
    'Inertia',
    'InertiaStamped',
    'Point',
    'Point32',
    'PointStamped',
    'Polygon',
    'PolygonInstance',
    'PolygonInstanceStamped',
    'PolygonStamped',
    'Pose',
    'Pose2D',
    'PoseArray',
    'PoseStamped',
    'PoseWithCovariance',
    'PoseWithCovarianceStamped',
    'Quaternion',
    'QuaternionStamped',
    'Transform',
    'TransformStamped',
    'Twist',
    'TwistStamped',
    'TwistWithCovariance',
    'TwistWithCovarianceStamped',
    'Vector3',
    'Vector3Stamped',
    'VelocityStamped',
    'Wrench',
    'WrenchStamped',
]

Vector3 = _msg('geometry_msgs/msg/Vector3', '''\
# This represents a vector in free space.

# This is semantically different than a point.
# A vector is always anchored at the origin.
# When a transform is applied to a vector, only the rotational component is applied.

float64 x
float64 y
float64 z
''', globals())

Accel = _msg('geometry_msgs/msg/Accel', '''\
# This expresses acceleration in free space broken into its linear and angular parts.
Vector3  linear
Vector3  angular
''', globals())

AccelStamped = _msg('geometry_msgs/msg/AccelStamped', '''\
# An accel with reference coordinate frame and timestamp
std_msgs/Header header
Accel accel
''', globals())

AccelWithCovariance = _msg('geometry_msgs/msg/AccelWithCovariance', '''\
# This expresses acceleration in free space with uncertainty.

Accel accel

# Row-major representation of the 6x6 covariance matrix
# The orientation parameters use a fixed-axis representation.
# In order, the parameters are:
# (x, y, z, rotation about X axis, rotation about Y axis, rotation about Z axis)
float64[36] covariance
''', globals())

AccelWithCovarianceStamped = _msg('geometry_msgs/msg/AccelWithCovarianceStamped', '''\
# This represents an estimated accel with reference coordinate frame and timestamp.
std_msgs/Header header
AccelWithCovariance accel
''', globals())

Inertia = _msg('geometry_msgs/msg/Inertia', '''\
# Mass [kg]
float64 m

# Center of mass [m]
geometry_msgs/Vector3 com

# Inertia Tensor [kg-m^2]
#     | ixx ixy ixz |
# I = | ixy iyy iyz |
#     | ixz iyz izz |
float64 ixx
float64 ixy
float64 ixz
float64 iyy
float64 iyz
float64 izz
''', globals())

InertiaStamped = _msg('geometry_msgs/msg/InertiaStamped', '''\
# An Inertia with a time stamp and reference frame.

std_msgs/Header header
Inertia inertia
''', globals())

Point = _msg('geometry_msgs/msg/Point', '''\
# This contains the position of a point in free space
float64 x
float64 y
float64 z
''', globals())

Point32 = _msg('geometry_msgs/msg/Point32', '''\
# This contains the position of a point in free space(with 32 bits of precision).
# It is recommended to use Point wherever possible instead of Point32.
#
# This recommendation is to promote interoperability.
#
# This message is designed to take up less space when sending
# lots of points at once, as in the case of a PointCloud.

float32 x
float32 y
float32 z
''', globals())

PointStamped = _msg('geometry_msgs/msg/PointStamped', '''\
# This represents a Point with reference coordinate frame and timestamp

std_msgs/Header header
Point point
''', globals())

Polygon = _msg('geometry_msgs/msg/Polygon', '''\
# A specification of a polygon where the first and last points are assumed to be connected

Point32[] points
''', globals())

PolygonInstance = _msg('geometry_msgs/msg/PolygonInstance', '''\
# A specification of a polygon where the first and last points are assumed to be connected
# It includes a unique identification field for disambiguating multiple instances

geometry_msgs/Polygon polygon
int64 id
''', globals())

PolygonInstanceStamped = _msg('geometry_msgs/msg/PolygonInstanceStamped', '''\
# This represents a Polygon with reference coordinate frame and timestamp
# It includes a unique identification field for disambiguating multiple instances

std_msgs/Header header
geometry_msgs/PolygonInstance polygon
''', globals())

PolygonStamped = _msg('geometry_msgs/msg/PolygonStamped', '''\
# This represents a Polygon with reference coordinate frame and timestamp

std_msgs/Header header
Polygon polygon
''', globals())

Quaternion = _msg('geometry_msgs/msg/Quaternion', '''\
# This represents an orientation in free space in quaternion form.

float64 x 0
float64 y 0
float64 z 0
float64 w 1
''', globals())

Pose = _msg('geometry_msgs/msg/Pose', '''\
# A representation of pose in free space, composed of position and orientation.

Point position
Quaternion orientation
''', globals())

Pose2D = _msg('geometry_msgs/msg/Pose2D', '''\
# Deprecated as of Foxy and will potentially be removed in any following release.
# Please use the full 3D pose.

# In general our recommendation is to use a full 3D representation of everything and for \
2D specific applications make the appropriate projections into the plane for their \
calculations but optimally will preserve the 3D information during processing.

# If we have parallel copies of 2D datatypes every UI and other pipeline will end up \
needing to have dual interfaces to plot everything. And you will end up with not being \
able to use 3D tools for 2D use cases even if they're completely valid, as you'd have to \
reimplement it with different inputs and outputs. It's not particularly hard to plot the \
2D pose or compute the yaw error for the Pose message and there are already tools and \
libraries that can do this for you.# This expresses a position and orientation on a 2D manifold.

float64 x
float64 y
float64 theta
''', globals())

PoseArray = _msg('geometry_msgs/msg/PoseArray', '''\
# An array of poses with a header for global reference.

std_msgs/Header header

Pose[] poses
''', globals())

PoseStamped = _msg('geometry_msgs/msg/PoseStamped', '''\
# A Pose with reference coordinate frame and timestamp

std_msgs/Header header
Pose pose
''', globals())

PoseWithCovariance = _msg('geometry_msgs/msg/PoseWithCovariance', '''\
# This represents a pose in free space with uncertainty.

Pose pose

# Row-major representation of the 6x6 covariance matrix
# The orientation parameters use a fixed-axis representation.
# In order, the parameters are:
# (x, y, z, rotation about X axis, rotation about Y axis, rotation about Z axis)
float64[36] covariance
''', globals())

PoseWithCovarianceStamped = _msg('geometry_msgs/msg/PoseWithCovarianceStamped', '''\
# This expresses an estimated pose with a reference coordinate frame and timestamp

std_msgs/Header header
PoseWithCovariance pose
''', globals())

QuaternionStamped = _msg('geometry_msgs/msg/QuaternionStamped', '''\
# This represents an orientation with reference coordinate frame and timestamp.

std_msgs/Header header
Quaternion quaternion
''', globals())

Transform = _msg('geometry_msgs/msg/Transform', '''\
# This represents the transform between two coordinate frames in free space.

Vector3 translation
Quaternion rotation
''', globals())

TransformStamped = _msg('geometry_msgs/msg/TransformStamped', '''\
# This expresses a transform from coordinate frame header.frame_id
# to the coordinate frame child_frame_id at the time of header.stamp
#
# This message is mostly used by the
# <a href="https://docs.ros.org/en/rolling/p/tf2/">tf2</a> package.
# See its documentation for more information.
#
# The child_frame_id is necessary in addition to the frame_id
# in the Header to communicate the full reference for the transform
# in a self contained message.

# The frame id in the header is used as the reference frame of this transform.
std_msgs/Header header

# The frame id of the child frame to which this transform points.
string child_frame_id

# Translation and rotation in 3-dimensions of child_frame_id from header.frame_id.
Transform transform
''', globals())

Twist = _msg('geometry_msgs/msg/Twist', '''\
# This expresses velocity in free space broken into its linear and angular parts.

Vector3  linear
Vector3  angular
''', globals())

TwistStamped = _msg('geometry_msgs/msg/TwistStamped', '''\
# A twist with reference coordinate frame and timestamp

std_msgs/Header header
Twist twist
''', globals())

TwistWithCovariance = _msg('geometry_msgs/msg/TwistWithCovariance', '''\
# This expresses velocity in free space with uncertainty.

Twist twist

# Row-major representation of the 6x6 covariance matrix
# The orientation parameters use a fixed-axis representation.
# In order, the parameters are:
# (x, y, z, rotation about X axis, rotation about Y axis, rotation about Z axis)
float64[36] covariance
''', globals())

TwistWithCovarianceStamped = _msg('geometry_msgs/msg/TwistWithCovarianceStamped', '''\
# This represents an estimated twist with reference coordinate frame and timestamp.

std_msgs/Header header
TwistWithCovariance twist
''', globals())

Vector3Stamped = _msg('geometry_msgs/msg/Vector3Stamped', '''\
# This represents a Vector3 with reference coordinate frame and timestamp

# Note that this follows vector semantics with it always anchored at the origin,
# so the rotational elements of a transform are the only parts applied when transforming.

std_msgs/Header header
Vector3 vector
''', globals())

VelocityStamped = _msg('geometry_msgs/msg/VelocityStamped', '''\
# This expresses the timestamped velocity vector of a frame 'body_frame_id' in the \
reference frame 'reference_frame_id' expressed from arbitrary observation frame 'header.frame_id'.
# - If the 'body_frame_id' and 'header.frame_id' are identical, the velocity is observed \
and defined in the local coordinates system of the body
#   which is the usual use-case in mobile robotics and is also known as a body twist.

std_msgs/Header header
string body_frame_id
string reference_frame_id
Twist velocity
''', globals())

Wrench = _msg('geometry_msgs/msg/Wrench', '''\
# This represents force in free space, separated into its linear and angular parts.

Vector3  force
Vector3  torque
''', globals())

WrenchStamped = _msg('geometry_msgs/msg/WrenchStamped', '''\
# A wrench with reference coordinate frame and timestamp

std_msgs/Header header
Wrench wrench
''', globals())
