"""tf2_ros under both hosts: broadcasters and a listener in one program,
lookups before the frames exist, static frames, blocking and async waits."""

from __future__ import annotations

import math

from support.hosts import node_logs

BROADCASTS_BOTH_TURTLES = """
import math

import rclpy
from geometry_msgs.msg import TransformStamped, Twist
from rclpy.node import Node
from tf2_ros import TransformBroadcaster, TransformException
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener
from turtlesim.msg import Pose
from turtlesim.srv import Spawn


class Broadcaster(Node):
    '''world -> turtle1 and world -> turtle2 from their poses.'''

    def __init__(self):
        super().__init__('broadcaster')
        self.tf_broadcaster = TransformBroadcaster(self)
        for name in ('turtle1', 'turtle2'):
            self.create_subscription(Pose, f'/{name}/pose', lambda msg, name=name: self.send(name, msg), 1)

    def send(self, name, msg):
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = 'world'
        t.child_frame_id = name
        t.transform.translation.x = msg.x
        t.transform.translation.y = msg.y
        t.transform.rotation.z = math.sin(msg.theta / 2)
        t.transform.rotation.w = math.cos(msg.theta / 2)
        self.tf_broadcaster.sendTransform(t)
"""


def test_one_program_broadcasts_and_turtle2_chases_turtle1(controller_host):
    result = controller_host.run(
        BROADCASTS_BOTH_TURTLES
        + """

class Chaser(Node):
    def __init__(self):
        super().__init__('chaser')
        self.tf_buffer = Buffer()
        self.tf_listener = TransformListener(self.tf_buffer, self)
        self.spawner = self.create_client(Spawn, 'spawn')
        self.publisher = self.create_publisher(Twist, 'turtle2/cmd_vel', 1)
        self.spawned = None
        self.timer = self.create_timer(0.5, self.on_timer)

    def on_timer(self):
        if self.spawned is None:
            self.spawned = self.spawner.call_async(Spawn.Request(x=4.0, y=2.0, name='turtle2'))
        try:
            t = self.tf_buffer.lookup_transform('turtle2', 'turtle1', rclpy.time.Time())
        except TransformException as ex:
            self.get_logger().info(f'{type(ex).__name__}: {ex}')
            return
        msg = Twist()
        msg.angular.z = math.atan2(t.transform.translation.y, t.transform.translation.x)
        msg.linear.x = 0.5 * math.hypot(t.transform.translation.x, t.transform.translation.y)
        self.publisher.publish(msg)


def main():
    rclpy.init()
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(Broadcaster())
    executor.add_node(Chaser())
    executor.spin()
""",
        duration=20.0,
        distro="jazzy",
    )
    assert result.ok, result.crashes
    assert node_logs(result, "chaser") == [
        'LookupException: "turtle2" passed to lookupTransform argument target_frame does not exist. '
    ]
    one, two = result.turtles["turtle1"], result.turtles["turtle2"]
    assert math.hypot(two.x - one.x, two.y - one.y) < 0.05
    assert two.distance > 3.0


def test_static_frames_reach_a_late_listener_and_hold_at_any_time(controller_host):
    result = controller_host.run(
        """
import rclpy
import tf2_geometry_msgs  # noqa: F401  (registers PointStamped for buffer.transform)
from geometry_msgs.msg import PointStamped, TransformStamped
from rclpy.node import Node
from rclpy.time import Time
from tf2_ros import Buffer, StaticTransformBroadcaster, TransformListener


def main():
    rclpy.init()
    talker = Node('static_talker')
    broadcaster = StaticTransformBroadcaster(talker)
    for child, z in (('mystaticturtle', 1.0), ('other', 2.0), ('mystaticturtle', 5.0)):
        t = TransformStamped()
        t.header.stamp = talker.get_clock().now().to_msg()
        t.header.frame_id = 'world'
        t.child_frame_id = child
        t.transform.translation.z = z
        t.transform.rotation.w = 1.0
        broadcaster.sendTransform(t)
    rclpy.spin_once(talker, timeout_sec=1.0)
    node = Node('late_listener')
    buffer = Buffer()
    listener = TransformListener(buffer, node)
    rclpy.spin_once(node, timeout_sec=0.5)
    log = node.get_logger().info
    for when in (Time(), Time(seconds=3), Time(seconds=2e9)):
        t = buffer.lookup_transform('world', 'mystaticturtle', when)
        log(f'z={t.transform.translation.z} stamp={t.header.stamp.sec}')
    log(buffer.all_frames_as_string().strip().replace(chr(10), ' | '))
    point = PointStamped()
    point.header.frame_id = 'mystaticturtle'
    point.point.x = 2.0
    moved = buffer.transform(point, 'world')
    log(f'point in {moved.header.frame_id}: {moved.point.x} {moved.point.y} {moved.point.z}')
    listener.unregister()
""",
        duration=3.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "late_listener") == [
        "z=1.0 stamp=0",  # the first transform sent for a child stays, as tf2_ros's broadcaster keeps it
        "z=1.0 stamp=3",
        "z=1.0 stamp=2000000000",
        "Frame mystaticturtle exists with parent world. | Frame other exists with parent world.",
        "point in world: 2.0 0.0 1.0",
    ]


