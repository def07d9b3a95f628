"""declare_parameter as beginners call it: with no default, with None, with an empty list
(rclpy guesses BYTE_ARRAY and then refuses a list of floats), a tuple, a list of ints then a
set to floats, a float declared then set to an int, declare_parameters with namespace='',
get_parameters of several names, a Parameter built with a type its value does not have, what
print() shows of a Parameter, and the declarations rclpy refuses (a typed None, a type of
NOT_SET, a type with dynamic typing, malformed tuples). A name alone is deprecated: the
UserWarning is caught and printed."""
import warnings

import rclpy
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.exceptions import ParameterUninitializedException
from rclpy.node import Node
from rclpy.parameter import Parameter


def show(node, name):
    try:
        parameter = node.get_parameter(name)
        print(f"  {name}: {parameter.type_.name} {parameter.value!r}")
    except ParameterUninitializedException as err:
        print(f"  {name}: {type(err).__name__}: {err}")


def try_set(node, name, value):
    try:
        [result] = node.set_parameters([Parameter(name, value=value)])
        print(f"  set {name}={value!r}: {result.successful} {result.reason!r}")
    except Exception as err:
        print(f"  set {name}={value!r}: {type(err).__name__}: {err}")


def main():
    rclpy.init()
    node = Node("edges")
    for name, args in (("nothing", ()), ("none", (None,)), ("empty", ([],)), ("pair", ((1.0, 2.0),)),
                       ("ints", ([1, 2, 3],)), ("speed", (1.0,)), ("flag", (False,)), ("words", (["a", "b"],))):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                node.declare_parameter(name, *args)
            except Exception as err:
                print(f"declare {name}: {type(err).__name__}: {err}")
                continue
        print(f"declared {name}", [(w.category.__name__, str(w.message)) for w in caught])
        show(node, name)
    try_set(node, "empty", [1.0, 2.0])
    try_set(node, "empty", [b"a"])
    try_set(node, "pair", [3.0])
    try_set(node, "ints", [1.5, 2.5])
    try_set(node, "speed", 2)
    try_set(node, "flag", 1)
    try_set(node, "nothing", 3)
    try_set(node, "none", "text")
    for name in ("empty", "pair", "speed", "nothing", "none"):
        show(node, name)
    declared = node.declare_parameters("", [("a", 1), ("b", "two"), ("c.d", 3.0)])
    print("declare_parameters(''):", [(p.name, p.value) for p in declared])
    print("get_parameters:", [(p.name, p.value) for p in node.get_parameters(["a", "b", "c.d"])])
    print("by prefix c:", sorted(node.get_parameters_by_prefix("c")))
    print("by prefix '':", sorted(k for k in node.get_parameters_by_prefix("") if k != "use_sim_time"))
    for args in (("p", Parameter.Type.DOUBLE, 1), ("p", Parameter.Type.INTEGER, 1.0), ("p", Parameter.Type.STRING, None)):
        try:
            parameter = Parameter(*args)
            print("Parameter", args[1].name, repr(args[2]), "->", parameter.type_.name, parameter.value)
        except Exception as err:
            print("Parameter", args[1].name, repr(args[2]), "->", type(err).__name__, err)
    print("print():", node.get_parameter("speed"))
    refused = (
        ("typed None", lambda: node.declare_parameter("t1", None, ParameterDescriptor())),
        ("tuple with None", lambda: node.declare_parameters("", [("t2", None)])),
        ("type NOT_SET", lambda: node.declare_parameter("t3", Parameter.Type.NOT_SET)),
        ("type and dynamic", lambda: node.declare_parameter(
            "t4", Parameter.Type.DOUBLE, ParameterDescriptor(dynamic_typing=True))),
        ("third not a descriptor", lambda: node.declare_parameters("", [("t5", 1, "text")])),
        ("empty tuple", lambda: node.declare_parameters("", [()])),
        ("name not a str", lambda: node.declare_parameters("", [(3, 1)])),
        ("declared again", lambda: node.declare_parameter("speed", 2.0)),
    )
    for label, declare in refused:
        try:
            declare()
            print(label, "declared")
        except Exception as err:
            print(label, type(err).__name__, err)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        node.declare_parameters("ns", [("alone",), ("dynamic", None, ParameterDescriptor(dynamic_typing=True))])
    print("warned:", [str(w.message).splitlines()[0] for w in caught])
    show(node, "ns.alone")
    show(node, "ns.dynamic")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
