"""Start sandboxed controllers by forking a warm interpreter (Linux).

Starting Python and importing the child runtime costs ~45 ms per run, a sixth
of a sandboxed 60 s lockstep run. A fork server is an interpreter started
exactly like a sandbox child (same environment, same user, a session of its
own) that has done those imports and waits; each request forks a child that
runs one controller as ``turtletui.runtime.child.main`` does in a fresh process.

Trust: a server serves the runs of one submission only (:class:`ForkServers`
keys them by controller file and user), so a controller that tampers with it
(it runs as the same user) changes nothing but its own later runs. The server
cannot be traced or read by them (not dumpable). The run child is handed over
to the caller (double fork; the caller is a child subreaper), so it is the
caller's child as one started by subprocess is: waited for, its parent is the
caller, and the pid the server reports is accepted only if it is the caller's
own child. A run that cannot be forked (the server died) starts the usual way.

Starting a server costs what starting a run child did, ~0.3 s of imports, so
each submission's server is itself forked from a template: a warm server
that never forks a run, only a new server for each submission, with a
sandbox token of its own (:func:`_retoken`). Nothing of a run reaches the
template: it is not dumpable either, and no run holds its socket. A run that
stops or kills it (same user) only makes the next server start the usual way.
"""

from __future__ import annotations

import gc
import json
import os
import select
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from functools import partial
from typing import Any

from turtletui.runtime.processes import TOKEN_VAR, kill_children, kill_tree, reap_zombie_children

_SERVER = (
    "import sys; sys.path.insert(0, {root!r}); "
    "from turtletui.runtime.forkserver import serve; "
    "serve(int(sys.argv[1]), int(sys.argv[2]), sys.argv[3] or None, sys.argv[4:] == ['template'])"
)
_real_sleep = time.sleep  # an in-process controller may get a simulated one
_PR_SET_PDEATHSIG = 1
_PR_SET_DUMPABLE = 4
_PR_SET_CHILD_SUBREAPER = 36


def _prctl(option: int, value: int) -> bool:
    try:
        import ctypes

        return ctypes.CDLL(None, use_errno=True).prctl(option, value, 0, 0, 0) == 0
    except (OSError, AttributeError):
        return False


# -- the server process ---------------------------------------------------------


def serve(sock_fd: int, parent: int, distro: str | None = None, template: bool = False) -> None:
    """The server's loop: one request (a JSON config and four descriptors:
    the child's input, its answers, its stdout and its stderr) forks one run child of
    ROS 2 ``distro``; a ``template``'s request (a token and a socket) forks a
    server instead. It ends with the process that started it (``parent``),
    killed by the kernel then if it is still busy, not only when its socket closes."""
    _prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
    if os.getppid() != parent:
        return  # the parent died before the line above
    # What every run would import: done once, before the first fork.
    import datetime  # noqa: F401  (the child's simulated clocks and waits patch these)
    import queue  # noqa: F401
    import selectors  # noqa: F401

    import turtletui.compat  # noqa: F401
    import turtletui.compat.context  # noqa: F401
    import turtletui.runtime.loader  # noqa: F401
    import turtletui.runtime.scheduler  # noqa: F401
    import turtletui.runtime.virtual_time  # noqa: F401
    from turtletui.runtime import child, fastpath  # noqa: F401  (its copy of the simulation: numpy)

    _warm(distro)
    gc.collect()  # the warm-up's throwaway simulation: no child inherits it
    _prctl(_PR_SET_DUMPABLE, 0)  # the runs (same user) cannot trace or read it
    sock = socket.socket(fileno=sock_fd)
    if template:
        _make_servers(sock, parent, child.main)
    else:
        _serve_runs(sock, child.main)


def _serve_runs(sock: socket.socket, main: Callable[[dict[str, Any]], None]) -> None:
    """A server's loop: each request (its config, and the run's four to six
    descriptors) forks a run child."""

    def run_child(request: Any, fds: list[int]) -> int:
        return _fork(request, fds, sock, main) if _FIXED_FDS <= len(fds) <= _FIXED_FDS + len(_EXTRA_FDS) else 0

    _answer(sock, 1 << 20, _FIXED_FDS + len(_EXTRA_FDS), run_child)


def _answer(sock: socket.socket, size: int, max_fds: int, fork: Callable[[Any, list[int]], int]) -> None:
    """Answer each request on ``sock`` (JSON and descriptors, closed once
    used) with the pid ``fork(request, fds)`` gives, 0 for a bad request,
    until the caller goes away."""
    while True:
        try:
            data, fds, _, _ = socket.recv_fds(sock, size, max_fds)
        except OSError:
            return
        if not data:
            return  # the caller went away
        try:
            pid = fork(json.loads(data), fds)
        except (OSError, ValueError, KeyError, TypeError):
            pid = 0
        finally:
            for fd in fds:
                os.close(fd)
        try:
            sock.send(str(pid).encode())
        except OSError:
            return


