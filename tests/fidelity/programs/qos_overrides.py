"""QoS overrides (the qos_overrides demos): a publisher and a subscription made with
QoSOverridingOptions declare read-only qos_overrides.<topic>.<entity>.<policy> parameters
holding their QoS, parameter overrides (-p) change the QoS they get, an entity id, a
validation callback that accepts or refuses (InvalidQosOverridesError), and a read-only
override refused at set time."""
import rclpy
from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import QoSPolicyKind, QoSProfile, ReliabilityPolicy
from rclpy.qos_overriding_options import InvalidQosOverridesError, QoSOverridingOptions
from std_msgs.msg import String


def keep_depth_small(qos):
    if qos.depth > 20:
        return SetParametersResult(successful=False, reason="depth above 20")
    return SetParametersResult(successful=True)


def main():
    rclpy.init(args=["prog", "--ros-args",
                     "-p", "qos_overrides./chatter.publisher.depth:=15",
                     "-p", "qos_overrides./chatter.subscription.reliability:=best_effort",
                     "-p", "qos_overrides./big.publisher.depth:=50"])
    node = Node("talker")
    pub = node.create_publisher(String, "chatter", 10,
                                qos_overriding_options=QoSOverridingOptions.with_default_policies())
    sub = node.create_subscription(String, "chatter", lambda msg: None, QoSProfile(depth=5),
                                   qos_overriding_options=QoSOverridingOptions.with_default_policies())
    other = node.create_publisher(String, "chatter", 10, qos_overriding_options=QoSOverridingOptions(
        [QoSPolicyKind.DURABILITY, QoSPolicyKind.LIFESPAN, QoSPolicyKind.DEADLINE], entity_id="second"))
    node.create_publisher(String, "plain", 10)
    for name in sorted(node._parameters):
        if name.startswith("qos_overrides"):
            parameter = node.get_parameter(name)
            descriptor = node.describe_parameter(name)
            print(f"{name} = {parameter.value!r} read_only={descriptor.read_only} {descriptor.description!r}")
    print("pub:", pub.qos_profile.depth, pub.qos_profile.reliability.name, pub.qos_profile.history.name)
    print("sub:", sub.qos_profile.depth, sub.qos_profile.reliability.name)
    print("other:", other.qos_profile.durability.name, other.qos_profile.lifespan)
    print("plain declares none:", not any("plain" in name for name in node._parameters))
    print(node.get_parameters_by_prefix("qos_overrides./chatter.publisher").keys())
    try:
        node.create_publisher(String, "big", 10, qos_overriding_options=QoSOverridingOptions.with_default_policies(
            callback=keep_depth_small))
    except InvalidQosOverridesError as err:
        print(f"{type(err).__name__}: {err}")
    node.create_publisher(String, "small", 10, qos_overriding_options=QoSOverridingOptions.with_default_policies(
        callback=keep_depth_small))
    result = node.set_parameters([Parameter("qos_overrides./chatter.publisher.depth", value=3)])[0]
    print("set read-only:", result.successful, result.reason)
    again = node.create_publisher(String, "chatter", QoSProfile(depth=2, reliability=ReliabilityPolicy.BEST_EFFORT),
                                  qos_overriding_options=QoSOverridingOptions.with_default_policies())
    print("again:", again.qos_profile.depth, again.qos_profile.reliability.name)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
