"""An executor runs the callbacks of the nodes added to it only: spin_once and spin_until_future_complete
on one node leave another node's timers and subscriptions waiting (its messages kept, up to its queue's
depth), a service served by a node nobody spins never answers, and the waiting callbacks run once their
node is spun."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future
from std_msgs.msg import Int32
from std_srvs.srv import Trigger


def main():
    rclpy.init()
    spun = Node("spun")
    idle = Node("idle")
    ticks = {"spun": 0, "idle": 0}
    heard = []
    spun.create_timer(0.1, lambda: ticks.__setitem__("spun", ticks["spun"] + 1))
    idle.create_timer(0.1, lambda: ticks.__setitem__("idle", ticks["idle"] + 1))
    idle.create_subscription(Int32, "numbers", lambda msg: heard.append(msg.data), 3)

    def serve(request, response):
        response.success = True
        response.message = "served"
        return response

    idle.create_service(Trigger, "ask_idle", serve)
    publisher = spun.create_publisher(Int32, "numbers", 10)
    while publisher.get_subscription_count() < 1:
        rclpy.spin_once(spun, timeout_sec=0.05)
    ticks["spun"] = 0
    for n in range(6):
        publisher.publish(Int32(data=n))
        rclpy.spin_once(spun, timeout_sec=0.2)
    print("spin_once on spun: spun ticked", ticks["spun"] > 0, "idle ticked", ticks["idle"], "heard", heard)

    client = spun.create_client(Trigger, "ask_idle")
    print("service ready:", client.wait_for_service(timeout_sec=2.0))
    future = client.call_async(Trigger.Request())
    rclpy.spin_until_future_complete(spun, future, timeout_sec=1.0)
    print("answered while only spun spins:", future.done())

    never = Future()
    rclpy.spin_until_future_complete(idle, never, timeout_sec=0.35)
    print("after spinning idle: idle ticked", ticks["idle"] > 0, "heard", heard)
    rclpy.spin_until_future_complete(spun, future, timeout_sec=1.0)
    print("answered now:", future.done(), future.result().message if future.done() else None)

    executor = SingleThreadedExecutor()
    executor.add_node(spun)
    executor.add_node(idle)
    ticks["spun"] = ticks["idle"] = 0
    end = Future()
    executor.spin_until_future_complete(end, timeout_sec=0.55)
    print("both in one executor: spun ticked", ticks["spun"] > 0, "idle ticked", ticks["idle"] > 0)
    executor.remove_node(idle)
    ticks["idle"] = 0
    executor.spin_until_future_complete(end, timeout_sec=0.55)
    print("idle removed: idle ticked", ticks["idle"])
    executor.shutdown()
    spun.destroy_node()
    idle.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
