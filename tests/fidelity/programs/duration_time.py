"""rclpy Duration and Time arithmetic and their messages (no clock reading: the values are made up)."""
from rclpy.duration import Duration
from rclpy.time import Time


def main():
    d = Duration(seconds=1.5)
    print(d.nanoseconds, d.to_msg())
    print(Duration(seconds=2, nanoseconds=500_000_000).nanoseconds)
    print(d + Duration(nanoseconds=1), d == Duration(nanoseconds=1_500_000_000), d < Duration(seconds=2))
    t = Time(seconds=10, nanoseconds=5)
    print(t.nanoseconds, t.seconds_nanoseconds(), t.to_msg())
    later = t + Duration(seconds=0.25)
    print(later.nanoseconds, (later - t).nanoseconds, later > t)
    print(Time.from_msg(later.to_msg()).nanoseconds)
    print(Duration.from_msg(d.to_msg()).nanoseconds)
    try:
        t + t
    except TypeError as err:
        print("TypeError:", err)


if __name__ == "__main__":
    main()
