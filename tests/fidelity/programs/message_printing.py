"""Printing messages as students do to debug: print(msg) of filled nested messages, str() and
f-strings, array fields as they come back (float32 lists, float64, bytes, strings), a numpy
array's list assigned to an array field (turtletui checks fields as Humble does, which refuses
the array itself), a list assigned to a float32 field rounded, and repr of one field."""
import numpy as np
from geometry_msgs.msg import Point, Pose, PoseArray, Twist, Vector3
from sensor_msgs.msg import JointState, LaserScan
from std_msgs.msg import ColorRGBA, Float32MultiArray, Header, String


def main():
    twist = Twist(linear=Vector3(x=1.0), angular=Vector3(z=-0.5))
    print(twist)
    print(f"{twist.linear}")
    print(str(String(data="it's \"quoted\"\n")))
    scan = LaserScan(header=Header(frame_id="laser"), angle_min=-1.5707963, range_max=3.5)
    scan.ranges = [0.1, 0.2, float("inf"), float("nan")]
    scan.intensities = np.array([1.5, 2.25], dtype=np.float32).tolist()
    print(scan)
    print(repr(scan.ranges), type(scan.ranges).__name__, scan.angle_min)
    joints = JointState(name=["left", "right"], position=[0.1, 0.2], velocity=np.array([1.0, 2.0]).tolist())
    print(joints)
    print(type(joints.position).__name__, type(joints.velocity).__name__, joints.velocity.tolist())
    color = ColorRGBA(r=0.1, g=0.2, b=1.0, a=1.0)
    print(color, color.r)
    arr = Float32MultiArray(data=[1.1, 2.2])
    print(arr, arr.data[0])
    poses = PoseArray(poses=[Pose(position=Point(x=1.0)), Pose()])
    print(poses)
    print(len(poses.poses), poses.poses[0].position)
    print([p.position.x for p in poses.poses])


if __name__ == "__main__":
    main()
