"""``far_call``: call a compiled kernel from jitted code through its machine-code address instead of linking it.

Why (issue 32 point 1, docs/cold_start.md): numba links every callee's optimised module into its caller's library
and runs LLVM's module passes and code generation over the whole again, in every layer of a call chain. The step
kernel's chain (step kernel -> fixed-step driver -> W method's loop -> right-hand side, Jacobian, ...) emitted the
same callee tree three times, and no layer could start compiling before the one below it had finished. A call made
through this module's function compiles as an indirect call: the caller's library holds its own code only, and the
caller compiles without the callee. Used where a call is rare and its callee large: the integrators under the
fixed-step driver (``kernels/fixed_steps.py``, one call per run of steps), the observation's element loop
(``kernels/rigid/kinds.py``, one call per env step) and the rigid kinds' right-hand sides under the entry Python
calls (``kernels/integrate.rhs_entry``: the static equilibria and trims).

How: ``f_far = far_call(f, restype)`` (``f`` a numba dispatcher defined at module level, ``restype`` the numba type
it returns, stated because the caller no longer compiles it) is an intrinsic with ``f``'s parameters. At a call
site it emits, in the caller's module, a private pointer cell (null when the code is loaded) and the call site's
key: ``f``'s module, name and the argument types of the call (pickled). The first call finds the cell null and
asks :func:`resolve` (a C callback registered with LLVM as ``laddermill_far_resolve``) for the address of ``f``
compiled for those types: it compiles ``f`` for them, or loads it from numba's on-disk cache, exactly the
specialisation a linked call would have used, checks the return type and stores the address in the cell. Every
later call loads the cell and calls through it with numba's own calling convention (its status and exception
propagate as from a linked call). So callers cache on disk as usual: nothing process-specific is compiled in.

What it costs: one load and a predictable branch per call, and every argument passed as numba passes it, each
namedtuple field by field (the model and workspace: some 500 values), where LLVM drops a linked callee's unused
ones or inlines it. So it is for calls that are rare beside their callee's work: called by address, the W step's
23 calls of its parts per step cost TetheredWing-v0's and Rotorcraft-v0's vector envs 5-17 % of their steps/s at
512 copies (2026-12-03), and they stay linked. The caller's arithmetic is the callee's as compiled on its own:
the same bits as linked unless LLVM had inlined it; each use here is checked by hashing the envs' trajectories
against the linked code. A failure to resolve (``f`` does not compile for the types, or returns another type)
prints its traceback to stderr and raises ``RuntimeError`` from the caller; it never calls a null address. A kernel
with parallel loops that reaches a call by address must be ``nogil``: its worker threads may ask the resolver,
which takes the GIL.
"""

from __future__ import annotations

import ctypes
import hashlib
import importlib
import inspect
import pickle
import sys
import traceback

import llvmlite.binding as llb
from llvmlite import ir
from numba.core import cgutils, config
from numba.core.callconv import excinfo_t
from numba.extending import intrinsic

__all__ = ["RESOLVE_SYMBOL", "far_call", "resolve", "resolved"]

#: the C symbol under which the callers' code finds :func:`resolve`
RESOLVE_SYMBOL = "laddermill_far_resolve"
#: call-site key (the pickled payload) -> address, the calls resolved in this process
_ADDRESSES: dict[bytes, int] = {}


def _callee(modname: str, qualname: str):
    obj = importlib.import_module(modname)
    for part in qualname.split("."):
        obj = getattr(obj, part)
    return obj


def resolve(payload: bytes) -> int:
    """The address of the kernel a call site names (``payload``: pickled (module, qualified name, argument types,
    return type)) compiled for those argument types; compiles it or loads it from numba's cache on the first
    request, raises ``TypeError`` when it returns another type than the call site expects."""
    got = _ADDRESSES.get(payload)
    if got is not None:
        return got
    modname, qualname, argtypes, restype = pickle.loads(payload)  # noqa: S301 (written by this module's codegen)
    disp = _callee(modname, qualname)
    sig = tuple(argtypes)
    disp.compile(sig)
    cres = disp.overloads[sig]
    if cres.signature.return_type != restype:
        raise TypeError(f"far_call: {modname}.{qualname} returns {cres.signature.return_type} for {sig}, "
                        f"its caller was compiled for {restype}")
    address = cres.library.get_pointer_to_function(cres.fndesc.llvm_func_name)
    if not address:
        raise RuntimeError(f"far_call: {modname}.{qualname} has no compiled function for {sig}")
    _ADDRESSES[payload] = address
    return address


def resolved() -> list[tuple[str, str]]:
    """(module, qualified name) of every call resolved in this process, in the order of their first calls."""
    return [pickle.loads(p)[:2] for p in _ADDRESSES]  # noqa: S301


def _resolve_from_c(ptr, n):
    """The callback the compiled call sites call (ctypes takes the GIL): 0 after printing the traceback on any
    error, so that the caller raises instead of calling a null address."""
    try:
        return resolve(ctypes.string_at(ptr, n))
    except BaseException:  # noqa: BLE001 (reported here; the caller raises RuntimeError)
        print("far_call: could not resolve a kernel's address:\n" + traceback.format_exc(), file=sys.stderr,
              flush=True)
        return 0