WAITS = BROADCASTS_BOTH_TURTLES + """

class Waiter(Node):
    def __init__(self):
        super().__init__('waiter')
        self.tf_buffer = Buffer()
        self.tf_listener = TransformListener(self.tf_buffer, self)
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        self.timer.cancel()
        start = self.get_clock().now()
        try:
            t = self.tf_buffer.lookup_transform(
                'world', 'turtle1', start, timeout=rclpy.duration.Duration(seconds=1.0))
            outcome = f'x={t.transform.translation.x:.3f}'
        except TransformException as ex:
            outcome = f'{type(ex).__name__}: {ex}'
        waited = (self.get_clock().now() - start).nanoseconds / 1e9
        self.get_logger().info(f'after {waited:.3f} s: {outcome}')


def main():
    rclpy.init()
    executor = EXECUTOR
    executor.add_node(Broadcaster())
    executor.add_node(Waiter())
    executor.spin()
"""


def test_a_blocking_lookup_in_a_single_threaded_callback_waits_its_timeout_and_fails(controller_host):
    result = controller_host.run(
        WAITS.replace("EXECUTOR", "rclpy.executors.SingleThreadedExecutor()"), duration=3.0, distro="jazzy"
    )
    assert result.ok, result.crashes
    # nothing runs the listener while the callback waits: the buffer stops just before it began
    assert node_logs(result, "waiter") == [
        "after 1.000 s: ExtrapolationException: Lookup would require extrapolation into the future.  Requested"
        " time 1700000001.000000 but the latest data is at time 1700000000.992000, when looking up transform"
        " from frame [turtle1] to frame [world]"
    ]


def test_a_blocking_lookup_returns_once_another_thread_brings_the_transform(controller_host):
    result = controller_host.run(
        WAITS.replace("EXECUTOR", "rclpy.executors.MultiThreadedExecutor()"), duration=3.0, distro="jazzy"
    )
    assert result.ok, result.crashes
    [line] = node_logs(result, "waiter")
    waited = float(line.split()[1])
    assert 0.0 < waited < 0.05 and line.endswith("s: x=5.544"), line


def test_async_waits_resolve_when_the_frame_arrives(controller_host):
    result = controller_host.run(
        BROADCASTS_BOTH_TURTLES
        + """

def main():
    rclpy.init()
    node = Node('asker')
    buffer = Buffer()
    TransformListener(buffer, node)
    future = buffer.wait_for_transform_async('world', 'turtle1', rclpy.time.Time())
    log = node.get_logger().info
    log(f'done at once: {future.done()}')
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(node)
    executor.add_node(Broadcaster())
    executor.spin_until_future_complete(future, timeout_sec=2.0)
    log(f'future: {future.result().child_frame_id} x={future.result().transform.translation.x:.3f}')

    async def later():
        t = await buffer.lookup_transform_async('turtle1', 'world', rclpy.time.Time())
        return t.transform.translation.y

    task = executor.create_task(later())
    executor.spin_until_future_complete(task, timeout_sec=2.0)
    log(f'coroutine: y={task.result():.3f}')
""",
        duration=3.0,
        distro="jazzy",
    )
    assert result.ok, result.crashes
    assert node_logs(result, "asker") == ["done at once: False", "future: turtle1 x=5.544", "coroutine: y=-5.544"]


def test_a_listener_s_spin_thread_fills_the_buffer_while_the_main_thread_blocks(controller_host):
    result = controller_host.run(
        BROADCASTS_BOTH_TURTLES
        + """

def main():
    rclpy.init()
    node = Broadcaster()
    buffer = Buffer()
    TransformListener(buffer, node, spin_thread=True)
    start = node.get_clock().now()
    t = buffer.lookup_transform('world', 'turtle1', rclpy.time.Time(), timeout=rclpy.duration.Duration(seconds=2.0))
    waited = (node.get_clock().now() - start).nanoseconds / 1e9
    node.get_logger().info(f'x={t.transform.translation.x:.3f} after {waited:.3f} s')
""",
        duration=3.0,
        distro="jazzy",
    )
    if not controller_host.sandboxed:  # one thread only: said at once, not a lookup that fails later
        [crash] = result.crashes
        assert crash.message.startswith("RuntimeError: TransformListener(spin_thread=True) spins its node on a")
        return
    assert result.ok, result.crashes
    [line] = node_logs(result, "broadcaster")
    assert line.startswith("x=5.544 after 0.0"), line
