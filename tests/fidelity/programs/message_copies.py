"""Copying, comparing and pickling messages, as course code does with poses and goals."""
import copy
import pickle

from geometry_msgs.msg import Pose, PoseStamped, Twist
from sensor_msgs.msg import LaserScan


def main():
    twist = Twist()
    twist.linear.x = 1.0
    same = copy.copy(twist)
    deep = copy.deepcopy(twist)
    print(same == twist, same is twist, same.linear is twist.linear, deep.linear is twist.linear)
    deep.linear.x = 2.0
    print(twist.linear.x, deep.linear.x, deep == twist)
    stamped = PoseStamped()
    stamped.header.frame_id = "map"
    stamped.pose = Pose()
    stamped.pose.position.y = 3.0
    back = pickle.loads(pickle.dumps(stamped))
    print(back == stamped, back)
    scan = LaserScan(ranges=[1.0, 2.5], range_max=10.0)
    print(pickle.loads(pickle.dumps(scan)) == scan, scan.ranges)
    print(Twist() != twist, Twist() == Pose())


if __name__ == "__main__":
    main()
