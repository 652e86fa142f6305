"""Turbulence as a frozen three-component field on an (along-wind, height) grid, advected by the mean wind.

:class:`Turbulence` is a disturbance: at every reset it draws, from the env's ``np_random``, a
:class:`~laddermill_gym.atmosphere.field.GustGrid` whose columns are the along-wind coordinate xi and whose rows
are heights; the kernels sample it at every wing, cable node and rotor point (``kernels/wind.py``).
Models (formulas and sources in ``turbulence_models.py`` and ``docs/wind.md``): IEC 61400-1 NTM and ETM with
Kaimal spectra, MIL-F-8785C Dryden and von Karman (light / moderate / severe, intensities and scales with
height).

Synthesis (:func:`synthesize`): per component and height a Gaussian series along xi with the model's
spectrum (a sum of Fourier modes with complex normal amplitudes; by default the discrete spectrum scaled so the
record's variance is sigma^2, else at the model's level plus a row offset for the variance below the first mode:
``Turbulence.low_frequencies``), correlated across heights with the exponential coherence Coh(r, kappa) =
exp(-k(kappa) r) of IEC 61400-1 eq. B.4. An exponential coherence on a line is a Markov chain in height, so the
correlated amplitudes follow exactly from a first-order recursion over the rows, X_j = rho_j X_(j-1) + sqrt(1 -
rho_j^2) e_j, rho_j = exp(-k dh): O(n_f n_h) work and no Cholesky factorisation.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np

from laddermill_gym.atmosphere import turbulence_models as tm
from laddermill_gym.atmosphere.disturbances import Disturbance
from laddermill_gym.atmosphere.field import GridGeometry, GustGrid

__all__ = ["Turbulence", "TURBULENCE_MODELS", "LOW_FREQUENCY_MODES", "low_band", "synthesize", "turbulence_spectra"]

TURBULENCE_MODELS = ("NTM", "ETM", "Dryden", "VonKarman")
#: What a grid shorter than the turbulence's longest scales does with the variance below its first mode: "rescale"
#: the modes it keeps so each row's record has the model's sigma^2 (the suites up to gusts-v5; on their grids this
#: raises the kept spectrum 1.4-2.5 times, docs/wind.md), or keep them at the spectrum's own level and add the
#: variance below the first mode as one random "offset" per row (coherent between rows as the spectrum at zero
#: wavenumber).
LOW_FREQUENCY_MODES = ("rescale", "offset")
#: Points of the Simpson rule for the variance below the first mode (the spectra are smooth there)
_LOW_BAND_POINTS = 129


def synthesize(spectra: np.ndarray, sigma: np.ndarray, decay: np.ndarray, dh: float, dkappa: float,
               n_xi: int, rng: np.random.Generator, rescale: bool = True, low=None) -> np.ndarray:
    """One component of a frozen field on n_xi columns x n_h rows.

    Parameters
    ----------
    spectra : (n_f, n_h)
        One-sided spatial spectrum S(kappa_k) at kappa_k = k dkappa, k = 1..n_f [m^3/s^2], per row.
    sigma : (n_h,)
        Standard deviation [m/s] of each row's record: the discrete spectrum is scaled to sum to sigma^2.
    decay : (n_f, n_h - 1)
        Coherence decay k [1/m] between rows j and j + 1 (rho = exp(-k dh)).
    dh : float
        Row spacing [m].
    dkappa : float
        Frequency spacing 1 / (n_xi dxi) [1/m].
    n_xi : int
        Record length (columns); n_f = ceil(n_xi / 2) - 1 (no mean, no Nyquist mode).
    rng : numpy Generator
        Draws 2 n_f n_h standard normals (and n_h more with ``low``).
    rescale : bool
        Scale the discrete spectrum so each row's record has variance sigma^2 (else S(kappa) dkappa per mode).
    low : (variance (n_h,), decay (n_h - 1,)) or None
        The variance [m^2/s^2] below the first mode, added as one random offset per row whose rows are correlated
        exp(-decay dh) (the coherence at zero wavenumber); None: nothing added.

    Returns
    -------
    values : (n_xi, n_h) [m/s]
    """
    n_f, n_h = spectra.shape
    eps = rng.standard_normal((n_f, n_h, 2))
    e = (eps[..., 0] + 1j * eps[..., 1]) / math.sqrt(2.0)  # E|e|^2 = 1
    x = np.empty((n_f, n_h), dtype=complex)
    x[:, 0] = e[:, 0]
    rho = np.exp(-decay * dh)
    for j in range(1, n_h):
        r = rho[:, j - 1]
        x[:, j] = r * x[:, j - 1] + np.sqrt(1.0 - r * r) * e[:, j]
    var = spectra * dkappa  # variance per mode
    if rescale:
        var *= (sigma ** 2 / np.maximum(var.sum(axis=0), 1e-300))[None, :]
    coef = np.zeros((n_xi // 2 + 1, n_h), dtype=complex)
    coef[1: n_f + 1] = np.sqrt(var / 2.0) * x * n_xi  # E|c|^2 = S dkappa / 2; irfft divides by n_xi
    values = np.fft.irfft(coef, n=n_xi, axis=0)
    if low is not None:
        low_var, low_decay = low
        z = rng.standard_normal(n_h)
        offset = np.empty(n_h)
        offset[0] = z[0]
        for j in range(1, n_h):
            r = math.exp(-low_decay[j - 1] * dh)
            offset[j] = r * offset[j - 1] + math.sqrt(1.0 - r * r) * z[j]
        values += (np.sqrt(low_var) * offset)[None, :]
    return values


def low_band(model: str, kappa_max: float, h: np.ndarray, *model_args) -> list[tuple[np.ndarray, np.ndarray]]:
    """Per component (u, v, w): the variance [m^2/s^2] of the spectrum between 0 and ``kappa_max`` [1/m] at each
    height h (n_h,) (Simpson's rule on the model's own spectrum) and the coherence decay [1/m] between rows at zero
    wavenumber (n_h - 1,). ``model_args``: as :func:`turbulence_spectra` after ``h``."""
    from scipy.integrate import simpson

    k = np.linspace(0.0, kappa_max, _LOW_BAND_POINTS)
    return [(simpson(s, x=k, axis=0), dec[0]) for s, _, dec in turbulence_spectra(model, k, h, *model_args)]


def turbulence_spectra(model: str, kappa: np.ndarray, h: np.ndarray, wind_class: str, wind_speed: float,
                       hub_height: float, severity: str, w20):
    """Per component (u, v, w): (spectra (n_f, n_h), sigma (n_h,), decay (n_f, n_h - 1)) of a model at the
    spatial frequencies kappa [1/m] and heights h [m]. Coherence decay: the IEC form with L_c the component's
    integral scale (IEC: L_c = 8.1 Lambda_1 for u, eq. B.4; our choice for v, w and the MIL models, which give
    no coherence across heights), at the mid-height of each row pair."""
    out = []
    mid = 0.5 * (h[1:] + h[:-1])
    if model in ("NTM", "ETM"):
        s1 = tm.iec_sigma1(wind_class, wind_speed, model)
        lam = tm.iec_lambda1(hub_height)
        for k in range(3):
            sig, length = tm.KAIMAL_SIGMA[k] * s1, tm.KAIMAL_SCALE[k] * lam
            s = np.repeat(tm.kaimal_spectrum(kappa, sig, length)[:, None], h.size, axis=1)
            dec = np.repeat(tm.iec_coherence_decay(kappa, length)[:, None], mid.size, axis=1)
            out.append((s, np.full(h.size, sig), dec))
        return out
    spec = tm.dryden_spectrum if model == "Dryden" else tm.von_karman_spectrum
    (sigs, scales) = tm.mil_intensity_scale(h, severity, w20, model)
    _, mid_scales = tm.mil_intensity_scale(mid, severity, w20, model)
    for k in range(3):
        s = np.stack([spec(kappa, sigs[k][j], scales[k][j], k == 0) for j in range(h.size)], axis=1)
        dec = np.zeros((kappa.size, mid.size))
        for j in range(mid.size):
            dec[:, j] = tm.iec_coherence_decay(kappa, mid_scales[k][j])
        out.append((s, sigs[k], dec))
    return out


def _pair(name: str, value) -> tuple[float, float]:
    if not (isinstance(value, (tuple, list)) and len(value) == 2
            and all(isinstance(v, numbers.Real) and not isinstance(v, bool) and math.isfinite(v) for v in value)
            and value[0] < value[1]):
        raise ValueError(f"Turbulence.{name} = {value!r}: must be a pair [low, high] of finite numbers, low < high")
    return float(value[0]), float(value[1])


def _number(name: str, value, positive: bool = True, allow_none: bool = False):
    if allow_none and value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value) or (
            positive and not value > 0):
        raise ValueError(f"Turbulence.{name} = {value!r}: must be a finite number{' > 0' if positive else ''}")
    return float(value)


@dataclass(frozen=True)
class Turbulence(Disturbance):
    """Frozen turbulence over heights ``heights`` [m] (rows every ``dh`` m) and along-wind positions
    ``along_wind`` [m] (p . e of the points the field must cover; columns every ``dxi`` m), advected downwind
    at ``wind_speed`` [m/s] over the episode.

    Parameters
    ----------
    model : "NTM", "ETM", "Dryden" or "VonKarman"
    wind_speed : float
        Mean wind U [m/s]: the advection speed; for NTM / ETM also V_hub.
    wind_class : str
        IEC class ("IA", "IIB", ..., "IA+"), NTM / ETM only.
    hub_height : float
        Reference height [m] of Lambda_1 (NTM / ETM only).
    severity : "light", "moderate" or "severe"
        Dryden / von Karman only.
    w20 : float or None
        Dryden / von Karman: wind at 20 ft [m/s] for the low-altitude intensities (default from the severity).
    heading : float
        Direction of the field's u axis [rad] (0: the undisturbed wind).
    fade_in : float
        Time [s] over which the field rises from 0 to full strength, 0.5 (1 - cos(pi t / fade_in)), so an
        episode starting from a state trimmed in steady wind does not meet the whole field at once (0: none).
    low_frequencies : "rescale" or "offset"
        The variance below the grid's first mode (:data:`LOW_FREQUENCY_MODES`): "rescale" (the default, the suites
        up to gusts-v5) puts it into the kept modes, "offset" keeps the spectrum's level and adds it as one
        random offset per row.
    record : float
        Length of the synthesised record as a multiple of the grid's (>= 1; default 1, the suites' fields): the
        inverse FFT is periodic over the record, so with 1 the field repeats with the grid's length and its
        correlation at lags near half of it is not the model's; with ``record`` r the record is r times longer (its
        modes r times finer, the low band below the finer first mode) and the grid keeps its first n_xi columns
        (docs/wind.md, "What a point between the nodes meets"). Memory while drawing grows by r, the grid's not.
    """

    model: str = "NTM"
    wind_speed: float = 10.0
    wind_class: str = "IA"
    hub_height: float = 100.0
    severity: str = "moderate"
    w20: float | None = None
    heights: tuple[float, float] = (0.0, 400.0)
    dh: float = 10.0
    along_wind: tuple[float, float] = (-500.0, 500.0)
    dxi: float = 5.0
    heading: float = 0.0
    fade_in: float = 0.0
    low_frequencies: str = "rescale"
    record: float = 1.0

    def __post_init__(self):
        if self.low_frequencies not in LOW_FREQUENCY_MODES:
            raise ValueError(f"Turbulence.low_frequencies = {self.low_frequencies!r}: must be one of "
                             f"{list(LOW_FREQUENCY_MODES)}")
        if self.model not in TURBULENCE_MODELS:
            raise ValueError(f"Turbulence.model = {self.model!r}: must be one of {list(TURBULENCE_MODELS)}")
        for name in ("wind_speed", "hub_height", "dh", "dxi"):
            _number(name, getattr(self, name))
        _number("heading", self.heading, positive=False)
        if _number("fade_in", self.fade_in, positive=False) < 0:
            raise ValueError(f"Turbulence.fade_in = {self.fade_in!r}: must be >= 0 s")
        _number("w20", self.w20, allow_none=True)
        if not _number("record", self.record) >= 1.0 or self.record > 1000.0:
            raise ValueError(f"Turbulence.record = {self.record!r}: must lie in 1 .. 1000 (the synthesised record's "
                             "length in grid lengths)")
        object.__setattr__(self, "heights", _pair("heights", self.heights))
        object.__setattr__(self, "along_wind", _pair("along_wind", self.along_wind))
        tm.parse_wind_class(self.wind_class, "Turbulence.wind_class")  # checked whatever the model: a typo is named
        if self.severity not in tm.MIL_W20_KT:
            raise ValueError(f"Turbulence.severity = {self.severity!r}: must be one of {sorted(tm.MIL_W20_KT)}")
        iec = self.model in ("NTM", "ETM")
        unused = (("severity", "moderate"), ("w20", None)) if iec else (("wind_class", "IA"), ("hub_height", 100.0))
        for name, default in unused:  # a field the model does not read, given: it would be ignored without a word
            if getattr(self, name) != default:
                raise ValueError(f"Turbulence.{name} = {getattr(self, name)!r}: model {self.model} does not use it "
                                 f"({'Dryden and VonKarman' if iec else 'NTM and ETM'} do); leave it out")
        if self.model == "ETM" and tm.iec_sigma1(self.wind_class, self.wind_speed, "ETM") <= 0:
            raise ValueError(f"Turbulence.wind_speed = {self.wind_speed!r}: the ETM's sigma_1 is not positive")

    def sample(self, t, rng):
        return np.ones_like(t), np.zeros_like(t)

    def grid_geometry(self, t_end: float) -> GridGeometry:
        """The grid covering xi = p . e - U t for p . e in ``along_wind`` and 0 <= t <= t_end (even n_xi)."""
        lo, hi = self.along_wind
        xi0 = lo - self.wind_speed * float(t_end) - self.dxi
        n_xi = int(math.ceil((hi + self.dxi - xi0) / self.dxi)) + 1
        n_xi += n_xi % 2
        h0, h1 = self.heights
        n_h = int(math.ceil((h1 - h0) / self.dh - 1e-9)) + 1
        return GridGeometry(xi0, self.dxi, n_xi, h0, self.dh, n_h, self.wind_speed, self.heading, self.fade_in)

    def record_columns(self, n_xi: int) -> int:
        """Columns [-] of the synthesised record for a grid of ``n_xi`` columns: n_xi itself with ``record`` 1, else
        the even number nearest above record x n_xi."""
        return n_xi if self.record == 1.0 else 2 * int(math.ceil(0.5 * self.record * n_xi))

    def gust_grid(self, t_end: float, rng: np.random.Generator) -> GustGrid:
        g = self.grid_geometry(t_end)
        h = g.h0 + g.dh * np.arange(g.n_h)
        n_rec = self.record_columns(g.n_xi)
        n_f = (n_rec + 1) // 2 - 1
        dkappa = 1.0 / (n_rec * g.dxi)
        kappa = dkappa * np.arange(1, n_f + 1)
        args = (self.wind_class, self.wind_speed, self.hub_height, self.severity, self.w20)
        comps = turbulence_spectra(self.model, kappa, h, *args)
        offset = self.low_frequencies == "offset"
        lows = low_band(self.model, 0.5 * dkappa, h, *args) if offset else [None] * len(comps)
        values = np.stack([synthesize(s, sig, dec, g.dh, dkappa, n_rec, rng, rescale=not offset, low=low)
                           for (s, sig, dec), low in zip(comps, lows, strict=True)], axis=-1)
        if n_rec != g.n_xi:  # the record's start: no repeat within the grid
            values = np.ascontiguousarray(values[: g.n_xi])
        return GustGrid(values, g.xi0, g.dxi, g.h0, g.dh, g.advection, g.heading, g.fade_in)
