"""The three kinds of set-parameters callbacks (Iron on): pre-set callbacks that change the list
being set, on-set callbacks that accept or refuse it (the newest runs first, the first refusal
wins), post-set callbacks after a set that went through, what declare_parameter runs, a
callback that raises, and a pre-set callback that empties the list."""
import rclpy
from rcl_interfaces.msg import SetParametersResult
from rclpy.exceptions import InvalidParameterValueException
from rclpy.node import Node
from rclpy.parameter import Parameter


def main():
    rclpy.init()
    node = Node("tuned")
    calls = []

    def pre(params):
        calls.append(("pre", [p.name for p in params]))
        if any(p.name == "speed" for p in params):
            doubled = [p for p in params if p.name == "speed"][0].value * 2
            return params + [Parameter("speed_x2", value=doubled)]
        if any(p.name == "wipe" for p in params):
            return []
        return params

    def first(params):
        calls.append(("first", [p.name for p in params]))
        return SetParametersResult(successful=True)

    def second(params):
        calls.append(("second", [p.name for p in params]))
        for p in params:
            if p.name == "speed" and p.value > 5.0:
                return SetParametersResult(successful=False, reason="too fast")
        return SetParametersResult(successful=True)

    def post(params):
        calls.append(("post", [(p.name, p.value) for p in params]))

    node.add_on_set_parameters_callback(first)
    node.add_on_set_parameters_callback(second)
    node.add_post_set_parameters_callback(post)
    node.declare_parameter("speed", 1.0)
    node.declare_parameter("speed_x2", 2.0)
    node.declare_parameter("wipe", 0)
    print("declare ran:", calls)
    calls.clear()
    node.add_pre_set_parameters_callback(pre)
    results = node.set_parameters([Parameter("speed", value=2.0)])
    print("set:", [(r.successful, r.reason) for r in results], node.get_parameter("speed_x2").value)
    print("calls:", calls)
    calls.clear()
    results = node.set_parameters([Parameter("speed", value=6.0)])
    print("refused:", [(r.successful, r.reason) for r in results], node.get_parameter("speed").value)
    print("calls:", calls)
    calls.clear()
    results = node.set_parameters([Parameter("wipe", value=1)])
    print("emptied:", [(r.successful, r.reason) for r in results], node.get_parameter("wipe").value)
    print("calls:", calls)
    calls.clear()
    atomic = node.set_parameters_atomically([Parameter("speed", value=3.0)])
    print("atomically:", atomic.successful, repr(atomic.reason), node.get_parameter("speed_x2").value)
    print("calls:", calls)
    calls.clear()
    try:
        node.declare_parameter("speed_limit", 9.0)
        print("declared speed_limit")
    except InvalidParameterValueException as err:
        print(type(err).__name__, err)

    def refuse_limits(params):
        ok = not any(p.name == "limit" for p in params)
        return SetParametersResult(successful=ok, reason="" if ok else "no limits here")

    node.add_on_set_parameters_callback(refuse_limits)
    try:
        node.declare_parameter("limit", 1.0)
    except InvalidParameterValueException as err:
        print(type(err).__name__, err)
    print("limit declared?", node.has_parameter("limit"))
    node.remove_on_set_parameters_callback(refuse_limits)

    def broken(params):
        raise RuntimeError("callback bug")

    node.add_on_set_parameters_callback(broken)
    try:
        node.set_parameters([Parameter("speed", value=1.0)])
    except RuntimeError as err:
        print("raised:", err)
    node.remove_on_set_parameters_callback(broken)
    node.remove_pre_set_parameters_callback(pre)
    node.remove_post_set_parameters_callback(post)
    try:
        node.remove_post_set_parameters_callback(post)
    except ValueError as err:
        print("removed twice:", type(err).__name__, err)
    print("final:", node.get_parameter("speed").value, len(calls))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
