"""The cases of ``laddermill stress`` (``studies/numerics/stress.py``). Each returns rows ``{"case", "scene", "passed",
"outcome", figures...}``.

Outcomes: "ok" (ran to the end); "terminated: ..." for a documented physical termination (a wing or free node at
the ground with ``ground_contact`` "stop", raised as a SimulationError naming the time, body and height; or a
wing whose alpha-rate terms make the mass matrix singular at large sideslip, in the last good state or met inside
the failed step, ``sim/reports.alpha_rate_cause`` and ``step_alpha_rate_cause``); "failed:
..." for a numerical breakdown (non-finite state, speed or rate limit, singular mass matrix, DP5(4) step
collapse or budget), which is a failure of the case unless the case provokes it on purpose (injections).
"""

from __future__ import annotations

import math
import re

import numpy as np

from laddermill_gym.kernels.contract import B3_POS, B3_QUAT, B3_RATE, B3_SIZE, B3_VEL, N3_POS, N3_VEL, OK
from laddermill_gym.kernels.integrate import dp54_advance
from laddermill_gym.sim.breakpoints import W_METHODS
from laddermill_gym.sim.simulator import SimulationError, Simulator
from laddermill_gym.sim.stable_step import estimate_stable_step
from laddermill_gym.studies.numerics.scenes import CRAFT_NAMES, build_simulator, with_settings


def kinetic_energy(sim: Simulator, x: np.ndarray | None = None) -> float:
    """Kinetic energy [J] of the wings (translation and rotation, body axes) and of the lumped node masses: the
    energy monitor (3D scenes; the cable's distributed mass is left out)."""
    a = sim.assembly
    x = sim.state if x is None else x
    e = 0.0
    for k in range(a.n_wings):
        wt = a.wing_types[a.wing_type_index[k]]
        o = B3_SIZE * k
        v, w = x[o + B3_VEL: o + B3_VEL + 3], x[o + B3_RATE: o + B3_RATE + 3]
        jxx, jyy, jzz, jxz = wt.inertia
        inertia = np.array([[jxx, 0.0, -jxz], [0.0, jyy, 0.0], [-jxz, 0.0, jzz]])
        e += 0.5 * wt.mass * float(v @ v) + 0.5 * float(w @ inertia @ w)
    off, ns = a.n_wings * a.wing_state_size, a.node_state_size
    for j in range(a.n_nodes):
        v = x[off + ns * j + N3_VEL: off + ns * j + N3_VEL + 3]
        e += 0.5 * float(np.atleast_1d(a.node_mass)[j % max(1, np.size(a.node_mass))]) * float(v @ v)
    return e


def outcome(err: Exception | None) -> tuple[str, bool]:
    """(outcome text, whether it is acceptable): ok, a documented termination, or a failure."""
    if err is None:
        return "ok", True
    text = str(err).splitlines()[0]
    if "ground" in text and ("height" in text or "contact" in text):
        return f"terminated: {text[:150]}", True
    if "alpha-rate terms make the mass matrix nearly singular" in text:  # sim/reports.alpha_rate_cause
        cause = [part for part in text.split("; ") if "alpha-rate terms make" in part][0]
        return f"terminated (limit of the quasi-steady model): {cause[:150]}", True
    return f"failed: {text[:150]}", False


def run_for(sim: Simulator, duration: float, controls=None, sample: float = 0.5) -> dict:
    """Advance ``sim`` by ``duration`` [s] (``controls``: a function t -> controls, applied every ``sample``);
    figures: lowest wing height [m], largest tension [N], largest kinetic energy [J]; the outcome."""
    n_per = max(1, int(round(sample / sim.settings.dt)))
    left = max(1, int(round(duration / sim.settings.dt)))
    h_min, t_max, e_max, err = math.inf, 0.0, 0.0, None
    try:
        while left > 0:
            u = None if controls is None else controls(sim.t)
            sim.step(u, n_steps=min(n_per, left))
            left -= n_per
            h_min = min(h_min, float(np.min(sim.body_heights()[0])))
            t_max = max(t_max, float(np.max(sim.tensions())))
            e_max = max(e_max, kinetic_energy(sim))
    except SimulationError as e:
        err = e
    text, ok = outcome(err)
    return {"outcome": text, "passed": ok, "t_end_s": sim.t, "min_wing_height_m": h_min, "max_tension_N": t_max,
            "max_kinetic_energy_J": e_max}


