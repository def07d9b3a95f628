"""The yaw of a turtle as a quaternion and back (what the tf2 tutorials do by hand), in geometry_msgs."""
import math

from geometry_msgs.msg import Quaternion, TransformStamped


def quaternion_from_yaw(yaw):
    return Quaternion(x=0.0, y=0.0, z=math.sin(yaw / 2.0), w=math.cos(yaw / 2.0))


def yaw_from_quaternion(q):
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def main():
    for yaw in (0.0, math.pi / 2, -math.pi / 4, 3.0):
        q = quaternion_from_yaw(yaw)
        print(f"{yaw:+.4f} -> ({q.x:.4f}, {q.y:.4f}, {q.z:.4f}, {q.w:.4f}) -> {yaw_from_quaternion(q):+.4f}")
    t = TransformStamped()
    t.header.frame_id = "world"
    t.child_frame_id = "turtle1"
    t.transform.translation.x = 5.544445
    t.transform.rotation = quaternion_from_yaw(1.0)
    print(t.transform)
    print(Quaternion())


if __name__ == "__main__":
    main()
