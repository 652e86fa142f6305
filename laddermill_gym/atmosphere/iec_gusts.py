"""The standard gusts: IEC 61400-1 ed. 3 (2005) extreme operating gust (EOG, 6.3.2.2), extreme direction change
(EDC, 6.3.2.4), extreme coherent gust with direction change (ECD, 6.3.2.5) and extreme (vertical) wind shear
(EWS, 6.3.2.6), with the turbine class (I/II/III, A+/A/B/C) as a parameter, and speed steps and ramps. The
discrete 1-cosine gust is :class:`~laddermill_gym.atmosphere.disturbances.OneMinusCosineGust`.

How they enter the air:

* EOG, EDC, ECD, steps and ramps are spatially uniform, as the standard states them: a speed factor
  s(t) = V(t) / V_hub (so the speed at the reference height, where the scene's wind should equal
  ``wind_speed``, is the standard's V(t); elsewhere the profile is scaled with it) and a direction offset.
* EWS varies with height, so it is a frozen gust grid (u only): the transient +-((z - z_hub) / D) A (1 -
  cos(2 pi tau / T)) over the rotor height range z_hub +- D/2 (held beyond it), arriving at the along-wind
  position ``reference`` at ``time`` and advected downwind at ``wind_speed`` (tau = t - time - (p . e -
  reference) / U; for a rotor or a single wing near ``reference`` this is the standard's time history).
  The standard's horizontal shear needs a lateral coordinate, which the (xi, h) grid does not have.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np

from laddermill_gym.atmosphere import turbulence_models as tm
from laddermill_gym.atmosphere.disturbances import Disturbance
from laddermill_gym.atmosphere.field import GridGeometry, GustGrid

__all__ = ["EOG", "EDC", "ECD", "EWS", "SpeedStep", "Ramp", "eog_speed", "edc_direction", "ecd_speed_direction",
           "ews_amplitude"]

EOG_T = 10.5  # s, IEC 61400-1 ed. 3 6.3.2.2
EDC_T = 6.0  # s, 6.3.2.4
ECD_T = 10.0  # s, 6.3.2.5
ECD_V_CG = 15.0  # m/s, 6.3.2.5
EWS_T = 12.0  # s, 6.3.2.6
EWS_BETA = 6.4  # -, 6.3.2.6


def _num(cls: str, name: str, value, low: float | None = 0.0, strict: bool = True) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value) or (
            low is not None and (value <= low if strict else value < low)):
        bound = "" if low is None else f" {'>' if strict else '>='} {low:g}"
        raise ValueError(f"{cls}.{name} = {value!r}: must be a finite number{bound}")
    return float(value)


def _sign(cls: str, value) -> int:
    if value not in (1, -1) or isinstance(value, bool):
        raise ValueError(f"{cls}.sign = {value!r}: must be +1 or -1")
    return int(value)


def eog_speed(tau: np.ndarray, wind_class: str, v_hub: float, diameter: float, hub_height: float) -> np.ndarray:
    """EOG hub speed [m/s] at tau = t - start [s] (eqs. 16-17): V_gust = min(1.35 (V_e1 - V_hub), 3.3 sigma_1 /
    (1 + 0.1 D / Lambda_1)), V_e1 = 0.8 V_e50 = 0.8 * 1.4 V_ref; V = V_hub - 0.37 V_gust sin(3 pi tau / T)
    (1 - cos(2 pi tau / T)) for 0 <= tau <= T, V_hub otherwise."""
    v_ref, _ = tm.parse_wind_class(wind_class)
    s1 = tm.iec_sigma1(wind_class, v_hub, "NTM")
    v_gust = min(1.35 * (0.8 * 1.4 * v_ref - v_hub), 3.3 * s1 / (1.0 + 0.1 * diameter / tm.iec_lambda1(hub_height)))
    x = np.clip(tau / EOG_T, 0.0, 1.0)
    return v_hub - 0.37 * v_gust * np.sin(3.0 * math.pi * x) * (1.0 - np.cos(2.0 * math.pi * x))


def edc_direction(tau: np.ndarray, wind_class: str, v_hub: float, diameter: float, hub_height: float) -> np.ndarray:
    """EDC direction change [rad] (eqs. 21-22): theta_e = 4 atan(sigma_1 / (V_hub (1 + 0.1 D / Lambda_1))),
    limited to 180 deg as the standard limits it (reached below about 1 m/s), theta = 0.5 theta_e (1 - cos(pi tau /
    T)) for 0 <= tau <= T, theta_e after."""
    s1 = tm.iec_sigma1(wind_class, v_hub, "NTM")
    theta_e = min(4.0 * math.atan(s1 / (v_hub * (1.0 + 0.1 * diameter / tm.iec_lambda1(hub_height)))), math.pi)
    x = np.clip(tau / EDC_T, 0.0, 1.0)
    return 0.5 * theta_e * (1.0 - np.cos(math.pi * x))


def ecd_speed_direction(tau: np.ndarray, v_hub: float) -> tuple[np.ndarray, np.ndarray]:
    """ECD hub speed [m/s] and direction [rad] (eqs. 23-25): V = V_hub + 0.5 V_cg (1 - cos(pi tau / T)),
    theta = 0.5 theta_cg (1 - cos(pi tau / T)), theta_cg = 180 deg below 4 m/s, 720 deg m/s / V_hub above;
    held after T."""
    theta_cg = math.pi if v_hub < 4.0 else math.radians(720.0) / v_hub
    c = 0.5 * (1.0 - np.cos(math.pi * np.clip(tau / ECD_T, 0.0, 1.0)))
    return v_hub + ECD_V_CG * c, theta_cg * c


def ews_amplitude(wind_class: str, v_hub: float, diameter: float, hub_height: float) -> float:
    """EWS shear amplitude A [m/s] (eq. 26): 2.5 m/s + 0.2 beta sigma_1 (D / Lambda_1)^(1/4), beta = 6.4; the
    transient at height z is ((z - z_hub) / D) A (1 - cos(2 pi tau / T)), T = 12 s."""
    s1 = tm.iec_sigma1(wind_class, v_hub, "NTM")
    return 2.5 + 0.2 * EWS_BETA * s1 * (diameter / tm.iec_lambda1(hub_height)) ** 0.25


@dataclass(frozen=True)
class _IEC(Disturbance):
    """Common parameters: ``wind_class`` (IEC class, e.g. "IA"), ``wind_speed`` V_hub [m/s] (the scene's wind at
    ``hub_height`` [m]), ``diameter`` D [m] (rotor; for a wing its span), ``time`` [s] of the event's start."""

    wind_class: str = "IA"
    wind_speed: float = 10.0
    hub_height: float = 100.0
    diameter: float = 20.0
    time: float = 5.0

    def __post_init__(self):
        name = type(self).__name__
        tm.parse_wind_class(self.wind_class, f"{name}.wind_class")
        for f in ("wind_speed", "hub_height", "diameter"):
            _num(name, f, getattr(self, f))
        _num(name, "time", self.time, low=None)


