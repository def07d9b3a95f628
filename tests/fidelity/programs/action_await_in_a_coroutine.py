"""A coroutine timer callback awaits an action's goal handle and result: with the client in
the node's default group (the timer's), rclpy holds that group while the coroutine waits, so
the client's answers are never taken; with the client in a group of its own they are."""
import rclpy
from rclpy.action import ActionClient, ActionServer
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from turtlesim_msgs.action import RotateAbsolute


class Compass(Node):
    def __init__(self, name, group):
        super().__init__(name)
        self.client = ActionClient(self, RotateAbsolute, "turn", callback_group=group)
        self.timer = self.create_timer(0.2, self.run)

    async def run(self):
        self.timer.cancel()
        print(self.get_name(), "server", self.client.wait_for_server(timeout_sec=5.0))
        for theta in (1.0, 2.0):
            handle = await self.client.send_goal_async(RotateAbsolute.Goal(theta=theta))
            print(self.get_name(), "accepted", handle.accepted)
            result = await handle.get_result_async()
            print(self.get_name(), "result", result.result.delta)


def main():
    rclpy.init()
    server = Node("server")

    def execute(handle):
        print("execute", handle.request.theta)
        handle.succeed()
        return RotateAbsolute.Result(delta=handle.request.theta)

    ActionServer(server, RotateAbsolute, "turn", execute)
    for name, group in (("default_group", None), ("own_group", ReentrantCallbackGroup())):
        compass = Compass(name, group)
        executor = SingleThreadedExecutor()
        executor.add_node(server)
        executor.add_node(compass)
        for _ in range(30):
            executor.spin_once(timeout_sec=0.1)
        executor.shutdown()
        compass.destroy_node()
    server.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
