"""rclpy's context managers: `with rclpy.init():` shuts down at its end (also when its body
raises), `with Node(...) as node:` destroys the node, `with SingleThreadedExecutor() as
executor:` shuts the executor down, and a timer, publisher and client used as one."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Trigger


def attempt(label, action):
    try:
        print(label, action())
    except Exception as err:
        print(label, "->", type(err).__name__, err)


def main():
    ticks = []
    with rclpy.init() as init:
        print("inside:", rclpy.ok(), type(init).__name__, init.context is rclpy.get_default_context())
        with Node("scoped") as node:
            print("node:", node.get_fully_qualified_name())
            with SingleThreadedExecutor() as executor:
                executor.add_node(node)
                with node.create_timer(0.05, lambda: ticks.append(len(ticks))) as timer:
                    while len(ticks) < 3:
                        executor.spin_once(timeout_sec=1.0)
                    print("timer:", type(timer).__name__, ticks)
                print("timers after with:", len(list(node.timers)))
                with node.create_publisher(String, "scoped_topic", 10) as publisher:
                    publisher.publish(String(data="hello"))
                attempt("publish after with:", lambda: publisher.publish(String(data="again")))
                print("publishers:", len(list(node.publishers)))
                with node.create_client(Trigger, "scoped_service") as client:
                    print("client:", client.srv_name)
                print("clients:", len(list(node.clients)))
            attempt("executor after with:", lambda: executor.spin_once(timeout_sec=0))
        attempt("node after with:", lambda: node.get_name())
        attempt("publisher of a destroyed node:", lambda: node.create_publisher(String, "late", 10))
        print("ok at the end of the with:", rclpy.ok())
    print("ok after:", rclpy.ok())
    try:
        with rclpy.init():
            raise ValueError("the body failed")
    except ValueError as err:
        print("raised:", err, "ok:", rclpy.ok())
    with rclpy.init():
        with Node("again") as again:
            print("again:", again.get_name(), rclpy.ok())


if __name__ == "__main__":
    main()
