"""Rate objects a node makes and destroys without sleeping on them: create_rate's type and
the timer it adds to node.timers, destroy_rate (and what it returns a second time),
rate.destroy() (which leaves the rate's timer to the node), a rate's sleep() after it was
destroyed, and the frequencies create_rate refuses (and the two odd ones it takes)."""
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("rates")
    before = len(list(node.timers))
    rate = node.create_rate(10.0)
    other = node.create_rate(2)
    print("type:", type(rate).__name__)
    print("timers added:", len(list(node.timers)) - before)
    print("destroy_rate:", node.destroy_rate(rate))
    print("timers after destroy_rate:", len(list(node.timers)) - before)
    print("destroy_rate again:", node.destroy_rate(rate))
    for label, sleeper in (("destroyed rate", rate),):
        try:
            sleeper.sleep()
            print(label, "slept")
        except Exception as err:
            print(label, type(err).__name__, err)
    other.destroy()
    print("timers after rate.destroy():", len(list(node.timers)) - before)
    try:
        other.sleep()
    except Exception as err:
        print("rate.destroy() then sleep:", type(err).__name__, err)
    for hz in (0, -1.0, "fast", None, float("nan"), float("inf"), True):
        try:
            made = node.create_rate(hz)
        except Exception as err:
            print(f"create_rate({hz!r}):", type(err).__name__, err)
        else:
            print(f"create_rate({hz!r}): a timer of period", made._timer.timer_period_ns, "ns")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
