"""Right, written differently: no class, closures and functools.partial, the targets as an
iterator over the parameters."""
import math
from functools import partial

import rclpy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
from turtlesim.srv import Kill, Spawn


def main():
    rclpy.init()
    node = rclpy.create_node("catch_game")
    node.declare_parameter("targets_x", [8.0, 5.0, 2.5, 3.5, 7.0, 9.0, 6.5, 3.0])
    node.declare_parameter("targets_y", [7.5, 9.0, 6.5, 3.0, 2.5, 5.0, 6.0, 8.5])
    targets = iter(zip(node.get_parameter("targets_x").value, node.get_parameter("targets_y").value))
    game = {"prey": None, "caught": 0}
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    spawn = node.create_client(Spawn, "/spawn")
    kill = node.create_client(Kill, "/kill")

    def on_spawned(x, y, future):
        game["prey"] = (future.result().name, x, y)

    def spawn_next():
        place = next(targets, None)
        if place is None:
            node.get_logger().info(f"done: {game['caught']} caught")
            return
        request = Spawn.Request()
        request.x, request.y = float(place[0]), float(place[1])
        spawn.call_async(request).add_done_callback(partial(on_spawned, request.x, request.y))

    def on_killed(future):
        game["caught"] += 1
        spawn_next()

    def on_pose(me):
        cmd = Twist()
        prey = game["prey"]
        if prey:
            name, x, y = prey
            dist = math.dist((me.x, me.y), (x, y))
            if dist < 0.6:
                game["prey"] = None
                req = Kill.Request()
                req.name = name
                kill.call_async(req).add_done_callback(on_killed)
            else:
                err = math.atan2(y - me.y, x - me.x) - me.theta
                while err > math.pi:
                    err -= 2 * math.pi
                while err < -math.pi:
                    err += 2 * math.pi
                cmd.angular.z = 4.0 * err
                cmd.linear.x = 3.0 if abs(err) < 0.5 else 0.3
        pub.publish(cmd)

    node.create_subscription(Pose, "/turtle1/pose", on_pose, 10)
    spawn.wait_for_service()
    spawn_next()
    rclpy.spin(node)


if __name__ == "__main__":
    main()
