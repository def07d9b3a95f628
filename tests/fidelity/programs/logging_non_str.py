"""What students hand to get_logger().info(): an int, a float, a message, a list, None, bytes, an
f-string with non-str values, %-formatting and str.format, a message with a newline, and a
log call of each severity from a helper that a loop calls (one call site, one severity)."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import String


def attempt(label, action):
    try:
        print(label, "->", action())
    except Exception as err:
        print(label, "raised", type(err).__name__)


def main():
    rclpy.init()
    node = Node("chatty")
    log = node.get_logger()
    attempt("int", lambda: log.info(42))
    attempt("float", lambda: log.info(1.5))
    attempt("message", lambda: log.info(String(data="hi")))
    attempt("list", lambda: log.info([1, 2]))
    attempt("None", lambda: log.info(None))
    attempt("bytes", lambda: log.info(b"raw bytes"))
    attempt("str(message)", lambda: log.info(str(String(data="hi"))))
    twist = Twist()
    twist.linear.x = 0.5
    log.info(f"twist: {twist.linear.x} {twist.angular} {[1, 2.0]} {None} {True}")
    log.info("%s says %d and %.2f" % ("turtle", 3, 2.0 / 3))  # noqa: UP031 - as students write it
    log.info("{} at {:.1f}".format("speed", 1.25))
    log.warning("two\nlines")
    log.info("")

    def report(level, text):
        if level == "info":
            log.info(text)
        else:
            log.error(text)

    for level in ("info", "error", "info"):
        report(level, f"level {level}")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
