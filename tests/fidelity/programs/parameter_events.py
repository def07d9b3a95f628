"""/parameter_events: declaring and setting parameters on one node publishes
ParameterEvent messages (new, changed, deleted) that another node receives;
a refused set and undeclare_parameter publish nothing."""
import rclpy
from rcl_interfaces.msg import ParameterDescriptor, ParameterEvent
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter


def spin_for(executor, seconds):
    for _ in range(int(seconds / 0.05)):
        executor.spin_once(timeout_sec=0.05)


def show(event):
    new = [(p.name, p.value.type) for p in event.new_parameters]
    changed = [(p.name, p.value.type, p.value.double_value, p.value.string_value) for p in event.changed_parameters]
    deleted = [p.name for p in event.deleted_parameters]
    print("event", event.node, event.stamp.sec > 0, new, changed, deleted)


def main():
    rclpy.init()
    watcher = Node("watcher")
    events = []
    watcher.create_subscription(ParameterEvent, "/parameter_events", events.append, 100)
    tuned = Node("tuned", namespace="/robot", allow_undeclared_parameters=True)
    executor = SingleThreadedExecutor()
    executor.add_node(watcher)
    executor.add_node(tuned)
    spin_for(executor, 0.5)
    tuned.declare_parameter("speed", 1.5)
    tuned.declare_parameter("mode", "slow", ParameterDescriptor(dynamic_typing=True))
    tuned.set_parameters([Parameter("speed", value=2.5)])
    tuned.set_parameters_atomically([Parameter("speed", value=3.0), Parameter("mode", value="fast")])
    print("refused", tuned.set_parameters([Parameter("speed", value="fast")])[0].successful)
    tuned.set_parameters([Parameter("extra", value=7)])
    tuned.set_parameters([Parameter("mode", Parameter.Type.NOT_SET)])
    tuned.undeclare_parameter("speed")
    spin_for(executor, 1.0)
    for event in events:
        if event.node == "/robot/tuned":
            show(event)
    print("events from the watcher itself", sorted({e.node for e in events} - {"/robot/tuned"}))
    tuned.destroy_node()
    watcher.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
