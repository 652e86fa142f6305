"""The on-disk caches of the wing's and the craft's starting points (``envs/start_cache.py``) and of the wing tables'
spline coefficients (``model/packing.table_spline``), issue 32 point 1: the warm start. Oracles: the recomputation
(the scene's ``initial_state``, the craft's ``trim``, scipy's ``CubicSpline``), which never reads a cache: a start
read back must be the same bits and roll out the same; every source file the computation runs lies in the hashed
set (traced in a fresh process); and a warm fresh process makes TetheredWing-v0 and Rotorcraft-v0 without
importing scipy's solvers or interpolators or another system's env modules."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import gymnasium
import numpy as np
import pytest
from scipy.interpolate import CubicSpline

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs import start_cache
from laddermill_gym.envs.laddermill import op_cache
from laddermill_gym.envs.rotorcraft.trim import craft_trim, trim_on_disk, untrimmed_craft
from laddermill_gym.envs.task import scene_trim
from laddermill_gym.ladder.scene import load_scene, options_key, options_kwargs
from laddermill_gym.model import disk_cache
from laddermill_gym.model.machine import ABOVE_AVX2
from laddermill_gym.model.packing import table_spline

WING = ("tethered_wing", options_key({"elements_per_piece": 1, "method": "ros34pw2"}))


@pytest.fixture()
def cache(tmp_path, monkeypatch):
    """A fresh cache folder and empty per-process memos (restored empty after the test)."""
    monkeypatch.setenv(disk_cache.CACHE_VARIABLE, str(tmp_path / "cache"))
    scene_trim.cache_clear()
    craft_trim.cache_clear()
    yield tmp_path / "cache"
    scene_trim.cache_clear()
    craft_trim.cache_clear()


def same_bits(a, b) -> bool:
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def rollout(env_id: str, seed: int = 3) -> np.ndarray:
    env = gymnasium.make(env_id)
    obs, _ = env.reset(seed=seed)
    rng = np.random.default_rng(seed)
    out = [obs]
    for _ in range(6):
        obs, r, *_ = env.step(rng.uniform(-0.5, 0.5, env.action_space.shape).astype(np.float32))
        out += [obs, np.array([r])]
    env.close()
    return np.concatenate([np.ravel(o) for o in out])


def test_the_wing_start_read_back_is_the_recomputation_bit_for_bit(cache):
    sc = load_scene(WING[0], **options_kwargs(WING[1]))
    x_ref, u_ref = sc.initial_state()  # the oracle: no cache involved
    _, x1, u1 = scene_trim(*WING)
    assert len(list((cache / "wing_starts").glob("*.npz"))) == 1
    scene_trim.cache_clear()
    _, x2, u2 = scene_trim(*WING)  # read back
    assert all(same_bits(a, b) for a, b in [(x1, x_ref), (u1, u_ref), (x2, x_ref), (u2, u_ref)])
    assert not x2.flags.writeable and not u2.flags.writeable


def test_the_craft_start_read_back_is_the_recomputation_bit_for_bit(cache):
    c, u = untrimmed_craft("roberts_flying_model")
    x_ref = c.trim(u[0])
    assert not trim_on_disk("roberts_flying_model")  # what the kernel warm-up asks: nothing stored yet
    _, x1, u1 = craft_trim("roberts_flying_model")
    assert trim_on_disk("roberts_flying_model") and not trim_on_disk("roberts_flying_model", wind_speed=9.0)
    craft_trim.cache_clear()
    _, x2, u2 = craft_trim("roberts_flying_model")
    assert len(list((cache / "craft_starts").glob("*.npz"))) == 1
    assert same_bits(x1, x_ref) and same_bits(x2, x_ref) and same_bits(u2, u) and not x2.flags.writeable
    craft_trim.cache_clear()
    _, x3, _ = craft_trim("roberts_flying_model", wind_speed=9.0)  # another input: another entry
    assert len(list((cache / "craft_starts").glob("*.npz"))) == 2 and not same_bits(x3, x_ref)


def test_the_spline_read_back_is_scipys_bit_for_bit_and_a_corrupt_entry_is_recomputed(cache):
    alpha = np.linspace(-np.pi, np.pi, 73)
    values = np.column_stack([np.sin(alpha) + 0.1 * k * np.cos(3 * alpha) for k in range(4)])
    values[-1] = values[0]  # periodic
    ref = CubicSpline(alpha, values, bc_type="periodic", axis=0).c
    first = table_spline(alpha, values)
    (entry,) = (cache / "aero_splines").glob("*.npz")
    second = table_spline(alpha, values)
    assert same_bits(first, ref) and same_bits(second, ref)
    entry.write_bytes(entry.read_bytes()[:200])  # truncated: recomputed and rewritten
    assert same_bits(table_spline(alpha, values), ref) and entry.stat().st_size > 200
    values2 = values.copy()
    values2[3, 1] = np.nextafter(values2[3, 1], 1.0)  # one last bit: another key
    table_spline(alpha, values2)
    assert len(list((cache / "aero_splines").glob("*.npz"))) == 2


@pytest.mark.parametrize("env_id", ["laddermill_gym/TetheredWing-v0", "laddermill_gym/Rotorcraft-v0"])
def test_a_start_read_back_rolls_out_as_a_recomputed_one(cache, monkeypatch, env_id):
    monkeypatch.setenv(disk_cache.CACHE_VARIABLE, disk_cache.OFF)
    ref = rollout(env_id)  # the cache off: the start computed
    monkeypatch.setenv(disk_cache.CACHE_VARIABLE, str(cache))
    scene_trim.cache_clear()
    craft_trim.cache_clear()
    rollout(env_id)  # fills the cache
    scene_trim.cache_clear()
    craft_trim.cache_clear()
    assert same_bits(rollout(env_id), ref)  # read back


TRACE = """
import sys
from laddermill_gym.envs.rotorcraft.trim import untrimmed_craft
from laddermill_gym.ladder.scene import load_scene
sc = load_scene("tethered_wing", elements_per_piece=1, method="ros34pw2")
c, u = untrimmed_craft("roberts_flying_model")
files = {"wing": set(), "craft": set()}
for kind, run in (("wing", sc.initial_state), ("craft", lambda: c.trim(u[0]))):
    sys.setprofile(lambda frame, event, arg: files[kind].add(frame.f_code.co_filename))
    run()
    sys.setprofile(None)
