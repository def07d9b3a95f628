"""The endpoints rcl gives every node besides its own: /rosout and /parameter_events
publishers, the parameter services, and the parameters every rclpy node declares."""
import rclpy
from _discovery import spin_until
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import String


def main():
    rclpy.init()
    talker = Node("talker")
    quiet = Node("quiet", namespace="/lab", enable_rosout=False)
    executor = SingleThreadedExecutor()
    executor.add_node(talker)
    executor.add_node(quiet)
    talker.create_publisher(String, "chatter", 10)
    print("discovered", spin_until(executor, lambda: talker.count_publishers("/parameter_events") >= 2))
    print("talker publishes", talker.get_publisher_names_and_types_by_node("talker", "/"))
    print("quiet publishes", talker.get_publisher_names_and_types_by_node("quiet", "/lab"))
    print("talker subscribes", talker.get_subscriber_names_and_types_by_node("talker", "/"))
    topics = dict(quiet.get_topic_names_and_types())
    print("rosout", topics.get("/rosout"), "parameter_events", topics.get("/parameter_events"))
    ours = {"/talker", "/lab/quiet"}
    rosout = [f"{i.node_namespace.rstrip('/')}/{i.node_name}" for i in talker.get_publishers_info_by_topic("/rosout")]
    events = talker.get_publishers_info_by_topic("/parameter_events")
    print("rosout publishers", sorted(set(rosout) & ours))
    for info in sorted(events, key=lambda i: i.node_name):
        if f"{info.node_namespace.rstrip('/')}/{info.node_name}" in ours:
            qos = info.qos_profile
            print("event publisher", info.node_name, qos.reliability.name, qos.durability.name)
    services = talker.get_service_names_and_types_by_node("talker", "/")
    print("services", [name for name, _ in services if name != "/talker/get_type_description"])
    print("parameters", talker.list_parameters([], 0).names)
    use_sim_time = talker.get_parameter("use_sim_time")
    print("use_sim_time", use_sim_time.type_.name, use_sim_time.value)
    print("descriptor", talker.describe_parameter("use_sim_time").type)
    read_only = talker.describe_parameter("start_type_description_service").read_only
    print("start_type_description_service read only", read_only)
    print("clock ros time active", talker.get_clock().ros_time_is_active)
    talker.destroy_node()
    quiet.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
