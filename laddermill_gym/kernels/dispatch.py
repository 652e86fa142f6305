"""Compile-time dispatch of the kernels on the model kind and on the vehicle (the body-loads plug-in).

A model kind (rigid 3D, rigid in-plane; room for point masses) and a vehicle (winged body, rotorcraft) are
small namedtuples whose *class* names them. Their modules register implementations here:

* :func:`register_kind` (marker class, rhs, check): ``rhs(kind, t, x, u, dx, M, W) -> status`` writes the
  state derivative; ``check(kind, x, M, limits) -> status`` renormalises and checks a state after a step.
* :func:`register_vehicle` (vehicle class, loads): ``loads(vehicle, k, t, x, R, u, M, W, Dk, env) ->
  (fx, fy, fz, mx, my, mz)`` gives the external loads on rigid body k (body axes, about the CG) and may add
  apparent-mass terms to its diagonal block Dk; ``env`` = (s_mod, d_mod, sd_mod, dd_mod, zd) is the wind
  modulation, its rates and the body's vertical speed.

The generic kernels call :func:`model_rhs`, :func:`model_check` and :func:`body_loads`; numba resolves each
call by the argument's type when it compiles, so no branch is left at run time, a scene compiles only the
code it uses, adding a kind or a vehicle changes no existing kernel signature, and the compiled functions
cache across processes (a jitted callable passed as an argument would be recompiled in every process).
The generic rigid-body kernels import this module, never a vehicle.
"""

from numba.core import types
from numba.core.errors import TypingError
from numba.core.typing.templates import infer, infer_global, make_overload_template

from laddermill_gym.kernels.contract import EF_L0

_RHS: dict[type, object] = {}
_CHECK: dict[type, object] = {}
_LOADS: dict[type, object] = {}
_ENDS: dict[type, tuple] = {}
_ASSEMBLE: dict[type, object] = {}
_TENSIONS: dict[type, object] = {}
_RHS_FAR: dict[type, object] = {}


class _TypedOnly:
    """Template mixin of :func:`inline_overload`: the implementation's dispatcher is typed, never compiled."""

    def _get_jit_decorator(self):
        jitter = super()._get_jit_decorator()

        def typed_only(**options):
            decorate = jitter(**options)

            def make(pyfunc):
                disp = decorate(pyfunc)
                # numba types its IR for the inliner; a compiled copy would go unused (disable_compile() insists on
                # one compiled signature, so the flag it sets is set here)
                disp._can_compile = False
                return disp
            return make
        return typed_only


def inline_overload(func):
    """``numba.extending.overload(func, inline="always")`` without compiling the implementation on its own.

    numba types an always-inlined overload's implementation from its IR and inlines that IR into the caller, but
    first compiles it as a function of its own (``Dispatcher.get_call_template``) that is never called: for the
    dispatch lambdas below, whose one call links the whole right-hand side, that cost up to 3 s of LLVM each, per
    signature, about a tenth of a cold start (issue 32). Here the implementation's dispatcher has compiling
    disabled, so only the typing runs; the caller's code is the same (the inlined IR is the same)."""
    opts = {"no_cpython_wrapper": True, "nopython": True}  # numba.extending.overload's defaults

    def decorate(overload_func):
        base = make_overload_template(func, overload_func, opts, True, "always")
        template = type(base)(base.__name__, (_TypedOnly, base), {})
        infer(template)
        infer_global(func, types.Function(template))
        return overload_func
    return decorate


def register_kind(marker: type, rhs, check) -> None:
    """Register the right-hand side and the post-step check of a model kind (``marker`` namedtuple class)."""
    _RHS[marker] = rhs
    _CHECK[marker] = check


def register_assemble(marker: type, assemble) -> None:
    """Register the assembly of a model kind whose velocities are the 3D rigid blocks (bodies, free nodes):
    ``assemble(kind, t, x, u, dx, M, W) -> status`` writes every rate of dx except the block velocities' (those
    are the solution of the block system), the mass matrix blocks into W.D, W.U, the generalised forces into W.bv,
    the tensions into W.tension and the rotations into W.Rw. A kind with one runs the linearly implicit
    integrators (``kernels/rigid/rosenbrock.py``)."""
    _ASSEMBLE[marker] = assemble


def register_tensions(marker: type, tensions) -> None:
    """Register what an observation reads of a state of a model kind without its right-hand side:
    ``tensions(kind, t, x, u, dx, M, W) -> status`` writes the element tensions into W.tension and the rotations into
    W.Rw, bit for bit as the kind's right-hand side leaves them. A kind without one is observed through its
    right-hand side (:func:`model_tensions`)."""
    _TENSIONS[marker] = tensions


def register_rhs_far(marker: type, rhs_far) -> None:
    """Register a model kind's right-hand side called through its compiled address (``kernels/far_call.py``):
    ``rhs_far(kind, t, x, u, dx, M, W) -> status``, the registered ``rhs`` (:func:`register_kind`) with its large
    callee not linked. :func:`model_rhs_entry` uses it: the right-hand side that Python calls (the static
    equilibria and trims) then compiles as a small function instead of linking the kind's whole right-hand side
    again (issue 32 point 1)."""
    _RHS_FAR[marker] = rhs_far


def has_assemble(kind) -> bool:
    """Whether the model kind ``kind`` (a marker instance) registered an assembly (Python side)."""
    return type(kind) in _ASSEMBLE


def register_vehicle(marker: type, loads) -> None:
    """Register the body-loads function of a vehicle (``marker`` namedtuple class)."""
    _LOADS[marker] = loads


