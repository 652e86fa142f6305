"""The wing and craft kernel warm-up (``envs/kernel_warmup.py``, ``envs/task_warmup.py``, issue 32 point 1): while
a cold start solves the trim, a second process compiles the step kernel into numba's cache. Oracles: the env run
with the warm-up switched off (every kernel compiled in the process itself) gives the same bits, in fresh processes
with empty caches (slow: two cold compiles per env); numba's compile events show that the process with the warm-up
compiles no step kernel and nothing at its first reset and steps. Fast: the stand-in trims have the real trims'
shapes, dtypes and flags, and the warm-up starts only when it can help."""

from __future__ import annotations

import json
import os
import pickle
import subprocess
import sys
import time
import types
import warnings

import numpy as np
import pytest

from laddermill_gym.envs import compile_trace, kernel_warmup
from laddermill_gym.envs.rotorcraft.trim import craft_trim
from laddermill_gym.envs.task import scene_trim
from laddermill_gym.envs.task_warmup import stand_in_craft_trim, stand_in_wing_trim


def _same_kind(a: np.ndarray, b: np.ndarray) -> bool:
    return (a.shape, a.dtype, a.flags.writeable, a.flags.c_contiguous) == (b.shape, b.dtype, b.flags.writeable,
                                                                          b.flags.c_contiguous)


def test_the_stand_in_trims_have_the_real_trims_types():
    sc, x, u = scene_trim("tethered_wing", ())
    s_sc, s_x, s_u = stand_in_wing_trim("tethered_wing", ())
    assert type(s_sc) is type(sc) and _same_kind(s_x, x) and _same_kind(s_u, u)
    c, x, u = craft_trim("roberts_flying_model")
    s_c, s_x, s_u = stand_in_craft_trim("roberts_flying_model")
    assert type(s_c) is type(c) and _same_kind(s_x, x) and _same_kind(s_u, u)


class FakeKernel:
    def __init__(self, signatures):
        self.signatures = signatures


def test_started_only_when_it_can_help(monkeypatch):
    monkeypatch.setenv(kernel_warmup.SWITCH, "off")
    assert kernel_warmup.start("m:f", {}, (FakeKernel([]),)) is None
    monkeypatch.delenv(kernel_warmup.SWITCH)
    assert kernel_warmup.start("m:f", {}, (FakeKernel([]), FakeKernel(["a signature"]))) is None  # compiled here
    assert kernel_warmup.start("m:f", {"x": lambda: 0}, (FakeKernel([]),)) is None  # arguments that do not pickle
    assert not kernel_warmup.on_disk((FakeKernel([]),))  # no cache to ask: not known to be on disk


#: a fresh process: make the env (compile events named, by phase), reset, roll out; prints the rollout's bits
CHILD = """import json
import gymnasium, numpy as np
from numba.core import event
names = {"make": [], "after": []}
phase = ["make"]
class Names(event.Listener):
    def on_start(self, ev):
        names[phase[0]].append(ev.data["dispatcher"].py_func.__qualname__)
    def on_end(self, ev):
        pass
event.register("numba:compile", Names())
import laddermill_gym
env = gymnasium.make(%r)
phase[0] = "after"
obs, _ = env.reset(seed=3)
out = [obs]
rng = np.random.default_rng(3)
for _ in range(8):
    obs, r, term, trunc, _ = env.step(rng.uniform(-0.5, 0.5, env.action_space.shape).astype(np.float32))
    out += [obs, np.array([r, term, trunc], dtype=float)]
print(json.dumps({"names": names, "bits": np.concatenate([np.ravel(o) for o in out]).astype(float).tobytes().hex()}))
"""


def fresh(tmp, env_id: str, warmup: bool, trace=None) -> dict:
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp / "numba"), LADDERMILL_CACHE_DIR=str(tmp / "ops"))
    env[kernel_warmup.SWITCH] = "on" if warmup else "off"
    if trace is not None:  # the warm-up processes' top-level compiles (envs/compile_trace.py)
        os.makedirs(trace, exist_ok=True)
        env[compile_trace.VARIABLE] = str(trace)
    r = subprocess.run([sys.executable, "-c", CHILD % (env_id,)], env=env, capture_output=True, text=True, check=True)
    return json.loads(r.stdout.strip().splitlines()[-1])


