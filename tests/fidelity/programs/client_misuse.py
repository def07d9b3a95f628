"""A service client misused as course code does: call_async with a request of the wrong type
(a Response, another service's Request, a string), and a client used after destroy_client():
service_is_ready, call_async, destroy_client again. What is raised, by type and text."""
import rclpy
from rclpy.node import Node
from std_srvs.srv import SetBool, Trigger


def attempt(label, action, text=True):
    try:
        print(label, "->", action())
    except Exception as err:
        print(label, "raised", type(err).__name__ + ":", err if text else "")


def main():
    rclpy.init()
    node = Node("client_misuse")
    node.create_service(Trigger, "ask", lambda request, response: Trigger.Response(success=True, message="ok"))
    client = node.create_client(Trigger, "ask")
    print("ready:", client.wait_for_service(timeout_sec=5.0))
    # the type only: rclpy's TypeError for a wrong request is empty, turtletui's says why
    attempt("response as request", lambda: client.call_async(Trigger.Response()), text=False)
    attempt("other service's request", lambda: client.call_async(SetBool.Request(data=True)), text=False)
    attempt("a string", lambda: client.call_async("please"), text=False)
    future = client.call_async(Trigger.Request())
    rclpy.spin_until_future_complete(node, future, timeout_sec=5.0)
    print("right request:", future.result().success, future.result().message)
    print("destroy_client:", node.destroy_client(client))
    print("clients left:", len(list(node.clients)))
    attempt("destroy_client again", lambda: node.destroy_client(client))
    attempt("service_is_ready after destroy", lambda: client.service_is_ready())
    attempt("call_async after destroy", lambda: type(client.call_async(Trigger.Request())).__name__)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
