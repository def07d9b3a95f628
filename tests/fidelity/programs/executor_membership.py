"""Which executor spins a node: node.executor, the global executor, a node added to two executors,
remove_node, spin_once on an executor with no nodes, spinning after executor.shutdown(timeout_sec),
and a wait_for_service on a service nobody offers."""
import rclpy
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.node import Node
from std_srvs.srv import Empty


def main():
    rclpy.init()
    node = Node("member")
    print("executor before:", node.executor)
    first = SingleThreadedExecutor()
    second = SingleThreadedExecutor()
    print("add first:", first.add_node(node), node.executor is first)
    print("add second:", second.add_node(node), node.executor is second)
    print("first nodes:", [n.get_name() for n in first.get_nodes()], "second:", [n.get_name() for n in second.get_nodes()])
    first.remove_node(node)
    print("removed:", first.get_nodes(), node.executor is second)
    first.remove_node(node)
    print("removed again: fine")
    first.spin_once(timeout_sec=0.05)
    print("empty spin_once returned")
    print("global executor:", type(rclpy.get_global_executor()).__name__)
    print("multi:", type(MultiThreadedExecutor(num_threads=3)).__name__)
    ticks = []
    node.create_timer(0.05, lambda: ticks.append(1))
    second.spin_once(timeout_sec=1.0)
    print("ticked:", len(ticks))
    print("shutdown:", second.shutdown(timeout_sec=1.0))
    try:
        second.spin_once(timeout_sec=0.1)
        print("spin_once after executor shutdown returned; ticks", len(ticks))
    except Exception as err:
        print("spin_once after executor shutdown:", type(err).__name__, err)
    client = node.create_client(Empty, "no_such_service")
    print("wait_for_service:", client.wait_for_service(timeout_sec=0.3), client.service_is_ready())
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
