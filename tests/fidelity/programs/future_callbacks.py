"""Futures of service calls: call_async with add_done_callback (run by the executor), a callback
added to a future already done, spin_until_future_complete with timeout_sec on a call nobody
answers, cancel, set_exception and result(), exception().

Done callbacks run as tasks of the executor that took the response: not inside
spin_until_future_complete, and not at once when added to a done future."""
import rclpy
from rclpy.node import Node
from rclpy.task import Future
from std_srvs.srv import Trigger


def main():
    rclpy.init()
    node = Node("futures")
    node.create_service(Trigger, "ask", lambda request, response: Trigger.Response(success=True, message="yes"))
    client = node.create_client(Trigger, "ask")
    print("ready:", client.wait_for_service(timeout_sec=5.0))
    seen = []
    future = client.call_async(Trigger.Request())
    future.add_done_callback(lambda f: seen.append(("done", f.result().message)))
    print("done before spinning:", future.done(), seen)
    rclpy.spin_until_future_complete(node, future, timeout_sec=5.0)
    print("after:", future.done(), seen)
    future.add_done_callback(lambda f: seen.append("late callback"))
    print("late callback at once:", seen)
    for _ in range(8):  # the first spins take the executor's own tasks first (how many: rclpy's business)
        rclpy.spin_once(node, timeout_sec=0.1)
    print("callbacks after spinning:", seen)
    own = Future()
    own.add_done_callback(lambda f: seen.append("no executor: at once"))
    own.set_result(None)
    print("a future of no executor:", seen[-1])
    nobody = node.create_client(Trigger, "nobody")
    pending = nobody.call_async(Trigger.Request())
    rclpy.spin_until_future_complete(node, pending, timeout_sec=0.3)
    print("unanswered:", pending.done(), pending.result())
    pending.cancel()
    print("cancelled:", pending.cancelled(), pending.done())
    print("remove_pending:", nobody.remove_pending_request(pending) if hasattr(nobody, "remove_pending_request") else None)
    failing = Future()
    failing.set_exception(ValueError("broken"))
    print("exception:", repr(failing.exception()), failing.done())
    try:
        failing.result()
    except ValueError as err:
        print("result raises:", err)
    plain = Future()
    plain.set_result(3)
    print("plain:", plain.result(), plain.exception(), repr(plain))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
