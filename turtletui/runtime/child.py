"""The sandboxed side: runs one controller in a child process.

The child has its own Graph holding the controller's nodes, and records
standing for everyone else's, rebuilt from the mirror of the parent's graph
the parent sends when it changed (turtletui.runtime.graph_mirror). Whenever the
controller waits (spin, spin_once, sleeps, waiting for a future) and has
nothing ready, the child sends the parent what its nodes did (declarations,
messages, calls, logs) and blocks until the parent answers with the new time
and what arrived for it. The parent's simulation never trusts anything else.
This module must not import numpy or Textual: start-up time counts.
"""

from __future__ import annotations

import errno
import itertools
import json
import os
import random
import sys
import traceback
from collections.abc import Callable
from select import select as _select
from time import monotonic as _monotonic
from typing import Any

from turtletui.graph.core import (
    ActionClientRecord,
    ActionServer,
    GoalHandle,
    Graph,
    NodeRecord,
    Publisher,
    Service,
    ServiceClient,
    Subscription,
    Topic,
)
from turtletui.graph.logs import WARN, LogRecord
from turtletui.interfaces import get_interface, interface_name, to_values, trusted_from_values
from turtletui.runtime import graph_mirror, wire
from turtletui.runtime.host import CallbackTracking
from turtletui.runtime.scheduler import Scheduler

OWNER = "child"
"""Immutable types whose very same objects always serialise the same way."""


class _RemoteGoal:
    """Child-side stand-in for a goal accepted by a server in the parent."""

    def __init__(self, wire_id: int) -> None:
        self.wire_id = wire_id
        self.goal_id = wire_id
        """The parent's goal id once it accepted the goal (the wire id until then)."""
        self.status = "pending"