@pytest.mark.slow
@pytest.mark.parametrize("env_id", ["laddermill_gym/TetheredWing-v0", "laddermill_gym/Rotorcraft-v0"])
def test_warmed_up_start_compiles_no_step_kernel_and_gives_the_same_bits(tmp_path, env_id):
    own = fresh(tmp_path / "own", env_id, warmup=False)
    warm = fresh(tmp_path / "warm", env_id, warmup=True, trace=tmp_path / "trace")
    assert any("step_observe" in n for n in own["names"]["make"])  # the oracle compiled the step kernel itself
    assert not any("step_observe" in n for n in warm["names"]["make"])  # loaded from the second process's cache
    assert warm["names"]["after"] == []  # nothing compiled at the reset and the steps
    assert warm["bits"] == own["bits"]
    # the W method's step (w_advance_one, which links the step's parts; its loop w_advance is small) compiled once over
    # all the processes (numba's compile events in each): by the craft's first process after its trim, by the wing's
    # tail warm-up after its share
    loops = {t["label"].rsplit(":", 1)[-1]: sum(r["name"].endswith(".w_advance_one") for r in t["rows"])
             for t in compile_trace.read(tmp_path / "trace")}
    loops["first"] = warm["names"]["make"].count("w_advance_one")
    assert sum(loops.values()) == 1 and loops[("first" if "Rotorcraft" in env_id else "compile_wing_tail")] == 1



#: a fresh process, warm-up off (each kernel compiled in it): make, reset and step the env (the task's keyword
#: arguments recorded where it would start the warm-up), then the warm-up's list of the step kernel's callees
#: (envs/task_warmup.py) for them; prints each listed dispatcher's number of signatures before and after the list
AHEAD = """import json, os
os.environ[%r] = "off"
import gymnasium, numpy as np
from laddermill_gym.envs import kernel_warmup, task_warmup
got = []
kernel_warmup.start = lambda target, kwargs, *a, **k: got.append(kwargs)
env = gymnasium.make(%r)
env.reset(seed=0)
env.step(np.zeros(env.action_space.shape, dtype=env.action_space.dtype))
calls = getattr(task_warmup, %r)(got[0])
calls = calls[0] + calls[1] if isinstance(calls, tuple) else calls
before = [len(d.signatures) for d, _ in calls]
done = task_warmup.compile_ahead(calls)
print(json.dumps({"names": [d.py_func.__qualname__ for d, _ in calls], "done": done, "before": before,
                  "after": [len(d.signatures) for d, _ in calls]}))
"""


@pytest.mark.slow
@pytest.mark.parametrize("env_id, lister", [("laddermill_gym/TetheredWing-v0", "wing_calls"),
                                            ("laddermill_gym/Rotorcraft-v0", "craft_calls")])
def test_the_callees_compiled_ahead_are_the_step_kernels_own(tmp_path, env_id, lister):
    # oracle: numba's own typing of the step kernel, compiled first in the same process: a listed callee whose
    # argument types differ from those the kernel passes gets a signature of its own from the list
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"), LADDERMILL_CACHE_DIR=str(tmp_path / "ops"))
    r = subprocess.run([sys.executable, "-c", AHEAD % (kernel_warmup.SWITCH, env_id, lister)], env=env,
                       capture_output=True, text=True, check=True)
    out = json.loads(r.stdout.strip().splitlines()[-1])
    assert out["done"] == len(out["names"]) >= 9  # the W step's own callees at least
    assert {"add_body_jacobian", "add_cable_stiffness", "tree_factor", "rigid3d_check", "w_advance",
            "advance_breaks"} <= set(out["names"])  # the last two: called through their addresses (far_call)
    assert out["after"] == out["before"]  # no new specialisation: each is the one the step kernel compiled
    assert min(out["before"]) >= 1


@pytest.mark.parametrize("env_id, lister", [("laddermill_gym/TetheredWing-v0", "wing_calls"),
                                            ("laddermill_gym/Rotorcraft-v0", "craft_calls")])
