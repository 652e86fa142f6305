"""LadderMill's kernel warm-up (``envs/laddermill/kernel_warmup.py``, issue 32 point 1): while a cold start computes
the operating point, a second process compiles the 3D kernels into numba's cache. Oracles: the env run with the
warm-up switched off (the kernels compiled in the process itself) gives the same bits, in fresh processes with
empty caches (slow: two cold compiles); numba's compile events show that the process with the warm-up compiles
nothing at its first reset and step, nor the static equilibrium's right-hand side. Fast: the stand-in point builds
the real task, the in-plane stand-ins reach both in-plane right-hand sides, and the warm-up starts only when the
operating point is to be computed and the kernels are not compiled yet."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest

from laddermill_gym.envs.laddermill import kernel_warmup, op_cache
from laddermill_gym.envs.laddermill.operating_point import (
    SettleConfig,
    mill_scene,
    operating_point,
    operating_point_pending,
)
from laddermill_gym.envs.laddermill.task import MillTask
from laddermill_gym.envs.laddermill.warmup_child import stand_in_point

N = 11
OPTIONS = (("n_wings", N),)
SETTLE = SettleConfig(max_time=30.0)
SMALL = dict(scene="laddermill", scene_options={"n_wings": N}, settle={"max_time": 30.0}, episode_time=2.0)


def test_the_stand_in_point_builds_the_task_and_resets():
    sc = mill_scene("laddermill", OPTIONS, 3)
    op = stand_in_point(sc, 2.0)
    assert op.state.shape == (sc.assembly.state_size,) and op.n_wings == N and not op.state.flags.writeable
    task = MillTask(**SMALL, operating_point=op)
    task.reset(np.ones(1, dtype=bool), [np.random.default_rng(0)])
    task.step(np.zeros((1, task.n_actions)))
    assert task.obs.shape == (1, task.obs_dim)


def test_the_in_plane_stand_ins_reach_their_kernels_without_raising():
    from laddermill_gym.kernels.integrate import rhs_entry  # what Simulator.rhs calls

    kernel_warmup.compile_statics("laddermill", OPTIONS)
    kernel_warmup.compile_in_plane("laddermill", OPTIONS)
    kinds = {str(sig[4].types[0]).split("(")[0] for sig in rhs_entry.signatures}  # (t, x, u, dx, model, work): kind
    assert {"Rigid2D", "MovingCable2D"} <= kinds, kinds  # the static equilibrium's cable and the moving cable


def test_the_search_driver_is_compiled_for_the_search_without_a_step(monkeypatch):
    """The fixed-step driver is compiled for exactly the types the search's steps pass (the oracle: numba's own
    dispatch of a real step adds no signature) and the stand-in is not stepped (a failed stand-in step's report
    compiled DP5(4), which the search never runs: about 4.5 s of CPU on the first process's path)."""
    from laddermill_gym.kernels.fixed_steps import advance_breaks
    from laddermill_gym.sim.simulator import Simulator

    def no_step(self, *args, **kwargs):
        raise AssertionError("compile_in_plane stepped the stand-in simulator")

    with monkeypatch.context() as m:
        m.setattr(Simulator, "step", no_step)
        kernel_warmup.compile_in_plane("laddermill", OPTIONS)
    compiled = set(advance_breaks.signatures)
    assert compiled
    sim = mill_scene("laddermill", OPTIONS, 2).simulator()
    sim.step(n_steps=3)
    assert sim.t > 0.0 and set(advance_breaks.signatures) == compiled


def test_the_first_process_waits_for_the_statics_line_not_for_any_output():
    def child(code):
        return kernel_warmup.Warmup(subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE))

    w = child(f"print('a warning on stdout'); print({kernel_warmup.STATICS_DONE!r}); print('more')")
    assert w.wait_for(kernel_warmup.STATICS_DONE)  # the line after other output
    assert w.wait() == 0 and w.proc is None and not w.wait_for(kernel_warmup.STATICS_DONE)
    w = child("print('statics kernel')")  # not the line, then the end of its output
    assert not w.wait_for(kernel_warmup.STATICS_DONE)
    w.wait()


def test_a_warm_up_that_writes_much_after_its_line_is_not_left_blocked(monkeypatch):
    """A warm-up whose output outgrows the pipe after the line its caller waited for (numba's debug variables print
    to it) blocked on its write until the wait's limit, then was killed (review of 2026-12-08). Oracle: the process's
    own exit status, 0, within seconds of a 60 s limit."""
    import time

    from laddermill_gym.envs import kernel_warmup as kw

    monkeypatch.setattr(kw, "WAIT_LIMIT_S", 60.0)
    code = (f"print({kw.CALLEES_DONE!r}, flush=True)\n"
            "for i in range(20000): print('[cache] data saved to /a/numba/cache/path/kernel-123.py311.1.nbc')\n")
    w = kw.Warmup(subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE))
    assert w.wait_for(kw.CALLEES_DONE)
    t0 = time.monotonic()
    assert w.wait() == 0 and time.monotonic() - t0 < 30.0