@dataclass(frozen=True)
class EOG(_IEC):
    """IEC extreme operating gust: speed factor V(t) / V_hub (the Mexican-hat of eq. 17, T = 10.5 s)."""

    def __post_init__(self):
        super().__post_init__()
        v_e1 = 0.8 * 1.4 * tm.parse_wind_class(self.wind_class)[0]
        if self.wind_speed > v_e1:  # the standard's V_hub stops at cut-out, below V_e1
            raise ValueError(f"EOG.wind_speed = {self.wind_speed!r}: above V_e1 = {v_e1:g} m/s of class "
                             f"{self.wind_class} (0.8 x 1.4 V_ref), where eq. 16's 1.35 (V_e1 - V_hub) turns the "
                             "gust over")
        x = np.linspace(0.0, EOG_T, 4001)
        vmin = float(eog_speed(x, self.wind_class, self.wind_speed, self.diameter, self.hub_height).min())
        if vmin < 0.0:
            raise ValueError(f"EOG.wind_speed = {self.wind_speed!r}: the gust's dip reaches {vmin:.3g} m/s < 0")

    def sample(self, t, rng):
        v = eog_speed(t - self.time, self.wind_class, self.wind_speed, self.diameter, self.hub_height)
        return v / self.wind_speed, np.zeros_like(t)


@dataclass(frozen=True)
class EDC(_IEC):
    """IEC extreme direction change: direction offset sign * theta(t) (eq. 22, T = 6 s), held after."""

    sign: int = 1

    def __post_init__(self):
        super().__post_init__()
        _sign("EDC", self.sign)

    def sample(self, t, rng):
        d = edc_direction(t - self.time, self.wind_class, self.wind_speed, self.diameter, self.hub_height)
        return np.ones_like(t), self.sign * d


