"""Waiting for and listing nodes as launch-less multi-node programs do: node.wait_for_node for
a node that exists, one made later in a timer, and one that never comes (False after the
timeout), get_node_names_and_namespaces_with_enclaves, get_fully_qualified_node_names, and
a destroyed node leaving the lists."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node


def ours(names):
    """Leave out turtlesim, which turtletui runs beside the program."""
    return sorted(name for name in names if "turtlesim" not in str(name))


def main():
    rclpy.init()
    main_node = Node("coordinator")
    helper = Node("helper", namespace="/lab")
    executor = SingleThreadedExecutor()
    executor.add_node(main_node)
    print("helper:", main_node.wait_for_node("/lab/helper", timeout=2.0))
    print("relative name:", main_node.wait_for_node("lab/helper", timeout=0.5))
    print("ghost:", main_node.wait_for_node("/ghost", timeout=0.5))
    print(ours(main_node.get_node_names_and_namespaces_with_enclaves()))
    print(ours(main_node.get_fully_qualified_node_names()))
    print(ours(main_node.get_node_names()), ours(main_node.get_node_names_and_namespaces()))
    helper.destroy_node()
    for _ in range(10):
        executor.spin_once(timeout_sec=0.05)
    print(ours(main_node.get_fully_qualified_node_names()))
    print("helper after destroy:", main_node.wait_for_node("/lab/helper", timeout=0.5))
    late = Node("late")
    print("late:", main_node.wait_for_node("/late", timeout=2.0))
    print("late, timeout 0:", main_node.wait_for_node("/late", timeout=0.0))
    print("late, negative timeout:", main_node.wait_for_node("/late", timeout=-1.0))
    late.destroy_node()
    main_node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
