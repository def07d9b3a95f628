"""What the container (or cgroup) this process runs in allows: its memory and
its CPUs, so that grading fits in it.

Grading platforms run each submission in a container with a memory limit
(Gradescope's default is 768 MB) and a CPU quota. A sandboxed run that may use
more memory than the container has gets the whole container killed by the
kernel (no results at all) instead of a clean "ran out of its memory limit"
for that run; runs side by side beyond the CPU quota only wait for each other.

Read from cgroup v2 (``memory.max``, ``memory.current``, ``cpu.max``) along the
process's cgroup and its parents, with the cgroup v1 files as a fallback
(``memory.limit_in_bytes``, ``memory.usage_in_bytes``, ``cpu.cfs_quota_us``
and ``cpu.cfs_period_us``).
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path

CGROUP_ROOT = Path("/sys/fs/cgroup")
UNLIMITED = 1 << 60
"""cgroup v1 reports "no limit" as a huge number (PAGE_COUNTER_MAX pages)."""
GRADER_RESERVE = 160 * 1024**2
"""Bytes kept for each grading worker (its Python, numpy, the simulation)."""
MIN_RUN_MEMORY = 192 * 1024**2
"""Less than this per run cannot start a controller that imports numpy."""


@dataclass(frozen=True)
class ContainerLimits:
    """What the cgroup allows; None where it sets no limit."""

    memory_bytes: int | None = None
    memory_used: int | None = None
    cpus: float | None = None


def _read(path: Path) -> str | None:
    try:
        return path.read_text(encoding="ascii").strip()
    except (OSError, UnicodeDecodeError):
        return None


def _number(text: str | None) -> int | None:
    if text is None or text == "max":
        return None
    try:
        value = int(text)
    except ValueError:
        return None
    return None if value <= 0 or value >= UNLIMITED else value


def _cgroup_paths(proc_self: Path) -> dict[str, str]:
    """Controller (``""`` for cgroup v2) -> this process's cgroup path."""
    paths: dict[str, str] = {}
    text = _read(proc_self / "cgroup") or ""
    for line in text.splitlines():
        parts = line.split(":", 2)
        if len(parts) != 3:
            continue
        _, controllers, path = parts
        if not controllers:
            paths[""] = path
        for controller in controllers.split(","):
            paths.setdefault(controller, path)
    return paths


def _folders(base: Path, path: str) -> list[Path]:
    """``base``/``path`` and each parent up to ``base``: a parent's limit applies too."""
    folders = []
    relative = Path(path.lstrip("/"))
    while True:
        folder = base / relative
        if folder.is_dir():
            folders.append(folder)
        if relative == Path("."):
            break
        relative = relative.parent
    return folders


def read_limits(root: Path = CGROUP_ROOT, proc_self: Path = Path("/proc/self")) -> ContainerLimits:
    """The memory and CPU limits of this process's cgroup (the tightest along
    its parents) and the memory it uses now."""
    paths = _cgroup_paths(proc_self)
    memory: list[int] = []
    used: int | None = None
    cpus: list[float] = []
    if "" in paths or (root / "cgroup.controllers").exists():
        for folder in _folders(root, paths.get("", "/")):
            limit = _number(_read(folder / "memory.max"))
            if limit is not None:
                memory.append(limit)
            if used is None:
                used = _number(_read(folder / "memory.current"))
            quota = (_read(folder / "cpu.max") or "").split()
            if len(quota) == 2 and _number(quota[0]) and _number(quota[1]):
                cpus.append(int(quota[0]) / int(quota[1]))
    if not memory:
        base = root / "memory" if (root / "memory").is_dir() else root
        for folder in _folders(base, paths.get("memory", "/")):
            limit = _number(_read(folder / "memory.limit_in_bytes"))
            if limit is not None:
                memory.append(limit)
            if used is None:
                used = _number(_read(folder / "memory.usage_in_bytes"))
    if not cpus:
        for name in ("cpu,cpuacct", "cpu"):
            base = root / name
            if base.is_dir():
                for folder in _folders(base, paths.get("cpu", "/")):
                    quota = _number(_read(folder / "cpu.cfs_quota_us"))
                    period = _number(_read(folder / "cpu.cfs_period_us"))
                    if quota and period:
                        cpus.append(quota / period)
                break
    return ContainerLimits(min(memory) if memory else None, used, min(cpus) if cpus else None)


def available_cpus() -> int:
    """CPUs this process may use: its affinity, within the cgroup's quota."""
    try:
        count = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        count = os.cpu_count() or 1
    quota = read_limits().cpus
    if quota is not None:
        count = min(count, max(1, math.ceil(quota)))
    return count


def run_memory(jobs: int, wanted: int, limits: ContainerLimits | None = None) -> int:
    """Bytes each of ``jobs`` runs side by side may use: ``wanted``, or less so
    that the runs, their graders and what is used already fit in the container."""
    limits = read_limits() if limits is None else limits
    if limits.memory_bytes is None:
        return wanted
    free = limits.memory_bytes - (limits.memory_used or 0) - jobs * GRADER_RESERVE
    return max(MIN_RUN_MEMORY, min(wanted, free // max(1, jobs)))


def fitting_jobs(jobs: int, limits: ContainerLimits | None = None) -> int:
    """At most ``jobs`` runs side by side, fewer when the container's memory
    would leave each less than :data:`MIN_RUN_MEMORY`."""
    limits = read_limits() if limits is None else limits
    if limits.memory_bytes is None:
        return jobs
    free = limits.memory_bytes - (limits.memory_used or 0)
    return max(1, min(jobs, free // (GRADER_RESERVE + MIN_RUN_MEMORY)))