class ChildGraph(Graph):
    """A Graph that also reports everything to the parent."""

    def __init__(self) -> None:
        super().__init__(type_name=interface_name)
        self.out: dict[str, list] = {
            "decl": [], "pub": [], "call": [], "goal": [], "cancel": [], "log": [], "resp": [], "removed": [],
            "served": [],
        }
        self._ids = itertools.count(1)
        self._own: dict[int, Any] = {}
        """The controller's nodes, publishers and subscriptions by wire id."""
        self._calls: dict[int, Callable[[Any], None]] = {}
        self._goals: dict[int, tuple] = {}
        self._cancels: dict[int, list[Callable[[int, bool], None]]] = {}
        """Who waits for the parent's answer to a cancel request, by goal wire id."""
        self._served: dict[int, GoalHandle] = {}
        """Goals of the controller's own action servers, by the parent's goal id."""

    def take_out(self) -> dict[str, Any]:
        out = {}
        for key, value in self.out.items():
            if value:
                out[key] = value
        for key in out:
            self.out[key] = []
        if self.logs_dropped:
            out["logs_dropped"] = self.logs_dropped
        return out

    # -- declarations --------------------------------------------------------
    def add_node(self, name: str, namespace: str = "", owner: str = OWNER, **options: Any) -> NodeRecord:
        node = super().add_node(name, namespace, owner, **options)
        node.wire_id = next(self._ids)
        self._own[node.wire_id] = node
        self.out["decl"].append(["node", node.wire_id, name, namespace])
        return node

    def set_parameter(self, node: NodeRecord, name: str, value: Any, *, remove: bool = False) -> None:
        super().set_parameter(node, name, value, remove=remove)
        if isinstance(value, (bytes, bytearray)):
            value = list(value)
        self.out["decl"].append(["param", node.wire_id, name, value, remove])

    def remove_node(self, node: NodeRecord) -> None:
        super().remove_node(node)
        self._own.pop(node.wire_id, None)
        self.out["decl"].append(["rmnode", node.wire_id])

    def add_publisher(self, node: NodeRecord, name: str, msg_type: type, depth: int, **options: Any) -> Publisher:
        pub = super().add_publisher(node, name, msg_type, depth, **options)
        pub.wire_id = next(self._ids)
        self._own[pub.wire_id] = pub
        qos = graph_mirror.QosPolicies.of(pub.qos)
        self.out["decl"].append(["pub", pub.wire_id, node.wire_id, name, pub.topic.type_name, depth, "", qos])
        return pub

    def add_subscription(self, node, name, msg_type, depth, callback, **options) -> Subscription:
        sub = super().add_subscription(node, name, msg_type, depth, callback, **options)
        sub.wire_id = next(self._ids)
        self._own[sub.wire_id] = sub
        label = getattr(callback, "label", "")
        qos = graph_mirror.QosPolicies.of(sub.qos)
        self.out["decl"].append(["sub", sub.wire_id, node.wire_id, name, sub.topic.type_name, depth, label, qos])
        return sub

    def add_timer(self, node: NodeRecord, period_ns: int, callback: Callable[[], None], **options: Any) -> Any:
        timer = super().add_timer(node, period_ns, callback, **options)
        # named in the parent's report of a controller too slow for its timer
        self.out["decl"].append(["timer", node.wire_id, period_ns, getattr(callback, "label", "")])
        return timer

    def remove_endpoint(self, endpoint: Publisher | Subscription) -> bool:
        removed = super().remove_endpoint(endpoint)
        self._own.pop(endpoint.wire_id, None)
        self.out["decl"].append(["rm", endpoint.wire_id])
        return removed

    def add_client(self, node, name, srv_type):
        client = super().add_client(node, name, srv_type)
        self.out["decl"].append(["client", node.wire_id, name, client.type_name])
        return client

    def add_service(self, node, name, srv_type, handler):
        service = super().add_service(node, name, srv_type, handler)
        self.out["decl"].append(["srv", node.wire_id, name, service.type_name])
        return service

    def add_action_client(self, node, name, action_type):
        client = super().add_action_client(node, name, action_type)
        self.out["decl"].append(["aclient", node.wire_id, name, client.type_name])
        return client

    def add_action_server(self, node, name, action_type, on_goal, **options):
        server = super().add_action_server(node, name, action_type, on_goal, **options)
        self.out["decl"].append(["asrv", node.wire_id, name, server.type_name])
        return server

    def remove_action_server(self, server: ActionServer) -> bool:
        return self._removed("action_server", server, super().remove_action_server(server))

    def remove_service(self, service: Service) -> bool:
        return self._removed("service", service, super().remove_service(service))

    def remove_client(self, client: ServiceClient) -> bool:
        return self._removed("client", client, super().remove_client(client))

    def remove_action_client(self, client: ActionClientRecord) -> bool:
        return self._removed("action_client", client, super().remove_action_client(client))

    def _removed(self, kind: str, record: Any, removed: bool) -> bool:
        """Tell the parent (other nodes see it gone from the next exchange on)."""
        if removed:
            self.out["removed"].append(graph_mirror.Removed(kind, record.node.wire_id, record.name))
        return removed

    # -- traffic ------------------------------------------------------------------
    def publish(self, topic: Topic, msg: Any, source: str | None = None, publisher: Publisher | None = None) -> None:
        super().publish(topic, msg, graph_mirror.MIRROR_OWNER, publisher)  # the parent delivers to those
        if publisher is None or self.known_to_others(publisher):
            self.out["pub"].append([topic.name, to_values(msg)])  # else no other process knows it yet

    def call(self, name: str, request: Any, on_response: Callable[[Any], None], owner: str) -> None:
        service = self.services.get(name)
        if service is None or service.owner != graph_mirror.MIRROR_OWNER:
            super().call(name, request, on_response, owner)  # ours, or never answered (as in ROS)
            return
        call_id = next(self._ids)
        self._calls[call_id] = on_response
        self.out["call"].append([call_id, name, to_values(request)])

    def send_goal(self, name, goal, owner, on_accepted, on_feedback, on_result, on_status=None) -> Any:
        server = self.action_servers.get(name)
        if server is None or server.owner != graph_mirror.MIRROR_OWNER:
            return super().send_goal(name, goal, owner, on_accepted, on_feedback, on_result, on_status)
        goal_id = next(self._ids)
        handle = _RemoteGoal(goal_id)
        self._goals[goal_id] = (handle, on_accepted, on_feedback, on_result, on_status, server.action_type)
        self.out["goal"].append([goal_id, name, to_values(goal)])
        return handle

    def cancel_goal(self, handle: Any, owner: str | None = None, on_answer: Any = None) -> None:
        if not isinstance(handle, _RemoteGoal):
            super().cancel_goal(handle, owner, on_answer)
            return
        wire_id = handle.wire_id
        self._cancels.setdefault(wire_id, []).append(on_answer)
        self.out["cancel"].append(wire_id)

    log_budget = 1 << 62
    """Log records still worth sending: the parent keeps only Limits.log_lines
    (and notices one more), so a log flood costs no more than that."""

    logs_dropped = 0
    """Log records not sent for being over the budget (the parent says how many)."""

    def log(self, node: str, level: int, msg: str) -> LogRecord:
        if self.log_budget > 0:
            self.log_budget -= 1
            self.out["log"].append([level, node, msg])
        else:
            self.logs_dropped += 1
        return LogRecord(self.epoch_ns + self.now_ns, self.now_ns / 1e9, level, node, msg)

    # -- what the parent sent ---------------------------------------------------------
    def receive(self, message: dict) -> None:
        ready = self.ready
        if "graph" in message:  # first: what arrives with it may come from nodes it adds
            graph_mirror.apply(self, graph_mirror.GraphMirror.from_wire(message["graph"]), self._own)
        for sub_id, fields in message.get("msgs", ()):
            sub = self._own.get(sub_id)
            if sub is None:
                continue
            sub.queue.append(trusted_from_values(sub.topic.msg_type)(fields))
            if not sub.pending:
                sub.pending = True
                ready.append(sub.ready_item)
        for call_id, type_name, fields in message.get("responses", ()):
            on_response = self._calls.pop(call_id, None)
            if on_response is not None:
                response = trusted_from_values(get_interface(type_name))(fields)
                ready.append((OWNER, lambda cb=on_response, r=response: cb(r)))
        for goal_id, kind, payload in message.get("goals", ()):
            if kind == "cancel":  # may come after the goal's result
                waiting = self._cancels.get(goal_id)
                on_answer = waiting.pop(0) if waiting else None
                if on_answer is not None:
                    ready.append((OWNER, lambda cb=on_answer, p=payload: cb(*p)))
                continue
            entry = self._goals.get(goal_id)
            if entry is None:
                continue
            handle, on_accepted, on_feedback, on_result, on_status, action = entry
            if kind == "accepted":
                handle.goal_id, handle.status = payload
                ready.append((OWNER, lambda cb=on_accepted, h=handle: cb(h)))
            elif kind == "rejected":
                self._goals.pop(goal_id, None)
                handle.status = "rejected"
                ready.append((OWNER, lambda cb=on_accepted: cb(None)))
            elif kind == "status":
                handle.status = payload
                if on_status is not None:
                    ready.append((OWNER, lambda cb=on_status, s=payload: cb(s)))
            elif kind == "feedback":
                feedback = trusted_from_values(action.Feedback)(payload)
                ready.append((OWNER, lambda cb=on_feedback, f=feedback: cb(f)))
            else:
                self._goals.pop(goal_id, None)
                handle.status = payload[0]
                result = trusted_from_values(action.Result)(payload[1])
                ready.append((OWNER, lambda cb=on_result, s=payload[0], r=result: cb(s, r)))
        for goal_id, kind, payload in message.get("served", ()):
            self._serve(goal_id, kind, payload)
        for req_id, name, fields in message.get("requests", ()):
            service = self.services.get(name)
            if service is None:
                continue
            request = trusted_from_values(service.srv_type.Request)(fields)

            def respond(response: Any, req_id: int = req_id) -> None:
                self.out["resp"].append([req_id, to_values(response)])

            ready.append((OWNER, lambda s=service, q=request, r=respond: s.handler(q, r)))
        for node_id, name, value in message.get("params", ()):
            node = next((n for n in self.nodes if getattr(n, "wire_id", None) == node_id), None)
            if node is not None and node.parameter_setter is not None:
                ready.append((OWNER, lambda n=node, k=name, v=value: self._set_parameter(n, k, v)))

    def _serve(self, goal_id: int, kind: str, payload: Any) -> None:
        """A goal for one of the controller's action servers, or a request to cancel one."""
        def send(*event: Any) -> None:
            self.out["served"].append(list(event))

        if kind == "cancel":
            handle = self._served.get(goal_id)
            if handle is not None:
                answer = lambda code, canceling: send(goal_id, "cancel", [code, canceling])  # noqa: E731
                self.ready.append((OWNER, lambda: handle.request_cancel(answer)))
            return
        name, fields = payload
        server = self.action_servers.get(name)
        if server is None or server.owner == graph_mirror.MIRROR_OWNER:
            return  # destroyed meanwhile: never answered, as in ROS

        def finished(status: str, result: Any) -> None:
            self._served.pop(goal_id, None)
            send(goal_id, "result", [status, to_values(result)])

        handle = GoalHandle(
            server,
            goal_id,
            trusted_from_values(server.action_type.Goal)(fields),
            on_feedback=lambda feedback: send(goal_id, "feedback", to_values(feedback)),
            on_result=finished,
            status="pending",
            on_answer=lambda h: send(goal_id, "accept", h.status) if h else send(goal_id, "reject", None),
            on_status=lambda status: send(goal_id, "status", status),
        )
        self._served[goal_id] = handle
        self.ready.append((OWNER, lambda: server.on_goal(handle)))

    def _set_parameter(self, node: NodeRecord, name: str, value: Any) -> None:
        """``ros2 param set`` from the app; the parent checked the name and type,
        the node's own on-set callbacks may still refuse."""
        reason = node.parameter_setter(name, value)
        if reason:
            self.log(node.name, WARN, f"Setting parameter {name} failed: {reason}")


