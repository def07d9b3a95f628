"""A timer's attributes as rclpy's Timer has them: its rcl handle (timer.handle, used as a context
manager, its calls, refused once destroyed), the period read and changed, is_ready, time until the
next call and since the last one, cancel and reset, timer.destroy() (the timer stays in node.timers
until destroy_timer), a timer made with autostart=False, and a timer in a with block."""
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("timers")
    timer = node.create_timer(10.0, lambda: None)
    print(sorted(a for a in dir(timer) if not a.startswith("_")))
    handle = timer.handle
    print("handle:", type(handle).__module__, type(handle).__name__, bool(handle), handle.pointer > 0)
    with timer.handle:
        print("handle calls:", handle.is_timer_ready(), handle.is_timer_canceled(), handle.get_timer_period())
    print("period:", timer.timer_period_ns, timer.is_ready(), timer.is_canceled())
    print("until:", 0 < timer.time_until_next_call() <= 10_000_000_000, type(timer.time_until_next_call()).__name__)
    print("since:", 0 <= timer.time_since_last_call() < 10_000_000_000, type(timer.time_since_last_call()).__name__)
    timer.timer_period_ns = 5_000_000_000
    print("period now:", timer.timer_period_ns, handle.get_timer_period())
    timer.cancel()
    print("canceled:", timer.is_canceled(), timer.time_until_next_call(), timer.is_ready(), handle.is_timer_canceled())
    timer.reset()
    print("reset:", timer.is_canceled())
    print("in node:", timer in node.timers, timer.callback is not None, timer.callback_group is node.default_callback_group)
    timer.destroy()
    print("destroyed, in node:", timer in node.timers)
    for call in ("is_ready", "is_canceled", "cancel", "reset", "time_until_next_call", "time_since_last_call"):
        try:
            print(call, getattr(timer, call)())
        except Exception as err:
            print(call, type(err).__name__, err)
    for what, use in (("period", lambda: timer.timer_period_ns), ("handle", lambda: handle.__enter__())):
        try:
            print(what, use())
        except Exception as err:
            print(what, type(err).__name__, err)
    print("destroy_timer:", node.destroy_timer(timer), node.destroy_timer(timer), timer in node.timers)
    idle = node.create_timer(0.25, lambda: None, autostart=False)
    print("autostart off:", idle.is_canceled(), idle.time_until_next_call(), idle.is_ready())
    with node.create_timer(0.1, lambda: None) as scoped:
        print("with:", type(scoped).__name__, scoped.is_canceled())
    print("after with:", scoped in node.timers)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
