"""Logging where there is no node or no rclpy.init(): a module-level logger from
rclpy.logging.get_logger used before init, during a run and after shutdown, its child,
set_level on it and on a node's logger (and what the name tree inherits), and a node's
logger kept after destroy_node() and after rclpy.shutdown()."""
import rclpy
import rclpy.logging
from rclpy.logging import LoggingSeverity
from rclpy.node import Node

logger = rclpy.logging.get_logger("my_module")
logger.info("at import, before init")


def main():
    logger.warning("in main, before init")
    rclpy.init()
    node = Node("driver")
    child = logger.get_child("helper")
    print("names:", logger.name, child.name, node.get_logger().name, node.get_logger().get_child("part").name)
    child.info("child before set_level")
    logger.set_level(LoggingSeverity.WARN)
    print("levels:", logger.get_effective_level().name, child.get_effective_level().name)
    child.info("child info after parent WARN (hidden)")
    child.error("child error after parent WARN")
    node.get_logger().set_level(LoggingSeverity.DEBUG)
    node.get_logger().debug("node debug shown")
    node.get_logger().get_child("part").debug("node child debug shown")
    print("node levels:", node.get_logger().get_effective_level().name,
          node.get_logger().get_child("part").get_effective_level().name)
    kept = node.get_logger()
    node.destroy_node()
    kept.info("after destroy_node")
    rclpy.shutdown()
    kept.info("after shutdown")
    logger.error("module logger after shutdown")
    print("ok after shutdown:", rclpy.ok())


if __name__ == "__main__":
    main()
