"""tf2_ros.BufferClient against tf2_ros's buffer_server (the bundled
tf2_buffer_server controller), in both hosts: lookups, can_transform and
transform() answered over the LookupTransform action, tf2's exceptions as
the server reports them, and the waits tf2_ros's client makes."""

from __future__ import annotations

from support.hosts import node_logs

from turtletui.api import run
from turtletui.plugins.bundled import reference_dir
from turtletui.runtime.loader import ControllerSpec

SERVER = ControllerSpec("tf2_buffer_server", path=reference_dir() / "tf2_buffer_server.py")
"""Sandboxed, in its own process as ``ros2 run tf2_ros buffer_server`` (one
controller at most runs in-process: the client, for the in-process host)."""


def with_server(controller_host, source: str, duration: float):
    client = ControllerSpec("client", path=controller_host.write(source, "client.py"), trusted=not controller_host.sandboxed)
    return run([SERVER, client], duration=duration)

CLIENT = """
import rclpy
import tf2_geometry_msgs  # noqa: F401  (registers PointStamped for transform())
from geometry_msgs.msg import PointStamped, TransformStamped
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup
from rclpy.duration import Duration
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.time import Time
from tf2_ros import BufferClient, LookupException, StaticTransformBroadcaster, TimeoutException


class Client(Node):
    def __init__(self):
        super().__init__("tf_client")
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = "world"
        t.child_frame_id = "base"
        t.transform.translation.x = 1.0
        t.transform.rotation.w = 1.0
        self.static = StaticTransformBroadcaster(self)
        self.static.sendTransform(t)
        self.tf = BufferClient(self, "tf2_buffer_server")
        self.nobody = BufferClient(self, "nobody_serves_this")
        self.create_timer(0.5, self.once, callback_group=MutuallyExclusiveCallbackGroup())
        self.done = False

    def once(self):
        if self.done:
            return
        self.done = True
        log = self.get_logger()
        try:
            self.nobody.lookup_transform("world", "base", Time())
        except TimeoutException as ex:
            log.info(f"no server: {ex}")
        found = self.tf.lookup_transform("world", "base", Time(), timeout=Duration(seconds=1.0))
        log.info(f"{found.header.frame_id} -> {found.child_frame_id}: x={found.transform.translation.x}")
        log.info(f"can: {self.tf.can_transform('world', 'base', Time())} {self.tf.can_transform('world', 'mars', Time())}")
        try:
            self.tf.lookup_transform("world", "mars", Time())
        except LookupException as ex:
            log.info(f"{type(ex).__name__}: {ex}")
        point = PointStamped()
        point.header.frame_id = "base"
        point.point.x = 0.5
        moved = self.tf.transform(point, "world")
        log.info(f"point in {moved.header.frame_id}: x={moved.point.x}")
        before = self.get_clock().now()
        empty = self.tf.lookup_transform("world", "mars", Time(), timeout=Duration(seconds=0.3))
        waited = (self.get_clock().now() - before).nanoseconds / 1e9
        log.info(f"gave up after {waited:.2f} s: frame '{empty.header.frame_id}', w={empty.transform.rotation.w}")
        try:
            self.tf.lookup_transform("world", "base", 0.0)
        except TypeError as ex:
            log.info(f"TypeError: {ex}")


def main():
    rclpy.init()
    executor = MultiThreadedExecutor()
    executor.add_node(Client())
    executor.spin()
"""


def test_buffer_client_lookups_through_the_buffer_server(controller_host):
    result = with_server(controller_host, CLIENT, 2.0)
    assert result.ok, result.crashes
    logs = node_logs(result, "tf_client")
    assert logs[:5] == [
        "no server: The BufferServer is not ready.",
        "world -> base: x=1.0",
        "can: True False",
        'LookupException: "mars" passed to lookupTransform argument source_frame does not exist. ',
        "point in world: x=1.5",
    ]
    # a wait that runs out: tf2_ros's server aborts with no error, the client returns the empty transform
    assert logs[5].startswith("gave up after 0.3") and logs[5].endswith("frame '', w=1.0")
    assert logs[6:] == ["TypeError: Must pass a rclpy.time.Time object."]


ONE_THREAD = """
import rclpy
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.time import Time
from tf2_ros import BufferClient, TimeoutException


class Client(Node):
    def __init__(self):
        super().__init__("tf_client")
        self.tf = BufferClient(self, "tf2_buffer_server")
        self.timer = self.create_timer(0.5, self.once)

    def once(self):
        self.timer.cancel()
        start = self.get_clock().now()
        try:
            self.tf.lookup_transform("world", "base", Time(), timeout=Duration(seconds=0.5))
        except TimeoutException as ex:
            waited = (self.get_clock().now() - start).nanoseconds / 1e9
            self.get_logger().info(f"after {waited:.1f} s: {ex}")


def main():
    rclpy.init()
    rclpy.spin(Client())
"""


def test_inside_a_single_threaded_callback_the_answer_never_comes(controller_host):
    """The executor that would deliver the answer is busy waiting: tf2_ros's
    client gives up after the timeout plus its 2 s of padding."""
    result = with_server(controller_host, ONE_THREAD, 4.0)
    assert result.ok, result.crashes
    assert node_logs(result, "tf_client") == [
        "after 2.5 s: The LookupTransform goal sent to the BufferServer did not come back in the specified time. "
        "Something is likely wrong with the server."
    ]