def test_a_threaded_tasks_callees_are_listed_as_a_single_ones(monkeypatch, env_id, lister):
    """A vector env's copies on numba's threads reach the step kernel through its launcher: the warm-up must still
    find the kernel's arguments (oracle: the single env's list; an empty list would leave every callee, the W
    method's loop too, to the first process's first step)."""
    import gymnasium as gym
    import numba

    from laddermill_gym.envs import task_warmup

    if numba.config.NUMBA_NUM_THREADS < 2:
        pytest.skip("needs two numba threads")
    got = []

    class Stop(Exception):
        pass

    def start(target, kwargs, *args, **kw):
        got.append(kwargs)
        raise Stop

    monkeypatch.setattr(kernel_warmup, "start", start)
    with pytest.raises(Stop):
        gym.make(env_id)
    monkeypatch.setattr(kernel_warmup, "start", lambda *args, **kw: None)  # the listers build the task again

    def names(calls):
        calls = calls[0] + calls[1] if isinstance(calls, tuple) else calls
        return [d.py_func.__qualname__ for d, _ in calls]

    numba.set_num_threads(2)
    try:
        one = names(getattr(task_warmup, lister)(got[0]))
        many = names(getattr(task_warmup, lister)(dict(got[0], n_copies=64, parallel=True)))
    finally:
        numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
    assert len(one) >= 9 and "w_advance" in one
    assert many == one


def _sleeper(procs: list):
    """A warm-up whose process sleeps a minute (it stands for a compile in progress)."""
    procs.append(subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"]))
    return kernel_warmup.Warmup(procs[-1])


def test_a_failed_construction_stops_its_warm_ups(monkeypatch):
    # oracle: the operating system's view of the child processes (poll() gives an exit status once one is reaped)
    from laddermill_gym.envs import task as wing_task
    from laddermill_gym.envs.rotorcraft import task as craft_task

    procs = []
    monkeypatch.setattr(kernel_warmup, "start", lambda *a, **k: _sleeper(procs))
    with pytest.raises(ValueError, match="no_such_scene"):
        wing_task.WingTask(scene="no_such_scene", physics_step="ros34pw2")
    with pytest.raises(ValueError, match="no_such_craft"):
        craft_task.CraftTask(craft="no_such_craft")
    assert len(procs) == 3 and all(p.poll() is not None for p in procs)  # the wing's two, the craft's one


def test_the_tail_warm_up_starts_for_a_w_method_step_only(monkeypatch):
    # oracle: task_warmup.step_callees lists no callee for an RK4 step, so a third process could compile nothing
    from laddermill_gym.envs import task as wing_task

    targets = []

    def record(target, *args, **kwargs):
        targets.append(target)
        return None

    monkeypatch.setattr(kernel_warmup, "start", record)
    for step in ("ros34pw2", "rk4"):
        with pytest.raises(ValueError, match="no_such_scene"):
            wing_task.WingTask(scene="no_such_scene", physics_step=step)
    assert targets == [wing_task.WARMUP_TARGET, wing_task.WARMUP_TAIL_TARGET, wing_task.WARMUP_TARGET]


class CachedKernel(FakeKernel):
    """A dispatcher stand-in with numba's cache directory (``_cache._cache_path``), as numba's dispatchers have."""

    def __init__(self, directory):
        super().__init__([])
        self._cache = types.SimpleNamespace(_cache_path=str(directory))


def test_one_warm_up_per_task_and_cache_at_a_time(monkeypatch, tmp_path):
    # oracle: the operating system's flock, asked from other processes while the warm-up runs and after it ended
    (tmp_path / "sleeper_target.py").write_text("import time\ndef run(kwargs):\n    time.sleep(kwargs['s'])\n")
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(tmp_path), os.environ.get("PYTHONPATH", "")]))
    task, cache = ("sleeper_target:run", {"s": 3.0}), tmp_path / "numba"
    payload, kernels = pickle.dumps(task), (CachedKernel(cache),)
    assert kernel_warmup.cache_directory(kernels) == str(cache)

    def refused_elsewhere(directory=cache) -> bool:
        ask = (f"from laddermill_gym.envs.kernel_warmup import claim; "
               f"print(claim({payload!r}, {str(directory)!r})[0] is None)")
        return subprocess.run([sys.executable, "-c", ask], capture_output=True, text=True).stdout.strip() == "True"

    held, path = kernel_warmup.claim(payload, str(cache))
    assert held >= 0 and os.path.dirname(path) == str(cache)  # the lock file beside the cache it guards
    assert kernel_warmup.claim(payload, str(cache)) == (None, path)  # a second claimant refused
    peer = kernel_warmup.start(*task, kernels)
    assert isinstance(peer, kernel_warmup.PeerWarmup) and peer.proc is None  # no process of its own
    os.close(held)
    assert not refused_elsewhere() and peer.wait() == 0  # released with the descriptor: the peer's wait ends
    began = time.monotonic()
    warmup = kernel_warmup.start(*task, kernels)
    assert isinstance(warmup, kernel_warmup.Warmup) and warmup.proc.poll() is None
    assert refused_elsewhere()  # held by the child
    assert not refused_elsewhere(tmp_path / "other")  # another cache: its own warm-up
    peer = kernel_warmup.start(*task, kernels)
    assert isinstance(peer, kernel_warmup.PeerWarmup) and peer.wait() == 0
    assert time.monotonic() - began >= 2.5 and warmup.proc.poll() == 0  # it waited for the child's 3 s sleep to end
    assert warmup.wait() == 0 and not refused_elsewhere()  # released when the child ended
    warmup = kernel_warmup.start(*task, kernels)
    warmup.stop()
    assert not refused_elsewhere()  # a stopped child releases it too
    assert kernel_warmup.claim(payload, None) == (-1, None)  # no cache directory: no lock