_RESOLVE_TYPE = ctypes.CFUNCTYPE(ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int64)
_RESOLVE_C = _RESOLVE_TYPE(_resolve_from_c)  # kept alive with the module
llb.add_symbol(RESOLVE_SYMBOL, ctypes.cast(_RESOLVE_C, ctypes.c_void_p).value)

_I8P = ir.IntType(8).as_pointer()
_UNRESOLVED = "a kernel called through its address could not be resolved (far_call: the traceback is on stderr)"


def _global(module, name: str, make):
    try:
        return module.get_global(name)
    except KeyError:
        return make()


def _address_of(builder, payload: bytes):
    """The callee's address for this call site: the module's cell, filled by the resolver on the first call."""
    module = builder.module
    key = hashlib.sha1(payload).hexdigest()  # noqa: S324 (a name, not security)

    def make_cell():
        cell = ir.GlobalVariable(module, _I8P, name=f".laddermill.far.cell.{key}")
        cell.linkage = "internal"
        cell.initializer = ir.Constant(_I8P, None)
        return cell

    def make_key():
        data = ir.Constant(ir.ArrayType(ir.IntType(8), len(payload)), bytearray(payload))
        glob = ir.GlobalVariable(module, data.type, name=f".laddermill.far.key.{key}")
        glob.linkage = "internal"
        glob.global_constant = True
        glob.initializer = data
        return glob

    cell = _global(module, f".laddermill.far.cell.{key}", make_cell)
    keyed = _global(module, f".laddermill.far.key.{key}", make_key)
    resolver = _global(module, RESOLVE_SYMBOL,
                       lambda: ir.Function(module, ir.FunctionType(_I8P, [_I8P, ir.IntType(64)]), name=RESOLVE_SYMBOL))
    slot = cgutils.alloca_once(builder, _I8P)
    builder.store(builder.load_atomic(cell, "monotonic", 8), slot)
    with builder.if_then(cgutils.is_null(builder, builder.load(slot)), likely=False):
        got = builder.call(resolver, [builder.bitcast(keyed, _I8P), ir.Constant(ir.IntType(64), len(payload))])
        builder.store_atomic(got, cell, "monotonic", 8)
        builder.store(got, slot)
    return builder.load(slot)


def _call_through(context, builder, restype, argtypes, llargs, payload: bytes):
    address = _address_of(builder, payload)
    with builder.if_then(cgutils.is_null(builder, address), likely=False):
        context.call_conv.return_user_exc(builder, RuntimeError, (_UNRESOLVED,))
    cc = context.call_conv
    callee = builder.bitcast(address, cc.get_function_type(restype, argtypes).as_pointer())
    retty = cc.get_return_type(restype).pointee
    retval = cgutils.alloca_once(builder, retty)
    builder.store(cgutils.get_null_value(retty), retval)
    excinfo = cgutils.alloca_once(builder, ir.PointerType(excinfo_t), name="excinfo")
    packed = list(cc._get_arg_packer(argtypes).as_arguments(builder, llargs))  # numba's own argument layout
    code = builder.call(callee, [retval, excinfo, *packed])
    status = cc._get_return_status(builder, code, builder.load(excinfo))
    with cgutils.if_unlikely(builder, status.is_error):
        cc.return_status_propagate(builder, status)
    return context.get_returned_value(builder, restype, builder.load(retval))


def far_call(dispatcher, restype):
    """A function for jitted code that calls ``dispatcher`` (module level, positional parameters) through its
    compiled address; ``restype`` is the numba type it returns (``types.int64``, ``types.none``, ...). Every
    parameter is passed (a default of the kernel's is not applied). Under
    ``NUMBA_DISABLE_JIT`` it is the Python function itself."""
    py = dispatcher.py_func
    if config.DISABLE_JIT:
        return py
    params = list(inspect.signature(py).parameters.values())
    if any(p.kind not in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) for p in params):
        raise TypeError(f"far_call: {py.__qualname__} must take positional parameters only")
    modname, qualname = py.__module__, py.__qualname__
    if getattr(sys.modules.get(modname), qualname, None) is not dispatcher:
        raise TypeError(f"far_call: {qualname} is not a module-level name of {modname}: the resolver finds the "
                        "kernel by that name")

    def typer(typingctx, *argtypes):
        payload = pickle.dumps((modname, qualname, tuple(argtypes), restype), protocol=4)

        def codegen(context, builder, signature, llargs):
            return _call_through(context, builder, restype, list(argtypes), list(llargs), payload)
        return restype(*argtypes), codegen

    names = ", ".join(p.name for p in params)
    namespace = {"typer": typer}
    exec(f"def {py.__name__}_far(typingctx, {names}):\n    return typer(typingctx, {names})\n",  # noqa: S102
         namespace)
    fn = namespace[f"{py.__name__}_far"]
    fn.__module__ = modname
    fn.__qualname__ = f"{qualname}_far"
    fn.__doc__ = f"{qualname} called through its compiled address (kernels/far_call.py)"
    return intrinsic(fn)
