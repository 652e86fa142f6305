"""The turbulence models' formulas: intensities, length scales, spectra and coherence (plain numpy, SI units).

* IEC 61400-1 ed. 3 (2005): wind turbine classes (clause 6.2, Table 1: V_ref, I_ref), the normal turbulence
  model NTM (6.3.1.3), the extreme turbulence model ETM (6.3.2.3), the turbulence scale parameter Lambda_1
  (6.3.1.3, eq. 5), the Kaimal spectra and the exponential coherence model (Annex B, B.2). Class A+ (I_ref
  0.18) is ed. 4's (2019) addition.
* MIL-F-8785C (1980) section 3.7.2 / MIL-HDBK-1797 (1997) section 4.9.1 (appendix): Dryden and von Karman
  spectra in space, the low-altitude intensities and scales (below 1000 ft, from the wind at 20 ft: light
  15 kt, moderate 30 kt, severe 45 kt), the medium / high-altitude intensities from the probability of
  exceedance table (above 2000 ft; isotropic scales of 1750 ft for the Dryden form and 2500 ft for the von Karman
  form, MIL-F-8785C 3.7.2.1), linear interpolation between 1000 and 2000 ft.

All spectra are one-sided in the spatial frequency kappa [cycles/m] along the mean wind: the variance is
the integral of S(kappa) over kappa in (0, inf). A frozen field advected at U gives the temporal spectrum
S_t(f) = S(f / U) / U.
"""

from __future__ import annotations

import math

import numpy as np

FT = 0.3048  # m per ft (exact)
KNOT = 1852.0 / 3600.0  # m/s per kt (exact)

#: IEC 61400-1 Table 1: reference wind speed V_ref [m/s] per class.
IEC_V_REF = {"I": 50.0, "II": 42.5, "III": 37.5}
#: IEC 61400-1 Table 1: reference turbulence intensity I_ref [-] per category (A+ from ed. 4).
IEC_I_REF = {"A+": 0.18, "A": 0.16, "B": 0.14, "C": 0.12}
#: Kaimal integral scales L_k / Lambda_1 for u, v, w (IEC 61400-1 ed. 3 Table B.1).
KAIMAL_SCALE = (8.1, 2.7, 0.66)
#: Kaimal standard deviation ratios sigma_k / sigma_1 for u, v, w (IEC 61400-1 ed. 3 Table B.1).
KAIMAL_SIGMA = (1.0, 0.8, 0.5)

#: MIL-F-8785C low-altitude wind at 20 ft [kt] per severity (section 3.7.2.3).
MIL_W20_KT = {"light": 15.0, "moderate": 30.0, "severe": 45.0}
#: MIL-F-8785C Figure 7 (MIL-HDBK-1797 Figure 266): rms intensity [ft/s] against altitude [ft] for the
#: probabilities of exceedance 1e-2 (light), 1e-3 (moderate) and 1e-5 (severe).
MIL_HIGH_ALT_FT = np.array([500.0, 1750.0, 3750.0, 7500.0, 15000.0, 25000.0, 35000.0, 45000.0, 55000.0,
                            65000.0, 75000.0, 80000.0])
MIL_HIGH_SIGMA_FTPS = {
    "light": np.array([6.6, 6.9, 7.4, 6.7, 4.6, 2.7, 0.4, 0.0, 0.0, 0.0, 0.0, 0.0]),
    "moderate": np.array([8.6, 9.6, 10.6, 10.1, 8.0, 6.6, 5.0, 4.2, 2.7, 0.0, 0.0, 0.0]),
    "severe": np.array([15.6, 17.6, 23.0, 23.6, 22.1, 20.0, 16.0, 15.1, 12.1, 7.9, 6.2, 5.1]),
}
#: MIL-F-8785C 3.7.2.1: the isotropic scale L_u = L_v = L_w [ft] above 2000 ft, Dryden form and von Karman form
MIL_HIGH_SCALE_FT = 1750.0
MIL_HIGH_SCALE_VK_FT = 2500.0
VK_A = 1.339  # von Karman's constant: the scale factor of L in the spectra (MIL-F-8785C)


def parse_wind_class(wind_class: str, where: str = "wind_class") -> tuple[float, float]:
    """(V_ref [m/s], I_ref [-]) of an IEC class such as 'IA', 'IIB', 'IIIC' or 'IA+'."""
    s = str(wind_class).strip().upper()
    for roman in ("III", "II", "I"):
        if s.startswith(roman) and s[len(roman):] in IEC_I_REF:
            return IEC_V_REF[roman], IEC_I_REF[s[len(roman):]]
    raise ValueError(f"{where} = {wind_class!r}: must be an IEC 61400-1 class I/II/III followed by A+/A/B/C "
                     "(e.g. 'IA', 'IIB')")


def iec_lambda1(hub_height: float) -> float:
    """Longitudinal turbulence scale parameter Lambda_1 [m] (IEC 61400-1 ed. 3 eq. 5): 0.7 z_hub up to 60 m,
    42 m above."""
    return 0.7 * hub_height if hub_height <= 60.0 else 42.0


def iec_sigma1(wind_class: str, v_hub: float, model: str = "NTM") -> float:
    """Longitudinal standard deviation sigma_1 [m/s] at hub speed v_hub [m/s]: NTM (6.3.1.3, eq. 11:
    I_ref (0.75 V_hub + b), b = 5.6 m/s) or ETM (6.3.2.3, eq. 19: c I_ref (0.072 (V_ave/c + 3)(V_hub/c - 4)
    + 10), c = 2 m/s, V_ave = 0.2 V_ref)."""
    v_ref, i_ref = parse_wind_class(wind_class)
    if model == "NTM":
        return i_ref * (0.75 * v_hub + 5.6)
    if model == "ETM":
        c = 2.0
        return c * i_ref * (0.072 * (0.2 * v_ref / c + 3.0) * (v_hub / c - 4.0) + 10.0)
    raise ValueError(f"model = {model!r}: must be 'NTM' or 'ETM'")