class ChildHost(CallbackTracking):
    """The compat Host inside the sandbox: waiting means asking the parent.

    The controller's threads take turns (turtletui.runtime.scheduler): a
    thread that waits lets the others run, and when none can, the exchange
    with the parent moves simulated time on.
    """

    owner = OWNER

    def __init__(self, graph: ChildGraph, fd_in: int, fd_out: int, *, spin_seconds: float = 0.0) -> None:
        self.graph = graph
        self.fd_in = fd_in
        self.fd_out = fd_out
        self.spin_seconds = spin_seconds
        """How long a read polls for the parent's answer (turtletui.runtime.wire.FrameReader)."""
        self.running = True
        self.scheduler = Scheduler(graph, self.exchange, lambda: self.running)

    def spin(self, stop: Callable[[], bool]) -> None:
        """Run every callback as it becomes ready until ``stop()`` or the end."""
        graph = self.graph
        ready = graph.ready
        scheduler = self.scheduler

        def work() -> bool:
            return bool(ready) or stop()

        while self.running:
            while ready:
                ready.popleft()[1]()
                if stop():
                    return
            if stop():
                return
            if scheduler.alone():
                self.exchange(graph.next_due())  # what wait() does then, on the hottest path
            else:
                scheduler.wait(work, None, spinning=True)

    def exchange(self, wake_ns: int | None, **extra: Any) -> None:
        """Report to the parent and wait for the next instant it gives us."""
        reply = self.graph.take_out()
        reply["wake"] = wake_ns
        reply.update(extra)
        wire.send_to_parent(self.fd_out, reply)
        message = wire.read_from_parent(self.fd_in, self.spin_seconds)
        if message.get("end"):
            self.running = False
            return
        graph = self.graph
        now = message["now"]
        # Timers due now first, as in-process: there they become ready before
        # anything the parent's callbacks of this instant publish.
        while graph.advance(now):
            pass
        graph.now_ns = now
        graph.receive(message)

    def spin_once(self, timeout_ns: int | None) -> bool:
        ready = self.graph.ready
        if not ready and self.running:
            if timeout_ns == 0:
                self.scheduler.poll()
            else:
                deadline = None if timeout_ns is None else self.graph.now_ns + max(timeout_ns, 0)
                self.scheduler.wait(lambda: bool(ready), deadline, spinning=True)
        if ready and self.running:
            ready.popleft()[1]()
            return True
        return False

    def spin_until(self, done: Callable[[], bool], timeout_ns: int | None, *, callbacks: bool = True) -> bool:
        graph = self.graph
        ready = graph.ready
        deadline = None if timeout_ns is None else graph.now_ns + max(timeout_ns, 0)

        def go_on() -> bool:
            return done() or (callbacks and bool(ready))

        while not done():
            if not self.running or (deadline is not None and graph.now_ns >= deadline):
                return False
            if callbacks and ready:
                ready.popleft()[1]()
                continue
            self.scheduler.wait(go_on, deadline, spinning=callbacks)
        return True

    def sleep_until(self, t_ns: int) -> bool:
        if self.graph.now_ns < t_ns:
            self.scheduler.wait(None, t_ns)  # after the run: passes at once
        elif self.running:
            self.scheduler.pause()  # time.sleep(0): let the other threads run
        return self.running