def test_a_wait_that_raises_stops_every_other_warm_up():
    """The waits for the warm-ups stood outside the block that stops them on an error: a Ctrl-C during the wait, or a
    failed warm-up's warning turned into an error, left the other warm-up compiling with its lock held (review of
    2026-12-08). Oracle: the processes' own state after the failed wait."""
    from laddermill_gym.envs import kernel_warmup as kw

    failing = kw.Warmup(subprocess.Popen([sys.executable, "-c", "raise SystemExit(1)"], stdout=subprocess.PIPE))
    sleeping = kw.Warmup(subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"],
                                          stdout=subprocess.PIPE))
    proc = sleeping.proc
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # the failed warm-up's warning as an error (pytest -W error)
        with pytest.raises(RuntimeWarning, match="exited with code 1"):
            kw.wait_all((failing, None, sleeping))
    assert proc.poll() is not None and sleeping.proc is None  # stopped and reaped, not left sleeping


def test_pending_until_returned_or_on_disk(tmp_path, monkeypatch):
    monkeypatch.setenv(op_cache.CACHE_VARIABLE, str(tmp_path / "cache"))
    operating_point.cache_clear()
    settle = SettleConfig(max_time=30.5)  # a key no other test in this process has returned
    try:
        assert operating_point_pending("laddermill", OPTIONS, settle)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            operating_point("laddermill", OPTIONS, settle)
        assert not operating_point_pending("laddermill", OPTIONS, settle)
        operating_point.cache_clear()
        entries = list((tmp_path / "cache" / "operating_points").glob("*.npz"))
        assert entries  # on disk: a new process would read it, not compute it
    finally:
        operating_point.cache_clear()


class FakeKernel:
    def __init__(self, signatures):
        self.signatures = signatures


def test_started_only_when_it_can_help(monkeypatch):
    monkeypatch.setenv(kernel_warmup.SWITCH, "off")
    assert kernel_warmup.start({}, (FakeKernel([]),)) is None
    monkeypatch.delenv(kernel_warmup.SWITCH)
    assert kernel_warmup.start({}, (FakeKernel([]), FakeKernel(["a signature"]))) is None  # compiled here already
    assert kernel_warmup.start({"x": lambda: 0}, (FakeKernel([]),)) is None  # arguments that do not pickle


#: a fresh process: make the small mill, reset, roll out; prints the compile events per phase and the rollout
CHILD = """import json, warnings
import numpy as np
from numba.core import event
count = {"make": 0, "reset": 0, "statics": 0}
phase = ["make"]
class Count(event.Listener):
    def on_start(self, ev):
        count[phase[0]] += 1
        f = ev.data["dispatcher"].py_func
        integrate_rhs = f.__module__.endswith("kernels.integrate") and f.__name__ == "rhs_entry"  # Simulator.rhs
        if integrate_rhs and str(ev.data["args"][4].types[0]).startswith("Rigid2D("):  # (t, x, u, dx, model, work)
            count["statics"] += 1  # the static equilibrium's right-hand side (the cable without the station)
    def on_end(self, ev):
        pass
event.register("numba:compile", Count())
from laddermill_gym.envs.laddermill.env import LadderMillEnv
with warnings.catch_warnings():
    warnings.simplefilter("ignore", RuntimeWarning)
    env = LadderMillEnv(**%r)
phase[0] = "reset"
obs, _ = env.reset(seed=3)
out = [obs]
rng = np.random.default_rng(3)
for _ in range(6):
    obs, r, *_ = env.step(rng.uniform(-0.3, 0.3, env.action_space.shape).astype(np.float32))
    out += [obs, np.array([r])]
print(json.dumps({"count": count, "bits": np.concatenate([np.ravel(o) for o in out]).astype(float).tobytes().hex()}))
"""


def fresh(tmp, warmup: bool) -> dict:
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp / "numba"), **{op_cache.CACHE_VARIABLE: str(tmp / "ops")})
    env[kernel_warmup.SWITCH] = "on" if warmup else "off"
    r = subprocess.run([sys.executable, "-c", CHILD % (SMALL,)], env=env, capture_output=True, text=True, check=True)
    return json.loads(r.stdout.strip().splitlines()[-1])


@pytest.mark.slow
def test_warmed_up_start_compiles_nothing_at_reset_and_gives_the_same_bits(tmp_path):
    own = fresh(tmp_path / "own", warmup=False)
    warm = fresh(tmp_path / "warm", warmup=True)
    assert own["count"]["reset"] > 0  # the oracle compiled its kernels itself, at the first reset
    assert warm["count"]["reset"] == 0  # loaded from what the second process compiled
    assert own["count"]["statics"] == 1 and warm["count"]["statics"] == 0  # the statics' kernel compiled there too
    assert warm["bits"] == own["bits"]
