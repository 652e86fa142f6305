"""Figures that depend on the machine: the numeric profile a run's last bits come from.

A knife-edge episode (a turbulent gust-bench episode that ends or survives by a hair) can end differently on
another machine: not through the code numba generates, but through the kernels numpy and OpenBLAS choose by the
CPU when they load (``laddermill_gym/model/machine.py``: numpy's SIMD level, OpenBLAS's kernels).

A *profile* is that pair. The pages name a profile by the LLVM CPU name of the machine it was first measured on
(:data:`PROFILES`): ``znver4`` (an AMD EPYC with AVX-512 whose OpenBLAS chose SkylakeX kernels; 2026-11-30 and
2026-12-02 before 07:00) and ``znver3`` (an AMD EPYC with AVX2; 2026-12-01); any other profile is named by its
parts, e.g. ``AVX512_ICL/Haswell`` (the ``znver5`` EPYC of 2026-12-02 07:00, whose environment sets
``OPENBLAS_CORETYPE=Haswell``). A page quotes such a figure once per profile, each followed by ``on NAME``, and
the ledger's check carries :data:`CPU` where the name goes: the check compares only the figure of the profile its
command ran on (recorded with each group's figures as ``"cpu"``), and a page that quotes no figure for that profile
fails it, naming it. A machine with AVX-512 runs either profile: ``python -m docsite.host_cpu --env znver3`` prints the
environment that selects its kernels; ``eval "export $(python -m docsite.host_cpu --env znver3)"`` sets it before Python
starts (numpy and OpenBLAS read it once, at load). On a machine whose own profile no page quotes,
``python -m docsite.readme_figures`` and the long tier (``docsite/long_figures.py``, the slow set's
``tests/test_long_tier.py``) run their commands under a quoted profile it can select (:func:`quoted_profile`) and
say so.
"""

from __future__ import annotations

import argparse
import functools
import os
import re
import shlex

from laddermill_gym.model.machine import KERNEL_ENV, KERNEL_VARIABLES, kernel_profile

#: The place of the profile's name in a ledger check's regular expression (``rf"the LQR (\\d+ / \\d+) on {CPU}"``).
CPU = "<host-cpu>"
#: What :data:`CPU` matches when a check is not compared (the page coverage): any profile name.
ANY_CPU = r"[A-Za-z][\w/-]*"

#: the profiles the pages quote, by their names there: (numpy's SIMD level, OpenBLAS's kernel class)
PROFILES = {"znver4": ("AVX512_ICL", "SkylakeX"), "znver3": ("X86_V3", "Haswell")}
#: the environment that selects a profile's kernels on a machine with AVX-512
PROFILE_ENV = {name: KERNEL_ENV[profile] for name, profile in PROFILES.items()}


def host_cpu(env: dict | None = None) -> str:
    """The name of the numeric profile of a process with environment ``env`` (default: this process, as numpy
    and OpenBLAS loaded here): a :data:`PROFILES` name, else ``LEVEL/KERNELS``. With ``env``, measured in a fresh
    Python of that environment (numpy and OpenBLAS choose at load); RuntimeError when that process fails (a CPU
    without the instructions of the kernels ``env`` names dies of SIGILL), naming the settings and the cause."""
    if env is not None:
        import subprocess
        import sys

        out = subprocess.run([sys.executable, "-m", "docsite.host_cpu"], env=env, capture_output=True, text=True,
                             cwd=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        if out.returncode != 0:
            import signal

            why = (f"died of {signal.Signals(-out.returncode).name}" if out.returncode < 0
                   else f"exited with {out.returncode}: {out.stderr.strip()[-300:]}")
            if out.returncode == -signal.SIGILL:
                why += ": this CPU lacks the instructions of the kernels those settings name"
            settings = {k: env.get(k) for k in KERNEL_VARIABLES if k in env}
            raise RuntimeError(f"python -m docsite.host_cpu with {settings} {why}")
        return out.stdout.strip()
    profile = kernel_profile()
    return next((name for name, p in PROFILES.items() if p == profile), "/".join(profile))


def selects(name: str) -> bool:
    """Whether :data:`PROFILE_ENV`'s settings of profile ``name`` select it on this machine (a fresh Python
    under them reports ``name``; on a CPU without AVX-512, ``znver4``'s die of SIGILL: False)."""
    try:
        return host_cpu({**os.environ, **PROFILE_ENV[name]}) == name
    except RuntimeError:
        return False


@functools.lru_cache(maxsize=1)
def quoted_profile() -> tuple[str, dict]:
    """(the profile the pages' commands are to run under, the settings to add to their environment for it): this
    machine's own with ``{}`` when the pages quote it (:data:`PROFILES`), else the first quoted profile this
    machine can select (:func:`selects`: ``znver4`` on a CPU with AVX-512, ``znver3`` on any with AVX2) with its
    :data:`PROFILE_ENV` settings, so that a knife-edge figure is compared with the page's figure of that profile,
    not failed for want of one; this machine's own with ``{}`` when none can be selected (its keyed checks then
    fail, naming the profile). Measured once per process (each try starts a fresh Python, about a second)."""
    here = host_cpu()
    if here in PROFILES:
        return here, {}
    name = next((n for n in PROFILES if selects(n)), None)
    return (here, {}) if name is None else (name, dict(PROFILE_ENV[name]))


def keyed(pattern: str, cpu: str | None) -> str:
    """``pattern`` with :data:`CPU` replaced by ``cpu``'s name (escaped), or by :data:`ANY_CPU` when ``cpu`` is
    None; a pattern without it is returned as it is."""
    return pattern.replace(CPU, ANY_CPU if cpu is None else re.escape(cpu))


def is_keyed(pattern: str) -> bool:
    """Whether a check's pattern quotes a figure per profile."""
    return CPU in pattern


def only_on(cpu: str) -> str:
    """A regular-expression comment that marks a check as one profile's (prefix it to the pattern; ``re`` ignores
    it): for a table of that profile's chaotic runs, whose other profiles' figures the page gives beside it."""
    return f"(?#cpu={cpu})"


def check_cpu(pattern: str) -> str | None:
    """The profile a pattern marked by :func:`only_on` belongs to; None for a check of every profile."""
    m = re.match(r"\(\?#cpu=([\w/-]+)\)", pattern)
    return m.group(1) if m else None


def main(argv=None) -> None:
    p = argparse.ArgumentParser(prog="python -m docsite.host_cpu",
                                description="Print this process's numeric profile, or (--env) the environment "
                                            "that selects a profile's kernels on a machine with AVX-512.")
    p.add_argument("--env", choices=sorted(PROFILE_ENV), help="print NAME=VALUE for this profile")
    args = p.parse_args(argv)
    if args.env:
        print(" ".join(f"{k}={shlex.quote(v)}" for k, v in PROFILE_ENV[args.env].items()))
    else:
        print(host_cpu())


if __name__ == "__main__":
    main()