def _out_of_memory(exc: BaseException) -> bool:
    """An error that is the memory limit showing through: mmap refused (ENOMEM),
    e.g. importing an extension module with too little address space left."""
    if isinstance(exc, OSError) and exc.errno == errno.ENOMEM:
        return True
    return isinstance(exc, ImportError) and "failed to map segment" in str(exc)


def _address_space() -> int:
    """Bytes of address space this process uses (Linux; 0 elsewhere)."""
    try:
        with open("/proc/self/statm", "rb") as f:
            return int(f.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0


CPU_GRACE_SECONDS = 5
"""The hard CPU limit is this much above the soft one: SIGXCPU at the soft
limit ends the child (and says why), SIGKILL at the hard one if it is ignored."""


def _apply_limits(limits: dict[str, int]) -> None:
    import resource

    cpu = limits.get("cpu_seconds")
    for name, value, grace in (
        ("RLIMIT_CPU", cpu, CPU_GRACE_SECONDS),
        ("RLIMIT_AS", limits.get("memory_bytes"), 0),
        ("RLIMIT_FSIZE", limits.get("file_bytes"), 0),
        ("RLIMIT_CORE", 0, 0),
    ):
        if value is None or not hasattr(resource, name):
            continue
        kind = getattr(resource, name)
        soft, hard = resource.getrlimit(kind)
        new_hard = value + grace if hard == resource.RLIM_INFINITY else min(value + grace, hard)
        try:
            resource.setrlimit(kind, (min(value, new_hard), new_hard))
        except (ValueError, OSError):
            pass  # the limit is lower already


def _become_subreaper() -> None:
    """Processes the controller starts stay in this process's tree even when
    their own parent dies (Linux), so that the parent finds and kills them all."""
    if not sys.platform.startswith("linux"):
        return
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER
    except (OSError, AttributeError):
        pass


def _wait_to_be_ended(fd_in: int, seconds: float = 10.0) -> None:
    """After the last report: stay alive until the parent has killed everything
    this process started (it ends us with them), or it went away."""
    deadline = _monotonic() + seconds
    while (remaining := deadline - _monotonic()) > 0:
        try:
            readable, _, _ = _select([fd_in], [], [], remaining)
            if readable and not os.read(fd_in, 65536):
                return
        except BlockingIOError:
            continue
        except OSError:
            return


def main(config: dict[str, Any] | None = None) -> None:
    """Run the controller ``config`` describes (by default: the JSON in argv[1]),
    report to the parent and exit."""
    if config is None:
        config = json.loads(sys.argv[1])
    fd_in, fd_out = config["fd_in"], config["fd_out"]
    os.set_inheritable(fd_in, False)
    os.set_inheritable(fd_out, False)
    _become_subreaper()
    _apply_limits(config.get("limits", {}))
    from turtletui import compat
    from turtletui.compat import context as compat_context
    from turtletui.runtime import scheduler, virtual_time
    from turtletui.runtime.loader import (
        ControllerError,
        ControllerSpec,
        resolve_factory,
        run_controller,
        seed_numpy,
        spin_nodes,
        user_frames,
    )

    compat.install(config.get("distro"))
    graph = ChildGraph()
    graph.epoch_ns = config["epoch_ns"]
    graph.discovery_ns = config.get("discovery_ns", 0)
    log_lines = config.get("limits", {}).get("log_lines")
    if log_lines is not None:
        graph.log_budget = int(log_lines) + 1
    host = ChildHost(graph, fd_in, fd_out, spin_seconds=config.get("spin_seconds", 0.0))
    compat_context.reset_default_context()
    compat_context.bind_host(host)
    scheduler.install(host.scheduler)
    virtual_time.install_simulated_sleep(host)
    virtual_time.install_simulated_select(host)
    if not config.get("realtime"):
        virtual_time.patch_clocks(graph, host.scheduler.clock_read)
    spec = ControllerSpec(
        name=config["name"],
        path=None if config.get("path") is None else __import__("pathlib").Path(config["path"]),
        module=config.get("module"),
        function=config.get("function"),
    )
    sys.argv = [spec.label, *config.get("ros_args", [])]
    random.seed(config.get("seed", 0))
    crash = None
    try:
        host.exchange(None)  # start together with the parent's clock
        memory_limit = config.get("limits", {}).get("memory_bytes")
        if memory_limit and _address_space() > memory_limit:
            raise MemoryError  # forked warm: a fresh interpreter would not have started
        if config.get("factory"):
            sys.path[1:1] = [p for p in config.get("sys_path", []) if p]
            factory = resolve_factory(config["factory"])
            seed_numpy(config.get("seed", 0))
            spin_nodes(list(factory()))
        else:
            seed_numpy(config.get("seed", 0))
            run_controller(spec)
        host.scheduler.join_threads()  # as Python does before it exits
    except ControllerError as err:
        crash = {"kind": "load", "message": str(err), "frames": []}
    except SystemExit as exc:
        if exc.code not in (None, 0):
            crash = {"kind": "exit", "message": f"exited with status {exc.code}", "frames": []}
    except MemoryError as exc:
        # Free what the failed frames hold before building the report.
        traceback.clear_frames(exc.__traceback__)
        try:
            frames = user_frames(exc.__traceback__, spec.path)
        except MemoryError:
            frames = []
        limit = config.get("limits", {}).get("memory_bytes")
        within = f" of {limit / 1024**2:g} MiB" if limit else ""
        crash = {"kind": "memory", "message": f"MemoryError: ran out of its memory limit{within}", "frames": frames}
    except BaseException as exc:  # noqa: BLE001 - controller code may raise anything
        message = f"{type(exc).__name__}: {exc}" if str(exc) else type(exc).__name__
        kind = "memory" if _out_of_memory(exc) else "exception"
        crash = {"kind": kind, "message": message, "frames": user_frames(exc.__traceback__, spec.path)}
    try:
        sys.stdout.flush()
        sys.stderr.flush()
        wire.send_to_parent(fd_out, {**graph.take_out(), "done": True, "crash": crash})
    except (OSError, wire.WireError):
        pass
    except Exception:  # noqa: BLE001 - the report itself failed; say so on stderr
        traceback.print_exc()
    _wait_to_be_ended(fd_in)
    os._exit(0)


if __name__ == "__main__":
    main()
