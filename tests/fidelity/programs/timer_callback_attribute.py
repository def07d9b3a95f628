"""Timer.callback, as rclpy keeps it: the function given to create_timer, read back and
replaced while the timer runs (from main, and by the callback itself: a timer that steps
through the states of a small machine), replaced by one whose parameter is annotated
TimerInfo (the executor then passes the call's TimerInfo), by an async def, and by a lambda;
with the timer's other surfaces a program reads: clock, callback_group, is_ready,
time_until_next_call, and the period set while it runs."""
import rclpy
from rclpy.node import Node
from rclpy.timer import TimerInfo


class Blinker(Node):
    def __init__(self):
        super().__init__("blinker")
        self.log = []
        self.timer = self.create_timer(0.1, self.on)

    def on(self):
        self.log.append("on")
        self.timer.callback = self.off

    def off(self):
        self.log.append("off")
        self.timer.callback = self.on


def main():
    rclpy.init()
    node = Blinker()
    timer = node.timer
    print("callback:", timer.callback == node.on, timer.callback.__name__)
    print("clock:", timer.clock is node.get_clock(), timer.clock.clock_type)
    print("group:", timer.callback_group is node.default_callback_group)
    for _ in range(5):
        rclpy.spin_once(node, timeout_sec=1.0)
    print("machine:", node.log, "now", timer.callback.__name__)

    infos = []

    def with_info(info: TimerInfo):
        infos.append(info)

    timer.callback = with_info
    print("set:", timer.callback is with_info)
    rclpy.spin_once(node, timeout_sec=1.0)
    rclpy.spin_once(node, timeout_sec=1.0)
    info = infos[-1]
    print(
        "info:", len(infos), type(info).__name__, type(info.expected_call_time).__name__,
        info.expected_call_time <= info.actual_call_time, info.actual_call_time.clock_type,
    )

    awaited = []

    async def coroutine():
        awaited.append("async")

    timer.callback = coroutine
    rclpy.spin_once(node, timeout_sec=1.0)
    print("async:", awaited)

    counted = []
    timer.callback = lambda: counted.append(len(counted))
    timer.timer_period_ns = 50_000_000
    print("period:", timer.timer_period_ns)
    for _ in range(4):
        rclpy.spin_once(node, timeout_sec=1.0)
    print("lambda:", counted, timer.callback.__name__)
    left = timer.time_until_next_call()
    print("until next:", 0 < left <= 50_000_000, "ready:", timer.is_ready(), "canceled:", timer.is_canceled())
    timer.cancel()
    print("after cancel:", timer.time_until_next_call(), timer.is_ready(), timer.is_canceled())
    print("callback kept:", timer.callback is not None)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
