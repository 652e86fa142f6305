"""Figures quoted per numeric profile (docsite/host_cpu.py): knife-edge episodes end differently where numpy's SIMD
loops or OpenBLAS's kernels differ, so a page quotes one figure per profile and the checks compare the one of the
profile the command ran on.

Oracles: the profiles' environments (numpy's AVX-512 targets switched off by name, OpenBLAS's kernels named), and
OpenBLAS's own answer read through ctypes; hand-written pages whose figures per profile are written out by hand; the
checks' regular expressions as the ledger writes them.
"""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite.host_cpu import ANY_CPU, CPU, host_cpu, is_keyed, keyed  # noqa: E402
from docsite.ledger_kinds import Printed  # noqa: E402
from docsite.long_checks import check_difference  # noqa: E402
from docsite.printed_numbers import printed_differences  # noqa: E402

PAGE = ("TetheredWing-v0 10 / 12 (the LQR 11 / 12 on znver4 (AVX512), 10 / 12 on znver3 (AVX2); open loop 7 / 12). "
        "The LQR holds it on znver4 and loses it at 42.05 s on znver3.")
CHECK = (rf"TetheredWing-v0 (\d+ / \d+) \(the LQR [^;]*?(\d+ / \d+) on {CPU} \([^)]*\)[^;]*; open loop "
         r"(\d+ / \d+)\)\.")
TEMPLATES = ("{g[ppo]}", "{g[lqr]}", "{g[open]}")
WORDS = ("printed no {}", "prints")


def _openblas_corename() -> str:
    """OpenBLAS's own name of its kernels (``openblas_get_corename`` of scipy's bundled library, through ctypes)."""
    import ctypes
    import glob

    import scipy

    libs = glob.glob(str(Path(scipy.__file__).parent.parent / "scipy.libs" / "*openblas*"))
    if not libs:
        pytest.skip("scipy without its bundled OpenBLAS")
    lib = ctypes.CDLL(libs[0])
    for name in ("scipy_openblas_get_corename", "openblas_get_corename", "scipy_openblas_get_corename64_"):
        if hasattr(lib, name):
            fn = getattr(lib, name)
            fn.restype = ctypes.c_char_p
            return fn().decode()
    pytest.skip("no corename function in scipy's OpenBLAS")


def test_the_profile_is_numpys_simd_level_and_openblas_kernels():
    from docsite.host_cpu import PROFILE_ENV
    from laddermill_gym.model.machine import SAME_KERNELS, blas_kernels
    from laddermill_gym.model.machine import numpy_simd_level as numpy_level

    assert blas_kernels() == SAME_KERNELS.get(_openblas_corename(), _openblas_corename())
    name = host_cpu()
    assert name in ("znver4", "znver3") or name == f"{numpy_level()}/{blas_kernels()}"
    # the AVX2 profile's environment selects it on any x86-64 with AVX2; AVX-512's only where the CPU has it
    env = {**os.environ, **PROFILE_ENV["znver3"]}
    assert host_cpu(env) == "znver3"
    assert host_cpu({**env, "OPENBLAS_CORETYPE": "Zen"}) == "znver3"  # Zen's kernels are Haswell's
    if numpy_level().startswith("AVX512"):
        assert host_cpu({**os.environ, **PROFILE_ENV["znver4"]}) == "znver4"
        # a profile's settings override another's (a shell that selected znver3 first)
        assert host_cpu({**os.environ, **PROFILE_ENV["znver3"], **PROFILE_ENV["znver4"]}) == "znver4"
        assert host_cpu({**os.environ, "OPENBLAS_CORETYPE": "Haswell"}) == f"{numpy_level()}/Haswell"


def test_a_keyed_pattern_takes_the_cpus_name_or_any():
    assert is_keyed(CHECK) and not is_keyed(r"(\d+ / \d+)")
    assert keyed("on " + CPU, "skylake-avx512") == r"on skylake\-avx512"
    assert keyed("on " + CPU, None) == "on " + ANY_CPU
    # with any CPU the check covers both figures of the page (the page coverage's use)
    assert re.search(keyed(CHECK, None), PAGE).group(0).endswith("open loop 7 / 12).")


def test_each_cpu_is_compared_at_its_own_figure():
    znver4 = {"g": {"ppo": "10 / 12", "lqr": "11 / 12", "open": "7 / 12"}}
    znver3 = {"g": {"ppo": "10 / 12", "lqr": "10 / 12", "open": "7 / 12"}}
    assert check_difference("p.md", PAGE, CHECK, TEMPLATES, znver4, WORDS, "znver4") is None
    assert check_difference("p.md", PAGE, CHECK, TEMPLATES, znver3, WORDS, "znver3") is None
    wrong = check_difference("p.md", PAGE, CHECK, TEMPLATES, znver4, WORDS, "znver3")
    assert wrong == ("docs/p.md: 'TetheredWing-v0 10 / 12 (the LQR 11 / 12 on znver4 (AVX512), 10 / 12 on znver3 "
                     "(AVX2); open loop 7 / 12).' quotes ('10 / 12', '10 / 12', '7 / 12'); prints ('10 / 12', "
                     "'11 / 12', '7 / 12')")
    unknown = check_difference("p.md", PAGE, CHECK, TEMPLATES, znver4, WORDS, "znver5")
    assert unknown.startswith("docs/p.md: quotes no figure for this profile (znver5, docsite/host_cpu.py)")


