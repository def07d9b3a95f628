"""The docs' client keeps one request (self.req) and changes it for each call: requests sent
before the server runs each keep the values they were sent with; a server changing the request
or keeping its response changes nothing the client holds; a float32 field arrives rounded, numpy
values plain."""
import enum

import numpy as np
import rclpy
from rclpy.node import Node
from turtlesim.srv import Spawn


class Kind(enum.IntEnum):
    ONE = 1


class Server(Node):
    def __init__(self):
        super().__init__("server")
        self.kept = None
        self.create_service(Spawn, "spawn_like", self.on_spawn)

    def on_spawn(self, request, response):
        print("server got", request)
        request.x = -1.0
        request.name = "changed by server"
        response.name = f"{request.name}:{request.y}"
        self.kept = response
        return response


class Client(Node):
    def __init__(self):
        super().__init__("client")
        self.cli = self.create_client(Spawn, "spawn_like")
        self.req = Spawn.Request()

    def send_request(self, x, y, name):
        self.req.x = x
        self.req.y = y
        self.req.name = name
        return self.cli.call_async(self.req)


def main():
    rclpy.init()
    server = Server()
    client = Client()
    ex = rclpy.executors.SingleThreadedExecutor()
    ex.add_node(server)
    ex.add_node(client)
    print(client.cli.wait_for_service(timeout_sec=5.0))
    futures = [client.send_request(float(i), np.float64(i) * 2, f"t{i}") for i in range(3)]
    for f in futures:
        ex.spin_until_future_complete(f, timeout_sec=5.0)
    print("client req", client.req)
    for f in futures:
        r = f.result()
        print(r, type(r.name).__name__)
    server.kept.name = "server changed it later"
    print(futures[-1].result())
    f = client.cli.call_async(Spawn.Request(x=np.float64(0.1), theta=float(Kind.ONE)))
    ex.spin_until_future_complete(f, timeout_sec=5.0)
    print(f.result())
    ex.shutdown()
    server.destroy_node()
    client.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
