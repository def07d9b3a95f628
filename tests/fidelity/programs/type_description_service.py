"""Every node serves ~/get_type_description: it lists it among its services and answers
with the description and RIHS01 hash of each type it uses (messages, services and actions,
turtlesim's included), its sources if asked, rcl's failure reasons for a malformed or an
unknown hash, and topic endpoint infos carry the same hashes."""
import hashlib
import json

import rclpy
from _discovery import spin_until
from geometry_msgs.msg import Twist
from rclpy.action import ActionClient
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_srvs.srv import SetBool, Trigger
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Pose
from type_description_interfaces.srv import GetTypeDescription


def rihs01(description):
    """The hash of a returned TypeDescription, computed as rosidl does."""
    def individual(t):
        fields = [{"name": f.name, "type": {"type_id": f.type.type_id, "capacity": f.type.capacity,
                                            "string_capacity": f.type.string_capacity,
                                            "nested_type_name": f.type.nested_type_name}} for f in t.fields]
        return {"type_name": t.type_name, "fields": fields}
    hashable = {"type_description": individual(description.type_description),
                "referenced_type_descriptions": [individual(t) for t in description.referenced_type_descriptions]}
    text = json.dumps(hashable, separators=(", ", ": "))
    return "RIHS01_" + hashlib.sha256(text.encode()).hexdigest()


KNOWN = {
    # from the ROS 2 Kilted share/<package>/*/*.json files rosidl writes
    "std_srvs/srv/SetBool": "RIHS01_abe9e4bb6b41b40e6789712c00ec8871923e089af3f667a79992a428cff2da0a",
    "turtlesim/action/RotateAbsolute": "RIHS01_08ba6dd83d976f1cb548edd1f75f16cf30cca624ce1410b6ce77f44b8a3c2895",
    "type_description_interfaces/srv/GetTypeDescription":
        "RIHS01_69b9c19c1021405984cc60dbbb1edceb147a6538b411d812ba6afabeed962cd5",
    "rcl_interfaces/msg/Log": "RIHS01_e28ce254ca8abc06abf92773b74602cdbf116ed34fbaf294fb9f81da9f318eac",
}


def main():
    rclpy.init()
    node = Node("describer")
    off = Node("quiet", parameter_overrides=[rclpy.parameter.Parameter("start_type_description_service", value=False)])
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    executor.add_node(off)
    node.create_publisher(Twist, "cmd", 10)
    node.create_subscription(Pose, "pose", lambda msg: None, 10)
    node.create_service(SetBool, "switch", lambda request, response: response)
    node.create_client(Trigger, "trigger")
    ActionClient(node, RotateAbsolute, "rotate")
    services = dict(node.get_service_names_and_types_by_node("describer", "/"))
    print("served", services.get("/describer/get_type_description"))
    print("quiet serves", "/quiet/get_type_description" in dict(off.get_service_names_and_types_by_node("quiet", "/")))
    print("quiet parameter", off.get_parameter("start_type_description_service").value)
    client = node.create_client(GetTypeDescription, "/describer/get_type_description")
    print("ready", spin_until(executor, client.service_is_ready))

    def ask(type_hash, sources=True):
        future = client.call_async(GetTypeDescription.Request(type_hash=type_hash, include_type_sources=sources))
        spin_until(executor, future.done)
        return future.result()

    print("default request", GetTypeDescription.Request())
    answer = ask("")
    print("empty hash", answer.successful, repr(answer.failure_reason))
    answer = ask("RIHS01_" + "0" * 64)
    print("unknown hash", answer.successful, repr(answer.failure_reason))
    [info] = node.get_publishers_info_by_topic("/cmd")
    twist = str(info.topic_type_hash)
    print("endpoint hash", twist)
    answer = ask("RIHS01_" + twist[7:].upper(), sources=False)
    print("upper-case hex", answer.successful, answer.type_description.type_description.type_name, len(answer.type_sources))
    [pose_info] = node.get_subscriptions_info_by_topic("/pose")
    for type_hash in (twist, str(pose_info.topic_type_hash)):
        answer = ask(type_hash)
        description = answer.type_description
        print(description.type_description.type_name, answer.successful, rihs01(description) == type_hash)
        print("  fields", [(f.name, f.type.type_id, f.default_value) for f in description.type_description.fields])
        print("  references", [t.type_name for t in description.referenced_type_descriptions])
        for source in answer.type_sources:
            print("  source", source.type_name, source.encoding, len(source.raw_file_contents),
                  source.raw_file_contents.splitlines()[-1:])
        print("  extra", answer.extra_information)
    for name, type_hash in KNOWN.items():
        answer = ask(type_hash)
        description = answer.type_description
        print(name, answer.successful, description.type_description.type_name, rihs01(description) == type_hash)
        print("  fields", [f.name for f in description.type_description.fields])
        print("  references", len(description.referenced_type_descriptions),
              [(s.type_name, s.encoding, len(s.raw_file_contents)) for s in answer.type_sources[:3]])
    node.destroy_node()
    off.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
