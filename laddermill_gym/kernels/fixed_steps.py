"""Fixed-step integration that steps onto the kinks of the wind's time modulation, for the single and the batched
simulators alike (one compiled implementation, so a batch copy and a single run agree bit for bit).

The modulation (``atmosphere/field.py``) is piecewise linear on the grid t0 + k dt_w and held outside it, so the
right-hand side has a kink wherever the slope of the speed factor or of the direction offset changes (the slopes
enter the wings' alpha-rate term). A Runge-Kutta or Rosenbrock-W step across a kink loses its order, and a step
that only ends on one still does: its last stage, evaluated on the kink, sees the next segment's slope. So a
step with a kink strictly inside is split there, and each piece runs with the straight line of its own segment
(``seg_*`` arrays of the workspace; the line is extended beyond the piece, so a stage on the piece's end sees the
piece's slope). ``ends`` mode also runs the steps that only start or end on a kink on their own line.

A kink closer than ``ALIGN_TOL`` of the step to a step's end counts as on it (no split), so a grid meant to be
aligned with the steps is not split by accumulated time roundoff. Steps away from every kink run exactly as the
plain fixed-step kernels run them (bit for bit).
"""

import math

from numba import njit, types

from laddermill_gym.kernels.contract import OK, TM_DT, TM_T0, KModel
from laddermill_gym.kernels.dispatch import inline_overload
from laddermill_gym.kernels.far_call import far_call
from laddermill_gym.kernels.integrate import rk4_advance
from laddermill_gym.kernels.rigid.rosenbrock import w_advance
from laddermill_gym.kernels.wind import modulation

#: a kink within this fraction of a step of the step's end is on it (see the module docstring)
ALIGN_TOL = 1e-9
#: the ``breaks`` argument: integrate across kinks / split steps with a kink inside / also give the steps that
#: start or end on a kink their own segment's line
BREAKS_OFF, BREAKS_INSIDE, BREAKS_ENDS = 0, 1, 2


# Inlined (no arithmetic, a tuple built): one compile less per caller signature (issue 32)
@njit(cache=True, inline="always")
def model_with_air(kind, vehicle, M, tmod, ms, md, gp, gv):
    """The packed model ``M`` with markers ``kind`` and ``vehicle`` and the given air (wind modulation grid tmod (2,),
    speed factors ms and direction offsets md (n_mod,), gust grid header gp and samples gv, or None)."""
    return KModel(kind, M.wf, tmod, ms, md, gp, gv, M.glob, M.wtype, M.tf, M.ac, M.node_mass, M.fixed, M.ek, M.ei,
                  M.ea, M.ef, M.ekd, M.echild, M.order, M.parent, M.bsz, M.sag, M.caero, vehicle)


def advance_fixed(t, x, u, dt, n, M, W, limits, tableau):
    """n fixed steps of dt [s] from t [s]: RK4 when ``tableau`` is None, else the Rosenbrock-W method of that
    tableau (``kernels/rigid/rosenbrock.py``). (status, steps). Jitted code only: the argument's type selects
    the method when numba compiles (an overload), so a scene compiles only its own method (``if tableau is
    None`` would prune the Rosenbrock branch for RK4 but compile RK4 beside every Rosenbrock method)."""
    raise NotImplementedError("advance_fixed is resolved inside numba kernels")


# The chosen integrator is called through its compiled address (kernels/far_call.py): its own cached dispatcher,
# compiled on its own, not linked into advance_breaks (numba optimised and emitted the whole integrator again in
# every caller, issue 32 point 1). An earlier version took the integrator's Python function as the overload's
# implementation, compiled (not cached: it crashed when it shared the integrator's cache index, 2026-11-30) in each
# process that compiled advance_breaks. rk4_advance takes (and ignores) ``tableau`` for this.
_RK4_FAR = far_call(rk4_advance, types.UniTuple(types.int64, 2))
_W_FAR = far_call(w_advance, types.UniTuple(types.int64, 2))


@inline_overload(advance_fixed)
def _advance_fixed(t, x, u, dt, n, M, W, limits, tableau):
    if isinstance(tableau, types.NoneType):
        return lambda t, x, u, dt, n, M, W, limits, tableau: _RK4_FAR(t, x, u, dt, n, M, W, limits, tableau)
    return lambda t, x, u, dt, n, M, W, limits, tableau: _W_FAR(t, x, u, dt, n, M, W, limits, tableau)


