"""Many copies of one scene advanced together: a fixed-step method (RK4 or a Rosenbrock-W method) over a batch,
parallel over copies.

Every copy shares the scene's packed model except its wind modulation (speed factor and direction offset
series, so each copy can see its own gust) and owns one slice of a batched workspace. The per-copy work is
the same compiled ``kernels/fixed_steps.advance_breaks`` a single simulator uses, so a batch copy and a single run
agree bit for bit. The env step kernels step a copy with :func:`advance_copy` (``fixed_steps.advance_breaks_for``:
the RK4 driver compiled with the kernels' fastmath flags).
"""

from numba import njit, prange, types
from numba.extending import overload

from laddermill_gym.kernels.contract import OK, KModel, KWork
from laddermill_gym.kernels.fixed_steps import advance_breaks, advance_breaks_for, model_with_air


def detach_markers(M: KModel) -> tuple[KModel, object, object]:
    """(M without its markers, kind, vehicle) for the parallel kernels. numba's parallel (prange) lowering passes
    the variables a loop body uses to a worker function and rebuilds a namedtuple only from a function
    argument, so a marker nested in the model must come in as an argument of its own; :func:`copy_views` puts
    the markers back for each copy."""
    return M._replace(kind=None, vehicle=None), M.kind, M.vehicle


def row_or_none(a, b):
    """Row ``b`` of the array ``a``, or None when ``a`` is None (Python only: the task's warm-up builds copy 0's
    model with it; compiled code uses :func:`copy_air_model`)."""
    return None if a is None else a[b]


def copy_air_model(kind, vehicle, M, AB, b):
    """The shared model ``M`` (markers ``kind`` and ``vehicle``) with copy ``b``'s air: row b of each array of the
    batched :class:`~laddermill_gym.kernels.contract.KAir` AB (the gust grid's header and samples: None when AB's are
    None). Jitted code only: an overload per gust grid type, so the kernels that inline it need not return a bare
    array view from a function, which numba forbids without its runtime (``_nrt=False``, below)."""
    raise NotImplementedError("copy_air_model is resolved inside numba kernels")


@overload(copy_air_model, inline="always")
def _copy_air_model(kind, vehicle, M, AB, b):
    gp_none = isinstance(AB.types[AB.fields.index("gp")], types.NoneType)
    gv_none = isinstance(AB.types[AB.fields.index("gv")], types.NoneType)
    if gp_none and gv_none:
        return lambda kind, vehicle, M, AB, b: model_with_air(kind, vehicle, M, AB.tmod[b], AB.ms[b], AB.md[b], None,
                                                              None)
    if gp_none:
        return lambda kind, vehicle, M, AB, b: model_with_air(kind, vehicle, M, AB.tmod[b], AB.ms[b], AB.md[b], None,
                                                              AB.gv[b])
    if gv_none:
        return lambda kind, vehicle, M, AB, b: model_with_air(kind, vehicle, M, AB.tmod[b], AB.ms[b], AB.md[b],
                                                              AB.gp[b], None)
    return lambda kind, vehicle, M, AB, b: model_with_air(kind, vehicle, M, AB.tmod[b], AB.ms[b], AB.md[b], AB.gp[b],
                                                          AB.gv[b])


@njit(cache=True, inline="always")  # inlined: no separate compile of its 60 array arguments (issue 32)
def copy_views(b, M, kind, vehicle, WB, AB):
    """(model, workspace) of copy ``b``: the shared model (markers ``kind`` and ``vehicle``) with that copy's air
    (row b of the batched :class:`~laddermill_gym.kernels.contract.KAir` AB: wind modulation and gust grid), and
    views of the copy's rows of the batched workspace WB (no copies made)."""
    Mb = copy_air_model(kind, vehicle, M, AB, b)
    Wb = KWork(WB.D[b], WB.U[b], WB.Y[b], WB.piv[b], WB.bv[b], WB.Rw[b], WB.tension[b], WB.Tr[b],
               WB.Ts[b], WB.er[b], WB.es[b], WB.coef[b], WB.aout[b], WB.vout[b], WB.vscratch[b], WB.k1[b],
               WB.k2[b], WB.k3[b], WB.k4[b], WB.k5[b], WB.k6[b], WB.k7[b], WB.xt[b], WB.xp[b], WB.Dm[b], WB.Um[b],
               WB.Ds[b], WB.Us[b], WB.Rn[b], WB.ke[b], WB.kb[b], WB.seg_tmod[b], WB.seg_ms[b], WB.seg_md[b],
               WB.Yw[b], WB.pivw[b], WB.wjac[b])
    return Mb, Wb


@njit(cache=True, error_model="numpy", inline="always")
def advance_copy(b, t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks):
    """Advance copy b by nsteps[b] fixed steps of dt [s] (``kernels/fixed_steps.advance_breaks_for``; 0: none) from
    its time t[b] [s], as the step-and-observe kernels do before observing it. Returns (whether the
    copy runs: False for nsteps[b] < 0, status, steps done, its model, its workspace: :func:`copy_views`)."""
    Mb, Wb = copy_views(b, M, kind, vehicle, WB, AB)
    n = nsteps[b]
    st, dn = OK, 0
    if n > 0:
        st, dn, _, _ = advance_breaks_for(t[b], X[b], U[b], dt, n, Mb, Wb, limits, tableau, breaks)
    return n >= 0, st, dn, Mb, Wb


# nogil: the integrator is called through its address, resolved on the first call in Python (kernels/far_call.py);
# a worker thread of the parallel loop that asked while this thread held the GIL would wait for ever. advance_breaks
# itself stays linked: called through its address from the env step kernels, it changed 3 of 800 rewards of a
# 40-copy TetheredWing-v0 by 7e-15 to 1e-10 (cause not found; issue 32 point 1).
@njit(cache=True, error_model="numpy", parallel=True, nogil=True, _nrt=True, fastmath=False)
def fixed_batch(t, X, U, dt, n, M, kind, vehicle, WB, AB, active, limits, tableau, breaks, status, done):
    """Advance the states X (B, n_state) in place by n fixed steps of size dt with controls U (B, n_controls): RK4
    (``tableau`` None) or a Rosenbrock-W method (its tableau, ``kernels/rigid/rosenbrock.py``), stepping onto the
    kinks of each copy's wind modulation as ``breaks`` says (``kernels/fixed_steps.py``).

    t (B,) [s] is each copy's time (not advanced here). AB is the per-copy air, a KAir of arrays with a leading
    copy axis (wind modulation grid tmod (B, 2), speed factors ms (B, n_mod) [-], direction offsets md (B, n_mod)
    [rad], gust grid header gp (B, GP_SIZE) and samples gv (B, n_grid)). Copies with active[b] == 0 are skipped.
    WB is a KWork whose arrays carry a leading batch axis. M is the packed model with its ``kind`` and
    ``vehicle`` markers passed separately (:func:`detach_markers`). Writes status (B,) (integrate.py's codes)
    and done (B,) (steps completed before a failure).
    """
    nb = X.shape[0]
    for b in prange(nb):
        if active[b] == 0:
            status[b] = OK
            done[b] = 0
            continue
        Mb, Wb = copy_views(b, M, kind, vehicle, WB, AB)
        st, dn, _, _ = advance_breaks(t[b], X[b], U[b], dt, n, Mb, Wb, limits, tableau, breaks)
        status[b] = st
        done[b] = dn
