"""Ending rclpy.spin from a callback, as course nodes do: KeyboardInterrupt (what Ctrl-C raises)
caught around spin, rclpy.shutdown() in a callback, a global executor used again after a
new rclpy.init(), and SystemExit(0) leaving spin and main through their finally blocks."""
import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node


class Stopper(Node):
    def __init__(self, how):
        super().__init__(f"stop_by_{how}")
        self.how = how
        self.ticks = 0
        self.create_timer(0.05, self.tick)

    def tick(self):
        self.ticks += 1
        self.get_logger().info(f"tick {self.ticks}")
        if self.ticks == 3:
            if self.how == "interrupt":
                raise KeyboardInterrupt
            if self.how == "shutdown":
                rclpy.shutdown()
                self.get_logger().info("after rclpy.shutdown() in the callback")
            if self.how == "exit":
                raise SystemExit(0)


def run(how):
    rclpy.init()
    node = Stopper(how)
    try:
        rclpy.spin(node)
        print(how, "-> spin returned", node.ticks)
    except KeyboardInterrupt:
        print(how, "-> KeyboardInterrupt", node.ticks)
    except ExternalShutdownException:
        print(how, "-> ExternalShutdownException", node.ticks)
    finally:
        node.destroy_node()
        print(how, "-> try_shutdown:", rclpy.try_shutdown(), "ok:", rclpy.ok())


def main():
    run("interrupt")
    run("shutdown")
    try:
        run("exit")
    finally:
        print("main's finally ran")
    print("not reached")


if __name__ == "__main__":
    main()
