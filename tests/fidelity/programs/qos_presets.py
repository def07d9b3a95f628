"""QoS profiles as printed and compared: the presets (qos_profile_sensor_data, QoSPresetProfiles),
a QoSProfile's str and equality, policies by short key, a profile with no depth, and a
publisher's and subscription's qos_profile."""
import rclpy
from rclpy.node import Node
from rclpy.qos import (
    DurabilityPolicy,
    HistoryPolicy,
    QoSPresetProfiles,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_sensor_data,
    qos_profile_services_default,
    qos_profile_system_default,
)
from std_msgs.msg import String


def main():
    print(qos_profile_sensor_data)
    for preset in QoSPresetProfiles:
        print(preset.name, preset.value)
    print(QoSPresetProfiles.short_keys())
    print(QoSProfile(depth=10) == QoSProfile(depth=10), QoSProfile(depth=10) == QoSProfile(depth=5))
    print([p.name for p in QoSPresetProfiles])
    print(QoSPresetProfiles.SENSOR_DATA.value == qos_profile_sensor_data)
    print(QoSPresetProfiles.get_from_short_key("system_default") == qos_profile_system_default)
    print(qos_profile_services_default.reliability, qos_profile_services_default.durability)
    print(ReliabilityPolicy.get_from_short_key("best_effort"), DurabilityPolicy.VOLATILE.short_key, ReliabilityPolicy.short_keys())
    print(HistoryPolicy.KEEP_LAST.value, ReliabilityPolicy.RELIABLE.value, DurabilityPolicy.TRANSIENT_LOCAL.value)
    try:
        QoSProfile()
    except Exception as err:
        print(type(err).__name__)
    all_history = QoSProfile(history=HistoryPolicy.KEEP_ALL)
    print("keep all depth:", all_history.depth, all_history.history)
    rclpy.init()
    node = Node("qos_printer")
    pub = node.create_publisher(String, "a", 7)
    sub = node.create_subscription(String, "a", lambda msg: None, qos_profile_sensor_data)
    print("publisher:", pub.qos_profile)
    print("subscription:", sub.qos_profile)
    try:
        node.create_publisher(String, "b", "ten")
    except Exception as err:
        print(type(err).__name__, err)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
