"""tf2_ros's buffer_server, written in rclpy: a ``tf_buffer`` node that keeps
``buffer_size`` seconds (120) of /tf and /tf_static and answers
``tf2_msgs/action/LookupTransform`` goals on ``tf2_buffer_server``, the
action tf2_ros.BufferClient sends its lookups to.

As tf2_ros's C++ server (buffer_server.cpp): every goal is accepted; a
transform that is available, or a goal whose timeout is 0, is answered at
once, with tf2's error in the result if the lookup fails; otherwise the goal
waits, checked every 10 ms, until the transform comes (then answered, aborted
with the error if the lookup still fails) or its timeout passes (aborted with
an empty result). A cancel request ends a waiting goal.
"""

import rclpy
import tf2_ros
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.task import Future
from rclpy.time import Time
from tf2_msgs.action import LookupTransform
from tf2_msgs.msg import TF2Error

# Most specific first: each is a TransformException.
ERRORS = (
    (tf2_ros.ConnectivityException, TF2Error.CONNECTIVITY_ERROR),
    (tf2_ros.LookupException, TF2Error.LOOKUP_ERROR),
    (tf2_ros.ExtrapolationException, TF2Error.EXTRAPOLATION_ERROR),
    (tf2_ros.InvalidArgumentException, TF2Error.INVALID_ARGUMENT_ERROR),
    (tf2_ros.TimeoutException, TF2Error.TIMEOUT_ERROR),
    (tf2_ros.TransformException, TF2Error.TRANSFORM_ERROR),
)


class BufferServer(Node):
    def __init__(self):
        super().__init__("tf_buffer")
        buffer_size = self.declare_parameter("buffer_size", 120.0).value
        self.buffer = tf2_ros.Buffer(cache_time=Duration(seconds=buffer_size))
        self.listener = tf2_ros.TransformListener(self.buffer, self)
        self.waiting = []  # [goal handle, end time, future of (outcome, result)]
        ActionServer(
            self,
            LookupTransform,
            "tf2_buffer_server",
            execute_callback=self.execute,
            goal_callback=lambda goal: GoalResponse.ACCEPT,
            cancel_callback=self.cancel,
            callback_group=ReentrantCallbackGroup(),
        )
        self.create_timer(0.01, self.check_waiting)

    def can_transform(self, goal):
        if not goal.advanced:
            return self.buffer.can_transform(goal.target_frame, goal.source_frame, Time.from_msg(goal.source_time))
        return self.buffer.can_transform_full(
            goal.target_frame, Time.from_msg(goal.target_time), goal.source_frame,
            Time.from_msg(goal.source_time), goal.fixed_frame,
        )

    def answer(self, goal):
        """The lookup's result, with tf2's error if it fails."""
        result = LookupTransform.Result()
        try:
            if not goal.advanced:
                result.transform = self.buffer.lookup_transform(
                    goal.target_frame, goal.source_frame, Time.from_msg(goal.source_time)
                )
            else:
                result.transform = self.buffer.lookup_transform_full(
                    goal.target_frame, Time.from_msg(goal.target_time), goal.source_frame,
                    Time.from_msg(goal.source_time), goal.fixed_frame,
                )
        except tf2_ros.TransformException as ex:
            result.error.error = next(code for kind, code in ERRORS if isinstance(ex, kind))
            result.error.error_string = str(ex)
        return result

    async def execute(self, goal_handle):
        goal = goal_handle.request
        now = self.get_clock().now()
        end = now + Duration.from_msg(goal.timeout)
        if self.can_transform(goal) or end <= now:
            goal_handle.succeed()  # even with an error in the result, as tf2_ros's server
            return self.answer(goal)
        decided = Future()
        self.waiting.append([goal_handle, end, decided])
        outcome, result = await decided
        getattr(goal_handle, outcome)()
        return result

    def check_waiting(self):
        now = self.get_clock().now()
        for entry in list(self.waiting):
            goal_handle, end, decided = entry
            if self.can_transform(goal_handle.request):
                result = self.answer(goal_handle.request)
                outcome = "succeed" if result.error.error == TF2Error.NO_ERROR else "abort"
            elif end < now:
                outcome, result = "abort", LookupTransform.Result()  # no error set, as tf2_ros's
            else:
                continue
            self.waiting.remove(entry)
            decided.set_result((outcome, result))

    def cancel(self, goal_handle):
        for entry in self.waiting:
            if entry[0] == goal_handle:
                self.waiting.remove(entry)
                entry[2].set_result(("canceled", LookupTransform.Result()))
                return CancelResponse.ACCEPT
        return CancelResponse.REJECT


def main():
    rclpy.init()
    node = BufferServer()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass


if __name__ == "__main__":
    main()