def stable_step_rows(scene: str, horizon: float = 4.0, iters: int = 8) -> list[dict]:
    """Largest stable RK4 step by bisection (a run passes if it completes, stays within 1 % of a piece length of
    a DP5(4) reference at 1e-9 in every position and keeps its kinetic energy below 1.5 x the reference's
    largest + 1 J) beside the eigenvalue estimate; DP5(4)'s mean accepted step at rtol 1e-6 beside its
    estimated stability limit (a step-size controller pinned at the limit is stability-bound); and the largest
    step of each linearly implicit method by the same test, bisected between RK4's estimated limit and 64 times it
    (capped at a quarter of the horizon; it passes when it holds at least twice RK4's limit, the point of the
    method)."""
    base = build_simulator(scene)
    x0 = base.initial_state.copy()
    rng = np.random.default_rng(0)
    for k in range(base.assembly.n_wings):
        x0[B3_SIZE * k + B3_VEL + 1] += 0.2 * rng.normal()
        x0[B3_SIZE * k + B3_RATE] += 0.02 * rng.normal()
    ref = with_settings(base, state=x0, method="dp54")
    e_ref = [kinetic_energy(ref)]
    for t in np.linspace(0, horizon, 41)[1:]:
        ref.advance_to(t, rtol=1e-9, atol=1e-9)
        e_ref.append(kinetic_energy(ref))
    pos_ref = np.vstack([ref.wing_positions(), ref.node_positions()])
    piece = 1.0 if scene in CRAFT_NAMES else _piece_length(scene)  # [m] the craft: its 1 m scale

    def ok(dt: float, method: str = "rk4") -> bool:
        n = int(round(horizon / dt))
        sim = with_settings(base, state=x0, dt=horizon / n, method=method)
        e_max = kinetic_energy(sim)
        try:
            for chunk in np.diff(np.linspace(0, n, 41).round().astype(int)):
                sim.step(n_steps=int(chunk))
                e_max = max(e_max, kinetic_energy(sim))
        except SimulationError:
            return False
        err = np.max(np.linalg.norm(np.vstack([sim.wing_positions(), sim.node_positions()]) - pos_ref, axis=1))
        return bool(err < 0.01 * piece and e_max <= 1.5 * max(e_ref) + 1.0)

    est = estimate_stable_step(base, "rk4")
    lo, hi = 0.5 * est.dt_max, 2.0 * est.dt_max
    if not ok(lo) or ok(hi):
        return [{"case": "largest stable step rk4", "scene": scene, "passed": False,
                 "outcome": f"bisection bracket [{lo:.4g}, {hi:.4g}] s does not hold the limit"}]
    for _ in range(iters):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if ok(mid) else (lo, mid)
    rows = [{"case": "largest stable step rk4", "scene": scene, "passed": abs(lo / est.dt_max - 1) < 0.1,
             "outcome": "ok", "dt_bisection_s": lo, "dt_fails_s": hi, "dt_estimate_s": est.dt_max,
             "ratio_bisection_to_estimate": lo / est.dt_max, "scene_dt_s": base.settings.dt}]
    sim = with_settings(base, state=x0, method="dp54")
    status, acc, rej, _, _ = dp54_advance(0.0, horizon, sim.state, sim.controls, 1e-3, 1e-6, 1e-6, sim.model,
                                          sim.work, sim.limits, 10_000_000)
    est5 = estimate_stable_step(base, "dp54", eigenvalues=np.array(est.fastest))
    rows.append({"case": "dp54 step at rtol 1e-6", "scene": scene, "passed": status == OK, "outcome": "ok",
                 "mean_step_s": horizon / max(acc, 1), "accepted": acc, "rejected": rej,
                 "dt_estimate_s": est5.dt_max, "ratio_step_to_estimate": horizon / max(acc, 1) / est5.dt_max})
    for method in (m for m in W_METHODS if m != "ros2t"):  # the L-stable ones (ros2t: work_precision.md)
        lo, hi = est.dt_max, min(64.0 * est.dt_max, 0.25 * horizon)
        row = {"case": f"largest stable step {method}", "scene": scene, "dt_estimate_rk4_s": est.dt_max}
        if ok(hi, method):
            rows.append({**row, "passed": True, "outcome": f"stable at the bracket's top, {hi:.4g} s",
                         "dt_bisection_s": hi, "ratio_to_rk4_limit": hi / est.dt_max})
            continue
        if not ok(lo, method):
            rows.append({**row, "passed": False, "outcome": f"fails at RK4's limit {lo:.4g} s already"})
            continue
        for _ in range(iters):
            mid = math.sqrt(lo * hi)
            lo, hi = (mid, hi) if ok(mid, method) else (lo, mid)
        rows.append({**row, "passed": lo >= 2.0 * est.dt_max, "outcome": "ok", "dt_bisection_s": lo, "dt_fails_s": hi,
                     "ratio_to_rk4_limit": lo / est.dt_max})
    return rows


