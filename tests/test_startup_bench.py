"""``laddermill bench --startup`` (issue 32 point 1): its quick path times a warm start of TetheredWing-v0 in a
fresh process. The oracle is independent of the timing code: this process fills the numba cache first by making
and stepping the env itself, so a correct warm start in the child compiles nothing (numba's own compile events,
counted in the child) and reads the cache this process names."""

import gymnasium
import numpy as np
import pytest

import laddermill_gym  # noqa: F401
from laddermill_gym.cli import main as cli_main
from laddermill_gym.studies.benchmarks import startup

ENV = "laddermill_gym/TetheredWing-v0"


def _fill_cache():
    env = gymnasium.make(ENV)
    env.reset(seed=0)
    env.step(np.zeros(env.action_space.shape, dtype=env.action_space.dtype))
    env.close()


def test_quick_startup_is_warm_and_compiles_nothing(capsys):
    _fill_cache()
    res = startup.run_startup(quick=True, envs=[ENV])
    warm = res[ENV]["warm"]
    assert warm["compiled"] == 0, warm
    from numba.core.config import CACHE_DIR

    assert warm["cache_dir"] == CACHE_DIR
    # the launch-to-step clock holds the interpreter's start beside what the child timed itself, and the process
    # outlives its step (its output is printed after it)
    assert 0.0 < warm["inside_s"] < warm["first_step_s"] < warm["wall_s"] < 60.0
    out = capsys.readouterr().out
    assert f"== start-up {ENV}" in out and "warm (caches filled)" in out and "cold" not in out.split("==")[1]


def test_cli_quick_startup_runs(capsys, monkeypatch):
    _fill_cache()
    monkeypatch.setattr(startup, "QUICK_ENVS", (ENV,))
    assert cli_main(["bench", "--startup", "--quick"]) == 0
    assert "0 functions compiled" in capsys.readouterr().out


def test_the_compile_trace_records_each_top_level_compile_once(tmp_path):
    # oracle: the script below compiles a kernel that calls another (the callee compiled inside the caller's
    # compile), then a third function at the top level; numba's cache is off, so each compiles in this process
    import json
    import subprocess
    import sys

    from laddermill_gym.envs import compile_trace

    script = f"""
from numba import njit
from laddermill_gym.envs import compile_trace
compile_trace.record({str(tmp_path)!r}, "a.b:c")
@njit
def inner(x):
    return x + 1.0
@njit
def outer(x):
    return inner(x) * 2.0
@njit
def alone(x):
    return x - 1.0
print(outer(1.0), alone(1.0))
"""
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["4.0", "0.0"]
    (trace,) = compile_trace.read(str(tmp_path))
    assert trace["label"] == "a.b:c" and json.loads((tmp_path / f"{trace['pid']}.json").read_text()) == trace
    names = [r["name"].rpartition(".")[2] for r in trace["rows"]]
    assert names == ["outer", "alone"]  # inner compiled inside outer: not a row of its own
    assert all(r["start"] <= r["end"] for r in trace["rows"]) and trace["rows"][0]["end"] <= trace["rows"][1]["start"]


def test_a_warm_vector_start_compiles_nothing_beyond_the_single_env(capsys):
    """``--copies``: the child makes the native vector env; after this process filled the cache with the single
    env's kernels only, the vector env's start must compile nothing (it runs the single env's kernel on threads)."""
    _fill_cache()
    res = startup.run_startup(quick=True, envs=[ENV], copies=40)
    assert res[ENV]["copies"] == 40 and res[ENV]["warm"]["compiled"] == 0, res
    assert "make_vec (40 copies) + reset + one step" in capsys.readouterr().out


def test_bad_copy_counts_are_refused_before_any_run():
    for bad in (0, -3, 2.5, True):
        with pytest.raises(ValueError, match="copies"):
            startup.run_startup(quick=True, envs=[ENV], copies=bad)
    with pytest.raises(SystemExit):
        startup.main(["--copies", "0"])


def test_several_cold_starts_each_from_empty_caches_give_their_median_and_range(monkeypatch, capsys):
    """``cold_runs``: the child is replaced by a recorder of the caches it is given and of made-up clocks; the
    oracle is the arithmetic done here on those numbers (median, range) and the folders each run received."""
    firsts = iter([30.0, 20.0, 25.0, 1.0, 3.0, 2.0])  # three cold starts, then three warm ones
    seen = []

    def fake_child(env_id, cache_dir, copies=None):
        seen.append(cache_dir)
        t = next(firsts)
        return {"first_step_s": t, "wall_s": t + 0.5, "inside_s": t - 0.1, "cpu_s": 2 * t, "compiled": int(t),
                "cache_dir": str(cache_dir)}

    monkeypatch.setattr(startup, "run_child", fake_child)
    res = startup.run_startup(envs=[ENV], cold_runs=3)[ENV]
    cold, warm = res["cold"], res["warm"]
    assert len(set(seen[:3])) == 3 and all(seen[:3])  # a new cache folder per cold start
    assert seen[3:] == [seen[2]] * 3  # the warm starts read the last cold start's caches
    assert cold["first_step_s"] == 25.0 and cold["all_s"] == [30.0, 20.0, 25.0] and cold["runs"] == 3
    assert cold["cpu_s"] == 50.0 and cold["compiled"] == 30
    assert warm["first_step_s"] == 2.0 and warm["runs"] == 3
    out = capsys.readouterr().out
    assert "25.0 s" in out and "median of 3: 20.0-30.0 s" in out
    for bad in (0, -1, 1.5, True):
        with pytest.raises(ValueError, match="cold_runs"):
            startup.run_startup(envs=[ENV], cold_runs=bad)
    with pytest.raises(SystemExit):
        startup.main(["--cold-runs", "0"])
