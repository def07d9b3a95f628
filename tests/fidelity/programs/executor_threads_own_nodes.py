"""Each executor takes only its own nodes' ready callbacks: while a thread spins an executor
with node ``server_b`` (its service, its timer), the main thread's rclpy.spin_once and
rclpy.spin_until_future_complete on node ``caller_a`` run all of caller_a's callbacks (its
timer, its guard condition, its client's response and the future's done callbacks) on the
main thread, never on the other one, whether the other thread spins a SingleThreadedExecutor or a
MultiThreadedExecutor. Sandboxed only: threads need turtletui's sandbox."""
import threading

import rclpy
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.node import Node
from std_srvs.srv import Trigger


def here():
    return "main" if threading.current_thread() is threading.main_thread() else "the other thread"


def compare(executor, round_):
    caller = Node(f"caller_a{round_}")
    server = Node(f"server_b{round_}")
    threads = {"service": set(), "server timer": set(), "caller timer": set(), "guard": set(), "done": set()}

    def handle(request, response):
        threads["service"].add(here())
        response.success = True
        return response

    server.create_service(Trigger, f"ping{round_}", handle)
    server_ticks = []

    def server_tick():
        server_ticks.append(1)
        threads["server timer"].add(here())

    server.create_timer(0.05, server_tick)
    executor.add_node(server)
    spinner = threading.Thread(target=executor.spin, name="spinner", daemon=True)
    spinner.start()

    client = caller.create_client(Trigger, f"ping{round_}")
    print("service found:", client.wait_for_service(timeout_sec=10.0))
    caller_ticks = []

    def caller_tick():
        caller_ticks.append(1)
        threads["caller timer"].add(here())

    timer = caller.create_timer(0.1, caller_tick)
    guard = caller.create_guard_condition(lambda: threads["guard"].add(here()))
    done_calls = []

    def on_done(future):
        done_calls.append(future.result().success)
        threads["done"].add(here())

    results = []
    for _ in range(3):
        future = client.call_async(Trigger.Request())
        future.add_done_callback(on_done)
        rclpy.spin_until_future_complete(caller, future, timeout_sec=10.0)
        results.append(future.result().success)
        guard.trigger()
    while len(done_calls) < 3 or len(caller_ticks) < 3 or not threads["guard"]:
        rclpy.spin_once(caller, timeout_sec=0.5)
    timer.cancel()
    while len(server_ticks) < 3:
        rclpy.spin_once(caller, timeout_sec=0.1)
    print(type(executor).__name__, "results:", results, "done callbacks:", done_calls)
    for what, names in threads.items():
        print(" ", what, "ran on:", sorted(names))
    executor.shutdown()
    spinner.join(timeout=5.0)
    caller.destroy_node()
    server.destroy_node()


def main():
    rclpy.init()
    compare(SingleThreadedExecutor(), 1)
    compare(MultiThreadedExecutor(num_threads=2), 2)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
