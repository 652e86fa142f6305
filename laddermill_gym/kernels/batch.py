"""Many copies of one scene advanced together: RK4 over a batch, parallel over copies.

Every copy shares the scene's packed model except its wind modulation (speed factor and direction offset
series, so each copy can see its own gust) and owns one slice of a batched workspace. The per-copy work is
the same compiled ``rk4_advance`` a single simulator uses, so a batch copy and a single run agree bit for bit.
"""

from numba import njit, prange

from laddermill_gym.kernels.contract import KModel, KWork
from laddermill_gym.kernels.integrate import OK, rk4_advance


def detach_markers(M: KModel) -> tuple[KModel, object, object]:
    """(M without its markers, kind, vehicle) for the parallel kernels. numba's parallel (prange) lowering passes
    the variables a loop body uses to a worker function and rebuilds a namedtuple only from a function
    argument, so a marker nested in the model must come in as an argument of its own; :func:`copy_views` puts
    the markers back for each copy."""
    return M._replace(kind=None, vehicle=None), M.kind, M.vehicle


@njit(cache=True)
def copy_views(b, M, kind, vehicle, WB, tmod, MS, MD):
    """(model, workspace) of copy ``b``: the shared model (markers ``kind`` and ``vehicle``) with that copy's wind
    modulation, and views of the copy's rows of the batched workspace WB (no copies made)."""
    Mb = KModel(kind, M.wf, tmod[b], MS[b], MD[b], M.glob, M.wtype, M.tf, M.ac, M.node_mass, M.fixed,
                M.ek, M.ei, M.ea, M.ef, M.ekd, M.echild, M.order, M.parent, M.bsz, M.sag, M.caero, vehicle)
    Wb = KWork(WB.D[b], WB.U[b], WB.Y[b], WB.piv[b], WB.bv[b], WB.Rw[b], WB.tension[b], WB.Tr[b],
               WB.Ts[b], WB.er[b], WB.es[b], WB.coef[b], WB.aout[b], WB.vout[b], WB.vscratch[b], WB.k1[b],
               WB.k2[b], WB.k3[b], WB.k4[b], WB.k5[b], WB.k6[b], WB.k7[b], WB.xt[b], WB.xp[b])
    return Mb, Wb


@njit(cache=True, error_model="numpy", parallel=True)
def rk4_batch(t, X, U, dt, n, M, kind, vehicle, WB, tmod, MS, MD, active, limits, status, done):
    """Advance the states X (B, n_state) in place by n RK4 steps of size dt with controls U (B, n_controls).

    t (B,) [s] is each copy's time (not advanced here). Wind modulation per copy: tmod (B, 2) start and
    sample spacing [s], MS (B, n_mod) speed factors [-], MD (B, n_mod) direction offsets [rad]. Copies with
    active[b] == 0 are skipped. WB is a KWork whose arrays carry a leading batch axis. M is the packed model
    with its ``kind`` and ``vehicle`` markers passed separately (:func:`detach_markers`). Writes status (B,)
    (integrate.py's codes) and done (B,) (steps completed before a failure).
    """
    nb = X.shape[0]
    for b in prange(nb):
        if active[b] == 0:
            status[b] = OK
            done[b] = 0
            continue
        Mb, Wb = copy_views(b, M, kind, vehicle, WB, tmod, MS, MD)
        st, dn = rk4_advance(t[b], X[b], U[b], dt, n, Mb, Wb, limits)
        status[b] = st
        done[b] = dn
