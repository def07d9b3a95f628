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
        def interrupted(root, marker):
            raise KeyboardInterrupt  # while its descendants are looked for, the child frozen

        monkeypatch.setattr(processes, "_sandboxed", interrupted)
        with pytest.raises(KeyboardInterrupt):
            processes.kill_tree(child.pid, "token")
        assert child.wait(timeout=30) == -signal.SIGKILL
    finally:
        if child.poll() is None:
            os.kill(child.pid, signal.SIGKILL)
            child.wait()
