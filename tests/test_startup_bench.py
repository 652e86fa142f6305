"""``laddermill bench --startup`` (issue 32 point 1): its quick path times a warm start of TetheredWing-v0 in a
fresh process. The oracle is independent of the timing code: this process fills the numba cache first by making
and stepping the env itself, so a correct warm start in the child compiles nothing (numba's own compile events,
counted in the child) and reads the cache this process names."""

import gymnasium
import numpy as np

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
    assert 0.0 < warm["inside_s"] < warm["wall_s"] < 60.0
    out = capsys.readouterr().out
    assert f"== start-up {ENV}" in out and "warm (caches filled)" in out and "cold" not in out.split("==")[1]


def test_cli_quick_startup_runs(capsys, monkeypatch):
    _fill_cache()
    monkeypatch.setattr(startup, "QUICK_ENVS", (ENV,))
    assert cli_main(["bench", "--startup", "--quick"]) == 0
    assert "0 functions compiled" in capsys.readouterr().out
