"""rclpy.serialization, as course code uses it to store or send messages as bytes:
serialize_message gives the CDR bytes rmw puts on the wire (a Twist, a turtlesim Pose, a
String, an empty message, a LaserScan with sequences, a Header, an Odometry with its fixed
covariance), deserialize_message makes the message back, and what each refuses."""
from geometry_msgs.msg import Twist, Vector3
from nav_msgs.msg import Odometry
from rclpy.serialization import deserialize_message, serialize_message
from sensor_msgs.msg import JointState, LaserScan
from std_msgs.msg import Empty, Header, String, UInt8MultiArray
from turtlesim_msgs.msg import Pose


def show(msg, padded=False):
    """Its bytes; those of a message with padding only counted (rmw leaves its padding unwritten)."""
    data = serialize_message(msg)
    back = deserialize_message(data, type(msg))
    print(f"{type(msg).__name__}: {type(data).__name__} of {len(data)} bytes, equal back: {back == msg}")
    if not padded:
        print(f"  {data.hex()}")
    return back


def main():
    show(Twist(linear=Vector3(x=2.0), angular=Vector3(z=-1.5)))
    back = show(Pose(x=5.544444561004639, y=1.0, theta=0.1, linear_velocity=2.0))
    print(f"  {back!r}")
    show(String(data="hello, turtle"))
    show(String(data="é"))
    show(Empty(), padded=True)
    show(Header(frame_id="odom"))
    scan = LaserScan(angle_min=-1.5, ranges=[1.0, 2.5, float("inf")], intensities=[])
    scan.header.stamp.sec = 12
    scan.header.frame_id = "laser"
    print(f"  {show(scan, padded=True).ranges!r}")
    show(JointState(name=["left", "right"], position=[0.5, -0.5], velocity=[], effort=[1.0]), padded=True)
    show(UInt8MultiArray(data=b"\x00\x01\xff"))
    odom = Odometry(child_frame_id="base_link")
    odom.pose.covariance[0] = 0.25
    odom.pose.pose.orientation.w = 1.0
    print(f"  {[float(value) for value in show(odom, padded=True).pose.covariance[:2]]}")

    data = serialize_message(Twist(linear=Vector3(x=1.0)))
    print(type(deserialize_message(data, Twist)).__name__)
    print(deserialize_message(data + b"\x00" * 8, Twist).linear)
    for bad in (lambda: serialize_message("hello"), lambda: serialize_message(Twist),
                lambda: deserialize_message(serialize_message(Vector3(x=1.0, y=2.0, z=3.0)), Twist),
                lambda: deserialize_message(b"\x00\x01\x00\x00\x03\x00\x00\x00abc", String),
                lambda: deserialize_message(bytearray(data), Twist),
                lambda: deserialize_message(data, "geometry_msgs/msg/Twist"),
                lambda: deserialize_message(data[:10], Twist),
                lambda: deserialize_message(b"", String),
                lambda: deserialize_message("text", String)):
        try:
            result = bad()
            print("no error:", result)
        except Exception as err:  # noqa: BLE001 - what rclpy raises is what is shown
            print(f"{type(err).__name__}: {err}")


if __name__ == "__main__":
    main()
