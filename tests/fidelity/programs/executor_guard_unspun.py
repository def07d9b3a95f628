"""Guard conditions of a node nobody spins: triggered while another node spins, the callback
waits and runs when its node is spun, once for two triggers made before; a guard triggered
from another node's timer callback waits for its own node too."""
import rclpy
from rclpy.node import Node
from rclpy.task import Future


def main():
    rclpy.init()
    spun = Node("guard_spun")
    idle = Node("guard_idle")
    ran = []
    guard = idle.create_guard_condition(lambda: ran.append("idle guard"))
    guard.trigger()
    rclpy.spin_until_future_complete(spun, Future(), timeout_sec=0.3)
    print("while another node spins:", ran)
    for _ in range(3):
        rclpy.spin_once(idle, timeout_sec=0.2)
    print("idle spun:", ran)

    ran.clear()
    guard.trigger()
    guard.trigger()
    rclpy.spin_until_future_complete(spun, Future(), timeout_sec=0.3)
    for _ in range(4):
        rclpy.spin_once(idle, timeout_sec=0.2)
    print("two triggers while unspun, then spun:", ran)

    ran.clear()
    fired = []

    def trigger_other():
        fired.append(1)
        if len(fired) == 1:
            guard.trigger()

    timer = spun.create_timer(0.1, trigger_other)
    rclpy.spin_until_future_complete(spun, Future(), timeout_sec=0.5)
    timer.cancel()
    print("triggered from spun's timer:", ran, len(fired) > 1)
    rclpy.spin_once(idle, timeout_sec=0.5)
    print("then idle spun:", ran)
    spun.destroy_node()
    idle.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