def test_a_printed_snippet_of_one_cpu_is_compared_on_that_cpu_only():
    entries = (Printed("g", ("loses it at 42.05 s on znver3.",), cpu="znver3"),
               Printed("g", ("TetheredWing-v0 10 / 12",)))
    on4 = {"g": {"printed": "ppo_tethered_wing NTM_IB 0 22.95\n10 / 12", "cpu": "znver4"}}
    on3 = {"g": {"printed": "lqr NTM_IB 0 42.05\n10 / 12", "cpu": "znver3"}}
    assert printed_differences("p.md", entries, on4) == []  # znver4 prints no 42.05: not its figure
    assert printed_differences("p.md", entries, on3) == []
    lost = {"g": {"printed": "lqr NTM_IB 0 41.00\n10 / 12", "cpu": "znver3"}}
    assert printed_differences("p.md", entries, lost) == [
        "docs/p.md: g printed none of ['42.05'] in 'loses it at 42.05 s on znver3.'"]


def test_a_check_marked_for_one_cpu_is_compared_on_that_cpu_only():
    """A table of one CPU's chaotic runs (``only_on``): re ignores the mark, the check skips other CPUs."""
    from docsite.host_cpu import check_cpu, only_on

    pattern = only_on("znver3") + r"breaks down at ([\d.]+) s"
    page = "RK4 10 ms breaks down at 24.0 s"
    assert check_cpu(pattern) == "znver3" and check_cpu(CHECK) is None
    assert re.search(pattern, page).group(1) == "24.0"
    znver4 = {"g": {"t": "35.7"}}
    assert check_difference("p.md", page, pattern, ("{g[t]}",), znver4, WORDS, "znver4") is None  # not its table
    wrong = check_difference("p.md", page, pattern, ("{g[t]}",), znver4, WORDS, "znver3")
    assert wrong == "docs/p.md: 'breaks down at 24.0 s' quotes ('24.0',); prints ('35.7',)"


def test_a_profile_the_cpu_cannot_run_is_named_not_a_crash():
    """The AVX-512 profile's settings on a CPU without AVX-512: OpenBLAS's SkylakeX kernels die of SIGILL in the
    fresh process; host_cpu names the settings and the cause, selects says no. Where the CPU has AVX-512 both quoted
    profiles are selected."""
    import llvmlite.binding as ll

    from docsite.host_cpu import PROFILE_ENV, selects

    assert selects("znver3")  # any x86-64 with AVX2
    if ll.get_host_cpu_features().get("avx512f"):
        assert selects("znver4")
        return
    assert not selects("znver4")
    with pytest.raises(RuntimeError, match=r"'OPENBLAS_CORETYPE': 'SkylakeX'.*died of SIGILL: this CPU lacks"):
        host_cpu({**os.environ, **PROFILE_ENV["znver4"]})


def test_a_machine_of_an_unquoted_profile_measures_under_a_quoted_one():
    """A process whose OpenBLAS runs its Nehalem kernels (a profile no page quotes) is told to run the pages'
    commands under the first quoted profile the CPU selects, and a fresh process under those settings is of that
    profile (oracle: the profile it reports); under a quoted profile nothing is added."""
    import json
    import subprocess

    from docsite.host_cpu import PROFILE_ENV, PROFILES

    code = "import json; from docsite.host_cpu import quoted_profile; print(json.dumps(quoted_profile()))"

    def asked(env):
        out = subprocess.run([sys.executable, "-c", code], env=env, cwd=ROOT, capture_output=True, text=True,
                             check=True)
        return json.loads(out.stdout)

    unquoted = {**os.environ, "OPENBLAS_CORETYPE": "Nehalem"}
    assert host_cpu(unquoted).endswith("/Nehalem")
    name, settings = asked(unquoted)
    assert name in PROFILES and settings == PROFILE_ENV[name]
    assert host_cpu({**unquoted, **settings}) == name
    assert asked({**os.environ, **PROFILE_ENV["znver3"]}) == ["znver3", {}]


def test_a_long_groups_own_settings_win_over_the_profiles():
    """A long group's command that names a kernel setting itself keeps it (the machine_bits study's runs)."""
    from docsite.long_figures import argv_env

    argv, env = argv_env("OPENBLAS_CORETYPE=Zen python -m laddermill_gym.cli bench",
                         {"OPENBLAS_CORETYPE": "Haswell", "NPY_DISABLE_CPU_FEATURES": "AVX512_ICL"})
    assert argv == ["laddermill_gym.cli", "bench"]
    assert env["OPENBLAS_CORETYPE"] == "Zen" and env["NPY_DISABLE_CPU_FEATURES"] == "AVX512_ICL"
