"""Log levels, a logger's own level, once and skip_first, child loggers: the lines rcutils writes to stderr."""
import rclpy
from rclpy.logging import LoggingSeverity
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("levels")
    log = node.get_logger()
    log.debug("debug is below the default level: not shown")
    log.info("info")
    log.warning("warning")
    log.error("error")
    log.fatal("fatal")
    log.set_level(LoggingSeverity.DEBUG)
    log.debug("debug now shown")
    log.set_level(LoggingSeverity.ERROR)
    log.warning("warning now hidden")
    log.error("error still shown")
    log.set_level(LoggingSeverity.INFO)
    for i in range(3):
        log.info(f"once {i}", once=True)
        log.info(f"skip_first {i}", skip_first=True)
    child = log.get_child("child")
    child.info("from a child logger")
    print("effective level:", log.get_effective_level())
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