@dataclass(frozen=True)
class ECD(_IEC):
    """IEC extreme coherent gust with direction change: speed factor (V_hub + 0.5 V_cg (1 - cos)) / V_hub and
    direction offset sign * theta(t) (eqs. 23-25, T = 10 s), both held after."""

    sign: int = 1

    def __post_init__(self):
        super().__post_init__()
        _sign("ECD", self.sign)

    def sample(self, t, rng):
        v, d = ecd_speed_direction(t - self.time, self.wind_speed)
        return v / self.wind_speed, self.sign * d


@dataclass(frozen=True)
class EWS(_IEC):
    """IEC extreme vertical wind shear as a frozen grid (u component): sign * ((z - z_hub) / D) A (1 - cos(2 pi
    tau / T)) over z_hub +- D/2 (held beyond), arriving at along-wind position ``reference`` [m] (p . e) at
    ``time`` and advected at ``wind_speed``; ``n_columns`` grid columns over the event (resolution)."""

    sign: int = 1
    reference: float = 0.0
    heading: float = 0.0
    n_columns: int = 96

    def __post_init__(self):
        super().__post_init__()
        _sign("EWS", self.sign)
        _num("EWS", "reference", self.reference, low=None)
        _num("EWS", "heading", self.heading, low=None)
        if isinstance(self.n_columns, bool) or not isinstance(self.n_columns, int) or self.n_columns < 4:
            raise ValueError(f"EWS.n_columns = {self.n_columns!r}: must be an integer >= 4")

    def sample(self, t, rng):
        return np.ones_like(t), np.zeros_like(t)

    def grid_geometry(self, t_end: float) -> GridGeometry:
        u = self.wind_speed
        dxi = u * EWS_T / self.n_columns
        xi0 = self.reference - u * (self.time + EWS_T) - dxi  # tau = T + dxi / U at the first column
        return GridGeometry(xi0, dxi, self.n_columns + 3, self.hub_height - 0.5 * self.diameter, self.diameter,
                            2, u, self.heading)

    def gust_grid(self, t_end: float, rng: np.random.Generator) -> GustGrid:
        g = self.grid_geometry(t_end)
        xi = g.xi0 + g.dxi * np.arange(g.n_xi)
        tau = -self.time - (xi - self.reference) / self.wind_speed
        inside = (tau >= 0.0) & (tau <= EWS_T)
        shape = np.where(inside, 1.0 - np.cos(2.0 * math.pi * tau / EWS_T), 0.0)
        a = self.sign * ews_amplitude(self.wind_class, self.wind_speed, self.diameter, self.hub_height)
        values = np.zeros((g.n_xi, 2, 3))
        values[:, 0, 0] = -0.5 * a * shape
        values[:, 1, 0] = 0.5 * a * shape
        return GustGrid(values, g.xi0, g.dxi, g.h0, g.dh, g.advection, g.heading)


@dataclass(frozen=True)
class SpeedStep(Disturbance):
    """A step of the speed factor from 1 to 1 + ``step`` [-] at ``time`` [s] (step > -1)."""

    step: float = 0.2
    time: float = 1.0

    def __post_init__(self):
        _num("SpeedStep", "step", self.step, low=-1.0)
        _num("SpeedStep", "time", self.time, low=None)

    def sample(self, t, rng):
        return np.where(t >= self.time, 1.0 + self.step, 1.0), np.zeros_like(t)


@dataclass(frozen=True)
class Ramp(Disturbance):
    """A linear ramp from ``time`` [s] over ``duration`` [s] of the speed factor to 1 + ``speed_change`` [-]
    (> -1) and of the direction offset to ``direction_change`` [rad], held after."""

    speed_change: float = 0.2
    direction_change: float = 0.0
    time: float = 1.0
    duration: float = 10.0

    def __post_init__(self):
        _num("Ramp", "speed_change", self.speed_change, low=-1.0)
        _num("Ramp", "direction_change", self.direction_change, low=None)
        _num("Ramp", "time", self.time, low=None)
        _num("Ramp", "duration", self.duration)

    def sample(self, t, rng):
        x = np.clip((t - self.time) / self.duration, 0.0, 1.0)
        return 1.0 + self.speed_change * x, self.direction_change * x
