"""Identical seeds give bit-identical rollouts whatever the state of numba's cache (issue 13 point 4): a process
that compiles the kernels and one that loads them from the cache it left must step LadderChain-v0 the same to the
last bit. They did not while the kernels allowed LLVM's reassociation ('reassoc' in fastmath): the observations
parted from step 8 at the float32 ulp. Slow: the first process compiles every kernel (about a minute)."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

_SCRIPT = textwrap.dedent("""
    import sys
    import gymnasium as gym
    import numpy as np
    import laddermill_gym
    env = gym.make("laddermill_gym/LadderChain-v0", episode_time=2.0)
    obs, _ = env.reset(seed=0)
    rng = np.random.default_rng(1)
    out = [obs]
    for _ in range(40):
        obs, _, term, trunc, _ = env.step(rng.uniform(-0.2, 0.2, env.action_space.shape).astype(np.float32))
        out.append(obs)
        if term or trunc:
            break
    np.save(sys.argv[1], np.array(out))
""")


def _rollouts(tmp_path, source: str, runs: dict) -> dict:
    """{name: the observations (steps + 1, obs_dim) the script ``source`` saved} of one fresh process per entry of
    ``runs`` (name -> the environment variables it adds), in order; each process must succeed."""
    script = tmp_path / "roll.py"
    script.write_text(source)
    out = {}
    for name, extra in runs.items():
        env = {**os.environ, "PYTHONDONTWRITEBYTECODE": "1", **extra}
        proc = subprocess.run([sys.executable, str(script), str(tmp_path / f"{name}.npy")], env=env,
                              capture_output=True, text=True, timeout=900)
        assert proc.returncode == 0, proc.stderr[-4000:]
        out[name] = np.load(tmp_path / f"{name}.npy")
    return out


@pytest.mark.slow
def test_compiled_and_cached_kernels_give_the_same_bits(tmp_path):
    cache = {"NUMBA_CACHE_DIR": str(tmp_path / "cache")}
    # the first fills the empty cache, the second loads from it
    r = _rollouts(tmp_path, _SCRIPT, {"compiled": cache, "cached": cache})
    a, b = r["compiled"], r["cached"]
    assert a.shape == b.shape and len(a) > 20
    np.testing.assert_array_equal(a, b)


_WING = textwrap.dedent("""
    import sys
    import warnings
    import gymnasium as gym
    import numpy as np
    import laddermill_gym
    warnings.simplefilter("ignore")
    env = gym.make("laddermill_gym/TetheredWing-v0")
    obs, _ = env.reset(seed=5)
    rng = np.random.default_rng(2)
    out = [obs]
    for _ in range(200):
        obs, _, term, trunc, _ = env.step((0.3 * rng.uniform(-1, 1, env.action_space.shape)).astype(np.float32))
        out.append(obs)
        if term or trunc:
            break
    venv = gym.make_vec("laddermill_gym/TetheredWing-v0", num_envs=3, vectorization_mode="vector_entry_point")
    obs, _ = venv.reset(seed=11)
    for _ in range(40):  # the vector env's step kernel: the one that parted on 2026-12-05
        obs, *_ = venv.step((0.3 * rng.uniform(-1, 1, venv.action_space.shape)).astype(np.float32))
        out.extend(obs)
    np.save(sys.argv[1], np.array(out))
""")


@pytest.mark.slow
def test_warmup_on_and_off_give_the_same_bits(tmp_path):
    """TetheredWing-v0 rolled out, single and as a 3-copy vector env, in two fresh processes, each with an empty numba
    cache and no start cache: one with the kernel warm-up (the default: the step kernel compiled in a second process
    against callees it loads from the cache), one with ``LADDERMILL_KERNEL_WARMUP=off`` (everything compiled in this
    process). Until 2026-12-06 they parted: a kernel that left numba's inherited options unset compiled with those of
    whichever caller needed it first (tests/test_kernel_flags.py; docs/numerics.md, "Bits and machines")."""
    r = _rollouts(tmp_path, _WING, {name: {"NUMBA_CACHE_DIR": str(tmp_path / f"cache_{name}"), "LADDERMILL_CACHE_DIR":
                                          "off", "LADDERMILL_KERNEL_WARMUP": name} for name in ("on", "off")})
    a, b = r["on"], r["off"]
    assert a.shape == b.shape and len(a) > 100
    np.testing.assert_array_equal(a, b)
