"""Several requests sent with call_async() before anything spins, as a node does that asks
a service for each waypoint: the first spin_once() runs one callback (the server handles
the oldest request only), the server sees them in order, every future completes with its
own response, and the done callbacks run in the order of the calls. (How rclpy interleaves
the server's, the client's and the done callbacks' turns spin by spin is not compared:
its wait set's order, not modelled.)"""
import rclpy
from rclpy.node import Node
from std_srvs.srv import SetBool


def main():
    rclpy.init()
    node = Node("waypoints")
    handled = []

    def handle(request, response):
        handled.append(request.data)
        response.success = request.data
        response.message = f"request {len(handled)}"
        return response

    node.create_service(SetBool, "toggle", handle)
    client = node.create_client(SetBool, "toggle")
    print("ready:", client.wait_for_service(timeout_sec=2.0))
    done = []
    futures = []
    for value in (True, False, True):
        future = client.call_async(SetBool.Request(data=value))
        future.add_done_callback(lambda f: done.append(f.result().message))
        futures.append(future)
    rclpy.spin_once(node, timeout_sec=0.5)
    print("after one spin_once: handled", handled, "done", [f.done() for f in futures])
    steps = 1
    while len(done) < 3 and steps < 30:
        rclpy.spin_once(node, timeout_sec=0.1)
        steps += 1
    print("results:", [(f.result().success, f.result().message) for f in futures])
    print("done callbacks:", done)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
