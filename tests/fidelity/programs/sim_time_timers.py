"""Timers on /clock time (use_sim_time): nothing fires while nothing publishes /clock;
a timer fires as /clock passes its next call, once however far /clock jumps (missed
calls are skipped); a jump back past its last call restarts its period; cancel and
reset; a clock jump callback's thresholds; use_sim_time switched off and on again
carries the part of the period gone over into the new time."""
import rclpy
from builtin_interfaces.msg import Time
from rclpy.clock import ClockChange, JumpThreshold
from rclpy.duration import Duration
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rosgraph_msgs.msg import Clock


def main():
    rclpy.init()
    node = Node("timed", parameter_overrides=[Parameter("use_sim_time", value=True)])
    simulator = Node("simulator")
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    executor.add_node(simulator)
    clock = node.get_clock()
    fired = []
    timer = node.create_timer(1.0, lambda: fired.append(clock.now().nanoseconds))
    print("made", timer.time_until_next_call(), timer.time_since_last_call(), timer.is_ready())
    jumps = []
    threshold = JumpThreshold(min_forward=Duration(seconds=2), min_backward=Duration(nanoseconds=-1))
    handle = clock.create_jump_callback(
        threshold,
        pre_callback=lambda: jumps.append("before"),
        post_callback=lambda jump: jumps.append((jump.clock_change.name, jump.delta.nanoseconds)),
    )
    publisher = simulator.create_publisher(Clock, "/clock", 10)
    while publisher.get_subscription_count() == 0:
        executor.spin_once(timeout_sec=0.05)
    for _ in range(10):
        executor.spin_once(timeout_sec=0.02)
    print("without /clock", fired)

    def clock_at(seconds, carried=False):
        sec, nanosec = divmod(round(seconds * 1e9), 10**9)
        publisher.publish(Clock(clock=Time(sec=sec, nanosec=nanosec)))
        while clock.now().nanoseconds != sec * 10**9 + nanosec:
            executor.spin_once(timeout_sec=0.05)
        for _ in range(5):
            executor.spin_once(timeout_sec=0.02)
        until = timer.time_until_next_call()  # in 10 ms: the part of it on the wall clock
        if carried:
            # wall time carried from while use_sim_time was off: 0.75 s and a few ms, tens
            # of ms for the real rclpy on a busy machine
            until = 0.745e9 <= until < 0.95e9
        else:
            until = None if until is None else round(until / 1e7)
        print("at", seconds, fired, until, round(timer.time_since_last_call() / 1e7), timer.is_ready(), jumps)
        fired.clear()
        jumps.clear()

    for seconds in (0.5, 1.0, 1.5, 3.5, 2.0, 3.0, 3.0, 10.0):
        clock_at(seconds)
    timer.cancel()
    clock_at(12.0)
    timer.reset()
    print("reset", timer.is_canceled(), timer.time_until_next_call())
    clock_at(13.5)
    node.set_parameters([Parameter("use_sim_time", value=False)])
    print("off", abs(timer.time_until_next_call() - 5e8) < 5e7, jumps)
    jumps.clear()
    node.set_parameters([Parameter("use_sim_time", value=True)])
    print("on again", abs(timer.time_until_next_call() - 5e8) < 5e7, jumps)
    jumps.clear()
    handle.unregister()
    publisher.publish(Clock(clock=Time(sec=13, nanosec=900_000_000)))
    while clock.now().nanoseconds != 13_900_000_000:
        executor.spin_once(timeout_sec=0.05)
    # in 100 ms: the wall time that passed while use_sim_time was off is carried
    # in too (10 ms more on a busy machine, for rclpy as for turtletui)
    print("at 13.9", fired, round(timer.time_until_next_call() / 1e8), jumps)
    jumps.clear()
    clock_at(14.25, carried=True)
    print("kinds", list(ClockChange.__members__))
    node.destroy_node()
    simulator.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
