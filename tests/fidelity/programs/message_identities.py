"""What students print about message classes: type(msg), its module, name and
qualname, the classes of services and actions and their parts, a received
message's type, and where import and pickle find a class (Kilted's names)."""
import importlib
import pickle

import rclpy
from action_msgs.msg import GoalStatus
from action_msgs.srv import CancelGoal
from builtin_interfaces.msg import Duration, Time
from geometry_msgs.msg import Point32, PoseWithCovarianceStamped, Twist
from lifecycle_msgs.srv import ChangeState
from nav_msgs.msg import Odometry
from nav_msgs.srv import GetMap
from rcl_interfaces.msg import Log, ParameterEvent
from rcl_interfaces.srv import SetParametersAtomically
from rclpy.node import Node
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float64MultiArray, Header, String
from std_srvs.srv import SetBool, Trigger
from turtlesim_msgs.action import RotateAbsolute
from turtlesim_msgs.msg import Color, Pose
from turtlesim_msgs.srv import SetPen, Spawn
from unique_identifier_msgs.msg import UUID

MESSAGES = (Twist, Point32, PoseWithCovarianceStamped, String, Header, Float64MultiArray, LaserScan, Odometry,
            Time, Duration, GoalStatus, Log, ParameterEvent, Clock, Pose, Color, UUID)
SERVICES = (Spawn, SetPen, SetBool, Trigger, CancelGoal, GetMap, ChangeState, SetParametersAtomically)
FIXED_ARRAYS = (PoseWithCovarianceStamped, Odometry, GoalStatus, UUID, CancelGoal.Request)
"""Classes with a fixed-size numeric array: numpy in ROS, a list in turtletui (a deliberate difference)."""


def describe(cls):
    print(cls, "|", cls.__module__, cls.__qualname__, cls.__name__, "|", type(cls).__name__)


def found(cls):
    """Where ``import`` and pickle find the class."""
    found = importlib.import_module(cls.__module__)
    for name in cls.__qualname__.split("."):
        found = getattr(found, name)
    print(f"  {cls.__module__}.{cls.__qualname__}: import {found is cls}, pickle {pickle.loads(pickle.dumps(cls)) is cls}")


def main():
    rclpy.init()
    node = Node("identities")
    heard = []
    node.create_subscription(Twist, "identity_twist", heard.append, 10)
    publisher = node.create_publisher(Twist, "identity_twist", 10)
    twist = Twist()
    twist.linear.x = 1.5
    for _ in range(100):
        if heard:
            break
        publisher.publish(twist)
        rclpy.spin_once(node, timeout_sec=0.1)
    received = heard[0]
    print(type(received), type(received).__module__, type(received).__qualname__, type(received).__name__)
    print(f"received {received} of {type(received)}, a Twist: {isinstance(received, Twist)}")
    for cls in MESSAGES:
        describe(cls)
        print("  ", repr(cls()) if cls not in FIXED_ARRAYS else sorted(cls.get_fields_and_field_types()))
    for cls in SERVICES:
        describe(cls)
        for part in (cls.Request, cls.Response, cls.Event):
            describe(part)
        print("  ", cls.Request() if cls.Request not in FIXED_ARRAYS else "(fixed arrays)", cls.Response())
    describe(RotateAbsolute)
    impl = RotateAbsolute.Impl
    for part in (RotateAbsolute.Goal, RotateAbsolute.Result, RotateAbsolute.Feedback, impl, impl.SendGoalService,
                 impl.SendGoalService.Request, impl.GetResultService.Response, impl.FeedbackMessage,
                 impl.CancelGoalService, impl.GoalStatusMessage):
        describe(part)
    print("  ", RotateAbsolute.Goal(theta=1.0), RotateAbsolute.Feedback(remaining=0.5))
    print(RotateAbsolute.Impl.FeedbackMessage.get_fields_and_field_types())
    print(Spawn.Event.get_fields_and_field_types())
    for cls in (Twist, Spawn, Spawn.Request, RotateAbsolute, RotateAbsolute.Impl, RotateAbsolute.Goal, UUID):
        found(cls)
    print(pickle.loads(pickle.dumps(received)) == received, pickle.loads(pickle.dumps(Pose(x=2.0))))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
