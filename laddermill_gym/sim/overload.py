"""Cable overload: element tensions checked against the cable's strength.

Each element of a built scene carries the breaking load of its cable (``Elements.breaking_load`` [N], from the
cable file's ``breaking_load``). A tension above ``fraction`` times it is an overload: the recorder
(``sim/recording.py``), the periodic search (``ladder/periodic.py``) and the studies report it as an event (time,
element, tension, limit); the run goes on, since the model has no broken cable. The check runs on tensions the
callers already have (one comparison per element and sample, O(n_e)); LadderMill-v0 terminates on the same
condition at the end of each control period (``envs/wing_failures.py``, failure 3).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

#: Default fraction of the breaking load above which a tension is reported [-]: the load itself (a design safety
#: factor is the caller's: ``fraction = 1 / factor``).
BREAKING_FRACTION: float = 1.0


class Overload(NamedTuple):
    """An element found over its tension limit: the time [s] of the first sample over it (of a spell over it), the
    element, its tension there [N] and the limit (fraction x breaking load) [N]."""

    t: float
    element: int
    tension: float
    limit: float

    def text(self) -> str:
        return (f"t = {self.t:.6g} s: element {self.element} tension {self.tension / 1e3:.4g} kN over "
                f"{self.limit / 1e3:.4g} kN")


def tension_limits(assembly, fraction: float = BREAKING_FRACTION) -> np.ndarray:
    """Per element, ``fraction`` times its breaking load [N] (n_e,); inf where the breaking load is not known.
    ValueError for a fraction that is not a finite number > 0."""
    if isinstance(fraction, bool) or not isinstance(fraction, (int, float, np.number)) or not (
            math.isfinite(fraction) and fraction > 0):
        raise ValueError(f"breaking_fraction = {fraction!r}: must be a finite number > 0 (the share of the cable's "
                         "breaking load above which a tension is reported)")
    el = assembly.elements
    if el.breaking_load is None:
        return np.full(el.count, np.inf)
    return fraction * np.asarray(el.breaking_load, dtype=float)


def overload_events(t: np.ndarray, tensions: np.ndarray, limits: np.ndarray) -> tuple[np.ndarray, list[Overload]]:
    """The samples over the limit and the events: ``t`` (n,) [s], ``tensions`` (n, n_e) [N], ``limits`` (n_e,)
    [N]. Returns (over (n, n_e) bool, events): one event per element and spell over its limit (its first sample),
    in time order."""
    over = np.asarray(tensions) > np.asarray(limits)[None, :]
    starts = over & ~np.vstack([np.zeros((1, over.shape[1]), dtype=bool), over[:-1]])
    events = [Overload(float(t[i]), int(e), float(tensions[i, e]), float(limits[e])) for i, e in np.argwhere(starts)]
    return over, sorted(events)


class OverloadWatch:
    """Running check of tension samples one at a time (a loop that already evaluates the tensions each step):
    ``first`` is the first :class:`Overload` seen (None: none), ``peak_ratio`` the largest tension over limit
    ratio so far [-] (0 where no limit is known)."""

    def __init__(self, limits: np.ndarray):
        self.limits = np.asarray(limits, dtype=float)
        self._inv = np.where(np.isfinite(self.limits), 1.0 / self.limits, 0.0)
        self.first: Overload | None = None
        self.peak_ratio = 0.0

    def see(self, t: float, tension: np.ndarray) -> bool:
        """Take one sample (time [s], tensions (n_e,) [N]); True when some element is over its limit."""
        ratio = tension * self._inv
        k = int(np.argmax(ratio))
        r = float(ratio[k])
        self.peak_ratio = max(self.peak_ratio, r)
        if r > 1.0:
            if self.first is None:
                self.first = Overload(float(t), k, float(tension[k]), float(self.limits[k]))
            return True
        return False

    def text(self) -> str:
        """One line: the first overload, or the peak tension as a share of the limit."""
        if self.first is not None:
            return f"cable overload: {self.first.text()} (peak {self.peak_ratio:.3g} x the limit)"
        return f"no cable overload (peak tension {self.peak_ratio:.3g} x the limit)"
