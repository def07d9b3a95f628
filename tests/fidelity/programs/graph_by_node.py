"""Graph queries by node: a node's own publishers, subscriptions, services and clients by name and
namespace, a node that does not exist, topic names and types with no_demangle, and endpoint
counts before and after destroying a subscription."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32, String
from std_srvs.srv import Trigger


def mine(pairs):
    return sorted((n, t) for n, t in pairs if not n.startswith(("/rosout", "/parameter_events", "/turtle1/")) and "/get_" not in n and "/set_" not in n and "/list_" not in n and "/describe_" not in n)


def main():
    rclpy.init()
    node = Node("mapper", namespace="/ns")
    node.create_publisher(String, "out", 10)
    node.create_publisher(Int32, "/abs/count", 10)
    sub = node.create_subscription(String, "~/in", lambda msg: None, 10)
    node.create_service(Trigger, "go", lambda request, response: response)
    node.create_client(Trigger, "/elsewhere/stop")
    print("pubs:", mine(node.get_publisher_names_and_types_by_node("mapper", "/ns")))
    print("subs:", mine(node.get_subscriber_names_and_types_by_node("mapper", "/ns")))
    print("srvs:", mine(node.get_service_names_and_types_by_node("mapper", "/ns")))
    print("clients:", mine(node.get_client_names_and_types_by_node("mapper", "/ns")))
    for query in (node.get_publisher_names_and_types_by_node, node.get_service_names_and_types_by_node):
        try:
            query("ghost", "/")
        except Exception as err:
            print(query.__name__, type(err).__name__, err)
    print("topics:", mine(node.get_topic_names_and_types()))
    print("counts:", node.count_subscribers("/ns/mapper/in"), node.count_publishers("out"), node.count_publishers("/abs/count"))
    node.destroy_subscription(sub)
    print("after destroy:", node.count_subscribers("/ns/mapper/in"), mine(node.get_subscriber_names_and_types_by_node("mapper", "/ns")))
    try:
        node.count_publishers("bad name!")
    except Exception as err:
        print("bad name:", type(err).__name__, err)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
