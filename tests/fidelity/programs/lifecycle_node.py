"""rclpy.lifecycle: a LifecycleNode driven through its states by another node's
service calls and by trigger_*(), transition callbacks that fail or raise, a
lifecycle publisher that sends only while active, and the transition events."""
import rclpy
from lifecycle_msgs.msg import Transition, TransitionEvent
from lifecycle_msgs.srv import ChangeState, GetAvailableStates, GetAvailableTransitions, GetState
from rclpy.executors import SingleThreadedExecutor
from rclpy.lifecycle import LifecycleNode, TransitionCallbackReturn
from rclpy.node import Node
from std_msgs.msg import String


class Talker(LifecycleNode):
    def __init__(self):
        super().__init__("lc_talker")
        self.pub = None
        self.fail_next = True

    def on_configure(self, state):
        self.get_logger().info(f"on_configure from {state}")
        self.pub = self.create_lifecycle_publisher(String, "lc_chatter", 10)
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state):
        self.get_logger().info(f"on_activate from {state.label} {state.state_id}")
        if self.fail_next:
            self.fail_next = False
            return TransitionCallbackReturn.FAILURE
        return super().on_activate(state)

    def on_deactivate(self, state):
        self.get_logger().info("on_deactivate")
        raise RuntimeError("boom")

    def on_error(self, state):
        self.get_logger().info(f"on_error from {state.label}")
        return TransitionCallbackReturn.SUCCESS


def main():
    rclpy.init()
    talker = Talker()
    manager = Node("manager")
    events, heard = [], []
    manager.create_subscription(TransitionEvent, "/lc_talker/transition_event", events.append, 10)
    manager.create_subscription(String, "/lc_chatter", lambda msg: heard.append(msg.data), 10)
    executor = SingleThreadedExecutor()
    executor.add_node(talker)
    executor.add_node(manager)
    change = manager.create_client(ChangeState, "/lc_talker/change_state")
    get = manager.create_client(GetState, "/lc_talker/get_state")
    available = manager.create_client(GetAvailableTransitions, "/lc_talker/get_available_transitions")
    states = manager.create_client(GetAvailableStates, "/lc_talker/get_available_states")
    graph = manager.create_client(GetAvailableTransitions, "/lc_talker/get_transition_graph")
    print("ready", change.wait_for_service(5.0))

    def call(client, request):
        future = client.call_async(request)
        executor.spin_until_future_complete(future, timeout_sec=5)
        return future.result()

    def spin(seconds):
        for _ in range(int(seconds / 0.05)):
            executor.spin_once(timeout_sec=0.05)

    def transition(id=0, label=""):
        request = ChangeState.Request()
        request.transition.id = id
        request.transition.label = label
        return call(change, request).success

    print("state", call(get, GetState.Request()).current_state)
    print("configure", transition(Transition.TRANSITION_CONFIGURE))
    print("activate fails", transition(label="activate"))
    print("state", call(get, GetState.Request()).current_state.label)
    talker.pub.publish(String(data="inactive"))
    print("activated?", talker.pub.is_activated)
    print("activate", transition(Transition.TRANSITION_ACTIVATE))
    talker.pub.publish(String(data="active"))
    print("activated?", talker.pub.is_activated)
    spin(0.3)
    print("bad label", transition(label="fly"))
    print("bad id", transition(99))
    print("deactivate raises", transition(Transition.TRANSITION_DEACTIVATE))
    print("state", call(get, GetState.Request()).current_state.label)
    answer = call(available, GetAvailableTransitions.Request())
    print("available", [(d.transition.id, d.transition.label) for d in answer.available_transitions])
    print("trigger", talker.trigger_configure())
    spin(0.3)
    print("heard", heard)
    for e in events:
        print("event", e.timestamp, e.transition.id, repr(e.transition.label), e.start_state.label, e.goal_state.label)
    print("states", [(s.id, s.label) for s in call(states, GetAvailableStates.Request()).available_states])
    edges = call(graph, GetAvailableTransitions.Request()).available_transitions
    print("graph", len(edges), [(d.transition.label, d.start_state.label, d.goal_state.label) for d in edges[:4]])
    print("shutdown", talker.trigger_shutdown(), talker.trigger_configure())
    try:
        talker.trigger_shutdown()
    except RuntimeError as err:
        print("finalized:", err)
    print("publishes", talker.get_publisher_names_and_types_by_node("lc_talker", "/"))
    services = talker.get_service_names_and_types_by_node("lc_talker", "/")
    print("services", [name for name, _ in services if "param" not in name and "type_description" not in name])
    talker.destroy_node()
    manager.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