def _warm(distro: str | None) -> None:
    """Do once what every run child of ``distro`` does first: import turtletui's
    rclpy and the course's message packages, numpy's random module (seeded in
    every run), and build the message classes a run's simulation uses. Nothing
    of the controller's runs here: these are turtletui's own modules, as a
    fresh child would import them, and every run still starts from a clean
    context (turtletui.runtime.child.main)."""
    import importlib
    import resource  # noqa: F401  (the child's limits)

    import numpy.random  # noqa: F401  (turtletui.runtime.loader.seed_numpy)

    from turtletui import compat
    from turtletui.compat.distro import package_renames, resolve_distro
    from turtletui.interfaces import copier, get_interface, trusted_from_values
    from turtletui.runtime.simulation import Simulation

    try:
        distro = resolve_distro(distro)
        compat.install(distro)
        turtlesim = package_renames(distro).get("turtlesim", "turtlesim")
        for name in ("rclpy", "rclpy.node", "geometry_msgs.msg", "std_msgs.msg", f"{turtlesim}.msg"):
            importlib.import_module(name)
        topics = Simulation(distro=distro).graph.topics.values()
        every_node = ("rcl_interfaces/msg/ParameterEvent", "rcl_interfaces/msg/SetParametersResult")
        for cls in {*(topic.msg_type for topic in topics), *map(get_interface, every_node)}:
            copier(cls)  # what publishing and delivering one needs
            trusted_from_values(cls)  # what a Report's or Tick's message needs
        compat.install(distro)  # again, as each child does: now with every interface these registered
    except Exception:  # noqa: BLE001 - a run child meets the same error and reports it
        pass


def _make_servers(sock: socket.socket, parent: int, main: Callable[[dict[str, Any]], None]) -> None:
    """The template's loop: each request (a JSON token and the new server's
    socket) forks a server that serves runs on that socket."""

    def server(request: Any, fds: list[int]) -> int:
        token = request["token"]
        if len(fds) != 1 or not isinstance(token, str):
            return 0
        return _handed_over(partial(_become_server, token, fds[0], sock, parent, main))

    _answer(sock, 4096, 1, server)


def _become_server(
    token: str, sock_fd: int, template_sock: socket.socket, parent: int, main: Callable[[dict[str, Any]], None],
    middle: int,
) -> None:
    """In a server forked by the template: become what a server started afresh
    is (a session of its own, the caller's child, dying with it, its own
    token), say so on its socket, then serve runs."""
    try:
        template_sock.close()
        os.setsid()
        _wait_for_new_parent(middle)
        _prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
        if os.getppid() != parent or not _retoken(token):
            return
        sock = socket.socket(fileno=sock_fd)
        sock.send(b"ready")
        _serve_runs(sock, main)
    except BaseException:  # noqa: BLE001 - nothing may return into the template's loop
        pass
    finally:
        os._exit(0)


def _retoken(token: str) -> bool:
    """Give this process (and what it forks and starts) the sandbox ``token``
    in place of the one it was started with: in the environment block the
    kernel shows as /proc/PID/environ (the one it was started with, found by
    /proc/self/stat's env_start and env_end; the new token must be as long)
    and in os.environ (for what it starts). Whether the block now holds it.
    (/proc/self/environ itself cannot be read back: the process is not
    dumpable, which makes it root's.)"""
    import ctypes

    entry = f"{TOKEN_VAR}=".encode()
    new = token.encode()
    try:
        with open("/proc/self/stat", "rb") as f:
            fields = f.read().rpartition(b")")[2].split()
        start, end = int(fields[47]), int(fields[48])  # fields 50 and 51 of proc(5)
        if not 0 < start < end:
            return False
        offset = 0
        for item in ctypes.string_at(start, end - start).split(b"\0"):
            if item.startswith(entry):
                break
            offset += len(item) + 1
        else:
            return False
        if len(item) != len(entry) + len(new):
            return False
        ctypes.memmove(start + offset + len(entry), new, len(new))
        os.environ[TOKEN_VAR] = token
        return ctypes.string_at(start, end - start).split(b"\0").count(entry + new) == 1
    except (OSError, ValueError, IndexError):
        return False