# The kink helpers below are inlined into the drivers (numba IR; about 4 s of a cold start as six compiles of
# their own, issue 32) and compiled with each driver's options (advance_breaks: no fastmath flags); the drivers'
# numpy error model only differs from theirs on a division by zero, which their guards (dt_w > 0, the step dt > 0)
# exclude; called from Python (sim/breakpoints.py) they compile on their own as before.
@njit(cache=True, inline="always")
def is_kink(k, ms, md):
    """Whether the slope of the modulation (speed factor ms or direction offset md, (n_mod,)) changes at grid
    point k (the slope is zero before the first and after the last point)."""
    n = ms.size
    ls = ms[k] - ms[k - 1] if k >= 1 else 0.0
    ld = md[k] - md[k - 1] if k >= 1 else 0.0
    rs = ms[k + 1] - ms[k] if k <= n - 2 else 0.0
    rd = md[k + 1] - md[k] if k <= n - 2 else 0.0
    return ls != rs or ld != rd


@njit(cache=True, inline="always")
def grid_range(ta, tb, tmod, n_mod):
    """Grid indices (first, last + 1) of the modulation points that may lie in [ta, tb] [s] (a superset by one
    point at each end; empty for a non-finite time or a single sample: no index is formed from a non-finite
    float)."""
    t0, dtw = tmod[TM_T0], tmod[TM_DT]
    if n_mod < 2 or not (math.isfinite(ta) and math.isfinite(tb) and dtw > 0.0):
        return 0, 0
    lo = (ta - t0) / dtw - 1.0
    hi = (tb - t0) / dtw + 2.0
    if hi < 0.0 or lo > n_mod:
        return 0, 0
    return max(0, int(math.floor(lo))), min(n_mod, int(math.ceil(hi)))


@njit(cache=True, inline="always")
def kink_place(k, tmod, t, dt):
    """Grid point k's time b [s] and where it falls among the steps of dt [s] from t [s]: (b, index i of the step
    it lies in, fraction f in [0, 1) of that step)."""
    b = tmod[TM_T0] + tmod[TM_DT] * k
    u = (b - t) / dt
    i = math.floor(u)
    return b, i, u - i


@njit(cache=True, inline="always")
def step_kinks(t, dt, j, tmod, ms, md):
    """Kinks of step j of the steps of dt [s] from t [s]: (how many lie strictly inside it, whether one lies on its
    start or end within ``ALIGN_TOL``). Classified by u = (kink - t) / dt against j, j + 1."""
    inside, on_end = 0, False
    k0, k1 = grid_range(t + j * dt, t + (j + 1) * dt, tmod, ms.size)
    for k in range(k0, k1):
        if not is_kink(k, ms, md):
            continue
        _, i, f = kink_place(k, tmod, t, dt)
        if f < ALIGN_TOL or f > 1.0 - ALIGN_TOL:
            r = i if f < 0.5 else i + 1  # the step boundary it sits on
            if r == j or r == j + 1:
                on_end = True
        elif i == j:
            inside += 1
    return inside, on_end


