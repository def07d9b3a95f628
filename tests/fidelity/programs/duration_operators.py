"""Duration and Time operators beyond those the other programs use: Duration times a float,
an int and a Duration, Duration divided, true-divided and negated, abs(), Duration plus or
minus a number, Time minus Time of another clock type, in-place += on a Time, Time compared
with a Duration, bool() of a zero Duration, and a Time's public attributes."""
from rclpy.clock import ClockType
from rclpy.duration import Duration
from rclpy.time import Time


def attempt(label, action):
    try:
        print(label, action())
    except Exception as err:
        print(label, "->", type(err).__name__, err)


def main():
    d = Duration(seconds=1.5)
    attempt("d * 2:", lambda: (d * 2).nanoseconds)
    attempt("2 * d:", lambda: (2 * d).nanoseconds)
    attempt("d * 0.1:", lambda: (d * 0.1).nanoseconds)
    attempt("d * d:", lambda: d * d)
    attempt("d * '2':", lambda: d * "2")
    attempt("d * inf:", lambda: d * float("inf"))
    attempt("d / 2:", lambda: d / 2)
    attempt("d // 2:", lambda: d // 2)
    attempt("-d:", lambda: -d)
    attempt("abs(d):", lambda: abs(d))
    attempt("d + 1:", lambda: d + 1)
    attempt("d - 1:", lambda: d - 1)
    attempt("1 + d:", lambda: 1 + d)
    attempt("d + d:", lambda: (d + d).nanoseconds)
    attempt("bool(Duration()):", lambda: bool(Duration()))
    attempt("d == 1.5:", lambda: d == 1.5)
    attempt("d != d:", lambda: d != Duration(seconds=1.5))
    attempt("d >= d:", lambda: d >= Duration(nanoseconds=1_500_000_000))
    t = Time(seconds=3)
    attempt("t += d:", lambda: _add_in_place(t, d))
    attempt("t - 1:", lambda: t - 1)
    attempt("t + 1:", lambda: t + 1)
    attempt("t < d:", lambda: t < d)
    attempt("t == d:", lambda: t == d)
    attempt("d + t:", lambda: d + t)
    attempt("t - d, other clock:", lambda: Time(seconds=3, clock_type=ClockType.STEADY_TIME) - d)
    attempt("time seconds float:", lambda: Time(seconds=1.5).nanoseconds)
    attempt("time seconds and ns:", lambda: Time(seconds=1, nanoseconds=2_000_000_000).nanoseconds)
    attempt("time negative ns:", lambda: Time(nanoseconds=-1))
    attempt("duration big:", lambda: Duration(seconds=2**63))
    attempt("time clock type int:", lambda: Time(seconds=1, clock_type=1))
    attempt("time attributes:", lambda: sorted(a for a in dir(Time()) if not a.startswith("_")))


def _add_in_place(t, d):
    t += d
    return t.nanoseconds, type(t).__name__


if __name__ == "__main__":
    main()