def _piece_length(scene: str) -> float:
    from laddermill_gym.ladder.scene import load_scene

    return float(load_scene(scene).piece_length)


#: the injections: (label, body kind, slot offset in the block, value)
INJECTIONS = (("position NaN", "wing", B3_POS, math.nan), ("quaternion NaN", "wing", B3_QUAT, math.nan),
              ("velocity 1e12 m/s", "wing", B3_VEL, 1e12), ("rate inf", "wing", B3_RATE, math.inf),
              ("node position NaN", "node", N3_POS, math.nan), ("node velocity 1e12 m/s", "node", N3_VEL, 1e12))


def injection_rows(scene: str, methods=("rk4", "dp54", "ros34pw2")) -> list[dict]:
    """Write a bad value into the state behind ``reset``'s back (last wing or node, mid-run) and step: every
    injection must raise a SimulationError naming the time, the body and a quantity, and leave no non-finite
    value in a state that is reported as good."""
    rows = []
    for method in methods:
        base = build_simulator(scene, method=method)
        if method == "rk4":  # a scene whose own step is a W-method's (the rotorcraft's 50 ms) needs RK4's limit
            est = estimate_stable_step(base, "rk4").dt_max
            if base.settings.dt > est:
                base = with_settings(base, dt=0.5 * est)
        base.step(n_steps=10)
        for label, kind, slot, value in INJECTIONS:
            a = base.assembly
            if kind == "node" and a.n_nodes == 0:
                continue
            k = (a.n_wings if kind == "wing" else a.n_nodes) - 1
            off = (a.wing_state_size * k if kind == "wing" else a.n_wings * a.wing_state_size + a.node_state_size * k)
            sim = with_settings(base, state=base.state.copy())
            sim.reset(base.state.copy(), t=base.t)
            sim.state[off + slot] = value
            try:
                sim.step(n_steps=5)
                text, passed = "escaped: no error", False
            except SimulationError as e:
                text = str(e).splitlines()[0]
                named = re.search(r"t = [-0-9.e+]+ s", text) and f"{kind} {k}" in str(e)
                passed = bool(named)
                text = ("reported: " if passed else "reported without time/body: ") + text[:150]
            rows.append({"case": f"inject {label}", "scene": scene, "method": method, "passed": passed,
                         "outcome": text})
    return rows
