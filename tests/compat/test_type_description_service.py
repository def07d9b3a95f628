"""~/get_type_description on turtlesim and on controllers' nodes, in both hosts
(the differential program tests/fidelity/programs/type_description_service.py
compares a node's own answers with the real rclpy's)."""

from __future__ import annotations

import pytest
from support.hosts import node_logs

ASKER = """
import rclpy
from rclpy.node import Node
from type_description_interfaces.srv import GetTypeDescription

HASHES = {HASHES!r}


def main():
    rclpy.init()
    node = Node("asker")
    log = node.get_logger().info
    client = node.create_client(GetTypeDescription, "/turtlesim/get_type_description")
    log(f"ready {{client.wait_for_service(timeout_sec=2.0)}}")
    for type_hash in HASHES:
        future = client.call_async(GetTypeDescription.Request(type_hash=type_hash))
        rclpy.spin_until_future_complete(node, future, timeout_sec=2.0)
        answer = future.result()
        description = answer.type_description
        log(f"{{answer.successful}} {{answer.failure_reason!r}} {{description.type_description.type_name!r}} "
            f"{{len(description.referenced_type_descriptions)}} {{[s.encoding for s in answer.type_sources][:2]}}")
    node.destroy_node()
    rclpy.shutdown()


main()
"""

TWIST = "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a"
POSE = {
    "turtlesim_msgs": "RIHS01_37b07ace09a0ed2c5b774b1410dec972dfd1d292de5656ebc2b075ac646e09c8",
    "turtlesim": "RIHS01_739beba26bcba6920404ba722b7b8321348512f92ea5be235c47251940dd8aa9",
}
UNKNOWN = "RIHS01_" + "0123456789abcdef" * 4
"""A well-formed hash of no type."""


def asker(hashes: list[str]) -> str:
    return ASKER.format(HASHES=hashes)


@pytest.mark.parametrize(("distro", "package"), [("lyrical", "turtlesim_msgs"), ("jazzy", "turtlesim")])
def test_turtlesim_describes_the_types_it_uses(controller_host, distro, package):
    other = POSE["turtlesim_msgs" if package == "turtlesim" else "turtlesim"]
    result = controller_host.run(asker([TWIST, POSE[package], other, UNKNOWN, ""]), duration=3.0, distro=distro)
    assert result.ok, result.crashes
    assert node_logs(result, "asker") == [
        "ready True",
        "True '' 'geometry_msgs/msg/Twist' 1 ['msg', 'msg']",
        f"True '' '{package}/msg/Pose' 0 ['msg']",
        "False 'Type not currently in use by this node' '' 0 []",  # the other distro's Pose
        "False 'Type not currently in use by this node' '' 0 []",
        "False 'Failed to parse type hash' '' 0 []",
    ]
    assert node_logs(result, "rcl") == ["Failed to parse type hash ''"]


def test_humble_nodes_serve_no_type_descriptions(controller_host):
    result = controller_host.run("""
        import rclpy
        from rclpy.node import Node

        rclpy.init()
        node = Node("asker")
        services = dict(node.get_service_names_and_types())
        node.get_logger().info(f"{'/turtlesim/get_type_description' in services} {'/asker/get_type_description' in services}")
        node.get_logger().info(f"{node.has_parameter('start_type_description_service')}")
    """, duration=0.5, distro="humble")
    assert result.ok, result.crashes
    assert node_logs(result, "asker") == ["False False", "False"]


def test_a_node_describes_its_actions_services_and_rcls_own_types(controller_host):
    result = controller_host.run("""
        import rclpy
        from rclpy.action import ActionServer
        from rclpy.node import Node
        from turtlesim_msgs.action import RotateAbsolute
        from type_description_interfaces.srv import GetTypeDescription

        rclpy.init()
        node = Node("server")
        server = ActionServer(node, RotateAbsolute, "spin", lambda goal: RotateAbsolute.Result())
        asker = Node("asker")
        client = asker.create_client(GetTypeDescription, "/server/get_type_description")
        hashes = {
            "action": "RIHS01_18617e6b742158766b7a9a14938f06be93e499368904e91955b75e8bcc1b0fcf",
            "cancel": "RIHS01_573d8b0a534451d7bc2ac8c5ffde8ac14b8593b7001175d0cd6516dcbeb8689a",
            "log": "RIHS01_e28ce254ca8abc06abf92773b74602cdbf116ed34fbaf294fb9f81da9f318eac",
        }
        from rclpy.executors import SingleThreadedExecutor
        executor = SingleThreadedExecutor()
        executor.add_node(node)
        executor.add_node(asker)
        for name, type_hash in hashes.items():
            future = client.call_async(GetTypeDescription.Request(type_hash=type_hash, include_type_sources=False))
            executor.spin_until_future_complete(future, timeout_sec=2.0)
            answer = future.result()
            asker.get_logger().info(f"{name} {answer.successful} {answer.type_description.type_description.type_name}")
        server.destroy()
        future = client.call_async(GetTypeDescription.Request(type_hash=hashes["action"]))
        executor.spin_until_future_complete(future, timeout_sec=2.0)
        asker.get_logger().info(f"after destroy {future.result().failure_reason}")
    """, duration=3.0, distro="kilted")
    assert result.ok, result.crashes
    assert node_logs(result, "asker") == [
        "action True turtlesim_msgs/action/RotateAbsolute",
        "cancel True action_msgs/srv/CancelGoal",
        "log True rcl_interfaces/msg/Log",
        "after destroy Type not currently in use by this node",
    ]