def register_moving_ends(marker: type, rest_length, elongation_rate) -> None:
    """Register element rest lengths that change in time for a model kind (the moving cable):
    ``rest_length(kind, e, t, x, M) -> l0`` [m] and ``elongation_rate(kind, e, t, x, M, ln, l0, ld) -> rate``
    [m/s], the material elongation rate l0 d(eps)/dt from the element's length ln [m] and its rate ld [m/s].
    A kind that registers none has the packed lengths ``M.ef[e, EF_L0]`` and rate ``ld``."""
    _ENDS[marker] = (rest_length, elongation_rate)


def has_moving_ends(kind_type) -> bool:
    """Whether the model kind of numba type ``kind_type`` (a marker's type, inside an overload) registered element
    rest lengths that change (:func:`register_moving_ends`)."""
    return getattr(kind_type, "instance_class", None) in _ENDS


def _lookup(table: dict, typ, what: str):
    cls = getattr(typ, "instance_class", None)
    if cls not in table:
        raise TypingError(f"no {what} registered for {typ} (known: {[c.__name__ for c in table]})")
    return table[cls]


def model_rhs(kind, t, x, u, dx, M, W):
    """State derivative of model kind ``kind`` (jitted code only)."""
    raise NotImplementedError("model_rhs is resolved inside numba kernels")


def model_rhs_entry(kind, t, x, u, dx, M, W):
    """:func:`model_rhs` for a kernel that Python calls: the kind's right-hand side through its address where it
    registered one (:func:`register_rhs_far`), else linked (jitted code only)."""
    raise NotImplementedError("model_rhs_entry is resolved inside numba kernels")


def model_check(kind, x, M, limits):
    """Post-step normalisation and check of model kind ``kind`` (jitted code only)."""
    raise NotImplementedError("model_check is resolved inside numba kernels")


def model_assemble(kind, t, x, u, dx, M, W):
    """Block assembly of model kind ``kind`` without the solve (jitted code only)."""
    raise NotImplementedError("model_assemble is resolved inside numba kernels")


def model_tensions(kind, t, x, u, dx, M, W):
    """Element tensions (W.tension) and rotations (W.Rw) of model kind ``kind`` at (t, x): its registered
    tensions (:func:`register_tensions`), else its right-hand side (into dx; status 1 for a singular mass
    matrix). Jitted code only."""
    raise NotImplementedError("model_tensions is resolved inside numba kernels")


def body_loads(vehicle, k, t, x, R, u, M, W, Dk, env):
    """External loads on rigid body k from its vehicle (jitted code only)."""
    raise NotImplementedError("body_loads is resolved inside numba kernels")


def rest_length(kind, e, t, x, M):
    """Unstretched length [m] of element e at time t in state x (jitted code only)."""
    raise NotImplementedError("rest_length is resolved inside numba kernels")


def elongation_rate(kind, e, t, x, M, ln, l0, ld):
    """Material elongation rate [m/s] of element e of length ln [m] changing at ld [m/s] (jitted code only)."""
    raise NotImplementedError("elongation_rate is resolved inside numba kernels")


@inline_overload(model_rhs)
def _model_rhs(kind, t, x, u, dx, M, W):
    impl = _lookup(_RHS, kind, "model kind right-hand side")
    return lambda kind, t, x, u, dx, M, W: impl(kind, t, x, u, dx, M, W)


@inline_overload(model_rhs_entry)
def _model_rhs_entry(kind, t, x, u, dx, M, W):
    cls = getattr(kind, "instance_class", None)
    impl = _RHS_FAR[cls] if cls in _RHS_FAR else _lookup(_RHS, kind, "model kind right-hand side")
    return lambda kind, t, x, u, dx, M, W: impl(kind, t, x, u, dx, M, W)


@inline_overload(model_check)
def _model_check(kind, x, M, limits):
    impl = _lookup(_CHECK, kind, "model kind check")
    return lambda kind, x, M, limits: impl(kind, x, M, limits)


@inline_overload(model_assemble)
def _model_assemble(kind, t, x, u, dx, M, W):
    impl = _lookup(_ASSEMBLE, kind, "model kind assembly (a linearly implicit integrator)")
    return lambda kind, t, x, u, dx, M, W: impl(kind, t, x, u, dx, M, W)


@inline_overload(model_tensions)
def _model_tensions(kind, t, x, u, dx, M, W):
    cls = getattr(kind, "instance_class", None)
    if cls in _TENSIONS:
        impl = _TENSIONS[cls]
        return lambda kind, t, x, u, dx, M, W: impl(kind, t, x, u, dx, M, W)
    rhs = _lookup(_RHS, kind, "model kind right-hand side")
    return lambda kind, t, x, u, dx, M, W: rhs(kind, t, x, u, dx, M, W)


@inline_overload(body_loads)
def _body_loads(vehicle, k, t, x, R, u, M, W, Dk, env):
    impl = _lookup(_LOADS, vehicle, "vehicle body loads")
    return lambda vehicle, k, t, x, R, u, M, W, Dk, env: impl(vehicle, k, t, x, R, u, M, W, Dk, env)


@inline_overload(rest_length)
def _rest_length(kind, e, t, x, M):
    cls = getattr(kind, "instance_class", None)
    if cls in _ENDS:
        impl = _ENDS[cls][0]
        return lambda kind, e, t, x, M: impl(kind, e, t, x, M)
    return lambda kind, e, t, x, M: M.ef[e, EF_L0]


@inline_overload(elongation_rate)
def _elongation_rate(kind, e, t, x, M, ln, l0, ld):
    cls = getattr(kind, "instance_class", None)
    if cls in _ENDS:
        impl = _ENDS[cls][1]
        return lambda kind, e, t, x, M, ln, l0, ld: impl(kind, e, t, x, M, ln, l0, ld)
    return lambda kind, e, t, x, M, ln, l0, ld: ld
