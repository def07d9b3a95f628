"""rclpy.init() and shutdown as course code gets them wrong: init twice, `with rclpy.init():`
inside an init, rclpy.shutdown() inside `with rclpy.init():` (the with's end then), try_shutdown
with nothing to shut down, shutdown without init, context.on_shutdown given a non-callable,
rclpy.ok() along the way, an on_shutdown hook that uses its node (rclpy destroyed it first),
one added after shutdown (called at once), and rclpy.get_rmw_implementation_identifier()."""
import rclpy
from rclpy.node import Node


def attempt(label, action):
    try:
        result = action()
        print(label, "->", result if result is None or isinstance(result, bool) else type(result).__name__)
    except Exception as err:
        print(label, "raised", type(err).__name__, err)


def main():
    print("ok before init:", rclpy.ok())
    attempt("try_shutdown before init:", rclpy.try_shutdown)
    attempt("shutdown before init:", rclpy.shutdown)
    rclpy.init()
    attempt("init again:", rclpy.init)
    attempt("with init inside init:", lambda: rclpy.init().__enter__())
    attempt("on_shutdown(5):", lambda: rclpy.get_default_context().on_shutdown(5))
    rclpy.shutdown()
    attempt("shutdown again:", rclpy.shutdown)
    attempt("try_shutdown again:", rclpy.try_shutdown)
    print("ok after shutdown:", rclpy.ok())
    try:
        with rclpy.init():
            node = Node("inner")
            print("inside with:", rclpy.ok(), node.get_name())
            rclpy.shutdown()
            print("after shutdown in with:", rclpy.ok())
        print("with ended quietly")
    except Exception as err:
        print("with ended with", type(err).__name__, err)
    with rclpy.init() as init:
        print("init's context ok:", init.context.ok())
        node = Node("hooked")

        def hook():
            try:
                print("on_shutdown: node", node.get_name())
            except Exception as err:
                print("on_shutdown: node", type(err).__name__, err)

        init.context.on_shutdown(hook)
        print("rmw:", rclpy.get_rmw_implementation_identifier())
    init.context.on_shutdown(lambda: print("on_shutdown after shutdown ran"))
    print("ok at the end:", rclpy.ok())


if __name__ == "__main__":
    main()
