"""``kernels/callee_jit.py``: kernels compiled without a CPython wrapper (issue 32 point 1).

Oracles: the pure-Python function (``py_func``) for what a call returns, from compiled code and from Python; numba's
own compile result for what was compiled (the functions LLVM defined in the kernel's library, against a plain
``njit`` of the same function as the control).
"""

from __future__ import annotations

import numpy as np
import pytest
from numba import njit, typeof

from laddermill_gym.kernels.callee_jit import CalleeDispatcher, callee_njit


def _weighted(x, w, scale=2.0):
    acc = 0.0
    for i in range(x.size):
        acc += x[i] * w[i]
    return acc * scale


kernel = callee_njit(error_model="numpy", fastmath={"contract"})(_weighted)
plain = njit(error_model="numpy", fastmath={"contract"})(_weighted)


@njit
def _caller(x, w):
    return kernel(x, w, 3.0) + kernel(x, w)


def _defined(disp, sig) -> list[str]:
    return [f.name for f in disp.overloads[sig].library.get_defined_functions()]


def test_compiled_without_the_cpython_wrapper():
    x, w = np.linspace(0.0, 1.0, 7), np.linspace(1.0, 2.0, 7)
    _caller(x, w)
    sig = (typeof(x), typeof(w), typeof(3.0))
    kernel.compile(sig)
    plain.compile(sig)
    assert any("cpython" in n for n in _defined(plain, sig))  # the control: njit emits one
    assert not any("cpython" in n for n in _defined(kernel, sig))
    assert isinstance(kernel, CalleeDispatcher)


def test_calls_from_compiled_code_and_from_python_give_the_python_result():
    rng = np.random.default_rng(4)
    x, w = rng.normal(size=11), rng.normal(size=11)
    want = _weighted(x, w, 3.0) + _weighted(x, w)
    assert _caller(x, w) == pytest.approx(want, rel=1e-12)
    # from Python: through the jitted entry (no crash on the missing wrapper), defaults and keywords kept
    assert kernel(x, w) == pytest.approx(_weighted(x, w), rel=1e-12)
    assert kernel(x, w, scale=-1.5) == pytest.approx(_weighted(x, w, -1.5), rel=1e-12)
    assert kernel.python_entry() is kernel.python_entry()  # built once


def test_keyword_only_parameters_are_refused_when_called_from_python():
    def f(x, *, k=1.0):
        return x * k

    d = callee_njit()(f)
    with pytest.raises(TypeError, match="positional parameters only"):
        d(1.0)


def test_the_rigid_kernels_callees_have_no_cpython_wrapper():
    """The kernels that only compiled code calls in a W step and the right-hand sides (the cold start's list in
    docs/cold_start.md) are compiled so, and cached on disk."""
    from laddermill_gym.kernels import moving_cable
    from laddermill_gym.kernels.rigid import body_jacobian, cable_jacobian, kinds, rhs2d, rhs3d, rosenbrock
    from laddermill_gym.rotorcraft import craft_kernels

    modules = (rhs3d, rhs2d, body_jacobian, cable_jacobian, rosenbrock, kinds, craft_kernels, moving_cable)
    found = {d.py_func.__name__: d for m in modules for d in vars(m).values() if isinstance(d, CalleeDispatcher)}
    assert set(found) == {
        "assemble3d", "rhs3d", "add_body_jacobian", "add_body_force", "_loads", "add_cable_stiffness",
        "add_stiffness_force", "_element_ends", "_add_lever_turn", "_add_end_pull", "_stage_increment", "_mass_times",
        "rigid3d_check", "craft_loads", "_air_at", "rhs2d", "rigid2d_check", "station3d_rhs", "station2d_rhs",
        "mill3d_check", "mill2d_check", "transfer_2d"}
    assert all(d.targetoptions["no_cpython_wrapper"] for d in found.values())
    assert all(type(d._cache).__name__ == "FunctionCache" for d in found.values())  # cache=True
