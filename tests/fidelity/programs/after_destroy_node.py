"""What still works on a node and its entities after destroy_node(), as course code meets it
when a shutdown path runs twice: publishing, counting, a timer's cancel, the logger, the clock,
parameters, names, destroy_node() again, and entities' names and QoS."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Trigger


def attempt(label, action):
    try:
        print(label, action())
    except Exception as err:
        print(label, "->", type(err).__name__, err)


def main():
    rclpy.init()
    node = Node("gone")
    node.declare_parameter("speed", 1.0)
    publisher = node.create_publisher(String, "chatter", 10)
    subscription = node.create_subscription(String, "chatter", print, 10)
    timer = node.create_timer(0.1, lambda: None)
    client = node.create_client(Trigger, "ask")
    service = node.create_service(Trigger, "ask", lambda q, r: r)
    node.destroy_node()
    attempt("publish:", lambda: publisher.publish(String(data="late")))
    attempt("subscription count:", lambda: publisher.get_subscription_count())
    attempt("publisher topic:", lambda: publisher.topic_name)
    attempt("publisher qos depth:", lambda: publisher.qos_profile.depth)
    attempt("subscription topic:", lambda: subscription.topic_name)
    attempt("publisher count:", lambda: subscription.get_publisher_count())
    attempt("timer cancel:", lambda: timer.cancel())
    attempt("timer canceled?:", lambda: timer.is_canceled())
    attempt("timer period:", lambda: timer.timer_period_ns)
    attempt("client ready:", lambda: client.service_is_ready())
    attempt("client name:", lambda: client.srv_name)
    attempt("call_async:", lambda: type(client.call_async(Trigger.Request())).__name__)
    attempt("service name:", lambda: service.srv_name)
    attempt("logger:", lambda: node.get_logger().info("the logger still logs"))
    attempt("clock:", lambda: type(node.get_clock().now()).__name__)
    attempt("name:", lambda: node.get_name())
    attempt("namespace:", lambda: node.get_namespace())
    attempt("fully qualified:", lambda: node.get_fully_qualified_name())
    attempt("get_parameter:", lambda: node.get_parameter("speed").value)
    attempt("declare_parameter:", lambda: node.declare_parameter("later", 2).value)
    attempt("set_parameters:", lambda: [r.successful for r in node.set_parameters([rclpy.parameter.Parameter("speed", value=3.0)])])
    attempt("node names:", lambda: node.get_node_names())
    attempt("count_publishers:", lambda: node.count_publishers("chatter"))
    attempt("publishers list:", lambda: len(list(node.publishers)))
    attempt("timers list:", lambda: len(list(node.timers)))
    attempt("destroy_node again:", lambda: node.destroy_node())
    attempt("destroy_publisher:", lambda: node.destroy_publisher(publisher))
    attempt("create_timer:", lambda: type(node.create_timer(0.1, lambda: None)).__name__)
    attempt("spin_once:", lambda: rclpy.spin_once(node, timeout_sec=0))
    rclpy.shutdown()


if __name__ == "__main__":
    main()
