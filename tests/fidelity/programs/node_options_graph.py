"""Node options that change what a node puts on the graph: enable_rosout=False (no /rosout
publisher, its log lines still on the console), start_parameter_services=False (none of the
six parameter services; get/set_parameters still work in the program), a namespaced node's
private ('~/') and relative service and client names (srv_name as given and resolved), and
count_services/count_clients."""
import rclpy
from rclpy.node import Node
from std_srvs.srv import Trigger


def own(pairs):
    return sorted(name for name, _ in pairs)


def main():
    rclpy.init()
    quiet = Node("quiet", enable_rosout=False, start_parameter_services=False)
    quiet.get_logger().info("still on the console")
    print("quiet publishers:", own(quiet.get_publisher_names_and_types_by_node("quiet", "/")))
    print("quiet services:", own(quiet.get_service_names_and_types_by_node("quiet", "/")))
    quiet.declare_parameter("gain", 2.0)
    print("quiet parameter:", quiet.get_parameter("gain").value)
    robot = Node("driver", namespace="robot1")
    service = robot.create_service(Trigger, "~/reset", lambda req, res: res)
    relative = robot.create_service(Trigger, "start", lambda req, res: res)
    client = robot.create_client(Trigger, "~/reset")
    absolute = robot.create_client(Trigger, "/robot1/start")
    print("service names:", service.srv_name, relative.srv_name)
    print("client names:", client.srv_name, absolute.srv_name)
    print("driver services:", [n for n in own(robot.get_service_names_and_types_by_node("driver", "/robot1"))
                               if n.endswith(("reset", "start"))])
    print("driver clients:", own(robot.get_client_names_and_types_by_node("driver", "/robot1")))
    for name in ("/robot1/driver/reset", "start", "~/reset", "/robot1/start", "/nobody"):
        print("count", name, robot.count_services(name), robot.count_clients(name))
    print("ready:", client.wait_for_service(timeout_sec=2.0), absolute.service_is_ready())
    future = client.call_async(Trigger.Request())
    rclpy.spin_until_future_complete(robot, future, timeout_sec=2.0)
    print("answered:", future.done(), future.result().success)
    quiet.destroy_node()
    robot.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