print(json.dumps({k: sorted(v) for k, v in files.items()}))
"""


def test_every_source_file_the_starts_run_is_hashed():
    out = subprocess.run([sys.executable, "-c", "import json" + TRACE], capture_output=True, text=True, check=True)
    ran = json.loads(out.stdout.strip().splitlines()[-1])
    pkg = op_cache.PACKAGE
    for kind, (dirs, files) in (("wing", start_cache.WING_SOURCES), ("craft", start_cache.CRAFT_SOURCES)):
        mine = {p for p in ran[kind] if p.startswith(str(pkg))}
        assert any("statics.py" in p for p in mine), kind
        outside = [p for p in mine if p not in {str(pkg / f) for f in files}
                   and not any(p.startswith(str(pkg / d) + "/") for d in dirs)]
        assert not outside, (kind, outside)


WARM = """
import sys, json
import gymnasium, numpy as np
import laddermill_gym
env = gymnasium.make({env_id!r})
env.reset(seed=0)
env.step(np.zeros(env.action_space.shape, dtype=env.action_space.dtype))
print(json.dumps(sorted(sys.modules)))
"""


@pytest.mark.parametrize("env_id", ["laddermill_gym/TetheredWing-v0", "laddermill_gym/Rotorcraft-v0"])
def test_a_warm_fresh_process_imports_no_solver_and_no_other_system(tmp_path, env_id):
    env = dict(os.environ, **{disk_cache.CACHE_VARIABLE: str(tmp_path / "cache")})
    runs = [subprocess.run([sys.executable, "-c", WARM.format(env_id=env_id)], env=env, capture_output=True,
                           text=True, check=True) for _ in range(2)]
    cold, warm = (set(json.loads(r.stdout.strip().splitlines()[-1])) for r in runs)
    assert "scipy.optimize" in cold  # the first process solved the start (the check can fail)
    banned = ("scipy.optimize", "scipy.interpolate", "laddermill_gym.envs.laddermill.env",
              "laddermill_gym.envs.pumping", "laddermill_gym.envs.pointmass", "laddermill_gym.ladder.initial")
    assert not [m for m in warm if m.startswith(banned)], env_id


#: what a fresh process prints: a digest of numpy's exp and of scipy's Riccati solution (LAPACK on OpenBLAS), and of
#: the cache's platform text
KERNEL_PROBE = """import hashlib
import numpy as np
import scipy.linalg as sl
from laddermill_gym.model.disk_cache import platform_text
r = np.random.default_rng(0)
x, A, B = r.uniform(0.1, 5.0, 4096), r.normal(size=(12, 12)), r.normal(size=(12, 3))
P = sl.solve_continuous_are(A, B, np.eye(12), np.eye(3))
bits = hashlib.sha256(np.exp(-x).tobytes() + P.tobytes()).hexdigest()
print(bits, hashlib.sha256(platform_text().encode()).hexdigest())
"""


def _kernel_probe(changes: dict) -> tuple[str, str]:
    keep = {k: v for k, v in os.environ.items() if k not in disk_cache.KERNEL_VARIABLES}
    out = subprocess.run([sys.executable, "-c", KERNEL_PROBE], env={**keep, **changes}, capture_output=True,
                         text=True, check=True)
    bits, key = out.stdout.split()
    return bits, key


def test_the_key_follows_the_kernels_numpy_and_openblas_choose():
    """numpy's SIMD loops and OpenBLAS's kernels, chosen when they load, move the last bits of exp and of a Riccati
    solution (the oracle: two fresh processes' results compared bit for bit), so a start computed under one choice
    must not be read under another: wherever the bits differ, so does the cache's platform text. Same settings, same
    bits and key."""
    import llvmlite.binding as ll

    base = _kernel_probe({"OPENBLAS_CORETYPE": "Haswell"})
    assert _kernel_probe({"OPENBLAS_CORETYPE": "Haswell"}) == base
    others = [{"OPENBLAS_CORETYPE": "Haswell", "NPY_DISABLE_CPU_FEATURES": ABOVE_AVX2}]
    avx512 = bool(ll.get_host_cpu_features().get("avx512f"))
    if avx512:
        others.append({"OPENBLAS_CORETYPE": "SkylakeX"})
    moved = 0
    for changes in others:
        bits, key = _kernel_probe(changes)
        if bits != base[0]:
            moved += 1
            assert key != base[1], f"{changes}: other bits under the same cache key"
    if avx512:  # on such a CPU both choices move the bits (AMD EPYC, 2026-12-02)
        assert moved == len(others)
