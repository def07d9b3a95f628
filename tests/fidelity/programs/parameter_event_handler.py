"""rclpy.parameter_event_handler.ParameterEventHandler, as the "Monitoring for parameter
changes" tutorial uses it: a callback for one parameter of one node (by relative and by
absolute name), callbacks for every parameter event (the newest first), removing them, a
handle removed twice, and the static helpers that read an event."""
import rclpy
from rcl_interfaces.msg import ParameterEvent
from rclpy.node import Node
from rclpy.parameter import Parameter, parameter_value_to_python
from rclpy.parameter_event_handler import ParameterEventHandler


def spin_a_while(executor):
    for _ in range(10):
        executor.spin_once(timeout_sec=0.05)


def main():
    rclpy.init()
    robot = Node("robot", namespace="lab")
    monitor = Node("monitor", namespace="lab")
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(robot)
    executor.add_node(monitor)
    handler = ParameterEventHandler(monitor)
    print(type(handler.parameter_event_subscription).__name__, handler.parameter_event_subscription.topic_name)

    def on_speed(parameter):
        print(f"speed callback: {parameter.name} = {parameter_value_to_python(parameter.value)}")

    def on_speed_absolute(parameter):
        print(f"speed callback (absolute name): type {parameter.value.type}")

    def on_event(event):
        names = [p.name for p in ParameterEventHandler.get_parameters_from_event(event)]
        deleted = [p.name for p in event.deleted_parameters]
        if event.node == "/lab/robot":
            print(f"event from {event.node}: new/changed {names} deleted {deleted}")

    def on_event_too(event):
        if event.node == "/lab/robot":
            print("second event callback (added last, runs first)")

    speed = handler.add_parameter_callback("speed", "robot", on_speed)
    print(type(speed).__name__, speed.parameter_name, speed.node_name)
    absolute = handler.add_parameter_callback("speed", "/lab/robot", on_speed_absolute)
    own = handler.add_parameter_callback("gain", "", on_speed)
    print("empty node name:", own.node_name)
    first = handler.add_parameter_event_callback(on_event)
    second = handler.add_parameter_event_callback(on_event_too)
    spin_a_while(executor)

    robot.declare_parameter("speed", 1.0)
    spin_a_while(executor)
    robot.set_parameters([Parameter("speed", value=2.5)])
    spin_a_while(executor)
    robot.declare_parameter("name", "turtle")
    robot.undeclare_parameter("name")
    spin_a_while(executor)

    handler.remove_parameter_callback(speed)
    handler.remove_parameter_event_callback(second)
    robot.set_parameters([Parameter("speed", value=3.0)])
    spin_a_while(executor)
    for remove, handle in ((handler.remove_parameter_callback, speed),
                           (handler.remove_parameter_event_callback, second)):
        try:
            remove(handle)
        except RuntimeError as err:
            print(f"removed twice: RuntimeError: {err}")
    handler.remove_parameter_callback(absolute)
    handler.remove_parameter_callback(own)
    handler.remove_parameter_event_callback(first)

    event = rclpy.parameter.Parameter("x", value=1).to_parameter_msg()
    message = ParameterEvent(node="/lab/robot", new_parameters=[event])
    print(ParameterEventHandler.get_parameter_from_event(message, parameter_name="x", node_name="/lab/robot"))
    print(ParameterEventHandler.get_parameter_from_event(message, parameter_name="x", node_name="robot"))
    handler.destroy()
    print("subscriptions left:", [s.topic_name for s in monitor.subscriptions])
    executor.shutdown()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
