"""Graph queries between two nodes of one program: counts, names and types, and a
destroyed service, publisher and node going away for the other node."""
import rclpy
from _discovery import spin_until
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Empty


def main():
    rclpy.init()
    talker = Node("talker")
    listener = Node("listener", namespace="/lab")
    executor = SingleThreadedExecutor()
    executor.add_node(talker)
    executor.add_node(listener)
    pub = talker.create_publisher(String, "chatter", 10)
    listener.create_subscription(String, "/chatter", lambda msg: None, 10)
    server = talker.create_service(Empty, "ping", lambda request, response: response)
    client = listener.create_client(Empty, "/ping")
    ours = {"/talker", "/lab/listener"}
    print("subscribed", spin_until(executor, lambda: pub.get_subscription_count() == 1))
    print("counts", talker.count_publishers("chatter"), listener.count_subscribers("/chatter"))
    print("nodes", spin_until(executor, lambda: ours <= set(talker.get_fully_qualified_node_names())))
    print(sorted(n for n in listener.get_node_names_and_namespaces() if n[0] in ("talker", "listener")))
    print("ready", client.wait_for_service(timeout_sec=10.0))
    print("chatter", dict(talker.get_topic_names_and_types()).get("/chatter"))
    print("ping", dict(listener.get_service_names_and_types()).get("/ping"))
    subscribed = listener.get_subscriber_names_and_types_by_node("listener", "/lab")
    print("listener subscribes", [t for t in subscribed if t[0] == "/chatter"])
    [info] = listener.get_publishers_info_by_topic("/chatter")
    print("publisher", info.node_namespace, info.node_name, info.topic_type, info.endpoint_type.name)
    print("destroyed", talker.destroy_service(server))
    print("service gone", spin_until(executor, lambda: not client.service_is_ready()))
    print("services", listener.count_services("/ping"), listener.count_clients("/ping"))
    talker.destroy_publisher(pub)
    print("publisher gone", spin_until(executor, lambda: listener.count_publishers("/chatter") == 0))
    talker.destroy_node()
    print("node gone", spin_until(executor, lambda: "/talker" not in listener.get_fully_qualified_node_names()))
    listener.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
