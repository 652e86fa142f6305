"""The on-disk cache of the mill's operating points (``envs/laddermill/op_cache.py``, issue 32 point 1). Oracle: a
recomputation (``compute_operating_point``, which never reads the cache) and the env built from it; a start read
back must give the same bits and the same rollout. Corrupt, foreign-key and truncated entries are recomputed, a
changed input is a new key, and every source file the computation runs lies in the hashed set (traced in a fresh
process). A small mill (11 wings, 30 s of settling: the fallback start, about a second) keeps it fast."""

from __future__ import annotations

import dataclasses
import subprocess
import sys
import warnings

import numpy as np
import pytest

from laddermill_gym.envs.laddermill import op_cache
from laddermill_gym.envs.laddermill.env import LadderMillEnv
from laddermill_gym.envs.laddermill.operating_point import (
    OperatingPoint,
    SettleConfig,
    cached_operating_point,
    compute_operating_point,
    mill_scene,
    operating_point,
)

N = 11
OPTIONS = (("n_wings", N),)
SETTLE = SettleConfig(max_time=30.0)
SMALL = dict(scene="laddermill", scene_options={"n_wings": N}, settle={"max_time": 30.0}, episode_time=2.0,
             reward={"failure_penalty": 0.0}, termination={"alpha_range_deg": (-180.0, 180.0),
                                                            "max_abs_beta_deg": 90.0})


@pytest.fixture()
def cache(tmp_path, monkeypatch):
    """A fresh cache folder and an empty per-process memo (restored empty after the test)."""
    monkeypatch.setenv(op_cache.CACHE_VARIABLE, str(tmp_path / "cache"))
    operating_point.cache_clear()
    yield tmp_path / "cache"
    operating_point.cache_clear()


def quiet(fn, *args):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the small mill's fallback start is reported
        return fn(*args)


def entries(folder):
    return sorted((folder / "operating_points").glob("*.npz"))


def same_bits(a: OperatingPoint, b: OperatingPoint) -> bool:
    for f in dataclasses.fields(OperatingPoint):
        x, y = getattr(a, f.name), getattr(b, f.name)
        if isinstance(x, np.ndarray):
            if x.dtype != y.dtype or x.shape != y.shape or x.tobytes() != y.tobytes():
                return False
        elif type(x) is not type(y) or (x != y and not (isinstance(x, float) and np.isnan(x) and np.isnan(y))):
            return False
    return True


def rollout(seed: int = 4) -> np.ndarray:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        env = LadderMillEnv(**SMALL)
    obs, _ = env.reset(seed=seed)
    rng = np.random.default_rng(seed)
    out = [obs]
    for _ in range(8):
        obs, r, *_ = env.step(rng.uniform(-0.3, 0.3, env.action_space.shape).astype(np.float32))
        out += [obs, np.array([r])]
    return np.concatenate([np.ravel(o) for o in out])


def test_read_back_is_the_recomputation_bit_for_bit_and_rolls_out_the_same(cache, monkeypatch):
    first, hit = quiet(cached_operating_point, "laddermill", OPTIONS, SETTLE)
    assert not hit and len(entries(cache)) == 1
    again, hit = quiet(cached_operating_point, "laddermill", OPTIONS, SETTLE)
    assert hit
    fresh = quiet(compute_operating_point, "laddermill", OPTIONS, SETTLE)  # never reads the cache
    assert same_bits(again, fresh) and same_bits(first, fresh)
    assert not again.state.flags.writeable and isinstance(again.converged, bool) and again.note == fresh.note
    cached = rollout()  # the env's start read from the entry
    operating_point.cache_clear()
    monkeypatch.setenv(op_cache.CACHE_VARIABLE, op_cache.OFF)  # the env's start computed again
    recomputed = rollout()
    assert entries(cache) and cached.tobytes() == recomputed.tobytes()


def test_a_non_converged_start_is_reported_when_read_back_too(cache):
    quiet(cached_operating_point, "laddermill", OPTIONS, SETTLE)
    with pytest.warns(RuntimeWarning, match="NO periodic motion"):
        op = operating_point("laddermill", OPTIONS, SETTLE)
    assert not op.converged


