"""A service client on one node and its server on another: an executor with both nodes gets
the answer; one with the client's node only waits in vain until the server's node is spun;
spin_until_future_complete(node_b, future) where node_a's timer completes the future ends
only by its timeout, and completes once an executor has node_a too."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future
from std_srvs.srv import SetBool


def main():
    rclpy.init()
    asker = Node("asker")
    server = Node("answerer")
    served = []

    def serve(request, response):
        served.append(request.data)
        response.success = request.data
        response.message = f"got {request.data}"
        return response

    server.create_service(SetBool, "decide", serve)
    client = asker.create_client(SetBool, "decide")
    print("ready:", client.wait_for_service(timeout_sec=5.0))

    both = SingleThreadedExecutor()
    both.add_node(asker)
    both.add_node(server)
    future = client.call_async(SetBool.Request(data=True))
    both.spin_until_future_complete(future, timeout_sec=5.0)
    print("both nodes:", future.done(), future.result().message if future.done() else None, served)
    both.shutdown()

    only = SingleThreadedExecutor()
    only.add_node(asker)
    future = client.call_async(SetBool.Request(data=False))
    only.spin_until_future_complete(future, timeout_sec=1.0)
    print("client's node only:", future.done(), served)
    only.add_node(server)
    only.spin_until_future_complete(future, timeout_sec=5.0)
    print("server added:", future.done(), future.result().message if future.done() else None, served)
    only.shutdown()

    completed = Future()
    fired = []

    def complete():
        fired.append(1)
        if not completed.done():
            completed.set_result("from asker's timer")

    timer = asker.create_timer(0.1, complete)
    rclpy.spin_until_future_complete(server, completed, timeout_sec=1.0)
    print("spinning answerer:", completed.done(), len(fired))
    rclpy.spin_until_future_complete(asker, completed, timeout_sec=2.0)
    print("spinning asker:", completed.done(), completed.result() if completed.done() else None, len(fired))
    timer.cancel()
    asker.destroy_node()
    server.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