def kaimal_spectrum(kappa: np.ndarray, sigma: float, length: float) -> np.ndarray:
    """Kaimal spectrum in space [m^3/s^2 per cycle/m]: S(kappa) = 4 sigma^2 L / (1 + 6 kappa L)^(5/3), the
    IEC form f S(f) / sigma^2 = (4 f L / V) / (1 + 6 f L / V)^(5/3) with kappa = f / V."""
    return 4.0 * sigma ** 2 * length / (1.0 + 6.0 * kappa * length) ** (5.0 / 3.0)


def dryden_spectrum(kappa: np.ndarray, sigma: float, length: float, longitudinal: bool) -> np.ndarray:
    """MIL-F-8785C Dryden spectrum per cycle/m: with Omega = 2 pi kappa [rad/m], Phi_u = sigma^2 (2 L / pi) /
    (1 + (L Omega)^2) and Phi_v = Phi_w = sigma^2 (L / pi) (1 + 3 (L Omega)^2) / (1 + (L Omega)^2)^2 (per
    rad/m, one-sided); S(kappa) = 2 pi Phi(2 pi kappa)."""
    lo = length * 2.0 * math.pi * kappa
    if longitudinal:
        phi = sigma ** 2 * (2.0 * length / math.pi) / (1.0 + lo ** 2)
    else:
        phi = sigma ** 2 * (length / math.pi) * (1.0 + 3.0 * lo ** 2) / (1.0 + lo ** 2) ** 2
    return 2.0 * math.pi * phi


def von_karman_spectrum(kappa: np.ndarray, sigma: float, length: float, longitudinal: bool) -> np.ndarray:
    """MIL-F-8785C von Karman spectrum per cycle/m: a = 1.339, Phi_u = sigma^2 (2 L / pi) / (1 + (a L
    Omega)^2)^(5/6), Phi_v = Phi_w = sigma^2 (L / pi) (1 + (8/3)(a L Omega)^2) / (1 + (a L Omega)^2)^(11/6)."""
    lo = VK_A * length * 2.0 * math.pi * kappa
    if longitudinal:
        phi = sigma ** 2 * (2.0 * length / math.pi) / (1.0 + lo ** 2) ** (5.0 / 6.0)
    else:
        phi = sigma ** 2 * (length / math.pi) * (1.0 + (8.0 / 3.0) * lo ** 2) / (1.0 + lo ** 2) ** (11.0 / 6.0)
    return 2.0 * math.pi * phi


def iec_coherence_decay(kappa: np.ndarray, length_c: float) -> np.ndarray:
    """Decay rate k [1/m] of the IEC exponential coherence Coh(r, f) = exp(-12 sqrt((f r / V)^2 + (0.12 r /
    L_c)^2)) = exp(-k r) (ed. 3 eq. B.4), with kappa = f / V."""
    return 12.0 * np.sqrt(kappa ** 2 + (0.12 / length_c) ** 2)


def mil_intensity_scale(h: np.ndarray, severity: str, w20: float | None = None, model: str = "Dryden"):
    """MIL-F-8785C intensities (sigma_u, sigma_v, sigma_w) [m/s] and scales (L_u, L_v, L_w) [m] at heights
    h [m] (arrays of h's shape) for the spectral form ``model`` ("Dryden" or "VonKarman"). Below 1000 ft: L_w =
    h, L_u = L_v = h / (0.177 + 0.000823 h)^1.2, sigma_w = 0.1 W_20, sigma_u = sigma_v = sigma_w / (0.177 +
    0.000823 h)^0.4 (h in ft; W_20 [m/s] from the severity unless given), both forms; above 2000 ft: isotropic,
    L = 1750 ft (Dryden) or 2500 ft (von Karman), sigma from the exceedance table; linear between. Heights below
    10 ft are taken as 10 ft (the low-altitude model's lower limit)."""
    if severity not in MIL_W20_KT:
        raise ValueError(f"severity = {severity!r}: must be one of {sorted(MIL_W20_KT)}")
    scales = {"Dryden": MIL_HIGH_SCALE_FT, "VonKarman": MIL_HIGH_SCALE_VK_FT}
    if model not in scales:
        raise ValueError(f"model = {model!r}: the MIL scales are those of {sorted(scales)}")
    high_scale = scales[model]
    w20_ftps = (MIL_W20_KT[severity] * KNOT if w20 is None else float(w20)) / FT
    hf = np.maximum(np.asarray(h, dtype=float) / FT, 10.0)

    def low(x):
        d = 0.177 + 0.000823 * x
        sw = 0.1 * w20_ftps
        su = sw / d ** 0.4
        lu = x / d ** 1.2
        return (su, su, sw * np.ones_like(x)), (lu, lu, x)

    def high(x):
        s = np.interp(x, MIL_HIGH_ALT_FT, MIL_HIGH_SIGMA_FTPS[severity])
        return (s, s, s), (np.full_like(x, high_scale),) * 3

    lo_s, lo_l = low(np.minimum(hf, 1000.0))
    hi_s, hi_l = high(np.maximum(hf, 2000.0))
    r = np.clip((hf - 1000.0) / 1000.0, 0.0, 1.0)
    sig = tuple(FT * ((1.0 - r) * a + r * b) for a, b in zip(lo_s, hi_s, strict=True))
    scl = tuple(FT * ((1.0 - r) * a + r * b) for a, b in zip(lo_l, hi_l, strict=True))
    return sig, scl
