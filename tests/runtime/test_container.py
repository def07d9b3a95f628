"""Container limits (turtletui.runtime.container) from a fake cgroup tree."""

from __future__ import annotations

from pathlib import Path

from turtletui.runtime.container import (
    MIN_RUN_MEMORY,
    ContainerLimits,
    fitting_jobs,
    read_limits,
    run_memory,
)

MB = 1024**2


def fake_cgroup(tmp_path: Path, files: dict[str, str], proc: str) -> tuple[Path, Path]:
    root = tmp_path / "cgroup"
    for name, text in files.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text)
    self_dir = tmp_path / "self"
    self_dir.mkdir()
    (self_dir / "cgroup").write_text(proc)
    return root, self_dir


def test_cgroup_v2_memory_max_and_cpu_max_along_the_parents(tmp_path: Path):
    root, proc = fake_cgroup(
        tmp_path,
        {
            "cgroup.controllers": "cpu memory",
            "job/memory.max": str(768 * 1000 * 1000),
            "job/cpu.max": "max 100000",
            "job/grader/memory.max": "max",
            "job/grader/memory.current": str(100 * MB),
            "job/grader/cpu.max": "150000 100000",
        },
        "0::/job/grader\n",
    )
    limits = read_limits(root, proc)
    assert limits == ContainerLimits(768 * 1000 * 1000, 100 * MB, 1.5)


def test_cgroup_v1_fallback(tmp_path: Path):
    root, proc = fake_cgroup(
        tmp_path,
        {
            "memory/docker/abc/memory.limit_in_bytes": str(512 * MB),
            "memory/docker/abc/memory.usage_in_bytes": str(50 * MB),
            "cpu,cpuacct/docker/abc/cpu.cfs_quota_us": "-1",
            "cpu,cpuacct/docker/abc/cpu.cfs_period_us": "100000",
            "memory/memory.limit_in_bytes": str(2**63 - 4096),  # the host: no limit
        },
        "5:memory:/docker/abc\n4:cpu,cpuacct:/docker/abc\n",
    )
    assert read_limits(root, proc) == ContainerLimits(512 * MB, 50 * MB, None)


def test_runs_fit_gradescopes_default_container():
    gradescope = ContainerLimits(memory_bytes=768 * 1000 * 1000, memory_used=120 * MB)
    per_run = run_memory(2, 2 * 1024**3, gradescope)
    assert MIN_RUN_MEMORY <= per_run < 300 * MB  # no longer 2 GiB in a 732 MiB container
    assert 2 * per_run + 120 * MB < gradescope.memory_bytes
    assert fitting_jobs(8, gradescope) == 1  # more runs would not leave each enough
    assert run_memory(2, 2 * 1024**3, ContainerLimits()) == 2 * 1024**3  # no container: as before
