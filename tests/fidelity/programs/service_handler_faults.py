"""Service callbacks that go wrong: one returns None, one returns the wrong type, one raises.
What the server side logs or raises out of spin, and what the client gets."""
import rclpy
from rclpy.node import Node
from std_srvs.srv import Trigger


def main():
    rclpy.init()
    node = Node("faulty")
    node.create_service(Trigger, "none", lambda request, response: None)
    node.create_service(Trigger, "wrong", lambda request, response: "not a response")

    def raising(request, response):
        raise RuntimeError("handler failed")

    node.create_service(Trigger, "raises", raising)
    for name in ("none", "wrong", "raises"):
        client = node.create_client(Trigger, name)
        client.wait_for_service(timeout_sec=5.0)
        future = client.call_async(Trigger.Request())
        try:
            rclpy.spin_until_future_complete(node, future, timeout_sec=1.0)
            print(name, "spin returned; done:", future.done())
        except Exception as err:
            # the type only: rclpy's TypeError for a wrong response is empty, turtletui's says why
            print(name, "spin raised:", type(err).__name__, err if name == "raises" else "")
        for _ in range(5):
            try:
                rclpy.spin_once(node, timeout_sec=0.05)
            except Exception as err:
                print(name, "later spin raised:", type(err).__name__, err)
        print(name, "answered:", future.done())
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
