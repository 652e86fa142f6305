"""The physics step of an env on an explicit method, chosen from the stability estimate in the strongest wind of
its disturbances.

Why (issue 13, point 4): TetheredWing-v0 on RK4 at 0.05 s is stable in its nominal wind (RK4's limit at the trim
is 0.11 s with one element per piece), but after a 5x wind step the wing's aerodynamic damping (an eigenvalue near
-121 1/s) puts the step past RK4's limit (0.023 s): the state grows about 30-fold per step, stays finite for a
few periods and the episode ends on an angle of attack "outside the aerodynamic range", a termination that looks
physical. The rerun of a failed control period at a finer step (``sim/batch.py``) cannot mend it, since the state
before the failing period is already off. So an env whose scene runs RK4 estimates the stable step
(``sim/stable_step.py``: the Jacobian's eigenvalues) at the trim with the speed factor held at the largest the
disturbances reach in a few draws, and, if the requested step is above ``ENV_STEP_MARGIN`` times that, steps at
the largest whole fraction of the control period below it, with a warning that names both. The rotorcraft env
does the same for ``physics_step="rk4"`` (:func:`stable_rk4_step` on its ``CraftSimulator``: the tether's
fast mode sets a limit of about 6 ms; at 12.5 ms a seeded episode ended 0.8 s in on a tether node at 91 m/s).
The W-methods (``ros2``, ``ros34pw2``) are stable there and keep their step.

What it does not see: a spatial gust grid (its speeds are not in the speed factor) and a state far from the trim;
a failure there is still rerun by the batch at dt / 4 and dt / 16.

The env argument ``physics_step`` (issue 32 point 3; :func:`env_physics_settings`) swaps the registered step for
another fixed-step method without changing the id's scene, start or spaces: ``"ros34pw2"`` steps the 101-wing
envs once per control period, within 1e-3 of the chain's and the mill's extent of RK4 at a quarter of the
registered step over a short episode (tests/test_fast_physics_step.py) and about twice as fast as the registered
RK4 (docs/benchmarks.md, "Environment throughput"); ``physics_step="ros2", jacobian_every=4`` (one ROS2 step per
period, its iteration matrix kept 4 steps) is the fastest step within that bound that runs the short episode
through on both (about 4x the registered step at 8 copies; kept 8 steps it ends the episode early), but it biases
the mill's power (-2 % over 10 s, docs/benchmarks.md) and broke the mill at 5 m/s in a review's runs;
``laddermill_gym/LadderMill-v3`` registers ``physics_step="ros2"`` with the matrix formed every step.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from laddermill_gym.atmosphere.disturbances import sample_modulation
from laddermill_gym.atmosphere.field import WindField
from laddermill_gym.envs.task_base import positive
from laddermill_gym.sim.breakpoints import FIXED_STEP_METHODS, W_METHODS
from laddermill_gym.sim.simulator import Simulator
from laddermill_gym.sim.stable_step import estimate_stable_step

#: the requested step is kept up to this fraction of the estimated stable step [-] (the estimate is for the
#: linearisation at the trim; the tethered wing's 5x step flies 60 s at 0.0167 s = 0.72 of it, and at 0.025 s)
ENV_STEP_MARGIN = 0.9
#: draws of the disturbances' random parameters for the largest speed factor
PEAK_DRAWS = 4


def peak_speed_factor(disturbances, episode_time: float, wind_dt: float) -> float:
    """The largest composed speed factor [-] of ``disturbances`` over an episode, over ``PEAK_DRAWS`` draws
    (seeds 0, 1, ...), at least 1."""
    peak = 1.0
    for seed in range(PEAK_DRAWS):
        speed, _ = sample_modulation(disturbances, episode_time, wind_dt, np.random.default_rng(seed))
        peak = max(peak, float(np.max(speed)))
    return peak


def stable_physics_step(scene, x: np.ndarray, u: np.ndarray, control_dt: float, disturbances, episode_time: float,
                        wind_dt: float) -> tuple[float, str]:
    """(physics step [s], reason): the scene's step if its method is not RK4 or the step is within
    ``ENV_STEP_MARGIN`` of RK4's estimated stable step at the trim (x, u) in the strongest wind of
    ``disturbances`` (reason ''); else ``control_dt / n`` for the smallest n below that, and the reason."""
    s = scene.settings
    if s.method != "rk4":
        return s.dt, ""
    return stable_rk4_step(Simulator(scene.assembly, x, s, u), s.dt, control_dt, disturbances, episode_time,
                           wind_dt)


def periods_below(control_dt: float, limit: float) -> int:
    """The fewest steps n per control period of ``control_dt`` [s] with control_dt / n at most ``limit`` [s]: the
    finer step an env takes in place of one past its stability limit (RK4 here, the point-mass explicit step)."""
    return max(1, math.ceil(control_dt / limit - 1e-9))


def stable_rk4_step(sim, dt: float, control_dt: float, disturbances, episode_time: float,
                    wind_dt: float) -> tuple[float, str]:
    """(physics step [s], reason) for RK4 at ``dt`` [s]: ``dt`` (reason '') if it is within ``ENV_STEP_MARGIN`` of
    RK4's estimated stable step at the state of ``sim`` (a simulator at the trim: a scene's, or the rotorcraft's
    ``CraftSimulator``; its wind is set here) in the strongest wind of ``disturbances``; else ``control_dt / n``
    for the smallest n below that, and the reason."""
    peak = peak_speed_factor(disturbances, episode_time, wind_dt)
    if peak != 1.0:
        sim.set_wind(WindField(0.0, 1.0, np.array([peak, peak]), np.zeros(2)))
    est = estimate_stable_step(sim, "rk4")
    limit = ENV_STEP_MARGIN * est.dt_max
    if dt <= limit:
        return dt, ""
    n = periods_below(control_dt, limit)
    step = control_dt / n
    lam = est.eigenvalue
    return step, (f"physics_dt = {dt:g} s is above {ENV_STEP_MARGIN:g} x RK4's estimated stable step "
                  f"{est.dt_max:.4g} s (eigenvalue {lam.real:.4g} {'+-' if lam.imag else '+'} {abs(lam.imag):.4g}i "
                  f"1/s) at the trim in the strongest wind of the disturbances (speed factor {peak:.3g}): stepping at "
                  f"{step:.4g} s, {n} steps per control period")



def check_physics_step(physics_step) -> None:
    """ValueError naming ``physics_step`` unless it is None or one of ``FIXED_STEP_METHODS``."""
    if physics_step is not None and physics_step not in FIXED_STEP_METHODS:
        raise ValueError(f"physics_step = {physics_step!r}: must be None (the scene's integrator) or one of "
                         f"{', '.join(repr(m) for m in FIXED_STEP_METHODS)}")


def physics_scene_options(scene_options, physics_step: str | None, physics_dt, control_dt: float) -> dict:
    """A wing env's ``load_scene`` overrides: ``scene_options`` with ``method`` = ``physics_step`` (unless None)
    and ``dt`` = ``physics_dt`` [s] (None: the control period ``control_dt`` [s] for a Rosenbrock-W method, else
    the scene's). ValueError naming both when ``scene_options`` sets another method."""
    options = dict(scene_options or {})
    check_physics_step(physics_step)
    if physics_step is not None:
        if options.get("method", physics_step) != physics_step:
            raise ValueError(f"physics_step = {physics_step!r} and scene_options['method'] = "
                             f"{options['method']!r}: give one of them")
        options["method"] = physics_step
        if physics_dt is None and physics_step in W_METHODS:
            physics_dt = control_dt
    if physics_dt is not None:
        options["dt"] = positive("physics_dt", physics_dt, "s")  # np.float32(0.025) read as 0.025
    return options


def env_physics_settings(settings, physics_step: str | None, physics_dt: float | None, control_dt: float):
    """The integrator settings an env steps with: ``settings`` (the scene's; the registered step) when
    ``physics_step`` and ``physics_dt`` are None; else ``settings`` with the method ``physics_step`` (one of
    ``FIXED_STEP_METHODS``; None keeps the scene's) and the step ``physics_dt`` [s] (None: the control period
    ``control_dt`` [s] for a Rosenbrock-W method, one linearly implicit step per period, else the scene's dt).
    ValueError naming the argument and its value otherwise."""
    check_physics_step(physics_step)
    if physics_step is None and physics_dt is None:
        return settings
    method = settings.method if physics_step is None else physics_step
    if physics_dt is None:
        dt = control_dt if method in W_METHODS else settings.dt
    else:
        dt = positive("physics_dt", physics_dt, "s")  # numpy's scalars too; np.float32(0.025) read as 0.025
    return dataclasses.replace(settings, method=method, dt=dt)


def jacobian_settings(settings, jacobian_every):
    """``settings`` with the iteration matrix of its W-method kept for ``jacobian_every`` steps (the env argument;
    ``IntegratorSettings.jacobian_every``). ValueError naming the argument and its value unless an integer >= 1,
    or > 1 with a method that is not a fixed-step W-method."""
    k = jacobian_every
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or not 1 <= k <= np.iinfo(np.int64).max:
        raise ValueError(f"jacobian_every = {k!r}: must be an integer >= 1 (physics steps per Jacobian), at most "
                         "2**63 - 1")
    if k != 1 and settings.method not in W_METHODS:
        raise ValueError(f"jacobian_every = {k!r}: only a W-method reuses its Jacobian (the physics step is "
                         f"{settings.method!r})")
    return dataclasses.replace(settings, jacobian_every=int(k))
