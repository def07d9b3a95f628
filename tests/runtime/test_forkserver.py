"""Sandboxed children forked from a submission's fork server (as grading
workers start them) behave as children started afresh; a server serves one
submission, and nothing it answers can make the grader act on another process.
(tests/runtime/test_sandbox.py runs every hostile behaviour both ways.)"""

from __future__ import annotations

import os
import socket
import textwrap
import threading
import time
from pathlib import Path

import pytest

from turtletui.api import run
from turtletui.runtime import forkserver
from turtletui.runtime.sandbox import Limits

NODE = """\
import os, random, signal
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


def note(name, value):
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), name), "a") as f:
        f.write(f"{value}\\n")


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        # hash order of strings and the seeded random module steer the turtle
        self.turns = [len(word) / 5.0 for word in {"left", "right", "around", "back"}]
        self.n = 0

    def on_pose(self, pose):
        self.n += 1
        msg = Twist()
        msg.linear.x = 1.0 + random.random()
        msg.angular.z = self.turns[self.n % len(self.turns)]
        self.pub.publish(msg)


def main():
    note("token", os.environ.get("TURTLETUI_SANDBOX"))
    note("parent", os.getppid())
    note("group", os.getpgrp() == os.getpid())
    note("cwd", os.getcwd())
    BEFORE
    rclpy.init()
    rclpy.spin(Driver())
"""


def controller(folder: Path, before: str = "pass", name: str = "node.py") -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / name
    path.write_text(NODE.replace("BEFORE", textwrap.indent(textwrap.dedent(before), "    ").strip()))
    return path


def noted(folder: Path, name: str) -> list[str]:
    return (folder / name).read_text().split()


def test_a_forked_run_is_the_same_run_as_a_fresh_one(tmp_path: Path) -> None:
    fresh = controller(tmp_path / "fresh")
    forked = controller(tmp_path / "forked")
    expected = run([fresh], duration=3.0, seed=5, keep_poses=True)
    graded = controller(tmp_path / "graded")
    with forkserver.serving():
        got = run([forked], duration=3.0, seed=5, keep_poses=True)
        again = run([forked], duration=3.0, seed=5, keep_poses=True)
        run([graded], duration=0.5, limits=Limits(file_folder=True))
    assert got.poses["turtle1"] == expected.poses["turtle1"] == again.poses["turtle1"]
    assert got.turtles["turtle1"].distance > 3.0
    for folder in (tmp_path / "fresh", tmp_path / "forked"):
        assert noted(folder, "parent")[0] == str(os.getpid()), "its parent is the grader"
        assert set(noted(folder, "group")) == {"True"}, "it leads its own process group"
        assert set(noted(folder, "cwd")) == {os.getcwd()}, "it starts where turtletui runs, as python3 FILE"
    assert noted(tmp_path / "graded", "cwd") == [str((tmp_path / "graded").resolve())], "graded: in its own folder"


def test_the_runs_of_one_submission_share_a_server_and_others_get_their_own(tmp_path: Path) -> None:
    first, second = controller(tmp_path / "ada"), controller(tmp_path / "bob")
    with forkserver.serving():
        run([first], duration=0.5)
        run([first], duration=0.5)
        run([second], duration=0.5)
        run([first], duration=0.5)
    ada, bob = noted(tmp_path / "ada", "token"), noted(tmp_path / "bob", "token")
    assert ada[0] == ada[1], "one server for a submission's runs in a row"
    assert len({ada[0], bob[0], ada[2]}) == 3, "a new server for every other submission"
    outside = controller(tmp_path / "outside")
    run([outside], duration=0.5)
    run([outside], duration=0.5)
    tokens = noted(tmp_path / "outside", "token")
    assert tokens[0] != tokens[1] and tokens[0] not in ada + bob


DISTRO_PROBE = """\
import importlib, os

import rclpy


def main():
    found = []
    for package in ("turtlesim", "turtlesim_msgs"):
        try:
            importlib.import_module(package + ".msg")
            found.append(package)
        except ImportError:
            pass
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "found"), "a") as f:
        f.write(",".join(found) + "\\n")
    rclpy.init()
"""


