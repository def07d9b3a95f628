"""One process uses a topic name with one type: a second type on the name, by another
node or the same one, publisher or subscription, raises rcl's RCLError (Fast DDS
refuses it in one participant), and the graph keeps the first type. Once the name's
endpoints are gone, it takes another type. (Between processes two types coexist and
never match: tests/compat/test_topic_types.py.)"""
import rclpy
from geometry_msgs.msg import Pose as GeometryPose
from rclpy.node import Node
from turtlesim_msgs.msg import Pose


def attempt(label, make):
    try:
        make()
        print(label, "created")
    except Exception as err:  # rclpy's RCLError, from its private module
        module = type(err).__module__
        print(label, "raised", f"{module}.{type(err).__name__}:", str(err).split(", at ")[0])


def main():
    rclpy.init()
    sim = Node("typed_sim")
    student = Node("typed_student", namespace="typed")
    pose = sim.create_publisher(Pose, "/typed/pose", 10)
    attempt("other node, subscription", lambda: student.create_subscription(GeometryPose, "pose", print, 10))
    attempt("other node, publisher", lambda: student.create_publisher(GeometryPose, "/typed/pose", 10))
    attempt("same node, subscription", lambda: sim.create_subscription(GeometryPose, "/typed/pose", print, 10))
    same = student.create_subscription(Pose, "pose", print, 10)
    print("same type created")
    print([entry for entry in sim.get_topic_names_and_types() if entry[0].startswith("/typed")])
    print("publishers", sim.count_publishers("/typed/pose"), "subscriptions", sim.count_subscribers("/typed/pose"))
    sim.destroy_publisher(pose)
    student.destroy_subscription(same)
    attempt("after both left", lambda: student.create_subscription(GeometryPose, "pose", print, 10))
    student.destroy_node()
    sim.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
