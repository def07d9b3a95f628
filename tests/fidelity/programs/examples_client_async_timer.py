"""ros2/examples' client_async_callback: an `async def` timer callback in a reentrant group that
awaits call_async, a service in the node's default group, the example's two
`while rclpy.ok() and not ...: executor.spin_once()` loops, and timer.cancel() after one run."""
import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException
from std_srvs.srv import SetBool


def main(args=None):
    try:
        with rclpy.init(args=args):
            node = rclpy.create_node("minimal_client")

            def set_bool(request, response):
                response.success = not request.data
                response.message = f"flipped {request.data}"
                node.get_logger().info(f"Incoming request data: {request.data}")
                return response

            node.create_service(SetBool, "set_bool", set_bool)

            executor = rclpy.executors.SingleThreadedExecutor()
            executor.add_node(node)

            cb_group = ReentrantCallbackGroup()
            cli = node.create_client(SetBool, "set_bool", callback_group=cb_group)
            did_run = False
            did_get_result = False
            runs = 0

            async def call_service():
                nonlocal did_run, did_get_result, runs
                did_run = True
                runs += 1
                try:
                    req = SetBool.Request()
                    req.data = True
                    future = cli.call_async(req)
                    result = await future
                    node.get_logger().info(
                        f"Result of set_bool: for {req.data} -> {result.success} {result.message!r}"
                    )
                    print("result:", result)
                finally:
                    did_get_result = True

            while not cli.wait_for_service(timeout_sec=1.0):
                node.get_logger().info("service not available, waiting again...")

            timer = node.create_timer(0.1, call_service, callback_group=cb_group)

            while rclpy.ok() and not did_run:
                executor.spin_once()

            if did_run:
                timer.cancel()

            while rclpy.ok() and not did_get_result:
                executor.spin_once()
            print("runs:", runs, "canceled:", timer.is_canceled())
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == "__main__":
    main()