def test_a_server_warmed_for_one_distro_never_serves_another(tmp_path: Path) -> None:
    """The server imports a distro's packages before it forks: a run of another
    distro must not find them (Kilted has only turtlesim_msgs, Jazzy only turtlesim)."""
    probe = tmp_path / "probe.py"
    probe.write_text(DISTRO_PROBE)
    with forkserver.serving():
        for distro in ("jazzy", "kilted", "jazzy", "kilted"):
            run([probe], duration=0.2, distro=distro)
    assert noted(tmp_path, "found") == ["turtlesim", "turtlesim_msgs", "turtlesim", "turtlesim_msgs"]


def _processes_with(token: str) -> set[int]:
    """Processes whose environment holds the sandbox token (those this user may read)."""
    found = set()
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/environ", "rb") as f:
                    if f"TURTLETUI_SANDBOX={token}".encode() in f.read().split(b"\0"):
                        found.add(int(entry))
            except OSError:
                pass
    return found


SERVER_MARK = "turtletui.runtime.forkserver import serve"


def _servers_of(parent: int) -> set[int]:
    """Fork servers the process ``parent`` started (their command lines say so),
    not counting killed ones its subreaper has not reaped yet."""
    found = set()
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat", "rb") as f:
                    state, ppid = f.read().rpartition(b")")[2].split()[:2]
                if state in (b"Z", b"X"):
                    continue
                ppid = int(ppid)
                with open(f"/proc/{entry}/cmdline", "rb") as f:
                    command = f.read().decode(errors="replace")
            except (OSError, ValueError, IndexError):
                continue
            if ppid == parent and SERVER_MARK in command:
                found.add(int(entry))
    return found


def _settled(look, expected, seconds: float = 30.0):
    """``look()`` once it gives ``expected``, or what it gives after ``seconds``:
    a killed process is listed until the kernel has taken it down."""
    deadline = time.monotonic() + seconds
    while (found := look()) != expected and time.monotonic() < deadline:
        time.sleep(0.02)
    return found


def test_the_server_and_everything_it_started_end_with_the_block(tmp_path: Path) -> None:
    path = controller(tmp_path, before="""
        noted, written = os.pipe()
        if os.fork() == 0:
            os.setsid()
            note("grandchild", os.getpid())
            os.write(written, b"x")
            signal.pause()
        os.read(noted, 1)  # the run goes on (and ends) once the grandchild is noted
    """)
    with forkserver.serving():
        run([path], duration=0.5)
        token = noted(tmp_path, "token")[0]
        grandchild = int(noted(tmp_path, "grandchild")[0])
        # the killed grandchild (a fork of the server: its command line) goes first
        servers = _servers_of(os.getpid()) - {grandchild}
        serving = servers & _processes_with(token)
        assert len(serving) == 1, "the server waits for the submission's next run"
        assert len(servers - serving) == 1, "the template waits for the next submission"
        assert grandchild not in _settled(lambda: _processes_with(token), serving), "killed with its run"
    assert _settled(lambda: _servers_of(os.getpid()), set()) == set()
    assert _settled(lambda: _processes_with(token), set()) == set()


def test_a_controller_that_kills_its_server_only_slows_its_own_later_runs(tmp_path: Path) -> None:
    killer = controller(tmp_path / "killer", before=f"""
        def _parent_of(pid):
            with open(f"/proc/{{pid}}/stat", "rb") as f:
                return int(f.read().rpartition(b")")[2].split()[1])

        for entry in os.listdir("/proc"):
            try:
                with open(f"/proc/{{entry}}/cmdline", "rb") as f:
                    mine = _parent_of(entry) == os.getppid()  # not another pytest worker's server
                    if {SERVER_MARK!r}.encode() in f.read() and int(entry) != os.getpid() and mine:
                        os.kill(int(entry), signal.SIGKILL)
                        note("killed", entry)
            except (OSError, ValueError):
                pass
    """)
    with forkserver.serving():
        first = run([killer], duration=1.0)
        second = run([killer], duration=1.0)
    assert noted(tmp_path / "killer", "killed"), "it found its server"
    for result in (first, second):
        assert result.crashes == [] and result.turtles["turtle1"].distance > 1.0
    tokens = noted(tmp_path / "killer", "token")
    assert tokens[0] != tokens[1], "the second run started afresh"


