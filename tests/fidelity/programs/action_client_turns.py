"""The turns of an action client's callbacks, the server on an executor of its own spun apart, so
that the client takes one answer at a time: the goal response's future is done on the spin that
takes it and its done callbacks run later, each a task of the client's executor on a spin of its
own, the client's own (removing the pending request) first; the same for a cancel's and a result's
futures; the goal's status comes with each answer; a rejected goal. Nothing of the client's runs
while only the server's executor spins."""
import rclpy
from rclpy.action import ActionClient, ActionServer, CancelResponse, GoalResponse
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from turtlesim_msgs.action import RotateAbsolute


def main():
    rclpy.init()
    server_node, client_node = Node("server"), Node("client")
    events = []
    accepted = []

    def execute(handle):
        events.append("execute")
        handle.succeed()
        return RotateAbsolute.Result(delta=handle.request.theta)

    def goal_cb(goal):
        events.append(f"goal_cb {goal.theta}")
        return GoalResponse.ACCEPT if goal.theta >= 0 else GoalResponse.REJECT

    ActionServer(server_node, RotateAbsolute, "turn", execute_callback=execute,
                 goal_callback=goal_cb,
                 handle_accepted_callback=accepted.append,
                 cancel_callback=lambda h: events.append("cancel_cb") or CancelResponse.ACCEPT)
    client = ActionClient(client_node, RotateAbsolute, "turn")
    server_ex, client_ex = SingleThreadedExecutor(), SingleThreadedExecutor()
    server_ex.add_node(server_node)
    client_ex.add_node(client_node)
    print("server:", client.wait_for_server(timeout_sec=10.0))

    def spin(executor, count):
        steps = []
        for _ in range(count):
            before = len(events)
            executor.spin_once(timeout_sec=0.2)
            steps.append("+".join(events[before:]) or "-")
        return " | ".join(steps)

    handles = []
    futures = {}

    def on_goal(future):
        handle = future.result()
        handles.append(handle)
        events.append(f"goal_done {handle.accepted} {handle.status}")

    goal_future = client.send_goal_async(RotateAbsolute.Goal(theta=2.0),
                                         feedback_callback=lambda m: events.append(f"feedback {m.feedback.remaining}"))
    goal_future.add_done_callback(on_goal)
    print("server takes the goal:", spin(server_ex, 2))
    print("client takes the answer:", spin(client_ex, 4))
    handle = handles[0]
    futures["cancel"] = handle.cancel_goal_async()
    futures["cancel"].add_done_callback(lambda f: events.append(f"cancel_done {f.result().return_code} {len(f.result().goals_canceling)}"))
    print("server takes the cancel:", spin(server_ex, 2))
    print("client takes the cancel answer:", spin(client_ex, 4), handle.status)
    accepted[0].execute()
    print("server executes:", spin(server_ex, 3))
    result = handle.get_result_async()
    result.add_done_callback(lambda f: events.append(f"result_done {f.result().status} {f.result().result.delta}"))
    print("server takes the result request:", spin(server_ex, 3))
    print("client takes the result:", spin(client_ex, 4), handle.status)
    rejected = client.send_goal_async(RotateAbsolute.Goal(theta=-1.0))
    rejected.add_done_callback(on_goal)
    print("server takes a goal it rejects:", spin(server_ex, 2))
    print("client takes the rejection:", spin(client_ex, 4), handles[-1].status, len(accepted))
    server_node.destroy_node()
    client_node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
