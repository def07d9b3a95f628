"""ros2/examples' custom executor (examples_rclpy_executors/custom_executor.py), adapted to
end by itself: a PriorityExecutor that subclasses Executor, whose spin_once takes each ready
callback from wait_for_ready_callbacks and submits its handler to one of two thread pools
(the e-stop node's to the high-priority pool). spin() runs the subclass's spin_once until the
e-stop callback shuts the executor down. Sandboxed only: the pools are threads."""
from concurrent.futures import ThreadPoolExecutor

import rclpy
from rclpy.executors import Executor, ExternalShutdownException, ShutdownException
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        super().__init__("talker")
        self.i = 0
        self.pub = self.create_publisher(String, "chatter", 10)
        self.estop = self.create_publisher(String, "estop", 10)
        self.timer = self.create_timer(0.5, self.timer_callback)

    def timer_callback(self):
        if self.pub.get_subscription_count() == 0 or self.estop.get_subscription_count() == 0:
            return
        if self.i == 3:  # a tick after the last message: the e-stop
            self.timer.cancel()
            self.get_logger().info("Publishing the e-stop")
            self.estop.publish(String(data="stop"))
            return
        msg = String()
        msg.data = f"Hello World: {self.i}"
        self.i += 1
        self.get_logger().info(f'Publishing: "{msg.data}"')
        self.pub.publish(msg)


class Listener(Node):
    def __init__(self):
        super().__init__("listener")
        self.heard = []
        self.sub = self.create_subscription(String, "chatter", self.chatter_callback, 10)

    def chatter_callback(self, msg):
        self.heard.append(msg.data)
        self.get_logger().info(f'I heard: "{msg.data}"')


class Estopper(Node):
    def __init__(self, executor):
        super().__init__("estopper")
        self.executor_to_stop = executor
        self.sub = self.create_subscription(String, "estop", self.estop_callback, 10)

    def estop_callback(self, msg):
        self.get_logger().info(f'I heard: "{msg.data}"')
        self.executor_to_stop.shutdown()


class PriorityExecutor(Executor):
    """Execute high priority callbacks in multiple threads, all others in a single thread."""

    def __init__(self):
        super().__init__()
        self.high_priority_nodes = set()
        self.hp_executor = ThreadPoolExecutor(max_workers=4)
        self.lp_executor = ThreadPoolExecutor(max_workers=1)
        self.taken = []

    def add_high_priority_node(self, node):
        self.high_priority_nodes.add(node)
        # add_node inherited
        self.add_node(node)

    def spin_once(self, timeout_sec=None):
        try:
            handler, group, node = self.wait_for_ready_callbacks(timeout_sec=timeout_sec)
        except StopIteration:
            pass
        else:
            self.taken.append((type(group).__name__, node.get_name()))
            if node in self.high_priority_nodes:
                self.hp_executor.submit(handler)
            else:
                self.lp_executor.submit(handler)


def main():
    rclpy.init()
    executor = PriorityExecutor()
    listener = Listener()
    talker = Talker()
    estopper = Estopper(executor)
    executor.add_high_priority_node(estopper)
    executor.add_node(listener)
    executor.add_node(talker)
    print("nodes:", sorted(n.get_name() for n in executor.get_nodes()))
    print("context is the default:", executor.context is rclpy.get_default_context())
    try:
        executor.spin()
        print("spin returned")
    except (ShutdownException, ExternalShutdownException):
        print("spin returned")
    executor.hp_executor.shutdown(wait=True)
    executor.lp_executor.shutdown(wait=True)
    print("heard:", listener.heard)
    print("nodes after shutdown:", executor.get_nodes())
    print("first taken:", executor.taken[:1])
    print("taken by node:", sorted({name for _, name in executor.taken}))
    print("entity types:", sorted({kind for kind, _ in executor.taken}))
    for node in (listener, talker, estopper):
        node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
