"""rclpy.spin/spin_once on a node that was in another executor: node.executor follows the last
add_node (rclpy.spin_once's global executor included, even after it removes the node), both
executors list it, and each runs its callbacks; rclpy.spin in a timer-ended program after the
node was in a shut down executor."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


def main():
    rclpy.init()
    node = Node("wanderer")
    ticks = []
    node.create_timer(0.1, lambda: ticks.append(1))
    first = SingleThreadedExecutor()
    first.add_node(node)
    first.spin_until_future_complete(Future(), timeout_sec=0.35)
    print("first ran:", len(ticks) > 0, "executor is first:", node.executor is first)
    ticks.clear()
    rclpy.spin_once(node, timeout_sec=1.0)
    print("spin_once ran:", len(ticks), "executor is global:", node.executor is rclpy.get_global_executor())
    print("first still has it:", [n.get_name() for n in first.get_nodes()],
          "global has it:", rclpy.get_global_executor().get_nodes())
    ticks.clear()
    first.spin_until_future_complete(Future(), timeout_sec=0.35)
    print("first runs it again:", len(ticks) > 0, "executor is global:", node.executor is rclpy.get_global_executor())
    first.shutdown()
    print("after first.shutdown:", first.get_nodes(), "executor is first:", node.executor is first)
    ticks.clear()
    stop = Future()
    node.create_timer(0.5, lambda: stop.done() or stop.set_result(True))
    rclpy.spin_until_future_complete(node, stop, timeout_sec=3.0)
    print("global spin:", stop.done(), len(ticks) > 0)
    second = SingleThreadedExecutor()
    print("add to second:", second.add_node(node), "executor is second:", node.executor is second)
    ticks.clear()
    rclpy.spin_once(node, executor=second, timeout_sec=1.0)
    print("spin_once with executor=second:", len(ticks), [n.get_name() for n in second.get_nodes()])
    second.shutdown()
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