def _template_of(parent: int, *tokens: str) -> int:
    """The one fork server of ``parent`` that holds none of ``tokens``: the template."""
    held = set().union(*map(_processes_with, tokens))
    (template,) = _servers_of(parent) - held
    return template


@pytest.fixture
def server_starts(monkeypatch: pytest.MonkeyPatch) -> list[bool]:
    """Each server started afresh from now on, as whether it was a template."""
    started: list[bool] = []
    real_init = forkserver.ForkServer.__init__

    def counting_init(self, *args, template: bool = False, **kwargs) -> None:
        started.append(template)
        real_init(self, *args, template=template, **kwargs)

    monkeypatch.setattr(forkserver.ForkServer, "__init__", counting_init)
    return started


def test_each_submission_gets_a_server_of_its_own_forked_from_one_template(
    tmp_path: Path, server_starts: list[bool]
) -> None:
    """A submission's server is forked (not started afresh) from a template
    that never runs a controller: its token, process and session are new."""
    names = ("ada", "bob", "cy")
    paths = [controller(tmp_path / name) for name in names]
    templates = []
    with forkserver.serving():
        for path in paths:
            run([path], duration=0.5)
            templates.append(_template_of(os.getpid(), noted(path.parent, "token")[0]))
    tokens = [noted(tmp_path / name, "token")[0] for name in names]
    assert len(set(tokens)) == 3
    assert len(set(templates)) == 1, "one template served every submission"
    assert server_starts == [True], "no server was started afresh"
    for name in names:
        assert noted(tmp_path / name, "parent")[0] == str(os.getpid())
        assert noted(tmp_path / name, "group") == ["True"]


@pytest.mark.parametrize("signal_name", ["SIGSTOP", "SIGKILL"])
def test_a_controller_that_stops_or_kills_the_template_slows_only_the_next_servers_start(
    tmp_path: Path, signal_name: str
) -> None:
    """The template runs as the same user as the runs: one that stops it
    must not hang the next submission, nor one that kills it fail it."""
    tamperer = controller(tmp_path / "tamperer", before=f"""
        mine = os.environ["TURTLETUI_SANDBOX"]
        for entry in os.listdir("/proc"):
            try:
                with open(f"/proc/{{entry}}/cmdline", "rb") as f:
                    command = f.read()
                with open(f"/proc/{{entry}}/stat", "rb") as f:
                    parent = int(f.read().rpartition(b")")[2].split()[1])
                if {SERVER_MARK!r}.encode() in command and parent == os.getppid():
                    with open(f"/proc/{{entry}}/environ", "rb") as f:
                        theirs = f.read()
                    if f"TURTLETUI_SANDBOX={{mine}}".encode() not in theirs.split(b"\\0"):
                        os.kill(int(entry), signal.{signal_name})
                        note("hit", entry)
            except (OSError, ValueError, IndexError):
                pass
    """)
    honest = controller(tmp_path / "honest")
    with forkserver.serving():
        run([tamperer], duration=0.5)
        after = run([honest], duration=0.5, seed=5, keep_poses=True)
        again = run([controller(tmp_path / "again")], duration=0.5)
    assert len(noted(tmp_path / "tamperer", "hit")) == 1, "it found the template"
    fresh = run([honest], duration=0.5, seed=5, keep_poses=True)
    assert after.crashes == [] == again.crashes
    assert after.poses["turtle1"] == fresh.poses["turtle1"]


def test_where_templates_cannot_fork_servers_one_is_tried_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, server_starts: list[bool]
) -> None:
    """A new template that forks no server (a system where the token cannot be
    set so) is not started again for every submission: servers start afresh."""
    monkeypatch.setattr(forkserver.ForkServer, "fork_server", lambda self, timeout: None)
    paths = [controller(tmp_path / name) for name in ("ada", "bob", "cy")]
    with forkserver.serving():
        results = [run([path], duration=0.5) for path in paths]
    assert [result.crashes for result in results] == [[], [], []]
    assert server_starts == [True, False, False, False], "one template, then a server started afresh per submission"