def _wait_for_new_parent(middle: int) -> None:
    """Until the middle process has exited, this process would see it as its
    parent instead of the caller (a child subreaper)."""
    deadline = time.monotonic() + 5.0
    while os.getppid() == middle and time.monotonic() < deadline:
        _real_sleep(0.0002)


_FIXED_FDS = 4
"""A run child's descriptors in every request: its input, its answers, its
stdout and its stderr (two pipes: the parent tells them apart, as a terminal does)."""
_EXTRA_FDS = ("fd_stack", "fd_journal")
"""A run child's optional descriptors after its input, answers, stdout and stderr: the
memory file for its stack dump (turtletui.runtime.stuck) and the fast path's
journal (turtletui.runtime.fastpath)."""


def _fork(request: dict[str, Any], fds: list[int], sock: socket.socket, main: Any) -> int:
    """Fork the run child (handed over to the caller). Its pid, or 0."""
    return _handed_over(lambda middle: _run(request, fds, sock, main, middle))


def _handed_over(body: Callable[[int], None]) -> int:
    """Fork a process that runs ``body(middle)`` through a middle process that
    exits at once, so that it is re-parented to the caller (a subreaper). Its pid, or 0."""
    report_r, report_w = os.pipe()
    middle = os.fork()
    if middle == 0:
        try:
            os.close(report_r)
            me = os.getpid()
            pid = os.fork()
            if pid == 0:
                os.close(report_w)
                body(me)
            os.write(report_w, str(pid).encode())
        finally:
            os._exit(0)
    os.close(report_w)
    with os.fdopen(report_r, "rb") as report:
        answer = report.read()
    os.waitpid(middle, 0)
    return int(answer or 0)


def _run(request: dict[str, Any], fds: list[int], sock: socket.socket, main: Any, middle: int) -> None:
    """In the run child (forked by the process ``middle``): become what
    subprocess would have started, then run."""
    code = 1
    try:
        sock.close()
        os.setsid()
        _prctl(_PR_SET_DUMPABLE, 1)  # an ordinary process again, as if freshly started
        fd_in, fd_out, output, errors, *extra = fds
        devnull = os.open(os.devnull, os.O_RDONLY)
        os.dup2(devnull, 0)
        os.dup2(output, 1)
        os.dup2(errors, 2)
        for fd in (devnull, output, errors):
            if fd > 2:
                os.close(fd)
        if request.get("cwd"):
            os.chdir(request["cwd"])
        config = dict(request["config"], fd_in=fd_in, fd_out=fd_out)
        # the optional descriptors the config names, in _EXTRA_FDS's order, are this process's now
        names = [name for name in _EXTRA_FDS if request["config"].get(name) is not None]
        config.update(zip(names, extra, strict=True))  # (ValueError: not as many: the child exits)
        sys.argv = ["-c", json.dumps(config)]
        # the controller sees the caller as its parent (os.getppid(), a signal
        # to its parent), as a child started by subprocess does
        _wait_for_new_parent(middle)
        main(config)
        code = 0
    except BaseException:  # noqa: BLE001 - nothing may return into the server's loop
        pass
    finally:
        os._exit(code)


# -- the caller's side --------------------------------------------------------------


class ForkedChild:
    """A run child (or a server) forked by a server (a template), seen like a
    subprocess.Popen of it."""

    def __init__(self, pid: int, output_fd: int | None = None, errors_fd: int | None = None) -> None:
        self.pid = pid
        self.returncode: int | None = None
        self.stdout = None if output_fd is None else os.fdopen(output_fd, "rb", buffering=0)
        self.stderr = None if errors_fd is None else os.fdopen(errors_fd, "rb", buffering=0)

    def poll(self) -> int | None:
        if self.returncode is None:
            try:
                pid, status = os.waitpid(self.pid, os.WNOHANG)
            except ChildProcessError:  # reaped elsewhere: its status is lost
                self.returncode = -9
                return self.returncode
            if pid:
                self.returncode = os.waitstatus_to_exitcode(status)
        return self.returncode

    def wait(self, timeout: float | None = None) -> int:
        if self.poll() is None:
            _await_exit(self.pid, timeout)
        deadline = None if timeout is None else time.monotonic() + timeout
        pause = 0.0005
        while self.poll() is None:
            if deadline is not None and time.monotonic() >= deadline:
                raise subprocess.TimeoutExpired(f"sandbox child {self.pid}", timeout or 0.0)
            _real_sleep(pause)
            pause = min(pause * 2, 0.01)
        assert self.returncode is not None
        return self.returncode


