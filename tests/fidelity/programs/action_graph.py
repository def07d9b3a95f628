"""The hidden topics and services behind actions in graph queries: an action server's
_action/feedback and _action/status publishers and _action/send_goal, cancel_goal and
get_result services, a client's subscriptions and clients (two clients of one action, a
client with no server), their types, counts, QoS and hashes, and their going away."""
import rclpy
from _discovery import spin_until
from rclpy.action import ActionClient, ActionServer, get_action_names_and_types
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from turtlesim_msgs.action import RotateAbsolute

OURS = ("/lab/", "/spin/", "/nobody/")
"""Names of this program's actions (the graph may hold others, turtlesim's)."""


def ours(names_and_types):
    return sorted((name, types) for name, types in names_and_types if f"{name}/".startswith(OURS))


def print_names(label, names_and_types):
    """One line a name (a sandbox cuts very long lines)."""
    print(label, len(names_and_types))
    for name, types in names_and_types:
        print("   ", name, types)



def print_queries(node, label):
    print_names(f"{label} topics", ours(node.get_topic_names_and_types()))
    print_names(f"{label} services", ours(node.get_service_names_and_types()))
    print_names(f"{label} actions", ours(get_action_names_and_types(node)))


def print_by_node(node, name, namespace):
    for kind in ("publisher", "subscriber", "service", "client"):
        query = getattr(node, f"get_{kind}_names_and_types_by_node")
        print_names(f"{namespace.rstrip('/')}/{name} {kind}s", ours(query(name, namespace)))


def print_endpoints(node, topic):
    print(topic, "publishers", node.count_publishers(topic), "subscribers", node.count_subscribers(topic))
    infos = node.get_publishers_info_by_topic(topic) + node.get_subscriptions_info_by_topic(topic)
    for info in sorted(infos, key=lambda i: (i.endpoint_type.name, i.node_namespace, i.node_name)):
        qos = info.qos_profile
        print(
            f"  {info.endpoint_type.name} {info.node_namespace} {info.node_name} {info.topic_type}"
            f" {qos.reliability.name} {qos.durability.name} {qos.history.name} {qos.depth} {info.topic_type_hash}"
        )


def main():
    rclpy.init()
    server_node = Node("server", namespace="/lab")
    client_node = Node("client")
    executor = SingleThreadedExecutor()
    executor.add_node(server_node)
    executor.add_node(client_node)
    server = ActionServer(server_node, RotateAbsolute, "rotate", lambda goal_handle: RotateAbsolute.Result())
    relative = ActionClient(client_node, RotateAbsolute, "/lab/rotate")
    absolute = ActionClient(client_node, RotateAbsolute, "/lab/rotate")
    lonely = ActionClient(server_node, RotateAbsolute, "/nobody")  # no server: its services are listed too
    ActionServer(client_node, RotateAbsolute, "spin", lambda goal_handle: RotateAbsolute.Result())  # its node keeps it
    print("ready", relative.wait_for_server(timeout_sec=10.0), absolute.wait_for_server(timeout_sec=10.0))
    print("discovered", spin_until(executor, lambda: client_node.count_subscribers("/lab/rotate/_action/status") == 2))
    print_queries(client_node, "all")
    print_by_node(client_node, "server", "/lab")
    print_by_node(server_node, "client", "/")
    for topic in ("/lab/rotate/_action/feedback", "/lab/rotate/_action/status", "/nobody/_action/status"):
        print_endpoints(server_node, topic)
    for part in ("send_goal", "cancel_goal", "get_result"):
        for action in ("/lab/rotate", "/nobody", "/spin"):
            name = f"{action}/_action/{part}"
            print(name, "services", client_node.count_services(name), "clients", client_node.count_clients(name))

    absolute.destroy()
    print("one client gone", spin_until(executor, lambda: client_node.count_clients("/lab/rotate/_action/send_goal") == 1))
    print_endpoints(client_node, "/lab/rotate/_action/feedback")
    server.destroy()
    print("server gone", spin_until(executor, lambda: client_node.count_services("/lab/rotate/_action/send_goal") == 0))
    print_queries(client_node, "server gone")  # the client's endpoints keep the names listed
    relative.destroy()
    lonely.destroy()
    print("clients gone", spin_until(executor, lambda: not client_node.count_subscribers("/nobody/_action/status")))
    print_queries(client_node, "clients gone")
    server_node.destroy_node()
    print("node gone", spin_until(executor, lambda: "/lab/server" not in client_node.get_fully_qualified_node_names()))
    print_by_node(client_node, "client", "/")
    client_node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