def test_a_stopped_template_is_not_asked() -> None:
    """A stopped template would keep the next submission waiting for its
    answer: it is given up at once."""
    import signal

    mine, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
    stopped = os.fork()
    if stopped == 0:
        time.sleep(600)
        os._exit(0)
    os.kill(stopped, signal.SIGSTOP)
    while _state(stopped) != "T":
        time.sleep(0.01)
    template = forkserver.ForkServer.__new__(forkserver.ForkServer)
    template.sock, template.proc, template.token = mine, _FakeProcess(stopped), "x" * 8
    try:
        assert template.fork_server(timeout=5.0) is None
        with pytest.raises(BlockingIOError):
            theirs.recv(4096, socket.MSG_DONTWAIT)
    finally:
        os.kill(stopped, signal.SIGKILL)
        os.waitpid(stopped, 0)
        mine.close()
        theirs.close()


def test_a_template_that_answers_a_child_that_never_says_ready_is_refused() -> None:
    """The server a template forks says it is ready once it holds its own
    token; one that does not (a template a run tampered with) is not used."""
    mine, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
    template = forkserver.ForkServer.__new__(forkserver.ForkServer)
    template.sock, template.proc, template.token = mine, _FakeProcess(os.getpid()), "x" * 8
    silent = os.fork()
    if silent == 0:
        time.sleep(600)
        os._exit(0)

    def fake_template() -> None:
        _, fds, _, _ = socket.recv_fds(theirs, 4096, 1)
        for fd in fds:
            os.close(fd)  # the new server's socket: closed, never a "ready"
        theirs.send(str(silent).encode())

    thread = threading.Thread(target=fake_template)
    thread.start()
    try:
        assert template.fork_server(timeout=5.0) is None
        assert not _running(silent), "and the child it named is stopped"
    finally:
        thread.join()
        mine.close()
        theirs.close()


class _FakeProcess:
    def __init__(self, pid: int) -> None:
        self.pid = pid

    def poll(self) -> None:
        return None


@pytest.mark.parametrize("answer", ["grader", "init", "server", "nonsense", "nothing"])
def test_a_pid_that_is_not_the_graders_own_new_child_is_refused(answer: str) -> None:
    """A server a controller tampered with could name any process as the new
    run child: the grader would signal and kill it at the end of the run."""
    mine, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
    server = forkserver.ForkServer.__new__(forkserver.ForkServer)
    server.sock, server.proc, server.token = mine, _FakeProcess(os.getpid() + 1), "x"
    reply = {
        "grader": str(os.getpid()), "init": "1", "server": str(server.proc.pid), "nonsense": "-x", "nothing": "",
    }[answer].encode()

    def fake_server() -> None:
        _, fds, _, _ = socket.recv_fds(theirs, 1 << 20, 3)
        for fd in fds:
            os.close(fd)
        theirs.send(reply) if reply else theirs.close()

    thread = threading.Thread(target=fake_server)
    thread.start()
    to_child_r, to_child_w = os.pipe()
    from_child_r, from_child_w = os.pipe()
    try:
        assert server.spawn({}, None, (to_child_r, from_child_w), timeout=5.0) is None
    finally:
        thread.join()
        for fd in (to_child_r, to_child_w, from_child_r, from_child_w):
            os.close(fd)
        mine.close()
        if answer != "nothing":
            theirs.close()


def test_a_new_child_that_ended_already_is_the_graders_own_with_its_status() -> None:
    """A controller that exits at once (on a busy machine, before the grader
    reads the server's answer) is still the new run child: refused, its run
    would start a second child on the same pipes, and its status be lost."""
    mine, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
    server = forkserver.ForkServer.__new__(forkserver.ForkServer)
    server.sock, server.proc, server.token = mine, _FakeProcess(os.getpid() + 1), "x"
    ended = os.fork()
    if ended == 0:
        os._exit(3)
    while _state(ended) != "Z":  # ended, and not reaped
        time.sleep(0.01)

    def fake_server() -> None:
        _, fds, _, _ = socket.recv_fds(theirs, 1 << 20, 3)
        for fd in fds:
            os.close(fd)
        theirs.send(str(ended).encode())

    thread = threading.Thread(target=fake_server)
    thread.start()
    to_child_r, to_child_w = os.pipe()
    from_child_r, from_child_w = os.pipe()
    try:
        child = server.spawn({}, None, (to_child_r, from_child_w), timeout=5.0)
        assert child is not None and child.pid == ended
        assert child.wait(timeout=5) == 3
        child.stdout.close()
    finally:
        thread.join()
        for fd in (to_child_r, to_child_w, from_child_r, from_child_w):
            os.close(fd)
        mine.close()
        theirs.close()


