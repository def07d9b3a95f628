from turtletui.compat.tf2.geometry_msgs import (  # noqa: F401
    do_transform_point,
    do_transform_pose,
    do_transform_pose_stamped,
    do_transform_vector3,
)
