"""Field type checks as rclpy makes them with ROS_PYTHON_CHECK_FIELDS=1: what is accepted, what is refused and why."""
import os

os.environ["ROS_PYTHON_CHECK_FIELDS"] = "1"

import array  # noqa: E402

from geometry_msgs.msg import Point32, Twist, Vector3  # noqa: E402
from nav_msgs.msg import OccupancyGrid  # noqa: E402
from sensor_msgs.msg import Image, JointState, LaserScan  # noqa: E402
from std_msgs.msg import Bool, Char, Float32MultiArray, Int8, String, UInt8  # noqa: E402


def attempt(label, action):
    try:
        value = action()
        print(label, "->", repr(value))
    except (AssertionError, TypeError, ValueError) as err:
        print(label, "->", type(err).__name__ + ":", str(err).split(" (")[0])


def setter(msg, field, value):
    def run():
        setattr(msg, field, value)
        return getattr(msg, field)
    return run


def main():
    twist = Twist()
    attempt("linear.x = 2.0", setter(twist.linear, "x", 2.0))
    attempt("linear.x = 2", setter(twist.linear, "x", 2))
    attempt("linear.x = '2'", setter(twist.linear, "x", "2"))
    attempt("linear = Vector3(x=1.0)", setter(twist, "linear", Vector3(x=1.0)))
    attempt("linear = Point32()", setter(twist, "linear", Point32()))
    attempt("Point32 x = 1e39", setter(Point32(), "x", 1e39))
    attempt("Int8 data = 128", setter(Int8(), "data", 128))
    attempt("UInt8 data = -1", setter(UInt8(), "data", -1))
    attempt("UInt8 data = True", setter(UInt8(), "data", True))
    attempt("Char data = 65", setter(Char(), "data", 65))
    attempt("Char data = 'A'", setter(Char(), "data", "A"))
    attempt("Bool data = 1", setter(Bool(), "data", 1))
    attempt("String data = 5", setter(String(), "data", 5))
    scan = LaserScan()
    attempt("ranges = [1.0, 2.0]", setter(scan, "ranges", [1.0, 2.0]))
    attempt("ranges = [1, 2]", setter(scan, "ranges", [1, 2]))
    attempt("ranges = array('f')", setter(scan, "ranges", array.array("f", [3.0])))
    attempt("ranges = array('d')", setter(scan, "ranges", array.array("d", [3.0])))
    attempt("LaserScan(ranges=[1, 2])", lambda: LaserScan(ranges=[1, 2]).ranges)
    image = Image()
    attempt("data = b'abc'", setter(image, "data", b"abc"))
    attempt("data = [1, 2, 300]", setter(image, "data", [1, 2, 300]))
    grid = OccupancyGrid()
    attempt("grid data = [-1, 0, 100]", setter(grid, "data", [-1, 0, 100]))
    attempt("grid data = [200]", setter(grid, "data", [200]))
    joints = JointState()
    attempt("names = ['a', 'b']", setter(joints, "name", ["a", "b"]))
    attempt("names = 'ab'", setter(joints, "name", "ab"))
    attempt("Float32MultiArray data = (1.5,)", setter(Float32MultiArray(), "data", (1.5,)))
    attempt("Twist(speed=1.0)", lambda: Twist(speed=1.0))
    attempt("Twist() == Twist()", lambda: Twist() == Twist())
    attempt("hash(Twist())", lambda: hash(Twist()))


if __name__ == "__main__":
    main()