def _state(pid: int) -> str:
    with open(f"/proc/{pid}/stat", "rb") as f:
        return f.read().rpartition(b")")[2].split()[0].decode()


@pytest.mark.parametrize("lockstep", [False, True], ids=["fast", "lockstep"])
def test_what_a_child_forked_too_late_wrote_is_not_read_as_the_runs(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, lockstep: bool
) -> None:
    """A server that answers too late is given up and the run starts the usual
    way, on the same pipes: a child it forked anyway wrote its first answer
    there (and on the fast path, records in the journal) before it was killed."""
    from turtletui.runtime.sandbox import Limits

    monkeypatch.setattr(forkserver.ForkServer, "spawn", _late)
    node = controller(tmp_path / "late")
    expected = run([node], duration=2.0, seed=5, keep_poses=True, limits=Limits(lockstep=lockstep))
    with forkserver.serving():
        got = run([node], duration=2.0, seed=5, keep_poses=True, limits=Limits(lockstep=lockstep))
    assert got.crashes == []
    assert got.poses["turtle1"] == expected.poses["turtle1"]
    assert got.turtles["turtle1"].distance > 1.0


def _late(self, config, cwd, fds, timeout):
    """A server's spawn that gave up while its late child had written its
    start report and (fast path) a first batch into the journal."""
    from turtletui.runtime import fastpath, protocol, wire

    wire.write_frame(fds[1], protocol.encode_report(protocol.Report()))
    if len(fds) > 2:
        payload = protocol.encode_report(protocol.Report())
        record = fastpath._RECORD.pack(123_000_000, 0.0, 0, 0, 0, len(payload)) + payload
        os.pwrite(fds[2], fastpath._HEADER.pack(0, len(record)) + record, 0)
    return None


def test_a_late_childs_journal_is_not_replayed_for_a_child_that_exits_at_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The run's own child ends before its first record: the journal the parent
    then reads must not hold the late child's."""
    from turtletui.runtime.sandbox import Limits

    monkeypatch.setattr(forkserver.ForkServer, "spawn", _late)
    node = controller(tmp_path / "quits", before="os._exit(0)")
    with forkserver.serving():
        got = run([node], duration=2.0, limits=Limits(lockstep=False))
    assert [(c.kind, c.message) for c in got.crashes] == [("exit", "exited with status 0 without finishing its run")]


def test_two_controllers_of_one_run_both_run_the_second_started_afresh(tmp_path: Path) -> None:
    """A server forks one run at a time: a second child alive at once starts the usual way."""
    first, second = controller(tmp_path / "first"), controller(tmp_path / "second", name="other.py")
    second.write_text(second.read_text().replace('super().__init__("driver")', 'super().__init__("other")'))
    with forkserver.serving():
        result = run([first, second], duration=1.0)
    assert result.crashes == []
    tokens = noted(tmp_path / "first", "token") + noted(tmp_path / "second", "token")
    assert len(set(tokens)) == 2
    assert _settled(lambda: _processes_with(tokens[0]) | _processes_with(tokens[1]), set()) == set()


