"""From Kilted on turtlesim's types are turtlesim_msgs': the graph names a node's own
Pose publisher, Spawn service and RotateAbsolute action turtlesim_msgs/..., in
get_topic_names_and_types, get_service_names_and_types(_by_node), the publishers' infos
and the action names, and the messages print so."""
import rclpy
from rclpy.action import ActionServer, get_action_names_and_types
from rclpy.node import Node
from turtlesim_msgs.action import RotateAbsolute
from turtlesim_msgs.msg import Pose
from turtlesim_msgs.srv import Spawn


def own(names_and_types):
    """This node's own endpoints (an action's hidden /_action/ ones left out)."""
    return sorted((name, types) for name, types in names_and_types
                  if name.startswith("/names_") and "/_" not in name)


def main():
    rclpy.init()
    node = Node("names_probe")
    node.create_publisher(Pose, "names_pose", 10)
    node.create_service(Spawn, "names_spawn", lambda request, response: response)
    ActionServer(node, RotateAbsolute, "names_rotate", lambda goal: RotateAbsolute.Result())
    for _ in range(20):
        rclpy.spin_once(node, timeout_sec=0.05)
    print("topics:", own(node.get_topic_names_and_types()))
    print("services:", own(node.get_service_names_and_types()))
    print("by node:", own(node.get_service_names_and_types_by_node("names_probe", "/")))
    print("publishers:", [info.topic_type for info in node.get_publishers_info_by_topic("/names_pose")])
    print("actions:", own(get_action_names_and_types(node)))
    print(Pose(x=1.5), Spawn.Request(name="t2"), RotateAbsolute.Goal(theta=0.5), sep="\n")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