def test_a_file_system_without_flock_means_no_lock_not_a_wait(monkeypatch, tmp_path):
    # oracle: the errno a file system without flock gives (NFS without lockd: ENOLCK), raised by flock itself
    import errno
    import fcntl

    def no_flock(fd, op):
        raise OSError(errno.ENOLCK, os.strerror(errno.ENOLCK))

    monkeypatch.setattr(fcntl, "flock", no_flock)
    assert kernel_warmup.claim(b"task", str(tmp_path)) == (-1, None)
    monkeypatch.setattr(kernel_warmup, "WAIT_LIMIT_S", 30.0)
    began = time.monotonic()
    with pytest.warns(RuntimeWarning, match="cannot be waited for"):
        assert kernel_warmup.PeerWarmup(str(tmp_path / "a.lock")).wait() is None
    assert time.monotonic() - began < 5.0  # at once, not after the 30 s limit


def test_the_warm_ups_started_together_share_one_deadline(monkeypatch, tmp_path):
    monkeypatch.setattr(kernel_warmup, "WAIT_LIMIT_S", 2.0)
    procs = [subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"]) for _ in range(2)]
    warmups = [kernel_warmup.Warmup(p) for p in procs]
    began = time.monotonic()
    with pytest.warns(RuntimeWarning, match="stopped 2 s after its start"):
        for w in warmups:
            assert w.wait() is None
    assert time.monotonic() - began < 3.5  # one limit for both, not one each (4 s)
    assert all(p.poll() is not None for p in procs)
    monkeypatch.setattr(kernel_warmup, "WAIT_LIMIT_S", 0.5)
    held, path = kernel_warmup.claim(pickle.dumps(("m:f", {"deadline": 1})), str(tmp_path))
    with pytest.warns(RuntimeWarning, match="still ran 0 s after this env's construction began"):
        assert kernel_warmup.PeerWarmup(path).wait() is None  # the other warm-up outlived the limit
    os.close(held)


def test_a_failed_warm_up_is_named_in_a_warning():
    failed = kernel_warmup.Warmup(subprocess.Popen([sys.executable, "-c", "raise SystemExit(3)"]))
    with pytest.warns(RuntimeWarning, match="exited with code 3"):
        assert failed.wait() == 3
    fine = kernel_warmup.Warmup(subprocess.Popen([sys.executable, "-c", "pass"]))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert fine.wait() == 0 and fine.wait() == 0  # idempotent, silent


def test_on_two_cores_the_trim_waits_for_the_callees_line_not_the_end(monkeypatch):
    # oracle: the child processes themselves: each prints (or not) and then sleeps a minute, so a wait that returns
    # while the child still runs cannot have waited for its end
    def child(code):
        return kernel_warmup.Warmup(subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE))

    line = f"print('other output'); print({kernel_warmup.CALLEES_DONE!r}, flush=True); import time; time.sleep(60)"
    silent = "import time; time.sleep(60)"
    monkeypatch.setattr(kernel_warmup, "usable_cores", lambda: 2)
    ws = [child(line), child(line), None, kernel_warmup.PeerWarmup(None)]
    try:
        kernel_warmup.await_callees(ws)
        assert all(w.proc.poll() is None for w in ws[:2])  # both lines read, neither child waited for
        monkeypatch.setattr(kernel_warmup, "usable_cores", lambda: kernel_warmup.SHARED_CORES)
        ws.append(child(silent))
        kernel_warmup.await_callees(ws[-1:])  # cores enough: no wait for a line that never comes
        assert ws[-1].proc.poll() is None
    finally:
        for w in ws:
            if w is not None:
                w.stop()


