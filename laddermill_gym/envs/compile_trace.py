"""When each kernel warm-up process compiles what (issue 32 point 1): the start-up profile's timeline of the
processes a cold start runs side by side (``python -m laddermill_gym.studies.benchmarks.startup --profile``).

With :data:`VARIABLE` naming a folder, ``envs/warmup_run.py`` calls :func:`record` before its target: numba's
``numba:compile`` events (numba's event API) give the start and end (seconds since the epoch, so that processes can
be put on one clock) of each function compiled at the top level, i.e. not as a callee inside another's compile (a
top-level compile includes its callees'); at exit the process writes them as one JSON file, ``<pid>.json``, with
its target's name. :func:`read` collects the files. Nothing is recorded when the variable is unset; a process that
is stopped before its exit writes nothing."""

from __future__ import annotations

import atexit
import json
import os
import time
from pathlib import Path

__all__ = ["VARIABLE", "read", "record"]

#: the environment variable naming the folder the warm-up processes write their compile timelines to
VARIABLE = "LADDERMILL_COMPILE_TRACE"


def record(directory: str, label: str) -> list[dict]:
    """Record this process's top-level compiles from now on and write them to ``directory/<pid>.json`` at exit
    ({"label": ``label``, "pid", "rows": [{"name", "start", "end"}]}, times in seconds since the epoch). Returns the
    list the rows go to (filled as the compiles end)."""
    from numba.core import event

    rows: list[dict] = []
    depth = [0]

    class TopLevel(event.Listener):
        def on_start(self, ev):
            if depth[0] == 0:
                f = ev.data["dispatcher"].py_func
                rows.append({"name": f"{f.__module__}.{f.__qualname__}", "start": time.time()})
            depth[0] += 1

        def on_end(self, ev):
            depth[0] -= 1
            if depth[0] == 0:
                rows[-1]["end"] = time.time()

    event.register("numba:compile", TopLevel())

    def write():
        path = Path(directory) / f"{os.getpid()}.json"
        done = [r for r in rows if "end" in r]
        path.write_text(json.dumps({"label": label, "pid": os.getpid(), "rows": done}))

    atexit.register(write)
    return rows


def read(directory: str) -> list[dict]:
    """The timelines :func:`record` wrote to ``directory``, in the order of their first compile (an unreadable
    file is left out)."""
    out = []
    for path in sorted(Path(directory).glob("*.json")):
        try:
            out.append(json.loads(path.read_text()))
        except (OSError, ValueError):
            continue
    return sorted(out, key=lambda t: min((r["start"] for r in t["rows"]), default=float("inf")))
