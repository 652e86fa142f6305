"""The machine-bits study's settings (``studies/numerics/machine_bits.py``) and the profile it prints
(``model/machine.py``). Oracles: LLVM's own feature list of the host; numpy's table of the SIMD extensions it found;
the AVX2 profile's environment, under which numpy must dispatch nothing above AVX2 (OpenBLAS's own kernel name is
read through ctypes in tests/test_host_cpu_figures.py)."""

from __future__ import annotations

import os
import subprocess
import sys

import llvmlite.binding as ll
import pytest

from laddermill_gym.model.machine import KERNEL_ENV, numpy_simd_level
from laddermill_gym.studies.numerics import machine_bits


def test_the_avx2_target_switches_off_every_avx512_extension_and_keeps_the_rest():
    host = ll.get_host_cpu_features()
    got = dict((f[1:], f[0] == "+") for f in machine_bits.avx2_features().split(","))
    assert set(got) == set(host)
    assert not any(on for name, on in got.items() if name.startswith("avx512"))
    assert all(got[name] == on for name, on in host.items() if not name.startswith("avx512"))


def test_each_variant_changes_one_thing_from_the_reference():
    table = machine_bits.variants()
    ref = table["reference"]
    assert ref == {"OPENBLAS_CORETYPE": "Haswell"}
    for name, changes in table.items():
        if changes is None or name == "reference":
            continue
        differ = {k for k in set(changes) | set(ref) if changes.get(k) != ref.get(k)}
        assert differ in ({"NUMBA_CPU_NAME", "NUMBA_CPU_FEATURES"}, {"NUMBA_CPU_NAME"}, {"NPY_DISABLE_CPU_FEATURES"},
                          {"OPENBLAS_CORETYPE"}), (name, differ)
    assert (table["OpenBLAS SkylakeX"] is None) == (not ll.get_host_cpu_features().get("avx512f"))


def test_numpys_level_is_the_best_extension_it_found():
    try:
        from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    except ImportError:  # numpy 1.x
        from numpy.core._multiarray_umath import __cpu_dispatch__, __cpu_features__

    found = [t for t in __cpu_dispatch__ if __cpu_features__[t]]
    assert numpy_simd_level() == (found[-1] if found else "baseline")
    env = {**os.environ, **KERNEL_ENV[("X86_V3", "Haswell")]}
    code = "from laddermill_gym.model.machine import numpy_simd_level; print(numpy_simd_level())"
    level = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert level.stdout.strip() in ("X86_V3", "baseline")


def test_a_variant_this_cpu_cannot_run_is_refused_by_name(capsys):
    with pytest.raises(SystemExit):
        machine_bits.main(["--variants", "numba AVX-1024"])
    assert "numba AVX-1024" in capsys.readouterr().err
