"""Node(enable_logger_service=True): its get_logger_levels and set_logger_levels services
(listed with the parameter services), the levels they read and set, an invalid level refused
with rclpy's reason, and a debug line shown once the level is set through the service."""
import rclpy
from rcl_interfaces.msg import LoggerLevel
from rcl_interfaces.srv import GetLoggerLevels, SetLoggerLevels
from rclpy.node import Node


def main():
    rclpy.init()
    server = Node("with_service", enable_logger_service=True)
    client_node = Node("client_node")
    names = [n for n, _ in server.get_service_names_and_types_by_node("with_service", "/")]
    print(sorted(names))
    print(sorted(n for n, _ in client_node.get_service_names_and_types_by_node("client_node", "/")))
    get = client_node.create_client(GetLoggerLevels, "/with_service/get_logger_levels")
    setc = client_node.create_client(SetLoggerLevels, "/with_service/set_logger_levels")
    print(get.wait_for_service(timeout_sec=5.0), setc.wait_for_service(timeout_sec=5.0))
    ex = rclpy.executors.SingleThreadedExecutor()
    ex.add_node(server)
    ex.add_node(client_node)
    req = GetLoggerLevels.Request(names=["with_service", "other"])
    f = get.call_async(req)
    ex.spin_until_future_complete(f, timeout_sec=5.0)
    print(f.result())
    req = SetLoggerLevels.Request(levels=[LoggerLevel(name="with_service", level=10), LoggerLevel(name="bad", level=7)])
    f = setc.call_async(req)
    ex.spin_until_future_complete(f, timeout_sec=5.0)
    print(f.result())
    server.get_logger().debug("debug now shown")
    f = get.call_async(GetLoggerLevels.Request(names=["with_service"]))
    ex.spin_until_future_complete(f, timeout_sec=5.0)
    print(f.result())
    print(server.get_logger().get_effective_level())
    ex.shutdown()
    server.destroy_node()
    client_node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
