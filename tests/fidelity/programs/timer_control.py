"""Timer control: cancel, is_canceled, reset, time_until_next_call after cancel, a timer made
with autostart=False, a callback whose parameter is annotated TimerInfo, destroy_timer then spinning, and the
timer's period and clock."""
import rclpy
from rclpy.node import Node
from rclpy.timer import TimerInfo


def main():
    rclpy.init()
    node = Node("timers")
    calls = {"fast": 0, "idle": 0, "gone": 0}

    def fast():
        calls["fast"] += 1

    def idle():
        calls["idle"] += 1

    def gone():
        calls["gone"] += 1

    fast_timer = node.create_timer(0.1, fast)
    idle_timer = node.create_timer(0.1, idle, autostart=False)
    gone_timer = node.create_timer(0.1, gone)
    print("period:", fast_timer.timer_period_ns, "clock:", fast_timer.clock.clock_type, f"{fast_timer.clock.clock_type}")
    print("canceled?", fast_timer.is_canceled(), idle_timer.is_canceled())
    print("destroyed:", node.destroy_timer(gone_timer))
    while calls["fast"] < 3:
        rclpy.spin_once(node, timeout_sec=1.0)
    print("after three:", calls)
    fast_timer.cancel()
    print("canceled now?", fast_timer.is_canceled(), "next call:", fast_timer.time_until_next_call())
    idle_timer.reset()
    print("idle started?", not idle_timer.is_canceled())
    while calls["idle"] < 2:
        rclpy.spin_once(node, timeout_sec=1.0)
    print("after idle two:", calls)
    idle_timer.cancel()
    infos = []

    def with_info(info: TimerInfo):
        infos.append(info)

    node.create_timer(0.05, with_info)
    while len(infos) < 2:
        rclpy.spin_once(node, timeout_sec=1.0)
    info = infos[0]
    print("timer info:", type(info).__name__, sorted(a for a in dir(info) if not a.startswith("_")))
    print("expected before actual:", info.expected_call_time <= info.actual_call_time)
    print("times:", type(info.expected_call_time).__name__, type(info.actual_call_time).__name__)
    print("annotation:", type(with_info.__annotations__["info"]).__name__)
    print("final:", calls)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
