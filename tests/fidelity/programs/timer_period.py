"""Timer periods: timer_period_ns read and changed while the timer runs (the next calls follow
the new period), a period of 0 (ready at every spin), negative and non-number periods,
is_ready, time_since_last_call, a timer destroyed by timer.destroy(), and a callback that
is not callable."""
import rclpy
from rclpy.node import Node


def attempt(label, action):
    try:
        print(label, action())
    except Exception as err:
        print(label, "->", type(err).__name__, str(err).split(", at ")[0])  # not rcl's source location


def main():
    rclpy.init()
    node = Node("periods")
    stamps = []

    def tick():
        stamps.append(node.get_clock().now().nanoseconds)
        if len(stamps) == 3:
            timer.timer_period_ns = 300_000_000
            print("changed to:", timer.timer_period_ns)

    timer = node.create_timer(0.1, tick)
    print("period:", timer.timer_period_ns, type(timer.timer_period_ns).__name__)
    while len(stamps) < 6:
        rclpy.spin_once(node, timeout_sec=1.0)
    gaps = [round((b - a) / 1e8) for a, b in zip(stamps[:-1], stamps[1:], strict=True)]
    print("gaps in tenths of a second:", gaps)
    timer.timer_period_ns = 0.25e9
    print("float period:", timer.timer_period_ns)
    timer.cancel()
    zero_calls = []
    zero = node.create_timer(0, lambda: zero_calls.append(1))
    print("zero period:", zero.timer_period_ns, zero.is_ready())
    for _ in range(5):
        rclpy.spin_once(node, timeout_sec=1.0)
    print("zero calls after 5 spins:", len(zero_calls))
    print("since last call:", zero.time_since_last_call() >= 0)
    zero.destroy()
    print("timers after destroy():", len(list(node.timers)))
    attempt("negative:", lambda: node.create_timer(-1.0, lambda: None))
    attempt("a string:", lambda: node.create_timer("fast", lambda: None))
    attempt("None period:", lambda: node.create_timer(None, lambda: None))
    attempt("not callable:", lambda: type(node.create_timer(0.1, 42)).__name__)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
