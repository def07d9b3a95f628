"""tf2_geometry_msgs: geometry_msgs' stamped types moved by a TransformStamped,
and registered so that ``Buffer.transform()`` takes them (on import, as there)."""

from __future__ import annotations

from turtletui.compat.tf2.buffer_interface import ConvertRegistration, TransformRegistration
from turtletui.compat.tf2.transform import Quat, Vec, add, multiply, rotate
from turtletui.interfaces.geometry_msgs import (
    Point,
    PointStamped,
    Pose,
    PoseStamped,
    TransformStamped,
    Vector3,
    Vector3Stamped,
)


def _parts(transform: TransformStamped) -> tuple[Vec, Quat]:
    t, q = transform.transform.translation, transform.transform.rotation
    return (t.x, t.y, t.z), (q.x, q.y, q.z, q.w)


def _moved(transform: TransformStamped, p: Vec, *, translate: bool = True) -> Vec:
    translation, rotation = _parts(transform)
    rotated = rotate(rotation, p)
    return add(rotated, translation) if translate else rotated


def do_transform_point(point: PointStamped, transform: TransformStamped) -> PointStamped:
    """``point`` moved by ``transform``, stamped with the transform's header."""
    x, y, z = _moved(transform, (point.point.x, point.point.y, point.point.z))
    return PointStamped(header=transform.header, point=Point(x=x, y=y, z=z))


def do_transform_vector3(vector3: Vector3Stamped, transform: TransformStamped) -> Vector3Stamped:
    """``vector3`` rotated by ``transform`` (a direction: no translation)."""
    x, y, z = _moved(transform, (vector3.vector.x, vector3.vector.y, vector3.vector.z), translate=False)
    return Vector3Stamped(header=transform.header, vector=Vector3(x=x, y=y, z=z))


def do_transform_pose(pose: Pose, transform: TransformStamped) -> Pose:
    """``pose`` moved by ``transform``."""
    x, y, z = _moved(transform, (pose.position.x, pose.position.y, pose.position.z))
    o = pose.orientation
    qx, qy, qz, qw = multiply(_parts(transform)[1], (o.x, o.y, o.z, o.w))
    result = Pose()
    result.position.x, result.position.y, result.position.z = x, y, z
    result.orientation.x, result.orientation.y, result.orientation.z, result.orientation.w = qx, qy, qz, qw
    return result


def do_transform_pose_stamped(pose: PoseStamped, transform: TransformStamped) -> PoseStamped:
    """``pose`` moved by ``transform``, stamped with the transform's header."""
    return PoseStamped(header=transform.header, pose=do_transform_pose(pose.pose, transform))


def _same(msg: object) -> object:
    return msg


for _type, _do in (
    (PointStamped, do_transform_point),
    (Vector3Stamped, do_transform_vector3),
    (PoseStamped, do_transform_pose_stamped),
):
    TransformRegistration().add(_type, _do)
    ConvertRegistration().add_to_msg(_type, _same)
    ConvertRegistration().add_from_msg(_type, _same)
del _type, _do
