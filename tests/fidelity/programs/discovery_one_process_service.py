"""A service and its client in one program (one DDS participant): the client
finds the server at once and its first request, sent right after
create_client, is answered."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_srvs.srv import Trigger


def answer(request, response):
    response.success = True
    response.message = "pong"
    return response


def main():
    rclpy.init()
    server = Node("server")
    server.create_service(Trigger, "ping", answer)
    caller = Node("caller")
    client = caller.create_client(Trigger, "ping")
    print(f"ready at once: {client.service_is_ready()}")
    future = client.call_async(Trigger.Request())
    executor = SingleThreadedExecutor()
    executor.add_node(server)
    executor.add_node(caller)
    executor.spin_until_future_complete(future, timeout_sec=2.0)
    print(f"answered: {future.done() and future.result().message}")
    executor.shutdown()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
