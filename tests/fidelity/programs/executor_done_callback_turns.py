"""A node that serves a service and calls it, spun one callback at a time with rclpy.spin_once:
the request's handler runs on one spin, the response on the next (the future is done then), and
the future's done callbacks later still, each a task of the executor on a spin of its own, the
client's own (removing the pending request) first. A cancelled call runs its done callbacks at
once and drops its response; so does a call whose pending request was removed."""
import rclpy
from rclpy.node import Node
from std_srvs.srv import Trigger


def main():
    rclpy.init()
    node = Node("both_ends")
    events = []

    def handle(request, response):
        events.append("service")
        response.success = True
        return response

    node.create_service(Trigger, "self_ping", handle)
    client = node.create_client(Trigger, "self_ping")
    print("service found:", client.wait_for_service(timeout_sec=10.0))

    def spins(future, count):
        steps = []
        for _ in range(count):
            before = len(events)
            rclpy.spin_once(node, timeout_sec=1.0)
            steps.append("+".join(events[before:]) or "-")
            steps[-1] += " (done)" if future.done() else ""
        return " | ".join(steps)

    for callbacks in (1, 2):
        future = client.call_async(Trigger.Request())
        for n in range(callbacks):
            future.add_done_callback(lambda f, n=n: events.append(f"done{n}"))
        print(callbacks, "done callback(s):", spins(future, 3 + callbacks))

    future = client.call_async(Trigger.Request())
    future.add_done_callback(lambda f: events.append("done of a cancelled call"))
    future.cancel()
    print("cancelled:", events[-1], future.cancelled(), future.done())
    print("then:", spins(future, 3), future.result())

    future = client.call_async(Trigger.Request())
    future.add_done_callback(lambda f: events.append("done of a removed call"))
    client.remove_pending_request(future)
    print("removed:", spins(future, 3), future.done(), future.result())
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
