"""Rotor aerodynamics of Roberts' tethered twin-rotor craft: the Python layer over ``rotorcraft/rotor_kernels.py``.

Gessow & Myers' closed forms for an untwisted, centrally hinged rotor with uniform (Glauert) inflow, as
Roberts uses them for his power-coefficient chart (his Fig. 3). All angles are in radians and all
coefficients non-dimensional (helicopter convention: velocities over the tip speed Omega R, forces over
rho pi R^2 (Omega R)^2). Formulas, sources and choices: ``laddermill_gym/docs/rotor.md``.

The functions here validate their inputs (``ValueError`` naming the argument and its value), pack the
parameters and call the numba kernels; root finding over collective or incidence uses scipy's ``brentq`` on
brackets found by a scan. A failed inflow solution is reported through :attr:`RotorState.converged`; a root
that cannot be bracketed raises :class:`RotorSolveError`.

The code lives in three modules, all re-exported here: ``rotor_params`` (parameters, rotor files, argument
checks), ``rotor_aero`` (coefficients at an operating point) and ``rotor_limits`` (root finding: autorotation,
the blade-incidence limit).

Examples
--------
>>> import math
>>> from laddermill_gym.rotorcraft.rotor import RotorParams, autorotation_angle
>>> p = RotorParams(sigma=0.05, a=5.73, delta=0.01, B=0.97, gamma=8.0)
>>> round(math.degrees(autorotation_angle(p, mu=0.1, theta0=0.0)), 1)  # oracles.md: 21.7 deg
21.7
"""

from laddermill_gym.rotorcraft.rotor_aero import (
    InflowSolution,
    RotorState,
    cable_angle,
    craft_incidence,
    ideal_power_coefficient,
    power_coefficient,
    rotor_coefficients,
    solve_inflow,
)
from laddermill_gym.rotorcraft.rotor_limits import (
    autorotation_angle,
    autorotation_angle_at_limit,
    best_power_within_limit,
    collective_at_limit,
    max_power_at_limit,
    min_autorotation_angle,
    solidity_for_autorotation,
)
from laddermill_gym.rotorcraft.rotor_params import (
    BLADE_INCIDENCE_LIMIT,
    DEFAULT_ROTOR_CONFIG,
    INFLOW_MAX_ITER,
    INFLOW_TOL,
    ROTOR_CONFIG_DIR,
    RotorConfig,
    RotorParams,
    RotorSolveError,
    load_rotor_config,
)

__all__ = [
    "BLADE_INCIDENCE_LIMIT",
    "DEFAULT_ROTOR_CONFIG",
    "ROTOR_CONFIG_DIR",
    "INFLOW_TOL",
    "INFLOW_MAX_ITER",
    "RotorParams",
    "RotorConfig",
    "RotorState",
    "InflowSolution",
    "RotorSolveError",
    "load_rotor_config",
    "solve_inflow",
    "rotor_coefficients",
    "power_coefficient",
    "craft_incidence",
    "cable_angle",
    "ideal_power_coefficient",
    "autorotation_angle",
    "collective_at_limit",
    "max_power_at_limit",
    "best_power_within_limit",
    "min_autorotation_angle",
    "autorotation_angle_at_limit",
    "solidity_for_autorotation",
]
