"""The "stop the turtle on Ctrl-C" pattern: rclpy.init(signal_handler_options=
SignalHandlerOptions.NO) so that rclpy leaves SIGINT to Python, KeyboardInterrupt caught
around spin (raised here by a callback, as Ctrl-C would raise it), and a last zero Twist
published while the context is still ok; rclpy.signals' current options through init and
shutdown, and the small modules such code imports (rclpy.constants, rclpy.clock_type)."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.clock import ClockType as ClockTypeOfClock
from rclpy.clock_type import ClockType
from rclpy.constants import S_TO_NS
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions, get_current_signal_handlers_options


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.ticks = 0
        self.create_timer(0.1, self.drive)

    def drive(self):
        self.ticks += 1
        self.pub.publish(Twist())
        if self.ticks == 3:
            raise KeyboardInterrupt  # what Ctrl-C raises once rclpy leaves SIGINT to Python


def main():
    print("S_TO_NS:", S_TO_NS, "ClockType:", ClockType is ClockTypeOfClock, ClockType.STEADY_TIME)
    print("options:", list(SignalHandlerOptions.__members__), SignalHandlerOptions.NO, int(SignalHandlerOptions.ALL))
    print("before init:", get_current_signal_handlers_options())
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    print("after init(NO):", get_current_signal_handlers_options())
    driver = Driver()
    listener = Node("listener")
    heard = []
    listener.create_subscription(Twist, "cmd_vel", lambda msg: heard.append(msg.linear.x), 10)
    try:
        while True:
            rclpy.spin_once(driver, timeout_sec=0.2)
            rclpy.spin_once(listener, timeout_sec=0)
    except KeyboardInterrupt:
        print("interrupted after", driver.ticks, "ticks; ok:", rclpy.ok())
        stop = Twist()
        stop.linear.x = 0.0
        driver.pub.publish(stop)
        driver.get_logger().info("stopped the turtle")
    finally:
        rclpy.spin_once(listener, timeout_sec=0.5)
        print("listener heard", len(heard), "commands")
        driver.destroy_node()
        listener.destroy_node()
        rclpy.try_shutdown()
    print("after shutdown:", get_current_signal_handlers_options(), rclpy.ok())
    with rclpy.init():
        print("in with rclpy.init():", get_current_signal_handlers_options())
    print("after the with:", get_current_signal_handlers_options())


if __name__ == "__main__":
    main()
