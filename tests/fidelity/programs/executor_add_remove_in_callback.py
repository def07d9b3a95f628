"""Changing an executor's nodes from inside its callbacks: add_node from a timer while the
executor spins makes the new node's callbacks run in that same spin; remove_node of the
callback's own node stops its timer; node.executor after add_node, remove_node and
rclpy.spin_once with another executor."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


def main():
    rclpy.init()
    host = Node("adder")
    guest = Node("guest")
    executor = SingleThreadedExecutor()
    executor.add_node(host)
    counts = {"host": 0, "guest": 0}
    done = Future()

    def guest_tick():
        counts["guest"] += 1
        if counts["guest"] == 3 and not done.done():
            done.set_result("guest ticked thrice")

    guest.create_timer(0.1, guest_tick)

    def add_guest():
        counts["host"] += 1
        if counts["host"] == 2:
            print("adding guest from a callback:", executor.add_node(guest), guest.executor is executor)

    host_timer = host.create_timer(0.1, add_guest)
    executor.spin_until_future_complete(done, timeout_sec=5.0)
    print("future:", done.result() if done.done() else None, "host ticked", counts["host"] >= 2)
    print("nodes:", sorted(n.get_name() for n in executor.get_nodes()))
    host_timer.cancel()

    removed = Future()

    def remove_self():
        executor.remove_node(guest)
        if not removed.done():
            removed.set_result(True)

    counts["guest"] = 0
    guest_timer = guest.create_timer(0.05, remove_self)
    executor.spin_until_future_complete(removed, timeout_sec=2.0)
    print("removed from its callback:", removed.done(), [n.get_name() for n in executor.get_nodes()])
    guest_timer.cancel()
    counts["guest"] = 0
    executor.spin_until_future_complete(Future(), timeout_sec=0.5)
    print("guest ticks after removal:", counts["guest"], "guest.executor is executor:", guest.executor is executor)
    rclpy.spin_once(guest, timeout_sec=0.5)
    print("after rclpy.spin_once: guest ticked", counts["guest"] > 0,
          "executor is global:", guest.executor is rclpy.get_global_executor())
    print("global nodes:", rclpy.get_global_executor().get_nodes())
    executor.shutdown()
    host.destroy_node()
    guest.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
