"""Figures that depend on the CPU numba compiles the simulator for.

numba compiles the kernels for the host's CPU (LLVM's name for it: ``znver4`` for an AMD EPYC with AVX-512,
``znver3`` for one with AVX2), so the last bits of a step differ between CPU kinds, and a knife-edge episode (a
turbulent gust-bench episode that ends or survives by a hair) can end differently. A page quotes such a figure
once per CPU, each followed by ``on NAME``, and the ledger's check carries :data:`CPU` where the name goes: the
check compares only the figure of the CPU its command ran on (recorded with each group's figures as ``"cpu"``),
and a page that quotes no figure for that CPU fails it, naming the CPU. Figures of the other kinds stay on the
page, checked when the tier runs there.
"""

from __future__ import annotations

import os
import re

#: The place of the CPU's name in a ledger check's regular expression (``rf"the LQR (\\d+ / \\d+) on {CPU}"``).
CPU = "<host-cpu>"
#: What :data:`CPU` matches when a check is not compared (the page coverage): any LLVM CPU name.
ANY_CPU = r"[a-z][\w-]*"


def host_cpu(env: dict | None = None) -> str:
    """The CPU name numba compiles for in a process with environment ``env`` (default: this one's):
    ``NUMBA_CPU_NAME`` when set, else LLVM's name of the host CPU."""
    name = (os.environ if env is None else env).get("NUMBA_CPU_NAME", "")
    if name:
        return name
    import llvmlite.binding as llvm

    return llvm.get_host_cpu_name()


def keyed(pattern: str, cpu: str | None) -> str:
    """``pattern`` with :data:`CPU` replaced by ``cpu``'s name (escaped), or by :data:`ANY_CPU` when ``cpu`` is
    None; a pattern without it is returned as it is."""
    return pattern.replace(CPU, ANY_CPU if cpu is None else re.escape(cpu))


def is_keyed(pattern: str) -> bool:
    """Whether a check's pattern quotes a figure per CPU."""
    return CPU in pattern


def only_on(cpu: str) -> str:
    """A regular-expression comment that marks a check as one CPU's (prefix it to the pattern; ``re`` ignores it):
    for a table of that CPU's chaotic runs, whose other CPUs' figures the page gives beside it."""
    return f"(?#cpu={cpu})"


def check_cpu(pattern: str) -> str | None:
    """The CPU a pattern marked by :func:`only_on` belongs to; None for a check of every CPU."""
    m = re.match(r"\(\?#cpu=([\w-]+)\)", pattern)
    return m.group(1) if m else None
