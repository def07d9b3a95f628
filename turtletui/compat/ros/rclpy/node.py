# the submodules rclpy/node.py imports, so that rclpy.publisher.Publisher and
# the like work after ``from rclpy.node import Node`` as under ROS
from rclpy import (  # noqa: E402,F401
    client,
    clock,
    clock_type,
    event_handler,
    executors,
    expand_topic_name,
    logging,
    parameter_service,
    publisher,
    qos_overriding_options,
    service,
    service_introspection,
    subscription,
    time,
    time_source,
    timer,
    topic_endpoint_info,
    type_hash,
    type_support,
    validate_full_topic_name,
    validate_namespace,
    validate_node_name,
    validate_topic_name,
)
from turtletui.compat.node import *  # noqa: F401,F403
from turtletui.compat.node import Client, Node, Publisher, Rate, Service, Subscription, Timer  # noqa: F401
from turtletui.compat.parameter import Parameter  # noqa: F401