@pytest.mark.parametrize("damage", ["truncate", "flip", "foreign", "garbage"])
def test_a_damaged_or_foreign_entry_is_recomputed(cache, damage):
    good, _ = quiet(cached_operating_point, "laddermill", OPTIONS, SETTLE)
    (path,) = entries(cache)
    raw = path.read_bytes()
    if damage == "truncate":
        path.write_bytes(raw[: len(raw) // 2])
    elif damage == "flip":  # one byte inside the state's float64 data (uncompressed npz)
        i = raw.index(good.state[:4].tobytes()) + 3
        path.write_bytes(raw[:i] + bytes([raw[i] ^ 0x55]) + raw[i + 1:])
    elif damage == "foreign":  # a whole entry with another key at this name
        op_cache.write_entry(path, "0" * 64, {f.name: getattr(good, f.name) for f in dataclasses.fields(good)})
    else:
        path.write_bytes(b"not an npz file")
    key = op_cache.entry_key("operating_point", mill_scene("laddermill", OPTIONS, 2), SETTLE)
    assert op_cache.read_entry(path, key) is None
    op, hit = quiet(cached_operating_point, "laddermill", OPTIONS, SETTLE)
    assert not hit and same_bits(op, good)
    assert op_cache.read_entry(path, key) is not None  # rewritten whole


def test_a_changed_input_is_a_new_key(cache):
    sc = mill_scene("laddermill", OPTIONS, 2)
    key = op_cache.entry_key("operating_point", sc, SETTLE)
    assert key == op_cache.entry_key("operating_point", mill_scene("laddermill", OPTIONS, 2), SETTLE)
    assert key != op_cache.entry_key("operating_point", sc, SettleConfig(max_time=31.0))
    assert key != op_cache.entry_key("operating_point", mill_scene("laddermill", (("n_wings", 21),), 2), SETTLE)
    wind = dataclasses.replace(sc.assembly.wind, v0=sc.assembly.wind.v0 * (1 + 1e-15))  # one ulp of the wind
    changed = sc.replace(assembly=dataclasses.replace(sc.assembly, wind=wind))
    assert key != op_cache.entry_key("operating_point", changed, SETTLE)
    assert key == op_cache.entry_key("operating_point", sc.replace(file=sc.file.parent / "elsewhere.yaml"), SETTLE)
    with pytest.raises(TypeError, match="cannot fingerprint"):
        op_cache.entry_key("operating_point", object())


def test_cache_folder_off_and_unwritable(tmp_path, monkeypatch):
    monkeypatch.setenv(op_cache.CACHE_VARIABLE, "off")
    assert op_cache.cache_dir() is None and op_cache.entry_path("operating_point", "x", "0" * 64) is None
    monkeypatch.delenv(op_cache.CACHE_VARIABLE)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert op_cache.cache_dir() == tmp_path / "xdg" / "laddermill_gym"
    blocker = tmp_path / "a_file"
    blocker.write_text("")
    monkeypatch.setenv(op_cache.CACHE_VARIABLE, str(blocker))
    path = op_cache.entry_path("operating_point", "mill", "1" * 64)
    with pytest.warns(RuntimeWarning, match=f"{op_cache.CACHE_VARIABLE}: cannot write the cache entry"):
        assert op_cache.write_entry(path, "1" * 64, {"x": np.zeros(3)}) is False
    assert op_cache.read_entry(path, "1" * 64) is None


#: the fresh process: every source file whose Python code runs while the operating point is computed
TRACE = """
import sys, warnings
warnings.simplefilter("ignore")
from laddermill_gym.envs.laddermill.operating_point import SettleConfig, compute_operating_point, mill_scene
# numba's cache index of a kernel the craft shares (kernels/integrate.rhs_entry) unpickles the craft's types, importing
# the rotorcraft's modules (none of their code runs in the computation); imported before the trace, as the
# package's import did before the envs' classes became lazy
import laddermill_gym.rotorcraft.craft_kernels
mill_scene("laddermill", (("n_wings", 11),), 2)
files = set()
def tracer(frame, event, arg):
    files.add(frame.f_code.co_filename)
sys.setprofile(tracer)
compute_operating_point("laddermill", (("n_wings", 11),), SettleConfig(max_time=5.0), warn=False)
sys.setprofile(None)
print("\\n".join(sorted(files)))
"""


def test_every_source_file_the_computation_runs_is_hashed():
    out = subprocess.run([sys.executable, "-c", TRACE], capture_output=True, text=True, check=True).stdout.split()
    pkg = op_cache.PACKAGE
    ran = {p for p in out if p.startswith(str(pkg))}
    assert any("periodic.py" in p for p in ran) and any("simulator.py" in p for p in ran)
    hashed = {str(pkg / f) for f in op_cache.SOURCE_FILES}
    outside = [p for p in ran if p not in hashed
               and not any(p.startswith(str(pkg / d) + "/") for d in op_cache.SOURCE_DIRS)]
    assert not outside, outside