def test_a_server_ends_with_the_process_that_started_it(tmp_path: Path) -> None:
    """A grading worker killed outright (its memory, an operator) leaves no
    fork server behind, even when its socket does not close (here a forked
    copy of the worker holds it open)."""
    import signal
    import subprocess
    import sys

    import turtletui

    root = str(Path(turtletui.__file__).resolve().parents[1])
    starter = subprocess.Popen(
        [sys.executable, "-c", textwrap.dedent(f"""\
            import os, sys, time
            sys.path.insert(0, {root!r})
            from turtletui.runtime import forkserver
            server = forkserver.ForkServer({root!r}, dict(os.environ), "token", {{}})
            holder = os.fork()
            if holder == 0:
                time.sleep(600)
                os._exit(0)
            print(server.proc.pid, holder, flush=True)
            time.sleep(600)
        """)],
        stdout=subprocess.PIPE, text=True,
    )
    server, holder = map(int, starter.stdout.readline().split())
    try:
        assert _running(server)
        starter.kill()
        starter.wait()
        deadline = time.monotonic() + 30  # generous: a busy machine is not a leak
        while _running(server) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not _running(server)
    finally:
        os.kill(holder, signal.SIGKILL)


def test_a_server_forked_by_a_template_ends_with_the_process_that_started_them(tmp_path: Path) -> None:
    """As a server started afresh: the forked one is the starter's child and
    dies with it (PR_SET_PDEATHSIG set once it is), and the template too."""
    import signal
    import subprocess
    import sys

    import turtletui

    root = str(Path(turtletui.__file__).resolve().parents[1])
    starter = subprocess.Popen(
        [sys.executable, "-c", textwrap.dedent(f"""\
            import os, sys, time
            sys.path.insert(0, {root!r})
            from turtletui.runtime import forkserver
            forkserver.enable()  # the starter is a child subreaper, as a grading worker
            template = forkserver.ForkServer({root!r}, dict(os.environ, TURTLETUI_SANDBOX="t" * 20), "t" * 20, {{}},
                                             template=True)
            server = template.fork_server(timeout=30)
            holder = os.fork()
            if holder == 0:
                time.sleep(600)
                os._exit(0)
            print(template.proc.pid, server.proc.pid, os.getppid() and server.token, holder, flush=True)
            time.sleep(600)
        """)],
        stdout=subprocess.PIPE, text=True,
    )
    template, server, token, holder = starter.stdout.readline().split()
    template, server, holder = int(template), int(server), int(holder)
    try:
        assert _running(template) and _running(server)
        assert _processes_with(token) == {server}, "its own token, as long as the template's"
        starter.kill()
        starter.wait()
        deadline = time.monotonic() + 30  # generous: a busy machine is not a leak
        while (_running(server) or _running(template)) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not _running(server) and not _running(template)
    finally:
        os.kill(holder, signal.SIGKILL)


def test_a_server_takes_a_token_of_its_own_though_it_cannot_read_its_environ_back() -> None:
    """A server is not dumpable, which makes its /proc/PID/environ root's: a
    server of a grader that is not root, or of one that runs student code as
    nobody, cannot read it back, and must still take its token."""
    import subprocess
    import sys

    import turtletui

    root = str(Path(turtletui.__file__).resolve().parents[1])
    code = textwrap.dedent(f"""\
        import os, sys
        sys.path.insert(0, {root!r})
        from turtletui.runtime import forkserver
        forkserver._prctl(4, 0)  # PR_SET_DUMPABLE 0, as a server (imports ctypes first)
        if os.geteuid() == 0:
            os.setgid(65534)
            os.setuid(65534)
        try:
            open("/proc/self/environ", "rb").close()
            readable = True
        except OSError:
            readable = False
        wrong = forkserver._retoken("c" * 5)  # not as long as the one it has
        right = forkserver._retoken("b" * 22)
        print(readable, wrong, right, os.environ["TURTLETUI_SANDBOX"], flush=True)
        sys.stdin.read()
    """)
    proc = subprocess.Popen(
        [sys.executable, "-c", code], env=dict(os.environ, TURTLETUI_SANDBOX="a" * 22),
        stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True,
    )
    try:
        readable, wrong, right, seen = proc.stdout.readline().split()
        assert readable == "False", "the case this test is about"
        assert (wrong, right, seen) == ("False", "True", "b" * 22)
        if os.geteuid() == 0:  # only root may read the environment of a process that is not dumpable
            assert _processes_with("b" * 22) == {proc.pid}
            assert proc.pid not in _processes_with("a" * 22)
    finally:
        proc.stdin.close()
        proc.wait()


def _running(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            return f.read().rpartition(b")")[2].split()[0] != b"Z"
    except OSError:
        return False
