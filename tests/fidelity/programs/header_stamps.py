"""Header stamps as course code makes them: Header(stamp=node.get_clock().now().to_msg()),
builtin_interfaces Time fields and their types, rclpy Time.from_msg round trips, Time and
Duration messages from fixed values, comparing stamps, and Time.from_msg of a Duration message."""
import rclpy
from builtin_interfaces.msg import Duration as DurationMsg
from builtin_interfaces.msg import Time as TimeMsg
from geometry_msgs.msg import PoseStamped
from rclpy.clock import ClockType
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.time import Time
from std_msgs.msg import Header


def attempt(label, action):
    try:
        print(label, "->", action())
    except Exception as err:
        print(label, "raised", type(err).__name__ + ":", err)


def main():
    rclpy.init()
    node = Node("stamps")
    now = node.get_clock().now()
    stamp = now.to_msg()
    header = Header(stamp=stamp, frame_id="map")
    print("types:", type(stamp).__name__, type(stamp.sec).__name__, type(stamp.nanosec).__name__)
    print("positive:", header.stamp.sec > 0, 0 <= header.stamp.nanosec < 10**9, header.frame_id)
    back = Time.from_msg(header.stamp)
    print("round trip:", back == now, back.nanoseconds == now.nanoseconds, back.clock_type)
    print("from_msg system:", Time.from_msg(stamp, clock_type=ClockType.SYSTEM_TIME).clock_type)
    fixed = Time(seconds=12, nanoseconds=345_000_000)
    print("fixed:", fixed.to_msg(), fixed.seconds_nanoseconds())
    print("big nanoseconds:", Time(nanoseconds=3_500_000_000).to_msg())
    print("duration msg:", Duration(seconds=1.25).to_msg(), Duration.from_msg(DurationMsg(sec=2, nanosec=5)))
    pose = PoseStamped()
    pose.header.stamp = fixed.to_msg()
    pose.header.frame_id = "odom"
    print("pose stamp:", pose.header.stamp.sec, pose.header.stamp.nanosec, pose.header == Header(stamp=TimeMsg(sec=12, nanosec=345000000), frame_id="odom"))
    print("later stamp:", Time.from_msg(TimeMsg(sec=13)) > Time.from_msg(pose.header.stamp))
    attempt("from_msg of a Duration msg", lambda: Time.from_msg(DurationMsg(sec=1)))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
