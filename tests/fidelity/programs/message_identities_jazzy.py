"""The course's own imports (turtlesim.msg, up to Jazzy): turtlesim's classes are
turtlesim.msg._pose.Pose and so on, a received Pose's type too."""
import pickle

import rclpy
from rclpy.node import Node
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Pose
from turtlesim.srv import Spawn


def main():
    rclpy.init()
    node = Node("jazzy_identities")
    heard = []
    node.create_subscription(Pose, "identity_pose", heard.append, 10)
    publisher = node.create_publisher(Pose, "identity_pose", 10)
    for _ in range(100):
        if heard:
            break
        publisher.publish(Pose(x=1.0))
        rclpy.spin_once(node, timeout_sec=0.1)
    print(type(heard[0]), heard[0])
    for cls in (Pose, Spawn, Spawn.Request, Spawn.Event, RotateAbsolute, RotateAbsolute.Impl,
                RotateAbsolute.Impl.FeedbackMessage):
        print(cls, cls.__module__, cls.__qualname__, type(cls), pickle.loads(pickle.dumps(cls)) is cls)
    print(RotateAbsolute.Impl.FeedbackMessage.get_fields_and_field_types())
    print(Spawn.Request(name="t2"), RotateAbsolute.Goal(theta=0.5))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
