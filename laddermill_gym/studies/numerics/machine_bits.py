"""Which machine differences move a run's last bits: ``python -m laddermill_gym.studies.numerics.machine_bits``.

One knife-edge episode (default: gusts-v1's NTM_IB scenario on TetheredWing-v0 under the LQR, seeds 0-2, through
``laddermill gust-bench``) is flown in fresh processes that differ from a reference in one thing each. The
reference: numba compiles for the host CPU, numpy runs its best SIMD loops, OpenBLAS its Haswell kernels
(``OPENBLAS_CORETYPE=Haswell``, set in every process but one so that the table does not depend on which kernels
OpenBLAS would pick here). The others:

* ``numba AVX2``: numba compiles the simulator for an AVX2 CPU (``NUMBA_CPU_NAME=haswell`` and the host's features
  without AVX-512: ``NUMBA_CPU_FEATURES``);
* ``numba generic``: numba compiles for LLVM's generic x86-64 (``NUMBA_CPU_NAME=generic``: no fused multiply-add,
  so the kernels' ``contract`` flag fuses nothing);
* ``numpy AVX2``: numpy's SIMD loops above AVX2 switched off (``NPY_DISABLE_CPU_FEATURES``);
* ``OpenBLAS SkylakeX``: OpenBLAS's AVX-512 kernels (only on a CPU with AVX-512).

Each process has its own empty numba cache, no start cache (``LADDERMILL_CACHE_DIR=off``) and none of the variables
above but its own, so nothing computed under one setting is read under another, and prints its profile
(``model/machine.py``). A setting that changes the episodes' outcome or their largest lateral excursion moves the bits;
one that leaves every figure as it was does not (for these episodes). Each process compiles from scratch: about 1.5-3
minutes each on two cores.
"""

from __future__ import annotations

import argparse
import csv
import os
import subprocess
import sys
import tempfile
from pathlib import Path

from tqdm import tqdm

from laddermill_gym.model.machine import ABOVE_AVX2, KERNEL_VARIABLES

#: what a process of the study prints first: the CPU numba compiles for, numpy's SIMD level, OpenBLAS's kernels
PROFILE_CODE = ("from laddermill_gym.model.machine import kernel_profile; import numba.core.config as c; "
                "print(c.CPU_NAME or 'host', *kernel_profile())")


def avx2_features() -> str:
    """The host's LLVM feature string with every AVX-512 extension switched off (``NUMBA_CPU_FEATURES``)."""
    import llvmlite.binding as ll

    feats = ll.get_host_cpu_features()
    return ",".join(("+" if on and not name.startswith("avx512") else "-") + name for name, on in sorted(feats.items()))


def variants() -> dict[str, dict | None]:
    """{name: environment changes} of the study's processes (None where this CPU cannot run the variant)."""
    import llvmlite.binding as ll

    avx512 = bool(ll.get_host_cpu_features().get("avx512f"))
    base = {"OPENBLAS_CORETYPE": "Haswell"}
    return {"reference": base,
            "numba AVX2": {**base, "NUMBA_CPU_NAME": "haswell", "NUMBA_CPU_FEATURES": avx2_features()},
            "numba generic": {**base, "NUMBA_CPU_NAME": "generic"},
            "numpy AVX2": {**base, "NPY_DISABLE_CPU_FEATURES": ABOVE_AVX2},
            "OpenBLAS SkylakeX": {"OPENBLAS_CORETYPE": "SkylakeX"} if avx512 else None}


def run_variant(changes: dict, env_id: str, scenario: str, controller: str, suite: str, work: Path) -> dict:
    """Fly the scenario in fresh processes with ``changes``: {"profile": (numba target, numpy level, OpenBLAS
    kernels), "rows": [(seed, outcome text)]}."""
    keep = {k: v for k, v in os.environ.items() if k not in KERNEL_VARIABLES + ("NUMBA_CPU_NAME", "NUMBA_CPU_FEATURES")}
    env = {**keep, **changes, "NUMBA_CACHE_DIR": str(work / "numba"), "LADDERMILL_CACHE_DIR": "off"}
    prof = subprocess.run([sys.executable, "-c", PROFILE_CODE], env=env, capture_output=True, text=True, check=True)
    out = work / "bench"
    proc = subprocess.run([sys.executable, "-m", "laddermill_gym.studies.gusts.gust_bench", "--suite", suite,
                           "--env", env_id, "--controllers", controller, "--scenarios", scenario, "--out", str(out)],
                          env=env, capture_output=True, text=True)
    if proc.returncode != 0 or not (out / "gust_bench.csv").exists():
        raise RuntimeError(f"gust-bench under {changes} exited with {proc.returncode}: {proc.stderr[-2000:]}")
    rows = []
    with open(out / "gust_bench.csv") as f:
        for r in csv.DictReader(f):
            if r["survived"] == "True":
                rows.append((int(r["seed"]), f"survives, {float(r['max_lateral_m']):.2f} m"))
            else:
                rows.append((int(r["seed"]), f"lost at {float(r['t_end_s']):.2f} s"))
    return {"profile": tuple(prof.stdout.split()), "rows": sorted(rows)}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.numerics.machine_bits",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default="laddermill_gym/TetheredWing-v0", help="environment id")
    p.add_argument("--scenario", default="NTM_IB", help="scenario of the suite")
    p.add_argument("--controller", default="lqr", help="controller (as gust-bench takes it)")
    p.add_argument("--suite", default="gusts-v1", help="gust suite")
    p.add_argument("--variants", nargs="*", help="names of the variants to run (default: all this CPU can)")
    args = p.parse_args(argv)
    table = variants()
    names = args.variants or [n for n, c in table.items() if c is not None]
    unknown = [n for n in names if n not in table or table[n] is None]
    if unknown:
        p.error(f"--variants {unknown}: not one this CPU can run; choose from "
                f"{[n for n, c in table.items() if c is not None]}")
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for i, name in enumerate(tqdm(names, desc="machine bits", unit="process")):
            work = Path(tmp) / str(i)
            work.mkdir()
            results[name] = run_variant(table[name], args.env, args.scenario, args.controller, args.suite, work)
    print(f"{args.env}, {args.suite} {args.scenario}, {args.controller}:")
    print(f"{'variant':<18} {'numba target':<13} {'numpy SIMD':<11} {'OpenBLAS':<9} outcome per seed")
    for name, res in results.items():
        target, level, kernels = (res["profile"] + ("?", "?", "?"))[:3]
        seeds = "; ".join(f"seed {s}: {text}" for s, text in res["rows"])
        print(f"{name:<18} {target:<13} {level:<11} {kernels:<9} {seeds}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
