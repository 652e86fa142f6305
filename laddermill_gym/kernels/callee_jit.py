"""``callee_njit``: numba's ``njit`` for kernels that other kernels call, compiled without a CPython entry.

numba compiles every ``@njit`` function with a CPython wrapper, the code that unboxes each argument from Python
objects, even when only compiled code calls it. For the rigid-body kernels, whose arguments are the model and
workspace namedtuples of some 50 arrays, that wrapper is a large function: LLVM optimises and emits it with the
kernel (0.2-0.6 s each on this 2-core machine) and again inside every caller that links the kernel, where it is
dropped unused. 22 kernels use it: the rigid, in-plane, moving-cable and craft right-hand sides, their checks
and parts, and the W step's (issue 32 point 1, docs/cold_start.md).

A kernel decorated with :func:`callee_njit` is compiled with numba's ``no_cpython_wrapper`` option; the machine
code of the kernel itself, and of every kernel that calls it, is what ``@njit`` gives. Called from Python (a test,
a timing study), it does not crash: its first such call compiles a small jitted entry that calls it (not cached,
so it costs a compile in each process that does so) and every call goes through that entry. numba's own options
are passed through as for ``njit``.
"""

from __future__ import annotations

import inspect

from numba import njit
from numba.core import config
from numba.core.registry import CPUDispatcher

__all__ = ["CalleeDispatcher", "callee_njit"]


class CalleeDispatcher(CPUDispatcher):
    """A CPU dispatcher compiled without CPython wrappers; a call from Python goes through :meth:`python_entry`."""

    _entry = None

    def python_entry(self):
        """A jitted function of the same parameters that calls this kernel (built on the first call, then kept)."""
        if self._entry is None:
            sig = inspect.signature(self.py_func)
            names = list(sig.parameters)
            if any(p.kind not in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) for p in sig.parameters.values()):
                raise TypeError(f"{self.py_func.__qualname__}: callee_njit takes positional parameters only")
            args = ", ".join(names)
            namespace = {"kernel": self}
            exec(f"def entry({args}):\n    return kernel({args})\n", namespace)  # noqa: S102 (fixed template)
            entry = namespace["entry"]
            entry.__defaults__ = self.py_func.__defaults__
            entry.__qualname__ = f"{self.py_func.__qualname__}.python_entry"
            self._entry = njit(entry)
        return self._entry

    def __call__(self, *args, **kwargs):
        return self.python_entry()(*args, **kwargs)


def callee_njit(cache: bool = False, **options):
    """``numba.njit(cache=cache, **options)`` giving a :class:`CalleeDispatcher` (no CPython wrapper); use it as
    ``@callee_njit(cache=True, fastmath=...)``."""
    targetoptions = {**options, "nopython": True, "no_cpython_wrapper": True}

    def decorate(func):
        if config.DISABLE_JIT:
            return func
        disp = CalleeDispatcher(py_func=func, locals={}, targetoptions=targetoptions)
        if cache:
            disp.enable_caching()
        return disp
    return decorate
