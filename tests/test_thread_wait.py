"""``import laddermill_gym`` makes numba's OpenMP workers wait passively unless the user chose a policy
(``kernels/thread_wait.py``, issue 32 point 3): the variable's logic, what libgomp itself reports it runs under
(``OMP_DISPLAY_ENV=verbose``, libgomp's own print-out of its settings: the oracle; its spin count before a worker
sleeps is 300000 by default and 0 when passive), and the same bits of a vector env's
steps whatever the policy."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import pytest

from laddermill_gym.kernels.thread_wait import PASSIVE, WAIT_VARIABLE, passive_openmp_wait

# a fresh process: import the package, run a small parallel numba function (numba's pool and libgomp start there)
_POOL = textwrap.dedent("""
    import os, sys
    import numpy as np
    if sys.argv[1] == "package":
        import laddermill_gym
    import numba
    from numba import njit, prange

    @njit(parallel=True)
    def twice(a):
        for i in prange(a.size):
            a[i] *= 2.0

    a = np.ones(64)
    twice(a)
    sys.stdout.write(repr((os.environ.get("OMP_WAIT_POLICY"), numba.threading_layer(), float(a.sum()))) + "\\n")
""")

# a fresh process: 12 steps of TetheredWing-v0's native vector env at 4 copies on two threads, the bits printed
_STEPS = textwrap.dedent("""
    import hashlib, sys
    import numpy as np
    import gymnasium as gym
    import laddermill_gym
    env = gym.make_vec("laddermill_gym/TetheredWing-v0", num_envs=4, vectorization_mode="vector_entry_point",
                       parallel=True)
    obs, _ = env.reset(seed=3)
    rng = np.random.default_rng(0)
    h = hashlib.sha256(obs.tobytes())
    for _ in range(12):
        obs, rew, term, trunc, _ = env.step(rng.uniform(-1, 1, env.action_space.shape).astype(np.float32))
        h.update(obs.tobytes() + rew.tobytes() + term.tobytes() + trunc.tobytes())
    sys.stdout.write(h.hexdigest() + "\\n")
""")


def _run(code: str, policy: str | None, display: bool = False, *args: str) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in (WAIT_VARIABLE, "OMP_DISPLAY_ENV")}
    env["NUMBA_NUM_THREADS"] = "2"
    if policy is not None:
        env[WAIT_VARIABLE] = policy
    if display:
        env["OMP_DISPLAY_ENV"] = "verbose"
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, env=env, check=True)


def test_sets_passive_only_where_the_user_set_nothing():
    env: dict[str, str] = {}
    assert passive_openmp_wait(env) is True and env == {WAIT_VARIABLE: PASSIVE}
    assert passive_openmp_wait(env) is False and env == {WAIT_VARIABLE: PASSIVE}
    for users in ("active", "ACTIVE", "", "passive"):
        env = {WAIT_VARIABLE: users, "OTHER": "1"}
        assert passive_openmp_wait(env) is False and env == {WAIT_VARIABLE: users, "OTHER": "1"}


@pytest.mark.parametrize("given, imported, reported", [
    (None, "package", ("PASSIVE", "0")),  # the import: workers sleep at once
    ("active", "package", ("ACTIVE", None)),  # the user's choice is kept
    (None, "numba only", ("PASSIVE", "300000")),  # the control: libgomp's default spin without the package
])
def test_libgomp_runs_under_the_policy(given, imported, reported):
    """libgomp's own print-out of its settings (OMP_DISPLAY_ENV=verbose, to stderr when numba's pool loads it)
    names the policy and the spin count: no spin after ``import laddermill_gym``, the user's policy where one was
    set before it, libgomp's default spin (300000) in a process that does not import the package."""
    out = _run(_POOL, given, True, imported)
    policy, layer, total = eval(out.stdout.strip().splitlines()[-1])
    assert total == 128.0
    assert policy == (given or (PASSIVE if imported == "package" else None))
    if layer != "omp":
        pytest.skip(f"numba's threading layer is {layer!r}, not OpenMP: the policy does not apply")
    assert f"OMP_WAIT_POLICY = '{reported[0]}'" in out.stderr
    if reported[1] is not None:
        assert f"GOMP_SPINCOUNT = '{reported[1]}'" in out.stderr


@pytest.mark.slow  # two fresh processes that compile the wing's batch kernels (about a minute)
def test_a_vector_env_steps_to_the_same_bits_whatever_the_policy():
    digests = {p: _run(_STEPS, p).stdout.strip().splitlines()[-1] for p in (None, "active")}
    assert len(digests[None]) == 64 and digests[None] == digests["active"]
