"""std_srvs' three services served and called in one node, as course nodes use them: Empty
(a reset: an empty request and response), Trigger (success and message) and SetBool; what
each Request and Response prints, their fields and equality, and a handler that fills the
response it is given against one that returns a new one."""
import rclpy
from rclpy.node import Node
from std_srvs.srv import Empty, SetBool, Trigger


class Robot(Node):
    def __init__(self):
        super().__init__("robot")
        self.count = 0
        self.armed = False
        self.create_service(Empty, "zero", self.on_reset)
        self.create_service(Trigger, "count", self.on_count)
        self.create_service(SetBool, "arm", self.on_arm)
        self.reset = self.create_client(Empty, "zero")
        self.trigger = self.create_client(Trigger, "count")
        self.arm = self.create_client(SetBool, "arm")

    def on_reset(self, request, response):
        self.get_logger().info(f"reset: request {request!r}")
        self.count = 0
        return Empty.Response()

    def on_count(self, request, response):
        self.count += 1
        response.success = self.count % 2 == 1
        response.message = f"count is {self.count}"
        return response

    def on_arm(self, request, response):
        if request.data == self.armed:
            return SetBool.Response(success=False, message="no change")
        self.armed = request.data
        response.success = True
        response.message = "armed" if self.armed else "disarmed"
        return response


def call(node, client, request):
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future)
    return future.result()


def main():
    rclpy.init()
    node = Robot()
    for client in (node.reset, node.trigger, node.arm):
        print(f"{client.srv_name}: ready={client.wait_for_service(timeout_sec=5.0)}")
    for request in (Empty.Request(), Trigger.Request(), SetBool.Request(), SetBool.Request(data=True)):
        print(repr(request), str(request), request.get_fields_and_field_types())
    for response in (Empty.Response(), Trigger.Response(), SetBool.Response(success=True, message="ok")):
        print(repr(response), response.get_fields_and_field_types())
    print("equal:", Empty.Request() == Empty.Request(), Trigger.Response() == Trigger.Response(message=""))
    print("unequal:", Trigger.Response(success=True) != Trigger.Response(), Empty.Request() == Empty.Response())
    for _ in range(3):
        print(call(node, node.trigger, Trigger.Request()))
    print(call(node, node.reset, Empty.Request()))
    print(call(node, node.trigger, Trigger.Request()))
    for data in (True, True, False):
        response = call(node, node.arm, SetBool.Request(data=data))
        print(f"arm({data}): success={response.success} message={response.message!r}")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
