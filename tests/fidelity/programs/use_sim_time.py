"""use_sim_time: false by default (the clock reads ROS time as usual); set true,
the node subscribes to /clock and its clock reads 0 until a rosgraph_msgs Clock
arrives, then the last one received; set false again, it reads ROS time."""
import rclpy
from _discovery import spin_until
from builtin_interfaces.msg import Time
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rosgraph_msgs.msg import Clock


def main():
    rclpy.init()
    node = Node("timed")
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    clock = node.get_clock()
    print("default", node.get_parameter("use_sim_time").value, clock.ros_time_is_active, clock.now().nanoseconds > 0)
    refused = node.set_parameters([Parameter("use_sim_time", value=1)])[0]
    print("refused", refused.successful, refused.reason)
    node.set_parameters([Parameter("use_sim_time", value=True)])
    print("sim time", clock.ros_time_is_active, clock.now().nanoseconds)
    print("subscribes", node.get_subscriber_names_and_types_by_node("timed", "/"))
    simulator = Node("simulator")
    executor.add_node(simulator)
    publisher = simulator.create_publisher(Clock, "/clock", 10)
    print("matched", spin_until(executor, lambda: publisher.get_subscription_count() == 1))
    publisher.publish(Clock(clock=Time(sec=42, nanosec=500)))
    print("followed", spin_until(executor, lambda: clock.now().nanoseconds != 0))
    print("now", clock.now().nanoseconds, clock.now().clock_type.name)
    node.set_parameters([Parameter("use_sim_time", value=False)])
    print("wall again", clock.ros_time_is_active, clock.now().nanoseconds > 10**18)
    print("subscribes", node.get_subscriber_names_and_types_by_node("timed", "/"))
    simulator.destroy_node()
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
