"""``kernels/far_call.py``: a kernel called through its compiled address gives what a linked call gives, is absent
from its caller's library, resolves again after a load from numba's cache in a fresh process, propagates the
callee's exception, and fails with a clear error (never a crash) when it cannot be resolved."""

import os
import subprocess
import sys
import textwrap
import threading

import numpy as np
import pytest
from numba import njit, types

from laddermill_gym.kernels.callee_jit import callee_njit
from laddermill_gym.kernels.far_call import far_call, resolved


@callee_njit(cache=False)
def scaled_sum(x, k):
    """Test kernel: writes sum(x) * k into x[0] and returns the count of entries above k (ValueError for k < 0)."""
    if k < 0.0:
        raise ValueError("scaled_sum: k must not be negative")
    s = 0.0
    n = 0
    for v in x:
        s += v
        if v > k:
            n += 1
    x[0] = s * k
    return n


scaled_sum_far = far_call(scaled_sum, types.int64)
scaled_sum_wrong = far_call(scaled_sum, types.float64)  # the kernel returns int64: resolving it must fail


@njit(nogil=True)
def through_address(x, k):
    return scaled_sum_far(x, k) + 100


scaled_sum_far_threads = far_call(scaled_sum, types.int64)  # a call site of its own, first called from six threads


@njit(nogil=True)
def through_address_threads(x, k):
    return scaled_sum_far_threads(x, k) + 100


@njit
def linked(x, k):
    return scaled_sum(x, k) + 100


@njit
def wrongly_typed(x, k):
    return scaled_sum_wrong(x, k)


def test_same_result_as_linked_and_python():
    x1, x2, x3 = (np.linspace(0.0, 2.0, 7) for _ in range(3))
    assert through_address(x1, 0.5) == linked(x2, 0.5) == scaled_sum.py_func(x3, 0.5) + 100
    assert x1.tobytes() == x2.tobytes() == x3.tobytes()
    assert ("tests.test_far_call", "scaled_sum") in resolved() or (__name__, "scaled_sum") in resolved()


def test_callee_not_linked_into_caller():
    x = np.ones(3)
    through_address(x, 1.0)
    linked(np.ones(3), 1.0)
    callee = scaled_sum.overloads[scaled_sum.signatures[0]].library
    far_lib = through_address.overloads[through_address.signatures[0]].library
    linked_lib = linked.overloads[linked.signatures[0]].library
    assert callee in linked_lib._linking_libraries  # the control: numba links a plain call's callee
    assert callee not in far_lib._linking_libraries
    assert ".laddermill.far.cell." in far_lib.get_llvm_str()


def test_callee_exception_propagates():
    with pytest.raises(ValueError, match="k must not be negative"):
        through_address(np.ones(3), -1.0)


def test_wrong_return_type_is_an_error_not_a_crash(capfd):
    with pytest.raises(RuntimeError, match="could not be resolved"):
        wrongly_typed(np.ones(3), 1.0)
    err = capfd.readouterr().err
    assert "scaled_sum returns int64" in err and "compiled for float64" in err


def test_first_calls_from_threads_at_once():
    """Six threads make the first calls of a call site at once (a site of its own: the file's other tests resolve
    ``through_address``'s first, so this test resolved nothing when the file ran in its order; review of
    2026-12-08)."""
    out = [None] * 6

    def run(i):
        x = np.arange(5.0)
        out[i] = (through_address_threads(x, 2.0), x[0])

    threads = [threading.Thread(target=run, args=(i,)) for i in range(6)]
    for th in threads:
        th.start()
    for th in threads:
        th.join(timeout=120)
    assert not any(th.is_alive() for th in threads)
    assert out == [(102, 20.0)] * 6


def test_refuses_what_it_cannot_find_again():
    @callee_njit()
    def local_kernel(x):
        return x

    with pytest.raises(TypeError, match="not a module-level name"):
        far_call(local_kernel, types.float64)


MODULE = """
import numpy as np
from numba import njit, types
from laddermill_gym.kernels.callee_jit import callee_njit
from laddermill_gym.kernels.far_call import far_call

@callee_njit(cache=True)
def inner(x, k):
    for i in range(x.size):
        x[i] = x[i] * k + 1.0
    return x.size

inner_far = far_call(inner, types.int64)

@njit(cache=True)
def outer(x, k):
    return inner_far(x, k) * 2
"""


def test_cached_caller_resolves_in_a_fresh_process(tmp_path):
    (tmp_path / "far_mod.py").write_text(textwrap.dedent(MODULE))
    script = ("import numpy as np, far_mod\nx = np.arange(4.0)\nr = far_mod.outer(x, 3.0)\n"
              "print(r, x.tolist(), sum(far_mod.outer.stats.cache_hits.values()))\n")
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"), PYTHONPATH=str(tmp_path))
    runs = [subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, timeout=300,
                           check=True).stdout.split() for _ in range(2)]
    expect = ["8", "[1.0,", "4.0,", "7.0,", "10.0]"]
    assert runs[0] == [*expect, "0"]  # compiled
    assert runs[1] == [*expect, "1"]  # loaded from the cache, the callee resolved in this process
