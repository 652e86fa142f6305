"""Breakpoints of the forcing: the integrators step exactly onto them.

The wind's time modulation (``atmosphere/field.py``) is piecewise linear in time on the grid t0 + k dt and held
before the first and after the last sample, so the right-hand side has a kink (a jump of the speed-factor and
direction rates, which enter the wings' alpha-rate term) wherever the slope changes. A Runge-Kutta step across a
kink loses its order: the CLI's direction step, a 1 ms ramp inside one 12.5 ms RK4 step, made RK4's error
4-7 orders of magnitude larger than on smooth dynamics. Here a step that holds a kink strictly inside is split
at it, and each piece is integrated with the modulation of its own linear segment (so the stage at the end of
a piece sees the left-hand slope, not the next segment's). Steps with no kink strictly inside are left exactly
as they were (bit for bit).

Control changes happen between calls of ``Simulator.step`` / ``advance_to`` (the controls are held within a
call), so they are breakpoints already. The frozen gust grid moves continuously with time (no time kinks
of its own). The fixed-step methods split their steps in the compiled ``kernels/fixed_steps.py``, which the batched
kernels (``BatchSimulator``, the envs) run too; the error-controlled ones are split here.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels.contract import OK, TM_DT, TM_SIZE, TM_T0
from laddermill_gym.kernels.fixed_steps import (
    ALIGN_TOL,
    BREAKS_ENDS,
    BREAKS_INSIDE,
    BREAKS_OFF,
    advance_breaks,
    fill_segment,
    is_kink,
)
from laddermill_gym.kernels.integrate import dp54_advance
from laddermill_gym.kernels.rigid.rosenbrock import ROS1, ROS2, ROS2T, ROS34PW2, with_jacobian_reuse
from laddermill_gym.kernels.rigid.rosenbrock_adaptive import w_adaptive

#: Tableaux of the fixed-step linearly implicit (Rosenbrock-W) methods by name (``kernels/rigid/rosenbrock.py``)
W_METHODS = {"ros1": ROS1, "ros2": ROS2, "ros2t": ROS2T, "ros34pw2": ROS34PW2}
#: The error-controlled Rosenbrock-W methods: (tableau, order of the embedded method)
W_ADAPTIVE = {"ros34pw2a": (ROS34PW2, 2)}
#: Integrators a simulator runs: fixed-step classical Runge-Kutta, adaptive Dormand-Prince 5(4) and the fixed-step
#: linearly implicit Rosenbrock-W methods (``kernels/rigid/rosenbrock.py``; 3D rigid models).
INTEGRATOR_METHODS: tuple[str, ...] = ("rk4", "dp54", *W_METHODS, *W_ADAPTIVE)
#: The fixed-step methods (``dt``): RK4 and the Rosenbrock-W methods.
FIXED_STEP_METHODS: tuple[str, ...] = ("rk4", *W_METHODS)
#: The error-controlled methods (``rtol``, ``atol``; ``dt`` is the first trial step).
ADAPTIVE_METHODS: tuple[str, ...] = ("dp54", *W_ADAPTIVE)


#: ``IntegratorSettings.breakpoints``: "off" integrates across kinks (as before); "inside" splits the steps that
#: hold a kink inside (steps that only end or start on one run as before, bit for bit); "all" also runs those
#: with their own segment's modulation (fourth order on a kink grid aligned with the steps too)
BREAKPOINT_MODES = ("off", "inside", "all")


def modulation_kinks(tmod: np.ndarray, ms: np.ndarray, md: np.ndarray) -> np.ndarray:
    """Times [s] where the packed modulation's slope changes (speed factor or direction offset), sorted.

    The slope is zero before the first and after the last sample (the modulation holds there), so the ends
    are kinks when the adjacent segment is not flat. Padding (repeated last samples) adds none."""
    ks = [k for k in range(ms.size) if is_kink(k, ms, md)]  # the compiled steppers' own test
    return float(tmod[TM_T0]) + float(tmod[TM_DT]) * np.array(ks, dtype=float)


def segment_model(model, ta: float, tb: float):
    """``model`` with its modulation replaced by the straight line that the real modulation follows on
    [ta, tb] (an interval holding no kink inside), extended beyond it; evaluated at ta or tb the line gives the
    value and the slope of this segment (the kernel's own grid gives the next segment's slope at a grid point)."""
    tmod, ms, md = np.zeros(TM_SIZE), np.zeros(4), np.zeros(4)
    fill_segment(model, ta, tb, tmod, ms, md)  # the compiled steppers' own line
    return model._replace(tmod=tmod, ms=ms, md=md)


def interior_kinks(kinks: np.ndarray, ta: float, tb: float, ends: bool = False) -> list[float]:
    """Kinks strictly inside (ta, tb) [s], beyond ``ALIGN_TOL`` of the span from either end (with ``ends``, the
    kinks at either end too, so that each piece runs with its own segment's modulation)."""
    if kinks.size == 0 or not tb > ta:
        return []
    tol = ALIGN_TOL * max(tb - ta, 1e-300)
    if ends:
        lo, hi = np.searchsorted(kinks, [ta - tol, tb + tol], side="right")
        return [float(b) for b in kinks[lo:hi]]
    lo, hi = np.searchsorted(kinks, [ta + tol, tb - tol], side="right")
    return [float(b) for b in kinks[lo:hi] if ta + tol < b < tb - tol]


def breaks_mode(settings) -> int:
    """The fixed-step kernels' ``breaks`` argument (``kernels/fixed_steps.py``) for ``settings.breakpoints``: a
    Rosenbrock-W method's last stage sits on the step's end, so a step that ends on a kink runs with its own
    segment's line too ("all"); RK4 keeps "inside" as its default for the pinned trajectories' sake."""
    mode = settings.breakpoints
    if mode == "off":
        return BREAKS_OFF
    return BREAKS_ENDS if mode == "all" or settings.method != "rk4" else BREAKS_INSIDE


def fixed_tableau(settings):
    """The fixed-step kernels' method argument for ``settings``: None (RK4) or the W-method's tableau, with its
    iteration matrix kept for ``settings.jacobian_every`` steps (``rosenbrock.with_jacobian_reuse``)."""
    tableau = W_METHODS.get(settings.method)
    if tableau is None:
        return None
    return with_jacobian_reuse(tableau, settings.jacobian_every)


def fixed_pieces_call(sim, n: int) -> tuple:
    """(kernel, arguments) of :func:`fixed_pieces`' one kernel call for n steps on ``sim``: the kernel warm-ups
    compile it for these arguments' types without running a step (``envs/laddermill/kernel_warmup.py``)."""
    s = sim.settings
    return advance_breaks, (sim.t, sim.state, sim.controls, s.dt, n, sim.model, sim.work, sim.limits,
                            fixed_tableau(s), breaks_mode(s))


def fixed_pieces(sim, n: int):
    """n steps of ``sim.settings.dt`` of its fixed-step method (RK4 or a Rosenbrock-W method) on ``sim`` (a
    ``Simulator``), a step that holds a kink split at it, each piece with its segment's modulation
    (``kernels/fixed_steps.advance_breaks``, the batched kernels' own stepper); advances ``sim.t`` and
    ``sim.state``. Returns (status, size of the failed step [s]); on a failure the state and time are those before
    the failed step (or piece)."""
    kernel, args = fixed_pieces_call(sim, n)
    status, _, t, h = kernel(*args)
    sim.t = t
    return status, h


def _adaptive(method: str, t, t_end, x, u, h, rtol, atol, model, work, limits, max_steps):
    """The error-controlled ``method`` ("dp54" or a name of :data:`W_ADAPTIVE`) from t to t_end [s]."""
    if method in W_ADAPTIVE:
        tableau, q = W_ADAPTIVE[method]
        return w_adaptive(t, t_end, x, u, h, rtol, atol, model, work, limits, max_steps, tableau, q)
    return dp54_advance(t, t_end, x, u, h, rtol, atol, model, work, limits, max_steps)


def adaptive_pieces(sim, t_end: float, h: float, rtol: float, atol: float, max_steps: int, method: str = "dp54"):
    """The error-controlled ``method`` (DP5(4) or an adaptive Rosenbrock-W method) on ``sim`` from its time to
    t_end [s] (first trial step h [s]), ending a step on every kink inside, each piece with its segment's
    modulation; the state is advanced in place, ``sim.t`` is left to the caller, the steps taken are added to
    ``sim.adaptive_steps`` (accepted, rejected). Returns (status, step size [s]: the failed step's, or on success
    the controller's proposal for the next one, time of the state [s]: t_end, or the last accepted step's)."""
    mode = sim.settings.breakpoints
    inside = interior_kinks(sim.breakpoint_times, sim.t, t_end, mode == "all") if mode != "off" else []
    ends = [sim.t, *[b for b in inside if sim.t < b < t_end], t_end]
    for ta, tb in zip(ends[:-1], ends[1:], strict=True):
        model = segment_model(sim.model, ta, tb) if inside else sim.model
        status, acc, rej, h, t = _adaptive(method, ta, tb, sim.state, sim.controls, h, rtol, atol, model, sim.work,
                                           sim.limits, max_steps)
        sim.adaptive_steps[0] += acc
        sim.adaptive_steps[1] += rej
        if status != OK:
            return status, h, t
    return OK, h, t_end
