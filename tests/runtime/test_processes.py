"""Killing a sandbox's processes: nothing is left stopped, even when the
killing is interrupted (the grader stopping a worker mid-way)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys

import pytest

from turtletui.runtime import processes


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")
def test_an_interrupted_kill_still_kills_what_it_stopped(monkeypatch):
    child = subprocess.Popen([sys.executable, "-c", "import time\nwhile True: time.sleep(0.1)"], start_new_session=True)
    try:
        def interrupted(root, marker, since=None):
            raise KeyboardInterrupt  # while its descendants are looked for, the child frozen

        monkeypatch.setattr(processes, "_sandboxed", interrupted)
        with pytest.raises(KeyboardInterrupt):
            processes.kill_tree(child.pid, "token")
        assert child.wait(timeout=30) == -signal.SIGKILL
    finally:
        if child.poll() is None:
            os.kill(child.pid, signal.SIGKILL)
            child.wait()


_CHILDREN_SCRIPT = """
import os, subprocess, sys, time, threading
from turtletui.runtime import processes

def exited(pid):
    try:
        return os.waitid(os.P_PID, pid, os.WEXITED | os.WNOHANG | os.WNOWAIT) is not None
    except ChildProcessError:
        return None  # reaped

def gone(pid):
    deadline = time.monotonic() + 30
    while exited(pid) is False and time.monotonic() < deadline:
        time.sleep(0.01)
    return exited(pid) is not False

sleeper = [sys.executable, "-c", "import time; time.sleep(60)"]
kept = subprocess.Popen(sleeper)
doomed = subprocess.Popen(sleeper)
from_thread = []
thread = threading.Thread(target=lambda: from_thread.append(subprocess.Popen(sleeper)))
thread.start(); thread.join()
dead = subprocess.Popen([sys.executable, "-c", "pass"])
while exited(dead.pid) is False:
    time.sleep(0.01)
processes.reap_zombie_children()
print("dead reaped:", exited(dead.pid) is None)
print("kept running:", exited(kept.pid) is False)
processes.kill_children({kept.pid})  # and reaps them: their Popen objects learn nothing
print("doomed killed:", gone(doomed.pid))
print("thread's child killed:", gone(from_thread[0].pid))
print("kept still running:", exited(kept.pid) is False)
kept.kill(); kept.wait()
"""


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")
def test_own_children_are_reaped_and_killed_but_those_kept(tmp_path):
    # In a process of its own: kill_children kills every child of its caller.
    script = tmp_path / "children.py"
    script.write_text(_CHILDREN_SCRIPT)
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == [
        "dead reaped: True",
        "kept running: True",
        "doomed killed: True",
        "thread's child killed: True",
        "kept still running: True",
    ]
