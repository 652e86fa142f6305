"""Reports of a run that stops: which body reached the ground and when, which body broke a speed or rate limit
or went non-finite in the step that failed, and what the last good state looks like (``diagnose``).
``Simulator`` (``sim/simulator.py``) raises them as ``SimulationError``; the functions take the simulator as their
first argument and never change its state, time or controls (only the workspace's scratch).

The integrators leave the state at the last good step, so a report re-runs the failed step once from there
with the speed, rate and ground checks off (``relaxed_limits``) and names what it finds in that trial state.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels.contract import (
    B2_Q,
    B2_U,
    B2_W,
    B2_Z,
    B3_POS,
    B3_QUAT,
    B3_RATE,
    B3_VEL,
    BUDGET,
    GROUND,
    LIM_GROUND,
    LIM_RATE,
    LIM_SPEED,
    LIMIT,
    N2_POS,
    N2_VEL,
    N3_POS,
    N3_VEL,
    NONFINITE,
    OK,
    SINGULAR,
    STALLED,
)
from laddermill_gym.kernels.integrate import dp54_advance
from laddermill_gym.kernels.integrate import rhs_entry as _rhs_kernel
from laddermill_gym.model.params import AERO_INDEX

#: Ground-contact modes of ``IntegratorSettings.ground_contact``.
GROUND_MODES: tuple[str, ...] = ("stop", "flag", "off")
_KIND = {SINGULAR: "singular mass matrix", NONFINITE: "non-finite state", LIMIT: "speed or rate limit exceeded",
         STALLED: "{method} step size collapsed below 1e-12 max(1 s, t)",
         BUDGET: "{method} used up its budget of steps (1e7 per step(), 1e8 per advance_to) before the end time"}
#: The error-controlled methods' names in reports (``advance_to`` runs DP5(4) unless the settings name another).
_ADAPTIVE_NAME = {"ros34pw2a": "ROS34PW2 (error-controlled)"}
#: Bodies named at most in one report.
_MAX_NAMED = 4


def relaxed_limits(limits: np.ndarray) -> np.ndarray:
    """A copy of the kernels' ``limits`` with no speed, rate or ground check (only non-finite states stop)."""
    lim = np.array(limits, dtype=np.float64)
    lim[LIM_SPEED] = lim[LIM_RATE] = np.inf
    lim[LIM_GROUND] = -np.inf
    return lim


