"""Every numba kernel of the package states the compile options numba would otherwise inherit (docs/numerics.md,
"Bits and machines").

numba compiles a jitted function that leaves ``_nrt``, ``fastmath`` or ``error_model`` unset with the values of the
function whose compile is in progress when it is first needed (numba's ``Flags.inherit_if_not_set``), and keeps that
one compile per argument types, in memory and in its on-disk cache. A kernel reached first from Python, or from a
caller with other options, so compiled to other machine code than when it was reached from a step kernel, and an
env's bits depended on which process compiled what first: the kernel warm-up on and off gave TetheredWing-v0's
vector env other bits (found 2026-12-05, fixed 2026-12-06)."""

from __future__ import annotations

import importlib
import pkgutil
import re

from numba import njit
from numba.core.compiler import Flags
from numba.core.dispatcher import Dispatcher

import laddermill_gym

#: the options numba's CPU target inherits from the caller when a function does not set them (numba/core/cpu.py);
#: ``forceinline`` is also inherited, and no kernel sets it (so none is compiled with it)
INHERITED = ("_nrt", "fastmath", "error_model")


def _dispatchers():
    """(module.name, dispatcher) of every numba dispatcher defined at the top level of a package module."""
    for info in pkgutil.walk_packages(laddermill_gym.__path__, "laddermill_gym."):
        if info.name.endswith("__main__"):
            continue
        module = importlib.import_module(info.name)
        for name, obj in vars(module).items():
            if isinstance(obj, Dispatcher) and obj.py_func.__module__ == info.name:
                yield f"{info.name}.{name}", obj


def _flags(dispatcher) -> str:
    """The options numba compiled the dispatcher's first overload with, from its mangled name's ABI tag."""
    tag = dispatcher.overloads[dispatcher.signatures[0]].fndesc.mangled_name
    m = re.search(r"B(\d+)(c8tJ)", tag)
    return Flags.demangle(tag[m.start(2):m.start(2) + int(m.group(1))])


def test_numba_still_compiles_a_callee_with_its_callers_unset_options():
    """The mechanism this file guards against: a callee without options compiled from a caller with fastmath and
    without NRT takes both; one that states its options keeps them."""

    @njit
    def loose(x):
        return x * 2.0 + 1.0

    @njit(_nrt=True, fastmath=False, error_model="python")
    def pinned(x):
        return x * 2.0 + 1.0

    @njit(fastmath={"contract"}, _nrt=False, error_model="numpy")
    def caller(x):
        return loose(x) + pinned(x)

    assert caller(1.0) == 6.0
    assert "contract" in _flags(loose) and "nrt=True" not in _flags(loose) and "error_model=numpy" in _flags(loose)
    assert "fastmath" not in _flags(pinned) and "nrt=True" in _flags(pinned)


def test_every_kernel_states_the_options_numba_would_inherit():
    found, missing = 0, []
    for name, d in _dispatchers():
        found += 1
        if d.targetoptions.get("inline") == "always":  # numba inlines its IR: compiled with its caller's options
            continue
        lacking = [k for k in INHERITED if k not in d.targetoptions]
        if lacking:
            missing.append(f"{name}: {', '.join(lacking)}")
    assert found > 200  # the walk reached the kernel modules
    assert not missing, "kernels that inherit their callers' options:\n" + "\n".join(missing)
