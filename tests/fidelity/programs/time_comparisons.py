"""Time and Duration beyond arithmetic: comparisons across clock types (refused), negative and
zero durations, repr and str, hashing, Time minus Time, Duration from messages with negative
values, seconds_nanoseconds, and invalid constructions."""
from builtin_interfaces.msg import Duration as DurationMsg
from builtin_interfaces.msg import Time as TimeMsg
from rclpy.clock import ClockType
from rclpy.duration import Duration, Infinite
from rclpy.time import Time


def attempt(label, action):
    try:
        print(label, action())
    except Exception as err:
        print(label, "->", type(err).__name__, err)


def main():
    t1 = Time(seconds=5, clock_type=ClockType.ROS_TIME)
    t2 = Time(seconds=5, clock_type=ClockType.SYSTEM_TIME)
    print(repr(t1), str(t1))
    print(repr(Duration(seconds=1.25)), str(Duration(seconds=1.25)))
    attempt("compare clocks:", lambda: t1 < t2)
    attempt("equal clocks:", lambda: t1 == t2)
    attempt("subtract clocks:", lambda: t1 - t2)
    attempt("time minus time:", lambda: (Time(seconds=7) - Time(seconds=5, nanoseconds=500)).nanoseconds)
    attempt("negative result:", lambda: Time(seconds=1) - Duration(seconds=2))
    attempt("negative duration:", lambda: Duration(seconds=-1.5).nanoseconds)
    attempt("negative to_msg:", lambda: Duration(seconds=-1.5).to_msg())
    attempt("negative time:", lambda: Time(seconds=-1))
    attempt("ns too big:", lambda: Time(nanoseconds=2**64))
    attempt("from msg:", lambda: Duration.from_msg(DurationMsg(sec=-2, nanosec=500_000_000)).nanoseconds)
    attempt("time from msg:", lambda: Time.from_msg(TimeMsg(sec=3, nanosec=7), clock_type=ClockType.STEADY_TIME))
    attempt("hash equal:", lambda: hash(Duration(seconds=1)) == hash(Duration(nanoseconds=10**9)))
    attempt("time hash:", lambda: len({Time(seconds=1), Time(nanoseconds=10**9)}))
    attempt("sorted:", lambda: [d.nanoseconds for d in sorted([Duration(seconds=2), Duration(), Duration(seconds=-1)])])
    attempt("compare to int:", lambda: Duration(seconds=1) < 5)
    attempt("eq to int:", lambda: Duration(seconds=1) == 10**9)
    attempt("duration plus time:", lambda: Duration(seconds=1) + Time(seconds=1))
    attempt("duration minus:", lambda: (Duration(seconds=1) - Duration(seconds=3)).nanoseconds)
    attempt("duration times:", lambda: (Duration(seconds=1) * 2.5).nanoseconds)
    attempt("infinite:", lambda: Infinite.nanoseconds)
    attempt("float seconds:", lambda: Time(seconds=1.999999999).seconds_nanoseconds())
    attempt("clock type:", lambda: (t1.clock_type, Time().clock_type))
    attempt("to_msg:", lambda: Time(nanoseconds=1_700_000_000_123_456_789).to_msg())


if __name__ == "__main__":
    main()
