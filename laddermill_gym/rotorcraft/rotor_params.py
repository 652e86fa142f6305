"""Rotor parameters of Roberts' craft: :class:`RotorParams` (Gessow & Myers' blade constants), the rotor YAML
files (:func:`load_rotor_config`), the solver settings, and the argument checks of the rotor functions (a
``ValueError`` naming the argument and its value)."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.model.configio import CONFIG_DIR, read_yaml
from laddermill_gym.rotorcraft import rotor_kernels as _k

#: Folder of the rotor YAML files and the default rotor (Roberts' craft).
ROTOR_CONFIG_DIR = CONFIG_DIR / "rotors"
DEFAULT_ROTOR_CONFIG = ROTOR_CONFIG_DIR / "roberts_rotor.yaml"

#: Blade-incidence limit of Roberts' Fig. 3 (section 4: "a blade incidence limit of 13 deg") [rad].
BLADE_INCIDENCE_LIMIT = math.radians(13.0)

#: Tolerance and iteration cap of the inflow solver (see rotorcraft.rotor_kernels.solve_inflow).
INFLOW_TOL = 1e-13
INFLOW_MAX_ITER = 300


class RotorSolveError(RuntimeError):
    """A root (autorotation angle, collective at the limit, solidity) could not be bracketed or solved."""


# ------------------------------------------------------------------------------------------- parameters
def _field_problem(name: str, value: float) -> str | None:
    """Why ``value`` is not valid for the RotorParams field ``name`` (None when it is)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        return "must be a number"
    v = float(value)
    if not math.isfinite(v):
        return "must be finite"
    if name == "sigma" and not 0.0 < v < 1.0:
        return "solidity must lie in (0, 1)"
    if name == "a" and not v > 0.0:
        return "lift-curve slope must be > 0"
    if name == "delta" and not v >= 0.0:
        return "profile-drag coefficient must be >= 0"
    if name == "B" and not 0.0 < v <= 1.0:
        return "tip-loss factor must lie in (0, 1]"
    if name == "gamma" and not v > 0.0:
        return "Lock number must be > 0"
    return None


@dataclass(frozen=True)
class RotorParams:
    """Blade and rotor constants of an untwisted rotor (Gessow & Myers' notation, as in Roberts eq. 1).

    Attributes
    ----------
    sigma : float
        Solidity b c / (pi R) [-]: blade area over disk area (b blades of chord c, radius R); in (0, 1).
    a : float
        Blade-section lift-curve slope [1/rad]; 5.73 is Gessow & Myers' usual value.
    delta : float
        Mean blade-section profile-drag coefficient [-] (constant over the disk); 0 is the ideal rotor.
    B : float
        Tip-loss factor [-]: the blade lifts only out to r = B R; in (0, 1].
    gamma : float
        Lock number rho a c R^4 / I_b [-] (aerodynamic over inertial flapping moment); sets the coning.

    Raises
    ------
    ValueError
        On a non-finite or out-of-range field; the message names the field and the value.
    """

    sigma: float
    a: float = 5.73
    delta: float = 0.01
    B: float = 0.97
    gamma: float = 8.0

    def __post_init__(self) -> None:
        for f in dataclasses.fields(self):
            value = getattr(self, f.name)
            why = _field_problem(f.name, value)
            if why is not None:
                raise ValueError(f"RotorParams: field '{f.name}' = {value!r}: {why}")
            object.__setattr__(self, f.name, float(value))

    def packed(self) -> np.ndarray:
        """The kernels' packed parameter array, float64[N_PARAMS] (rotorcraft.rotor_kernels.P_* order)."""
        p = np.empty(_k.N_PARAMS)
        p[_k.P_SIGMA], p[_k.P_A], p[_k.P_DELTA], p[_k.P_B], p[_k.P_GAMMA] = (
            self.sigma, self.a, self.delta, self.B, self.gamma)
        return p

    def ideal(self) -> RotorParams:
        """The same rotor without profile drag (delta = 0)."""
        return dataclasses.replace(self, delta=0.0)

    def with_solidity(self, sigma: float) -> RotorParams:
        """The same blades at another solidity [-]."""
        return dataclasses.replace(self, sigma=sigma)


@dataclass(frozen=True)
class RotorConfig:
    """A rotor read from ``configs/rotors/*.yaml``: its parameters and the blade-incidence limit [rad]."""

    name: str
    params: RotorParams
    blade_incidence_limit: float


def load_rotor_config(path: Path | str) -> RotorConfig:
    """Read a rotor YAML file strictly (unknown keys and invalid values raise ConfigError naming the field).

    Expected fields: ``name``, ``sigma`` [-], ``lift_slope`` [1/rad], ``profile_drag`` [-], ``tip_loss`` [-],
    ``lock_number`` [-], ``blade_incidence_limit_deg`` [deg].
    """
    s = read_yaml(path)
    name = s.text("name")
    values = {}
    for field, key in (("sigma", "sigma"), ("a", "lift_slope"), ("delta", "profile_drag"), ("B", "tip_loss"),
                       ("gamma", "lock_number")):
        v = s.number(key)
        why = _field_problem(field, v)
        if why is not None:
            raise s.error(key, v, why)
        values[field] = v
    limit_deg = s.number("blade_incidence_limit_deg", positive=True)
    if not limit_deg < 90.0:
        raise s.error("blade_incidence_limit_deg", limit_deg, "must be < 90")
    s.done()
    return RotorConfig(name=name, params=RotorParams(**values), blade_incidence_limit=math.radians(limit_deg))


# ------------------------------------------------------------------------------------------- validation
def check_number(name: str, value, lo: float = -math.inf, hi: float = math.inf, *, lo_open: bool = False,
                 hi_open: bool = False) -> float:
    """``value`` as a float when it is a finite number in [lo, hi] (ends excluded where ``lo_open``/``hi_open``);
    a ValueError naming the argument ``name`` and the value otherwise."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise ValueError(f"argument '{name}' = {value!r}: must be a number")
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"argument '{name}' = {value!r}: must be finite")
    if (v < lo or (lo_open and v == lo)) or (v > hi or (hi_open and v == hi)):
        lb = "(" if lo_open else "["
        rb = ")" if hi_open else "]"
        raise ValueError(f"argument '{name}' = {value!r}: must lie in {lb}{lo}, {hi}{rb}")
    return v


def check_params(params) -> RotorParams:
    """``params`` when it is a RotorParams (ValueError otherwise)."""
    if not isinstance(params, RotorParams):
        raise ValueError(f"argument 'params' = {params!r}: must be a RotorParams")
    return params


def check_mu(mu) -> float:
    """Advance ratio [-] in (0, 1)."""
    return check_number("mu", mu, 0.0, 1.0, lo_open=True, hi_open=True)


def check_alpha(alpha_c) -> float:
    """Craft incidence [rad] in (-pi/2, pi/2)."""
    return check_number("alpha_c", alpha_c, -0.5 * math.pi, 0.5 * math.pi, lo_open=True, hi_open=True)


def check_theta(theta0) -> float:
    """Collective [rad] in (-pi/2, pi/2)."""
    return check_number("theta0", theta0, -0.5 * math.pi, 0.5 * math.pi, lo_open=True, hi_open=True)


def check_limit(limit) -> float:
    """Blade-incidence limit [rad] in (0, pi/2)."""
    return check_number("limit", limit, 0.0, 0.5 * math.pi, lo_open=True, hi_open=True)