def _blocks(asm, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(wing blocks (n_wings, wing_state_size), node blocks (n_nodes, node_state_size)) of the state x."""
    nw, ws, ns = asm.n_wings, asm.wing_state_size, asm.node_state_size
    return x[: nw * ws].reshape(nw, ws), x[nw * ws: nw * ws + asm.n_nodes * ns].reshape(asm.n_nodes, ns)


def body_heights(asm, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Heights h = -z [m] of the wing CGs (n_wings,) and of the free cable nodes (n_nodes,) in the state x."""
    w, n = _blocks(asm, x)
    if asm.dim == 3:
        return -w[:, B3_POS + 2], -n[:, N3_POS + 2]
    return -w[:, B2_Z], -n[:, N2_POS + 1]


def trial_state(sim, h: float) -> tuple[float, np.ndarray] | None:
    """(time [s], state) one step of h [s] after the simulator's current state, integrated with the speed, rate
    and ground checks off (the settings' fixed-step method, or DP5(4) to t + h): the step that failed. None if that
    step fails too."""
    from laddermill_gym.kernels.fixed_steps import advance_breaks
    from laddermill_gym.sim.breakpoints import FIXED_STEP_METHODS, breaks_mode, fixed_tableau

    s = sim.settings
    x = sim.state.copy()
    lim = relaxed_limits(sim.limits)
    if s.method in FIXED_STEP_METHODS:
        status = advance_breaks(sim.t, x, sim.controls, h, 1, sim.model, sim.work, lim, fixed_tableau(s),
                                breaks_mode(s))[0]
    else:
        status = dp54_advance(sim.t, sim.t + h, x, sim.controls, h, s.rtol, s.atol, sim.model, sim.work, lim,
                              100_000)[0]
    return (sim.t + h, x) if status == OK else None


def ground_message(sim, h: float) -> str:
    """The report of a run stopped by ground contact in the step of h [s] after the current state: the time of
    the first state at or below the ground [s], the bodies there ("wing 3", "node 7") and their heights [m]."""
    hg = sim.settings.ground_height
    trial = trial_state(sim, h)
    t, x = trial if trial is not None else (sim.t, sim.state)
    wh, nh = body_heights(sim.assembly, x)
    names = [f"wing {k}" for k in range(wh.size)] + [f"node {j}" for j in range(nh.size)]
    heights = np.concatenate([wh, nh])
    at = np.flatnonzero(heights <= hg)
    at = at[np.argsort(heights[at])] if at.size else np.array([int(np.argmin(heights))])
    # above a ground not at 0 the depth as well: at four digits a height just below it read as above it (100.4 m
    # against a ground at 100.384 m); at 0 the height is the depth
    parts = [f"{names[i]} at height {heights[i]:.4g} m" + (f" ({heights[i] - hg:.3g} m from the ground)" if hg else "")
             for i in at[:_MAX_NAMED]]
    more = f" and {at.size - _MAX_NAMED} more" if at.size > _MAX_NAMED else ""
    return (f"ground contact at t = {t:.6g} s: {', '.join(parts)}{more} (ground height {hg:g} m); the state is "
            f"kept at t = {sim.t:.6g} s, the last one before the contact")


def lowest_body(asm, x: np.ndarray) -> tuple[str, float]:
    """("wing k" or "node j", its height [m]) of the lowest wing CG or free cable node of the state x."""
    wh, nh = body_heights(asm, x)
    h = np.concatenate([wh, nh])
    i = int(np.argmin(h))
    return (f"wing {i}" if i < wh.size else f"node {i - wh.size}"), float(h[i])


def start_below_ground(sim) -> str:
    """"" when every wing CG and free cable node of ``sim``'s state is above its ground, else a sentence naming the
    lowest body, its height [m] and the ground's."""
    name, h = lowest_body(sim.assembly, sim.state)
    if h > sim.settings.ground_height:
        return ""
    return f"the start has {name} at height {h:.4g} m, at or below the ground at {sim.settings.ground_height:g} m"


def ground_stop_text(asm, x: np.ndarray, ground_height: float) -> str:
    """Why a batch copy in the state x (its last state above the ground) stopped with status GROUND: the ground
    height [m] and the lowest wing CG or free cable node, which reached it in the next step (the environments)."""
    name, h = lowest_body(asm, x)
    above = f" ({h - ground_height:.3g} m above the ground)" if ground_height else ""  # at 0 the height says it
    return (f"ground contact in the next physics step (ground height {ground_height:g} m); lowest body "
            f"{name} at {h:.4g} m{above}")


def _limit_culprits(sim, x: np.ndarray) -> list[str]:
    """Bodies of the state x over the speed [m/s] or rate [rad/s] limit, with the quantity."""
    asm, s = sim.assembly, sim.settings
    w, n = _blocks(asm, x)
    if asm.dim == 3:
        ws, wr = np.linalg.norm(w[:, B3_VEL: B3_VEL + 3], axis=1), np.linalg.norm(w[:, B3_RATE: B3_RATE + 3], axis=1)
        ns = np.linalg.norm(n[:, N3_VEL: N3_VEL + 3], axis=1)
    else:
        ws, wr = np.hypot(w[:, B2_U], w[:, B2_W]), np.abs(w[:, B2_Q])
        ns = np.linalg.norm(n[:, N2_VEL: N2_VEL + 2], axis=1)
    out = [f"wing {k} speed {ws[k]:.4g} m/s > {s.max_speed:g} m/s" for k in np.flatnonzero(ws > s.max_speed)]
    out += [f"wing {k} angular rate {wr[k]:.4g} rad/s > {s.max_rate:g} rad/s" for k in np.flatnonzero(wr > s.max_rate)]
    out += [f"node {j} speed {ns[j]:.4g} m/s > {s.max_speed:g} m/s" for j in np.flatnonzero(ns > s.max_speed)]
    return out


def quaternion_problems(sim, x: np.ndarray) -> list[str]:
    """Wing quaternions of the (finite) state x with zero or overflowing norm (3D; outside 1e-8..1e8, where the
    kernels' renormalisation loses them), each with the wing and its norm; empty if none."""
    asm = sim.assembly
    if asm.dim != 3:
        return []
    w, _ = _blocks(asm, x)
    q = w[:, B3_QUAT: B3_QUAT + 4]
    scale = np.max(np.abs(q), axis=1)
    norm = scale * np.linalg.norm(q / np.where(scale > 0, scale, 1.0)[:, None], axis=1)
    return [f"wing {k} quaternion norm {norm[k]:.4g} (must be between 1e-8 and 1e8; it is renormalised)"
            for k in np.flatnonzero(~((norm > 1e-8) & (norm < 1e8)))]


def state_problems(sim, x: np.ndarray) -> list[str]:
    """What makes the (finite) state x unfit to start from: wing quaternions of zero or overflowing norm (3D), and
    bodies over the speed or rate limit, each with the body and the value; empty if none."""
    return quaternion_problems(sim, x) + _limit_culprits(sim, x)


def _rk4_trial(sim, h: float) -> np.ndarray | None:
    """One classic RK4 step of h [s] from the current state in Python with the kernels' right-hand side and no
    check at all (to see which entry turns non-finite); None if the mass matrix is singular on the way."""
    x0, u, t = sim.state, sim.controls, sim.t
    ks, xt = [], x0
    for c, a in ((0.0, 0.0), (0.5, 0.5), (0.5, 0.5), (1.0, 1.0)):
        if ks:
            xt = x0 + a * h * ks[-1]
        k = np.zeros_like(x0)
        if _rhs_kernel(t + c * h, xt, u, k, sim.model, sim.work) != 0:
            return None
        ks.append(k)
    return x0 + h / 6.0 * (ks[0] + 2.0 * (ks[1] + ks[2]) + ks[3])


def diagnose(sim) -> str:
    """Name the body, node or element with the largest speed, rate or derivative in the simulator's state."""
    a = sim.assembly
    badx = np.flatnonzero(~np.isfinite(sim.state))
    if badx.size:  # a state corrupted behind the integrator's back (or injected): its first bad entry is the cause
        i = int(badx[0])
        return f"{sim.state_name(i)} is {sim.state[i]} (state entry {i}): a non-finite state"
    dx = np.zeros(sim.n_state)
    if _rhs_kernel(float(sim.t), sim.state, sim.controls, dx, sim.model, sim.work) != 0:
        return f"t = {sim.t:.6g} s: the mass matrix is singular"
    msgs = quaternion_problems(sim, sim.state) if np.all(np.isfinite(sim.state)) else []
    bad = np.flatnonzero(~np.isfinite(dx))
    if bad.size:
        msgs.append(f"non-finite derivative of {sim.state_name(int(bad[0]))}")
    speeds = np.linalg.norm(sim.wing_velocities(), axis=1) if a.n_wings else np.zeros(0)
    if speeds.size:
        k = int(np.argmax(speeds))
        msgs.append(f"fastest wing {k}: speed {speeds[k]:.4g} m/s")
    if a.n_nodes:
        vn = sim.state[a.n_wings * a.wing_state_size: a.body_state_size].reshape(a.n_nodes, a.node_state_size)
        vel, nv = (N3_VEL, 3) if a.dim == 3 else (N2_VEL, 2)
        vn = np.linalg.norm(vn[:, vel: vel + nv], axis=1)
        j = int(np.argmax(vn))
        msgs.append(f"fastest node {j}: speed {vn[j]:.4g} m/s")
    rates = np.linalg.norm(sim.wing_rates(), axis=1) if a.n_wings else np.zeros(0)
    if rates.size:
        k = int(np.argmax(rates))
        msgs.append(f"wing {k} angular rate {rates[k]:.4g} rad/s")
    if a.elements.count:
        ten = sim.work.tension[: a.elements.count]  # of this state: the kernel call above left them there
        e = int(np.argmax(ten))
        msgs.append(f"element {e} tension {ten[e]:.4g} N")
    acc = np.abs(dx)
    i = int(np.nanargmax(np.where(np.isfinite(acc), acc, -1.0)))
    msgs.append(f"largest derivative {sim.state_name(i)} = {dx[i]:.4g}")
    cause = alpha_rate_cause(sim, dx, i)
    if cause:
        msgs.append(cause)
    return "; ".join(msgs)


#: a wing's largest acceleration [m/s^2 or rad/s^2] above which :func:`alpha_rate_cause` looks at the alpha-rate
#: terms, and the factor by which removing them must lower it to be named as the cause
ALPHA_RATE_CHECK, ALPHA_RATE_FACTOR = 1e4, 1e3


def alpha_rate_cause(sim, dx: np.ndarray, i: int) -> str:
    """The alpha-rate terms (C_L_alphadot, C_m_alphadot, Meijaard et al. 1999 eq. 6) enter the mass matrix as
    -k g^T, with g = d alpha / d v_a ~ 1 / (in-plane airspeed) and k ~ airspeed: at large sideslip (flow along
    the span) they can make the mass matrix singular, and the accelerations pass through a pole that no step
    size resolves (the error-controlled methods' steps collapse there; a fixed step jumps it). When state entry
    ``i`` (the largest derivative ``dx``) is a wing's acceleration above ``ALPHA_RATE_CHECK`` and the same state
    without those two columns gives ``ALPHA_RATE_FACTOR`` times less, say so, with the wing's angle of attack
    and sideslip; else ''."""
    return _alpha_rate_text(sim, float(sim.t), sim.state, dx, i, "")


def _alpha_rate_text(sim, t: float, x: np.ndarray, dx: np.ndarray, i: int, where: str) -> str:
    """:func:`alpha_rate_cause`'s test for the state x at t [s] (its derivative dx, entry i); ``where`` names a
    state inside a step (the angles are the step's start's)."""
    a = sim.assembly
    if not (a.n_wings and i < a.n_wings * a.wing_state_size and abs(dx[i]) > ALPHA_RATE_CHECK):
        return ""
    k, j = divmod(i, a.wing_state_size)
    vel = B3_VEL if a.dim == 3 else B2_U
    if j < vel:
        return ""
    cols = [AERO_INDEX["CLad"], AERO_INDEX["Cmad"]]
    ac = sim.model.ac.copy()
    if ac.ndim != 4 or ac.shape[-1] <= max(cols):  # a vehicle without the wing table (the rotorcraft)
        return ""
    ac[:, :, :, cols] = 0.0
    dx0 = np.zeros(sim.n_state)
    if _rhs_kernel(t, x, sim.controls, dx0, sim.model._replace(ac=ac), sim.work) != 0:
        return ""
    if not abs(dx0[i]) * ALPHA_RATE_FACTOR < abs(dx[i]):
        return ""
    al, be = np.degrees(sim.wing_alpha_beta()[k])
    at = f" at the step's start, {where}" if where else ""
    return (f"wing {k} (angle of attack {al:.3g} deg, sideslip {be:.3g} deg{at}): its alpha-rate terms make the "
            f"mass matrix nearly singular ({sim.state_name(i)} derivative {dx[i]:.3g}, {dx0[i]:.3g} without them), "
            "a limit of the quasi-steady alpha-rate model at large sideslip, not of the step size (docs/numerics.md)")


#: DP5(4)'s tolerances (relative, absolute) for the re-run of a failed step in :func:`step_alpha_rate_cause`: tight
#: enough that its steps follow the trajectory onto a pole instead of stepping over it (on the mill's 10 ms case
#: DP5(4) at 1e-6 and ROS34PW2 at 1e-5 step over the pole the trajectory meets 0.16 ms into the step; at 1e-9 /
#: 1e-12 they stop on it)
POLE_RTOL, POLE_ATOL = 1e-9, 1e-12
#: at most this many DP5(4) steps in that re-run (a step onto a pole collapses in a few hundred; the mill's 10 ms
#: step without one takes tens): a report costs at most seconds
POLE_MAX_STEPS = 10_000


def step_alpha_rate_cause(sim, h: float) -> str:
    """:func:`alpha_rate_cause` for the trajectory inside the failed step of h [s] from the last good state: the step
    re-run with DP5(4) at ``POLE_RTOL`` / ``POLE_ATOL`` (speed, rate and ground checks off); where that run stops
    inside the step and its last accepted state shows a wing's alpha-rate pole, the trajectory itself meets the pole
    there, and a fixed step that lands a stage next to it throws the wing to a speed or rate no physics gives. Then
    the pole is named with the time the re-run reached; else '' (the failure stays the step's)."""
    a = sim.assembly
    n = a.n_wings * a.wing_state_size
    if not n or _limit_culprits(sim, sim.state):  # no wing, or a state already past the limits (an injected 1e12)
        return ""
    x = sim.state.copy()
    status, _, _, _, t = dp54_advance(sim.t, sim.t + h, x, sim.controls, h / 8.0, POLE_RTOL, POLE_ATOL, sim.model,
                                      sim.work, relaxed_limits(sim.limits), POLE_MAX_STEPS)
    if status in (OK, BUDGET) or not np.all(np.isfinite(x)):
        return ""
    dx = np.zeros(sim.n_state)
    if _rhs_kernel(float(t), x, sim.controls, dx, sim.model, sim.work) != 0:
        return ""
    acc = np.zeros(n, dtype=bool)
    acc.reshape(a.n_wings, a.wing_state_size)[:, B3_VEL if a.dim == 3 else B2_U:] = True
    mag = np.where(acc & np.isfinite(dx[:n]), np.abs(dx[:n]), -1.0)
    return _alpha_rate_text(sim, float(t), x, dx, int(np.argmax(mag)),
                            f"the trajectory meets the pole at t = {float(t):.7g} s, where DP5(4) at rtol "
                            f"{POLE_RTOL:g} stops")


def failure_message(sim, status: int, h: float) -> str:
    """The report of a step of h [s] that failed with the integrators' ``status``: the time, the body, node or
    element and the quantity (a ground contact: :func:`ground_message`)."""
    if status == GROUND:
        return ground_message(sim, h)
    culprit = []
    if status == LIMIT:
        trial = trial_state(sim, h)
        culprit = _limit_culprits(sim, trial[1]) if trial is not None else []
        own = getattr(sim, "limit_cause", None)  # a model's physical limit of its own (the winch's reel-in end)
        own = own(h) if callable(own) else None
        if own and not culprit:  # that limit alone: a physical end of the model, not a numerical breakdown
            return f"physical limit at t = {sim.t:.6g} s, in the step to t = {sim.t + h:.6g} s: {own}"
        culprit = culprit + [own] if own else culprit
    elif status == NONFINITE and np.all(np.isfinite(sim.state)):
        x = _rk4_trial(sim, h)
        bad = np.flatnonzero(~np.isfinite(x)) if x is not None else np.zeros(0, dtype=int)
        culprit = [f"{sim.state_name(int(bad[0]))} non-finite"] if bad.size else []
    what = f"; in the step to t = {sim.t + h:.6g} s: {', '.join(culprit[:_MAX_NAMED])}" if culprit else ""
    if status in (LIMIT, NONFINITE) and np.all(np.isfinite(sim.state)):
        cause = step_alpha_rate_cause(sim, h)
        what += f"; {cause}" if cause else ""
    kind = _KIND.get(status, f"status {status}").format(method=_ADAPTIVE_NAME.get(sim.settings.method, "DP5(4)"))
    where = "last good state" if np.all(np.isfinite(sim.state)) else "the state"
    return f"integration failed at t = {sim.t:.6g} s ({kind}){what}; {where}: {sim.diagnose()}"
