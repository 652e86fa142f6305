"""The rotorcraft environments' starting point: the craft config, its control ranges, the trim (cached) and the
trim-holding action and open-loop controller."""

from __future__ import annotations

import dataclasses
import math
import numbers
import warnings

import numpy as np

from laddermill_gym.envs.start_cache import CRAFT_SOURCES, cached_start, start_on_disk
from laddermill_gym.kernels.contract import CU_COLLECTIVE
from laddermill_gym.model.input_cache import input_cache
from laddermill_gym.rotorcraft.config import DEFAULT_CRAFT, CraftConfig, load_craft_config
from laddermill_gym.rotorcraft.craft import Craft, load_craft
from laddermill_gym.warning_site import user_stacklevel

__all__ = ["craft_config", "control_ranges", "trim_controls", "untrimmed_craft", "craft_trim",
           "trim_on_disk", "trim_action"]


def craft_config(craft: str) -> CraftConfig:
    """The craft config of a name in configs/rotorcraft/ or a YAML path, cached in this process while the files it
    read (the craft's, its rotor's and its tethers' cable's YAML) hold the same bytes (``model/input_cache.py``);
    ValueError names ``craft``."""
    return _craft_config(str(craft))


@input_cache(maxsize=8)
def _craft_config(craft: str) -> CraftConfig:
    try:
        return load_craft_config(craft)
    except ValueError as err:
        raise ValueError(f"craft = {craft!r}: {err}") from None


def control_ranges(cfg: CraftConfig) -> tuple[np.ndarray, np.ndarray]:
    """(mid, half_range), each (2,) [rad], of the controls (collective, differential): the normalised action
    a in [-1, 1] maps onto mid + a half_range."""
    lim = np.array([cfg.collective_limits, cfg.differential_limits])
    return 0.5 * (lim[:, 0] + lim[:, 1]), 0.5 * (lim[:, 1] - lim[:, 0])


def trim_controls(cfg: CraftConfig, collective: float | None) -> np.ndarray:
    """The trim controls (collective [rad] (None: the config's initial collective), no differential), shape
    (2,); ValueError names ``collective`` outside the config's collective limits."""
    th = cfg.initial_collective if collective is None else collective
    lo, hi = cfg.collective_limits
    if isinstance(th, (bool, np.bool_)) or not isinstance(th, numbers.Real):  # numpy's scalars are real numbers too
        raise ValueError(f"collective = {th!r}: must be a number [rad], not {type(th).__name__}")
    if not (math.isfinite(th) and lo <= th <= hi):
        raise ValueError(f"collective = {th!r} rad: must lie in the craft's collective_limits [{lo:.4g}, {hi:.4g}] rad")
    return np.array([float(th), 0.0])


def untrimmed_craft(craft: str = DEFAULT_CRAFT, wind_speed: float | None = None, collective: float | None = None,
                    physics_dt: float | None = None) -> tuple[Craft, np.ndarray]:
    """(craft, u_trim (2,) [rad]) as :func:`craft_trim` builds them, before the trim (arguments as there)."""
    cfg = craft_config(craft)
    u = trim_controls(cfg, collective)
    if wind_speed is not None:
        cfg = cfg.with_wind_speed(wind_speed)
    if physics_dt is not None:
        cfg = cfg.replace(settings=dataclasses.replace(cfg.settings, dt=float(physics_dt)))
    return load_craft(config=cfg), u


def craft_trim(craft: str = DEFAULT_CRAFT, wind_speed: float | None = None, collective: float | None = None,
               physics_dt: float | None = None) -> tuple[Craft, np.ndarray, np.ndarray]:
    """(craft, x_trim (n_state,), u_trim (2,) [rad]) for a craft name or path, wind speed v0 [m/s] (None: the
    config's), trim collective [rad] (None: the config's) and physics step [s] (None: the config's).

    Cached on the arguments while the files the craft read hold the same bytes (``model/input_cache.py``: a trim
    takes about 0.5 s) and on disk for the next process (``envs/start_cache.py``); the returned arrays are read-only.
    ``craft_trim.cache_clear()`` empties the in-process cache."""
    return _craft_trim(str(craft), wind_speed, collective, physics_dt)


@input_cache(maxsize=16)
def _craft_trim(craft: str, wind_speed, collective, physics_dt) -> tuple[Craft, np.ndarray, np.ndarray]:
    c, u = untrimmed_craft(craft, wind_speed, collective, physics_dt)
    try:
        x, _ = cached_start("craft_start", c.config.name, (c, u), CRAFT_SOURCES, lambda: (c.trim(u[0]), u))
    except RuntimeError as err:
        v_note = "" if wind_speed is not None else " (the config's)"  # the values used, not the None given
        c_note = "" if collective is not None else " (the config's)"
        raise ValueError(f"wind_speed = {c.config.wind.v0:g} m/s{v_note}, collective = {float(u[0]):.4g} rad{c_note}: "
                         f"{err}") from None
    x.setflags(write=False)
    u.setflags(write=False)
    return c, x, u


craft_trim.cache_clear = _craft_trim.cache_clear


def trim_on_disk(craft: str = DEFAULT_CRAFT, wind_speed: float | None = None, collective: float | None = None,
                 physics_dt: float | None = None) -> bool:
    """Whether :func:`craft_trim` with these arguments reads its trim from the on-disk start cache (and so compiles
    no kernel of its own): the kernel warm-up's craft target (``envs/task_warmup.py``) then has nothing to wait for."""
    c, u = untrimmed_craft(craft, wind_speed, collective, physics_dt)
    return start_on_disk("craft_start", c.config.name, (c, u), CRAFT_SOURCES)


def trim_action(craft: str = DEFAULT_CRAFT, collective: float | None = None) -> np.ndarray:
    """The normalised action (2,) float32 that holds the trim controls (collective, zero differential).

    Needs only the config (no trim): the trim controls do not depend on the wind."""
    cfg = craft_config(str(craft))
    mid, half = control_ranges(cfg)
    return ((trim_controls(cfg, collective) - mid) / half).astype(np.float32)


class BladeLimitWarning(UserWarning):
    """A rotorcraft env's trim puts a retreating blade tip past the rotor model's blade-incidence limit."""


def check_trim_incidence(craft: Craft, sim, x_trim: np.ndarray, blade_stall: bool, where: str) -> float:
    """The larger retreating-tip incidence [rad] of ``sim`` (a CraftSimulator at the trim ``x_trim``) against the
    craft's blade-incidence limit (Roberts: 13 deg): past it, ValueError with ``blade_stall`` (such an episode would
    end at once), a :class:`BladeLimitWarning` without; both name ``where`` and the blade-limited collective
    (``Craft.operating_collective``, searched down from the trim's own collective)."""
    tip, limit = float(np.max(sim.rotor_outputs()["tip_incidence_rad"])), craft.config.blade_incidence_limit
    if tip <= limit:
        return tip
    try:
        bound = craft.operating_collective(x_trim, start=float(sim.controls[CU_COLLECTIVE]))[0]
        hint = f"collective <= {bound:.5g} rad (the blade-limited schedule)"
    except RuntimeError as err:
        hint = f"no collective within the limits holds it ({err})"
    text = (f"{where}: the trim puts a retreating blade tip at {math.degrees(tip):.1f} deg incidence, past the "
            f"{math.degrees(limit):.3g} deg limit of the rotor model; pass {hint}")
    if blade_stall:
        raise ValueError(text + " (termination.blade_stall would end the episode at once)")
    warnings.warn(text, BladeLimitWarning, stacklevel=user_stacklevel())
    return tip