def _await_exit(pid: int, timeout: float | None) -> None:
    """Sleep until process ``pid`` has ended or ``timeout`` has passed (Linux's
    pidfd; returns at once where there is none, and the caller polls)."""
    try:
        fd = os.pidfd_open(pid)
    except (AttributeError, OSError):
        return
    try:
        select.select([fd], [], [], timeout)
    except OSError:
        pass
    finally:
        os.close(fd)


class ForkServer:
    """One warm interpreter and the socket to ask it for run children."""

    proc: subprocess.Popen | ForkedChild

    def __init__(
        self, root: str, env: dict[str, str], token: str, credentials: dict[str, Any], distro: str | None = None,
        *, template: bool = False,
    ) -> None:
        self.token = token
        mine, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        try:
            self.proc = subprocess.Popen(
                [
                    sys.executable, "-s", "-c", _SERVER.format(root=root), str(theirs.fileno()), str(os.getpid()),
                    distro or "", *(["template"] if template else []),
                ],
                stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL,
                pass_fds=(theirs.fileno(),),
                start_new_session=True,
                env=env,
                **credentials,
            )
        except BaseException:
            mine.close()
            raise
        finally:
            theirs.close()
        self.sock = mine

    def spawn(self, config: dict[str, Any], cwd: str | None, fds: tuple[int, ...], timeout: float) -> ForkedChild | None:
        """Fork a run child reading ``fds[0]`` and answering on ``fds[1]`` (and
        given the descriptors after them that its config names: _EXTRA_FDS);
        its output comes from the returned child's ``stdout`` and ``stderr``. None if the
        server did not answer with a child of this process within ``timeout``."""
        output_r, output_w = os.pipe()
        errors_r, errors_w = os.pipe()
        try:
            payload = json.dumps({"config": config, "cwd": cwd}).encode()
            self.sock.settimeout(timeout)
            socket.send_fds(self.sock, [payload], [*fds[:2], output_w, errors_w, *fds[2:]])
            answer = self.sock.recv(64)
            pid = int(answer) if answer else 0
        except (OSError, ValueError):
            pid = 0
        finally:
            os.close(output_w)
            os.close(errors_w)
        if pid <= 0 or pid == self.proc.pid or not _is_my_child(pid):
            os.close(output_r)
            os.close(errors_r)
            return None
        os.set_blocking(output_r, False)
        os.set_blocking(errors_r, False)
        return ForkedChild(pid, output_r, errors_r)

    def alive(self) -> bool:
        return self.proc.poll() is None

    def fork_server(self, timeout: float) -> ForkServer | None:
        """A new server forked by this template, with a token of its own; None
        if the template did not answer with a ready child of this process
        within ``timeout`` (the caller then starts one the usual way)."""
        if _state(self.proc.pid) in ("T", "t", "Z", "X", ""):
            return None  # stopped (a run of the last submission?) or gone
        token = os.urandom(len(self.token)).hex()[: len(self.token)]  # as long: see _retoken
        deadline = time.monotonic() + timeout  # for its answer and the server's "ready" both
        mine, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        try:
            self.sock.settimeout(timeout)
            socket.send_fds(self.sock, [json.dumps({"token": token}).encode()], [theirs.fileno()])
            answer = self.sock.recv(64)
            pid = int(answer) if answer else 0
        except (OSError, ValueError):
            pid = 0
        finally:
            theirs.close()
        if pid <= 0 or pid == self.proc.pid or not _is_my_child(pid):
            mine.close()
            return None
        server = ForkServer.__new__(ForkServer)
        server.token, server.sock, server.proc = token, mine, ForkedChild(pid)
        try:
            mine.settimeout(max(deadline - time.monotonic(), 0.001))
            ready = mine.recv(16) == b"ready"
        except OSError:
            ready = False
        if not ready:
            server.close()
            return None
        return server

    def close(self) -> None:
        """Stop the server and whatever it started."""
        self.sock.close()
        kill_tree(self.proc.pid, self.token, reaped=self.proc.poll() is not None)
        try:
            self.proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            pass


