"""Service introspection (the "Configure service introspection" demo): a service and its
client publish service_msgs events on the hidden /<service>/_service_event topic once
configure_introspection turns it on: request sent, received, response sent, received, each
with the client's sequence number, the request and response with CONTENTS, neither with
METADATA, nothing with OFF or for a side left off; the event topic in the graph."""
import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_system_default
from rclpy.service_introspection import ServiceIntrospectionState
from service_msgs.msg import ServiceEventInfo
from std_srvs.srv import SetBool

EVENT_NAMES = {getattr(ServiceEventInfo, name): name
               for name in ("REQUEST_SENT", "REQUEST_RECEIVED", "RESPONSE_SENT", "RESPONSE_RECEIVED")}


class Switch(Node):
    def __init__(self):
        super().__init__("switch")
        self.service = self.create_service(SetBool, "enable", self.on_enable)
        self.client = self.create_client(SetBool, "enable")
        self.events = []
        self.create_subscription(SetBool.Event, "/enable/_service_event", self.events.append, 10)

    def on_enable(self, request, response):
        response.success = request.data
        response.message = f"set to {request.data}"
        return response


def call(node, value):
    future = node.client.call_async(SetBool.Request(data=value))
    rclpy.spin_until_future_complete(node, future)
    for _ in range(10):
        rclpy.spin_once(node, timeout_sec=0.02)
    return future.result()


def show(node, label):
    print(f"{label}: {len(node.events)} events")
    for event in sorted(node.events, key=lambda e: (e.info.sequence_number, e.info.event_type)):
        print(f"  {EVENT_NAMES[event.info.event_type]} seq={event.info.sequence_number}"
              f" request={[r.data for r in event.request]} response={[(r.success, r.message) for r in event.response]}"
              f" gid bytes={len(event.info.client_gid)} stamped={event.info.stamp.sec > 0}")
    node.events.clear()


def main():
    rclpy.init()
    node = Switch()
    node.client.wait_for_service(timeout_sec=5.0)
    call(node, True)
    show(node, "off by default")
    for state in (ServiceIntrospectionState.CONTENTS, ServiceIntrospectionState.METADATA, ServiceIntrospectionState.OFF):
        node.service.configure_introspection(node.get_clock(), qos_profile_system_default, state)
        node.client.configure_introspection(node.get_clock(), qos_profile_system_default, state)
        call(node, state == ServiceIntrospectionState.CONTENTS)
        show(node, state.name)
    print("after OFF:", sorted(t for t, _ in node.get_topic_names_and_types() if "enable" in t))
    node.service.configure_introspection(node.get_clock(), qos_profile_system_default,
                                         ServiceIntrospectionState.CONTENTS)
    call(node, False)
    show(node, "service only")
    print(sorted((t, types) for t, types in node.get_topic_names_and_types() if "enable" in t))
    print("publishers:", sorted(p.topic_name for p in node.publishers))
    print([(state.name, int(state)) for state in (ServiceIntrospectionState.OFF, ServiceIntrospectionState.METADATA,
                                                  ServiceIntrospectionState.CONTENTS)])
    print(repr(ServiceIntrospectionState.CONTENTS), str(ServiceIntrospectionState.METADATA))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
