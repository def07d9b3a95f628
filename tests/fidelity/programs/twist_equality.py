"""Messages as values: Twist(linear=Vector3(x=1.0)) compared with ==, copies and mutation,
__slots__ (no new attributes), positional arguments, repr and str, and hashing. (Wrong field
values are message_checks.py's: turtletui always checks them, Kilted only with
ROS_PYTHON_CHECK_FIELDS=1.)"""
import copy

from geometry_msgs.msg import Twist, Vector3


def attempt(label, action):
    try:
        print(label, "->", action())
    except Exception as err:
        print(label, "raised", type(err).__name__ + ":", err)


def main():
    a = Twist(linear=Vector3(x=1.0))
    b = Twist()
    b.linear.x = 1.0
    print("equal:", a == b, "not equal:", a != b, "identical:", a is b)
    b.angular.z = 0.5
    print("after changing b:", a == b)
    print("vs other type:", a == Vector3(x=1.0), Vector3(x=1.0) == Vector3(x=1.0))
    print("slots:", [slot for slot in Twist.__slots__ if slot != "_check_fields"], "_x" in Vector3.__slots__)
    print("has __dict__:", hasattr(a, "__dict__"))
    attempt("new attribute", lambda: setattr(a, "speed", 2.0))
    attempt("positional", lambda: Vector3(1.0, 2.0, 3.0))
    shallow = copy.copy(a)
    deep = copy.deepcopy(a)
    print("copies equal:", shallow == a, deep == a, "share linear:", shallow.linear is a.linear, deep.linear is a.linear)
    a.linear.x = 3.0
    print("after mutate:", shallow.linear.x, deep.linear.x)
    print(repr(Vector3(x=1.0, y=-2.5)))
    print(str(Twist(linear=Vector3(x=1.0))))
    attempt("hash", lambda: hash(Vector3()))
    attempt("in a set", lambda: len({Vector3(), Vector3()}))


if __name__ == "__main__":
    main()