@njit(cache=True, inline="always")
def fill_segment(M, ta, tb, seg_tmod, seg_ms, seg_md):
    """The straight line that the modulation of M follows on [ta, tb] [s] (no kink inside), extended beyond it,
    as a four-sample modulation: [ta, tb] maps to the grid's second segment, so a stage on either end sees this
    segment's value and slope."""
    tm = 0.5 * (ta + tb)
    s, d, sd, dd = modulation(tm, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
    h = max(tb - ta, 1e-12)
    seg_tmod[TM_T0] = ta - h
    seg_tmod[TM_DT] = h
    for i in range(4):
        off = (ta - tm) + (i - 1.0) * h
        seg_ms[i] = s + sd * off
        seg_md[i] = d + dd * off


@njit(cache=True, inline="always")
def next_kink(tc, te, t, dt, j, tmod, ms, md):
    """The first kink of step j (of the steps of dt [s] from t [s]) strictly inside it and after tc [s], or the
    step's end te [s] when none is left."""
    k0, k1 = grid_range(tc, te, tmod, ms.size)
    for k in range(k0, k1):
        if not is_kink(k, ms, md):
            continue
        b, i, f = kink_place(k, tmod, t, dt)
        if i == j and ALIGN_TOL <= f <= 1.0 - ALIGN_TOL and b > tc:
            return b
    return te


# Without numba's runtime (_nrt=False): no reference counting of the per-copy array views (about 60 per copy and
# step; 7-8 % of TetheredWing-v0's vector step went to the atomic counts, issue 32). The copy's gust grid rows come
# through kernels/batch.copy_air_model, not a function that returns a view (numba forbids that without its runtime:
# c2dd978, 45dd361 had reverted this for it).
@njit(cache=True, inline="always")
def _advance_breaks(t, x, u, dt, n, M, W, limits, tableau, breaks):
    """n fixed steps of dt [s] from t [s] (RK4 when ``tableau`` is None, else that Rosenbrock-W method) stepping
    onto the modulation's kinks as ``breaks`` says (``BREAKS_*``). Runs of plain steps go through
    :func:`advance_fixed` in one call, a step that needs its segments' lines piece by piece (one call site of the
    integrator, so the compiled code holds it once). Returns (status, whole steps done, time of the state [s], size
    of the failed step or piece [s], or dt); on a failure the state is that at the returned time."""
    tc = t
    done = 0
    nxt = 0  # the steps before it need no splitting (or are done)
    inside = False  # a split step in progress: its pieces from tc to te
    te = t
    b = t
    while done < n:
        if inside:
            b = next_kink(tc, te, t, dt, done, M.tmod, M.ms, M.md)
            fill_segment(M, tc, b, W.seg_tmod, W.seg_ms, W.seg_md)
            Mx = model_with_air(M.kind, M.vehicle, M, W.seg_tmod, W.seg_ms, W.seg_md, M.gp, M.gv)
            h, count = b - tc, 1
        else:
            while nxt < n and breaks != BREAKS_OFF:
                inside_kinks, on_end = step_kinks(t, dt, nxt, M.tmod, M.ms, M.md)
                if inside_kinks > 0 or (on_end and breaks == BREAKS_ENDS):
                    break
                nxt += 1
            if breaks == BREAKS_OFF:
                nxt = n
            if nxt == done:  # this step is split: its pieces come next
                inside, te = True, tc + dt
                nxt += 1
                continue
            Mx = M
            h, count = dt, nxt - done
        st, k = advance_fixed(tc, x, u, h, count, Mx, W, limits, tableau)
        if inside:
            if st != OK:
                return st, done, tc, h
            tc = b
            if b == te:
                inside = False
                done += 1
        else:
            tc += k * dt
            done += k
            if st != OK:
                return st, done, tc, dt
    return OK, done, tc, dt


# Two compiles of the driver above, their options stated (tests/test_kernel_flags.py): numba gives a function that
# leaves fastmath unset the options of the compile in progress when it is first needed, and keeps that compile. So
# before 2026-12-06 the driver's code depended on which process compiled what first (docs/numerics.md, "Bits and
# machines"). Each keeps the options its callers gave it in a default cold start (the envs' figures were made so):
# none for the single simulator and the rigid kinds' W-step kernels, the step kernels' flags for the others.
@njit(cache=True, error_model="numpy", _nrt=False, fastmath=False)
def advance_breaks(t, x, u, dt, n, M, W, limits, tableau, breaks):
    """n fixed steps of dt [s] from t [s] (RK4 when ``tableau`` is None, else that Rosenbrock-W method) stepping
    onto the modulation's kinks as ``breaks`` says (``BREAKS_*``). Runs of plain steps go through
    :func:`advance_fixed` in one call, a step that needs its segments' lines piece by piece (one call site of the
    integrator, so the compiled code holds it once). Returns (status, whole steps done, time of the state [s], size
    of the failed step or piece [s], or dt); on a failure the state is that at the returned time. Compiled without
    fastmath flags: the single simulator's driver and the rigid kinds' Rosenbrock-W step kernels'."""
    return _advance_breaks(t, x, u, dt, n, M, W, limits, tableau, breaks)


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract", "nsz", "arcp"})
def advance_breaks_contract(t, x, u, dt, n, M, W, limits, tableau, breaks):
    """:func:`advance_breaks` compiled with the kernels' fastmath flags (``contract``: fused multiply-adds in the
    step times): the other step kernels' driver (:func:`advance_breaks_for`)."""
    return _advance_breaks(t, x, u, dt, n, M, W, limits, tableau, breaks)


def advance_breaks_for(t, x, u, dt, n, M, W, limits, tableau, breaks):
    """The step kernels' driver, chosen by the arguments' types when numba compiles: :func:`advance_breaks` for a
    Rosenbrock-W method (``tableau`` not None) on the rigid 3D kind (the wing, the chain, the rotorcraft), whose driver
    the kernel warm-up compiled from Python (``envs/step_callees.py``), else :func:`advance_breaks_contract` (RK4,
    and the W method on the mill's moving cable: compiled inside the step kernel). Jitted code only."""
    raise NotImplementedError("advance_breaks_for is resolved inside numba kernels")


@inline_overload(advance_breaks_for)
def _advance_breaks_for(t, x, u, dt, n, M, W, limits, tableau, breaks):
    from laddermill_gym.kernels.rigid.kinds import Rigid3D

    kind = dict(zip(M.fields, M.types, strict=True))["kind"]
    if isinstance(tableau, types.NoneType) or getattr(kind, "instance_class", None) is not Rigid3D:
        return lambda t, x, u, dt, n, M, W, limits, tableau, breaks: advance_breaks_contract(
            t, x, u, dt, n, M, W, limits, tableau, breaks)
    return lambda t, x, u, dt, n, M, W, limits, tableau, breaks: advance_breaks(
        t, x, u, dt, n, M, W, limits, tableau, breaks)