def _state(pid: int) -> str:
    """A process's state letter (R, S, T...), "" if there is none."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            return f.read().rpartition(b")")[2].split()[0].decode()
    except (OSError, IndexError, UnicodeDecodeError):
        return ""


def _is_my_child(pid: int) -> bool:
    """Whether ``pid`` is this process's child, running or ended (not reaped:
    a controller that ends at once may have ended already, and its status
    says how)."""
    try:
        os.waitid(os.P_PID, pid, os.WEXITED | os.WNOHANG | os.WNOWAIT)
        return True
    except ChildProcessError:
        return False


class ForkServers:
    """The fork server of the submission a grading worker runs now: a new
    controller file (or user, or distro) gets a new server, forked from the
    worker's template, and the old one is stopped."""

    def __init__(self, *, sole_parent: bool = False) -> None:
        self._sole_parent = sole_parent
        """This process starts no children but its runs' (a grading worker)."""
        self._key: tuple[Any, ...] | None = None
        self._server: ForkServer | None = None
        self._given_up: set[tuple[Any, ...]] = set()
        self._child: ForkedChild | None = None
        self._template: ForkServer | None = None
        self._template_key: tuple[Any, ...] | None = None
        self._no_template: set[tuple[Any, ...]] = set()
        _prctl(_PR_SET_CHILD_SUBREAPER, 1)

    def spawn(
        self, key: tuple[Any, ...], start: Callable[..., ForkServer], config: dict[str, Any], cwd: str | None,
        fds: tuple[int, ...], timeout: float,
    ) -> tuple[ForkedChild, ForkServer] | None:
        """A run child forked by ``key``'s server, and that server; None if the
        run must start the usual way: a run is under way already, or the server
        failed (then for good). ``key`` is the submission (its controller file)
        and then what its server's template is for (user, distro): a server
        is forked from the template (``start(template=True)``, started once),
        or else started afresh (``start()``)."""
        if self._child is not None and self._child.returncode is None:
            return None  # one at a time: a server is stopped when the submission changes
        if key != self._key:
            self.close()
            self._key = key
        if self._server is not None and not self._server.alive():
            self._give_up()
        if key in self._given_up:
            return None
        if self._server is None:
            try:
                self._server = self._from_template(key[1:], start, timeout) or start()
            except OSError:
                self._given_up.add(key)
                return None
        child = self._server.spawn(config, cwd, fds, timeout)
        if child is None:
            self._give_up()
            return None
        self._child = child
        return child, self._server

    def _from_template(
        self, key: tuple[Any, ...], start: Callable[..., ForkServer], timeout: float
    ) -> ForkServer | None:
        if key != self._template_key:
            self._close_template()
            self._template_key = key
        if key in self._no_template:
            return None
        fresh = self._template is None or not self._template.alive()
        if fresh:
            self._close_template()
            try:
                self._template = start(template=True)
            except OSError:
                self._no_template.add(key)
                return None
        assert self._template is not None
        server = self._template.fork_server(timeout)
        if server is None:
            # one a run stopped or killed is started again for the next
            # submission; a new one that fails says templates fail here
            self._close_template()
            if fresh:
                self._no_template.add(key)
        return server

    def _close_template(self) -> None:
        if self._template is not None:
            self._template.close()
            self._template = None

    def end_of_run(self) -> None:
        """Between two runs of a process that starts no children but its runs'
        (a grading worker): kill every child but the template and the server.
        A run's processes all end with it; one that left its session and its
        sandbox's marks (its subreaper off, its token overwritten) was
        inherited here, and could otherwise stop the next submission's runs."""
        if self._sole_parent:
            kill_children({server.proc.pid for server in (self._template, self._server) if server is not None})

    def _give_up(self) -> None:
        assert self._key is not None
        self._given_up.add(self._key)
        if self._server is not None:
            self._server.close()
            self._server = None

    def close(self, *, template: bool = False) -> None:
        """Stop the server and what is left of its runs (and the ``template``)."""
        if self._server is not None:
            self._server.close()
            self._server = None
        self._key = None
        if template:
            self._close_template()
        reap_zombie_children()  # the killed orphans of the submission's runs


_servers: ForkServers | None = None


def _available() -> bool:
    return sys.platform.startswith("linux") and hasattr(socket, "send_fds")


def enable() -> None:
    """Start this process's sandboxed children from fork servers from now on
    (a grading worker: one run at a time, one submission after another). A
    server ends when this process does (end of file on its socket)."""
    global _servers
    if _servers is None and _available():
        _servers = ForkServers(sole_parent=True)


@contextmanager
def serving(*, sole_parent: bool = False) -> Iterator[None]:
    """Fork servers for the runs inside the block (one at a time), all stopped
    at its end; nothing changes if they are in use already. ``sole_parent``
    as for :class:`ForkServers`: this process starts no other children."""
    global _servers
    if _servers is not None or not _available():
        yield
        return
    _servers = ForkServers(sole_parent=sole_parent)
    try:
        yield
    finally:
        _servers.close(template=True)
        _servers = None
        _prctl(_PR_SET_CHILD_SUBREAPER, 0)


def servers() -> ForkServers | None:
    """The fork servers, if in use in this process."""
    return _servers
