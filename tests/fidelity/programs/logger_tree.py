"""Loggers by name: rclpy.logging.get_logger, set_logger_level and get_logger_effective_level,
a child's name and inherited level, a node in a namespace (its logger is ns.node), severities
by name, throttle_duration_sec in a timer, and a message that is not a str."""
import rclpy
import rclpy.logging
from rclpy.logging import LoggingSeverity
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("driver", namespace="/robot1")
    log = node.get_logger()
    print("node logger:", log.name)
    child = log.get_child("planner")
    print("child logger:", child.name)
    rclpy.logging.set_logger_level("robot1.driver", LoggingSeverity.WARN)
    print("levels:", log.get_effective_level(), child.get_effective_level())
    child.info("child info hidden by its parent's level")
    child.warning("child warning shown")
    rclpy.logging.set_logger_level("robot1.driver.planner", LoggingSeverity.DEBUG)
    child.debug("child debug shown by its own level")
    print("effective:", rclpy.logging.get_logger_effective_level("robot1.driver.planner"))
    free = rclpy.logging.get_logger("standalone")
    free.info("a logger of no node")
    print("severity names:", [s.name for s in LoggingSeverity])
    print("from string:", rclpy.logging.get_logging_severity_from_string("warn"))
    rclpy.logging.set_logger_level("robot1.driver", LoggingSeverity.INFO)
    ticks = []

    def tick():
        ticks.append(len(ticks) + 1)
        log.info(f"throttled at tick {len(ticks)}", throttle_duration_sec=0.35)

    node.create_timer(0.1, tick)
    while len(ticks) < 10:
        rclpy.spin_once(node, timeout_sec=1.0)
    for bad in (42, None):
        try:
            log.info(bad)
        except Exception as err:
            # the type only: rclpy's text is pybind11's signature dump, turtletui's says what to do
            print("logging", type(bad).__name__, "->", type(err).__name__)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
