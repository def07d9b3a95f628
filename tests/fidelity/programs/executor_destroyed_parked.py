"""A node destroyed while its callbacks wait for an executor: its timer, guard condition and
queued messages never run, an executor it is added to afterwards runs nothing of it, and the
other node goes on; a node that destroys itself in a callback runs no other callback
already ready."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future
from std_msgs.msg import String


def main():
    rclpy.init()
    keeper = Node("keeper")
    doomed = Node("doomed")
    ran = []
    doomed.create_timer(0.1, lambda: ran.append("timer"))
    guard = doomed.create_guard_condition(lambda: ran.append("guard"))
    doomed.create_subscription(String, "to_doomed", lambda msg: ran.append(msg.data), 10)
    publisher = keeper.create_publisher(String, "to_doomed", 10)
    for _ in range(200):
        if publisher.get_subscription_count() >= 1:
            break
        rclpy.spin_once(keeper, timeout_sec=0.05)
    ticks = []
    keeper.create_timer(0.1, lambda: ticks.append(1))
    publisher.publish(String(data="hello"))
    guard.trigger()
    rclpy.spin_until_future_complete(keeper, Future(), timeout_sec=0.5)
    print("while keeper spun:", ran, "keeper ticked", len(ticks) > 0)
    doomed.destroy_node()
    ticks.clear()
    executor = SingleThreadedExecutor()
    executor.add_node(keeper)
    print("add destroyed node:", executor.add_node(doomed))
    executor.spin_until_future_complete(Future(), timeout_sec=0.5)
    print("after destroy:", ran, "keeper ticked", len(ticks) > 0)
    rclpy.spin_once(doomed, timeout_sec=0.2)
    print("spin_once(destroyed):", ran)

    quitter = Node("quitter")
    quit_ran = []

    def quit_first():
        quit_ran.append("first")
        quitter.destroy_node()

    quitter.create_guard_condition(quit_first).trigger()
    quitter.create_guard_condition(lambda: quit_ran.append("second")).trigger()
    executor.add_node(quitter)
    executor.spin_until_future_complete(Future(), timeout_sec=0.5)
    print("destroyed by its own callback:", quit_ran)
    executor.shutdown()
    keeper.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
