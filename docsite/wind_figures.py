"""The page group of docs/wind.md (no command to run): the standards' constants as the code holds them
(``atmosphere/turbulence_models.py``, ``atmosphere/iec_gusts.py``: the page quotes them as the standards give them,
so a constant changed in the code and not on the page, or the reverse, is named), and the page's worked figures
reworked here in closed form from the standards' formulas as the page writes them (not through the package's
functions): the EOG and EDC check values, the integral scales, the coherence over 20 m, the memory of a field.
"""

from __future__ import annotations

import math

import numpy as np

FT = 0.3048  # [m] the international foot


def code_constants() -> dict:
    """The constants the page's tables quote, read from the modules that use them (formatted as the page does)."""
    from laddermill_gym.atmosphere import iec_gusts as ig
    from laddermill_gym.atmosphere import turbulence_models as tm

    v_ref, i_ref, w20 = tm.IEC_V_REF, tm.IEC_I_REF, tm.MIL_W20_KT
    return {"v_ref": "{:g} / {:g} / {:g}".format(*(v_ref[c] for c in ("I", "II", "III"))),
            "i_ref": "{:.2f} / {:.2f} / {:.2f}".format(*(i_ref[c] for c in ("A", "B", "C"))),
            "i_ref_plus": f"{i_ref['A+']:.2f}", "w20": "{:g} / {:g} / {:g}".format(*w20.values()),
            "kaimal": "{:g}, {:g}, {:g}".format(*tm.KAIMAL_SCALE), "lambda1_low": f"{tm.iec_lambda1(10.0) / 10.0:g}",
            "lambda1_high": f"{tm.iec_lambda1(1000.0):g}", "mil_scale_ft": f"{tm.MIL_HIGH_SCALE_FT:g}",
            "mil_scale_vk_ft": f"{tm.MIL_HIGH_SCALE_VK_FT:g}",
            "eog_t": f"{ig.EOG_T:g}", "edc_t": f"{ig.EDC_T:g}", "ecd_t": f"{ig.ECD_T:g}",
            "ecd_v_cg": f"{ig.ECD_V_CG:g}", "ews_t": f"{ig.EWS_T:g}", "ews_beta": f"{ig.EWS_BETA:g}",
            "vk_a": f"{tm.VK_A:g}"}


def eog_edc(v_ref: float = 50.0, i_ref: float = 0.16, v_hub: float = 10.0, diameter: float = 10.0,
            lambda1: float = 42.0) -> dict:
    """IEC 61400-1 ed. 3 eqs. 11, 16-17, 21 for the page's check case (class IA, V_hub 10 m/s, D 10 m, z_hub above
    60 m): EOG V_gust [m/s], the gust's peak [m/s] and its time [s] (argmax on a 1 ms grid), EDC theta_e [deg]."""
    sigma1 = i_ref * (0.75 * v_hub + 5.6)  # [m/s] NTM, eq. 11
    v_gust = min(1.35 * (0.8 * 1.4 * v_ref - v_hub), 3.3 * sigma1 / (1.0 + 0.1 * diameter / lambda1))
    t = np.arange(0.0, 10.5 + 5e-4, 1e-3)  # [s] T = 10.5 s
    v = v_hub - 0.37 * v_gust * np.sin(3.0 * np.pi * t / 10.5) * (1.0 - np.cos(2.0 * np.pi * t / 10.5))
    theta_e = 4.0 * math.atan(sigma1 / (v_hub * (1.0 + 0.1 * diameter / lambda1)))
    return {"v_gust": f"{v_gust:.2f}", "peak": f"{v.max():.1f}", "t_peak": f"{t[np.argmax(v)]:.2f}",
            "theta_e": f"{math.degrees(theta_e):.1f}"}


def field_memory(span: float = 4500.0, u: float = 13.5, duration: float = 600.0, dxi: float = 10.0,
                 h_top: float = 3600.0, dh: float = 25.0) -> dict:
    """The page's memory example: n_xi = (span + U T) / dxi + 3 rounded up to even, n_h = h_top / dh + 1, 3 float64
    components per node."""
    n_xi = int(math.ceil((span + u * duration) / dxi)) + 3
    n_xi += n_xi % 2
    n_h = int(round(h_top / dh)) + 1
    size = n_xi * n_h * 3 * 8
    return {"n_xi": str(n_xi), "n_h": str(n_h), "bytes": f"{size:,}", "mb": f"{size / 1e6:.2f}"}


def wind_data() -> dict:
    """``code``: :func:`code_constants`; ``worked``: the closed forms (:func:`eog_edc`, :func:`field_memory`, the
    IEC u scale L_1 = 8.1 x 42 m [m], the MIL high-altitude scales 1750 ft (Dryden) and 2500 ft (von Karman)
    [m], the IEC u coherence over 20 m at f -> 0, exp(-12 x 0.12 x 20 / L_1), and 1.2^3)."""
    l1 = 8.1 * 42.0
    worked = {**eog_edc(), **field_memory(), "l1": f"{l1:.0f}", "mil_scale_m": f"{1750.0 * FT:.0f}",
              "mil_scale_vk_m": f"{2500.0 * FT:.0f}",
              "coherence_20m": f"{math.exp(-12.0 * 0.12 * 20.0 / l1):.2f}", "cube": f"{1.2 ** 3:.2f}"}
    return {"code": code_constants(), "worked": worked}