def test_the_wing_warm_ups_print_the_line_and_only_a_w_method_waits_for_it(monkeypatch, capsys):
    # oracle: what the warm-up functions print, and the arguments the task hands kernel_warmup (recorded)
    from laddermill_gym.envs import task as wing_task
    from laddermill_gym.envs import task_warmup

    monkeypatch.setattr(task_warmup, "wing_calls", lambda kwargs: [])
    monkeypatch.setattr(task_warmup, "_build_and_step", lambda cls, kwargs: print("built"))
    monkeypatch.setattr(wing_task, "scene_trim", wing_task.scene_trim)  # compile_wing swaps in its stand-in: restored
    task_warmup.compile_wing_tail({})
    task_warmup.compile_wing({})
    assert capsys.readouterr().out.split("\n") == [kernel_warmup.CALLEES_DONE, kernel_warmup.CALLEES_DONE, "built", ""]
    started, awaited = [], []
    monkeypatch.setattr(kernel_warmup, "start", lambda target, kw, kernels, check, signals: started.append(signals))
    monkeypatch.setattr(kernel_warmup, "await_callees", lambda ws: awaited.append(len(ws)))
    for step in ("ros34pw2", "rk4"):
        with pytest.raises(ValueError, match="no_such_scene"):
            wing_task.WingTask(scene="no_such_scene", physics_step=step)
    assert started == [True, True, False] and awaited == [2, 1]


def test_the_trim_is_the_real_one_after_the_warm_up_tests():
    # oracle: the module's own function object; a test above that runs compile_wing in this process must leave it
    from laddermill_gym.envs import task as wing_task
    from laddermill_gym.envs import task_warmup

    assert wing_task.scene_trim is not task_warmup.stand_in_wing_trim and wing_task.scene_trim is scene_trim


def test_a_shared_compile_ahead_leaves_a_callee_that_another_process_compiles(tmp_path, monkeypatch):
    # oracle: the dispatcher's own list of compiled signatures, and a lock held through the operating system (flock
    # on a second open file description conflicts as another process's would)
    import numba

    from laddermill_gym.envs import step_callees
    from laddermill_gym.envs.step_callees import compile_ahead

    def plus_one(x):
        return x + 1.0

    def fresh_kernel():
        return numba.njit(plus_one)

    monkeypatch.setattr(step_callees, "cache_directory", lambda kernels: str(tmp_path))
    f = fresh_kernel()
    payload = f"{plus_one.__module__}.{plus_one.__qualname__}{(numba.typeof(1.0),)}".encode()
    held, _ = kernel_warmup.claim(payload, str(tmp_path))
    assert held is not None and held >= 0
    try:
        assert compile_ahead([(f, (1.0,))], shared=True) == 0 and f.signatures == []  # left to the holder
        g = fresh_kernel()
        assert compile_ahead([(g, (1.0,))]) == 1 and len(g.signatures) == 1  # not shared: compiled all the same
    finally:
        os.close(held)
    assert compile_ahead([(f, (1.0,))], shared=True) == 1 and len(f.signatures) == 1
    again, _ = kernel_warmup.claim(payload, str(tmp_path))  # released after the compile
    assert again is not None and again >= 0
    os.close(again)
