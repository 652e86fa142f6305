"""The ledger entry (:mod:`docsite.page_ledger`) of docs/wind.md: the standards' constants against the code that holds
them, the worked check values reworked in closed form (:mod:`docsite.wind_figures`), the standards' formulas given,
the gusts-v2 tables checked against gust-bench (``gusts_v2_pumping``, ``gusts_v2_mill``), the gusts-v1 first results
not re-run (their commands and costs as the page gives them)."""

from __future__ import annotations

from docsite.host_cpu import CPU
from docsite.ledger_kinds import Covered, History, Printed

W, C = "{wind_data[worked][%s]}", "{wind_data[code][%s]}"
#: The PumpingKite-v0 rows of the gusts-v2 table (laddermill gust-bench --suite gusts-v2 --env
#: laddermill_gym/PumpingKite-v0 --controllers open_loop lqr, 16 s): survived seeds, the failed seeds' end times, the
#: median largest lateral excursion [m] and energy ratio, as docsite.study_figures.gust_table writes them.
PUMPING_SCENARIOS = ("direction_step", "speed_step_20pct", "one_cos_4s", "one_cos_20s", "EOG_IA", "EDC_IA", "NTM_IB")
GUSTS_V2_CHECKS = tuple(  # the failure cell never names a slot: the mill's rows below are not matched
    (rf"\| {ctrl} \| {scen} \| (\S+) \| (-|[\d.]+(?:, [\d.]+)*)(?:(?!slot )[^|])*\| (\S+) \| (\S+) \|",
     tuple(f"{{gusts_v2_pumping[{ctrl}/{scen}][{k}]}}" for k in ("survived", "ends", "lateral", "ratio")))
    for ctrl in ("open_loop", "lqr") for scen in PUMPING_SCENARIOS) + (
    (r"61\.3 s: beta ([-\d.]+) deg \(seed 2\)", ("{gusts_v2_pumping[lqr/NTM_IB][beta]}",)),)

ON = r"(\d+ / \d+)"
#: The gusts-v1 table: each env's scorecard, open loop and LQR, exact (long groups gusts_v1_<env>: gust_bench.json)
#: The gusts-v6 table (long groups gusts_v6_<env>: gust_bench.json): each row's counts and the lost scenarios
GUSTS_V6_CHECKS = (
    (rf"\| TetheredWing-v0 \(gusts-v6\) \| {ON} \| {ON} \| {ON} [^|]*\| \|",
     tuple(f"{{gusts_v6_tethered_wing[scorecard][{c}]}}" for c in ("open_loop", "lqr", "ppo_tethered_wing"))),
    (rf"\| Rotorcraft-v0 \(gusts-v6\) \| {ON} \| {ON} \| {ON} [^|]*\| \|",
     tuple(f"{{gusts_v6_rotorcraft[scorecard][{c}]}}" for c in ("open_loop", "lqr", "ppo_rotorcraft"))),
    (rf"\| Rotorcraft-v1 \(gusts-v6\) \| {ON} \| {ON} \| {ON} [^|]*\| {ON} \|",
     tuple(f"{{gusts_v6_rotorcraft_v1[scorecard][{c}]}}" for c in ("open_loop", "lqr", "ppo_rotorcraft", "lqr_guard"))),
    (rf"LadderChain-v0's open loop {ON} and LQR {ON}; PumpingKite-v0's open loop {ON} and LQR-assisted cycle {ON}; "
     rf"PumpingKite-v1's crosswind controller {ON}; LadderMill-v0's open loop {ON} and LQR {ON}\.",
     ("{gusts_v6_ladder_chain[scorecard][open_loop]}", "{gusts_v6_ladder_chain[scorecard][lqr]}",
      "{gusts_v6_pumping[scorecard][open_loop]}", "{gusts_v6_pumping[scorecard][lqr]}",
      "{gusts_v6_pumping_v1[scorecard][crosswind]}", "{gusts_v6_laddermill[scorecard][open_loop]}",
      "{gusts_v6_laddermill[scorecard][lqr]}")),
    (r"On gusts-v6 the wing's LQR loses ([^:]*?), and the guard loses ([^:]*?): fields",
     ("@{gusts_v6_tethered_wing[lost][lqr]}", "@{gusts_v6_rotorcraft_v1[lost][lqr_guard]}")),
)
GUSTS_V1_CHECKS = tuple(
    (rf"\| {env} \| {ON} [^|]*\| {ON}", (f"{{gusts_v1_{group}[scorecard][open_loop]}}",
                                       f"{{gusts_v1_{group}[scorecard][lqr]}}"))
    for env, group in (("LadderChain-v0", "ladder_chain"), ("Rotorcraft-v0", "rotorcraft"),
                       ("LadderMill-v0", "laddermill"))) + tuple(
    # its notes' scenarios, as sets of gust_bench.json's scenario ids (docsite/gust_scorecards.py): the open loop's
    # held on every seed, the LQR's held beyond them, not held, lost by both
    (rf"\| {env} \| \d+ / \d+ \(([^|]*)\) \|", (f"@{{gusts_v1_{group}[held][open_loop]}}",))
    for env, group in (("TetheredWing-v0", "tethered_wing"), ("LadderChain-v0", "ladder_chain"),
                       ("Rotorcraft-v0", "rotorcraft"), ("LadderMill-v0", "laddermill"))) + (
    # TetheredWing-v0's LQR count, what it holds beyond the open loop and what ends both, quoted per CPU
    # (docsite/host_cpu.py): those of the CPU the group ran on
    (rf"\| TetheredWing-v0 \| {ON} ", ("{gusts_v1_tethered_wing[scorecard][open_loop]}",)),
    (rf"\| TetheredWing-v0 \| [^|]*\| [^|]*?{ON} on {CPU} \(AVX\w+; \+ ([^)]*)\)[^|]*",
     ("{gusts_v1_tethered_wing[scorecard][lqr]}", "@{gusts_v1_tethered_wing[held_beyond][lqr]}")),
    (rf"ends both: [^|]*?on {CPU} \(AVX\w+\) ([^;|]*?) ?(?:;|\|)", ("@{gusts_v1_tethered_wing[lost_by_both]}",)),
    (r"\| 8 / 9 \(all but ([^;|]*);", ("@{gusts_v1_rotorcraft[lost][lqr]}",)),
    (r"\| \d+ / \d+ \(fails ([^|)]*)\) \|", ("@{gusts_v1_laddermill[lost][lqr]}",)),
)

#: The LadderMill-v0 rows of the gusts-v2 table (laddermill gust-bench --suite gusts-v2 --env
#: laddermill_gym/LadderMill-v0 --scenarios EWS_IA NTM_IB dryden_light dryden_moderate --controllers open_loop lqr,
#: 2 min 50 s): per failed seed, the angles the page names (the page rounds the printed time and angles).
MILL_ROWS = {("open_loop", "EWS_IA"): (("alpha",),), ("open_loop", "NTM_IB"): (("alpha",), ("beta",), ("alpha",)),
             ("open_loop", "dryden_light"): (("beta",),) * 3,
             ("open_loop", "dryden_moderate"): (("beta",), ("alpha",), ("alpha",)),
             ("lqr", "EWS_IA"): (("alpha", "beta"),), ("lqr", "NTM_IB"): (("beta",),) * 3,
             ("lqr", "dryden_light"): (("alpha",), ("beta",), ("beta",)), ("lqr", "dryden_moderate"): (("beta",),) * 3}


def mill_row(ctrl: str, scen: str, angles: tuple) -> tuple:
    """The check of one LadderMill-v0 row: survived, each failed seed's time [s], slot and named angles [deg], the
    median largest lateral excursion [m] and energy ratio."""
    key = f"gusts_v2_mill[{ctrl}/{scen}]"
    items = [r"([\d.]+) s:? slot (\d+) " + ", ".join(rf"{a} ([-\d.]+) deg" for a in names) for names in angles]
    cells = [f"{{{key}[survived]}}"]
    for i, names in enumerate(angles):
        cells += [f"~{{{key}[f{i}][t]}}", f"{{{key}[f{i}][slot]}}", *(f"~{{{key}[f{i}][{a}]}}" for a in names)]
    return (rf"\| {ctrl} \| {scen} \| (\S+) \| " + "; ".join(items) + r" \| (\S+) \| (\S+) \|",
            (*cells, f"{{{key}[lateral]}}", f"{{{key}[ratio]}}"))


GUSTS_V2_CHECKS += tuple(mill_row(c, s, a) for (c, s), a in MILL_ROWS.items())
# the last wings before the hauled station that the EWS fails (the LQR's and the open loop's failed slot)
GUSTS_V2_CHECKS += ((r"\(slots (\d+)-(\d+)(?=, 129-199 m\))", ("{gusts_v2_mill[lqr/EWS_IA][f0][slot]}",
                                                                "{gusts_v2_mill[open_loop/EWS_IA][f0][slot]}")),)
WIND = Covered(
    groups=("wind_data", "gusts_v2_pumping", "gusts_v2_mill"),
    checks=GUSTS_V2_CHECKS + GUSTS_V1_CHECKS + GUSTS_V6_CHECKS + (
            (r"Check values \(class IA, 10 m/s, D = 10 m\): EOG V_gust = ([\d.]+) m/s, peak ([\d.]+) m/s at ([\d.]+) "
             r"s; EDC theta_e = ([\d.]+) deg", tuple(W % k for k in ("v_gust", "peak", "t_peak", "theta_e"))),
            (r"(\d+) x (\d+) x 3 floats = ([\d.]+) MB \(([\d,]+) bytes\)",
             tuple(W % k for k in ("n_xi", "n_h", "mb", "bytes"))),
            (r"\(L_1 = (\d+) m IEC; (\d+) m Dryden and (\d+) m von Karman MIL above 600 m\)",
             (W % "l1", W % "mil_scale_m", W % "mil_scale_vk_m")),
            (r"over 20 m at f -> 0 is exp\(-12 x 0\.12 x 20 m / (\d+) m\) = ([\d.]+)\)",
             (W % "l1", W % "coherence_20m")),
            (r"\(1\.2\^3 = ([\d.]+) for", (W % "cube",)),
            (r"Classes: V_ref = ([\d. /]+?) m/s \(I / II / III\), I_ref = ([\d. /]+?) \(A / B / C\), ([\d.]+) "
             r"\(A\+, ed\.",
             (C % "v_ref", C % "i_ref", C % "i_ref_plus")),
            (r"W_20 = ([\d /]+?) kt", (C % "w20",)),
            (r"L_k = ([\d., ]+?) Lambda_1; Lambda_1 = ([\d.]+) z_hub \(z_hub <= 60 m\), (\d+) m above",
             (C % "kaimal", C % "lambda1_low", C % "lambda1_high")),
            (r"(\d+) ft above 2000 ft", (C % "mil_scale_ft",)),
            (r"above 2000 ft L = (\d+) ft", (C % "mil_scale_vk_ft",)),
            (r"T = ([\d.]+) s; V_gust = min", (C % "eog_t",)),
            (r"\(1 - cos\(pi t / T\)\), T = (\d+) s, theta_e", (C % "edc_t",)),
            (r"V_cg = (\d+) m/s, T = (\d+) s", (C % "ecd_v_cg", C % "ecd_t")),
            (r"beta = ([\d.]+), T = (\d+) s \(vertical shear\)", (C % "ews_beta", C % "ews_t")),
            (r"\(1 \+ \(([\d.]+) L Omega\)\^2\)\^\(5/6\)", (C % "vk_a",))),
    given=(  # the profiles' names (docsite/host_cpu.py; numerics.md, Bits and machines)
           # grid_sampling's section: the review's date, the command's lags, NTM_IB's chain grid and IEC's scale
           "(found by a review, 2026-12-07)", "| u at 20 / 40 s: field; model |", "w's rows are 25 m apart",
           "against its integral scale of 0.66 Lambda_1)", "anticorrelates with itself 40 s later", "(95 % half",
           ", default 1, which every suite keeps)", "u's correlation at 20 / 40 s on the",
           "znver4 names numpy's AVX-512 loops with OpenBLAS's SkylakeX kernels",
           "(Meijaard et al. 1999 eqs. 1-3)", "(cos a, sin a, 0)",  # the standards' formulas and clauses
           "sigma_1 = I_ref (0.75 V_hub + 5.6 m/s) | Kaimal: f S_k / sigma_k^2 = (4 f L_k / V_hub) / (1 + 6 f L_k / "
           "V_hub)^(5/3)", "| IEC 61400-1 ed. 3, 6.3.1.3 (eqs. 5, 11), Annex B Table B.1 |",
           "sigma_1 = c I_ref (0.072 (V_ave/c + 3)(V_hub/c - 4) + 10), c = 2 m/s, V_ave = 0.2 V_ref | Kaimal | as NTM "
           "| IEC 61400-1 ed. 3, 6.3.2.3 (eq. 19) |", "below 1000 ft: sigma_w = 0.1 W_20, sigma_u = sigma_v = "
           "sigma_w / (0.177 + 0.000823 h)^0.4; above 2000 ft: the exceedance table (light 1e-2, moderate 1e-3, "
           "severe 1e-5); linear in between | Phi_u = sigma^2 (2L/pi) / (1 + (L Omega)^2); "
           "Phi_v,w = sigma^2 (L/pi)(1 + 3 (L Omega)^2) / (1 + (L Omega)^2)^2 | "
           "L_w = h, L_u = L_v = h / (0.177 + 0.000823 h)^1.2 (ft);",
           "| MIL-F-8785C 3.7.2 (Fig. 7 for the table); MIL-HDBK-1797 4.9.1 appendix |",
           "Phi_u = sigma^2 (2L/pi) / (1 + (1.339 L Omega)^2)^(5/6); Phi_v,w = sigma^2 (L/pi)(1 + (8/3)(1.339 L "
           "Omega)^2) / (1 + (1.339 L Omega)^2)^(11/6) | as Dryden below 2000 ft; above 2000 ft L =",
           "| MIL-F-8785C 3.7.2.1",
           "(A+, ed. 4); IEC 61400-1 ed. 3 Table 1.", "IEC 61400-1 ed. 3 eq. B.4, Coh(r, f) = exp(-12 sqrt((f r / "
           "V_hub)^2 + (0.12 r / L_c)^2)), L_c = 8.1 Lambda_1 for u", "S(kappa) dkappa / 2",
           "(IEC's sigma is the 10-minute standard deviation; see below)", "rho_j X_(j-1) + sqrt(1 - rho_j^2)",
           # the grid's length: gusts-v1's wing grid (its along_wind 200 m + 8.08 m/s x 60 s, rounded up to dxi),
           # the IEC averaging time, the first wavenumber's definition
           "700 m for the wing's 60 s scenarios, far shorter than the 10 minutes IEC's sigma stands for",
           "wavenumber dkappa = 1 / (n_xi dxi)",
           "A 3.5 km field (147 rows x 240 columns x 3)", "pyconturb 2.7.4", "a 3.5 km x 8 km box at 10 m",
           "40 lines of numpy", "by 0.5 (1 - cos(pi t / T_f))", "at t = 0,", "gusts-v1 fades turbulence in over 10 s",
           "24 bytes per node: n_xi = (span + U T) / dxi + 3 (even), n_h = (h_top - h_bottom) / dh + 1",
           "For the 3.5 km chain over 600 s (heights 0-3600 m every 25 m, along-wind -4000..500 m, U = 13.5 m/s, dxi "
           "= 10 m):", "In general the bound is 24 (span + U T + 3 dxi)/dxi ((h_top - h_bottom)/dh + 1) bytes",
           "(LadderChain-v0, 101 wings, 120 s field of 240 x 147 nodes;", "a = exp(-dx / L)",
           "(1 - r / 2L) exp(-r / L)", "2^(2/3) / Gamma(1/3) (r/a)^(1/3) K_(1/3)(r/a), a = 1.339 L",
           "Formulas from IEC 61400-1 ed. 3;", "V = V_hub - 0.37 V_gust sin(3 pi t / T)(1 - cos(2 pi t / T)),",
           "min(1.35 (V_e1 - V_hub), 3.3 sigma_1 / (1 + 0.1 D / Lambda_1)), V_e1 = 0.8 x 1.4 V_ref | 6.3.2.2 (eqs. "
           "16-17) |", "theta = 0.5 theta_e (1 - cos(pi t / T)),", "theta_e = 4 atan(sigma_1 / (V_hub (1 + 0.1 D / "
           "Lambda_1))); +-1 | 6.3.2.4 (eqs. 21-22) |", "V = V_hub + 0.5 V_cg (1 - cos(pi t / T)), theta = 0.5 "
           "theta_cg (1 - cos(pi t / T)),", ", theta_cg = 180 deg (V_hub < 4 m/s) else 720 deg m/s / V_hub | 6.3.2.5 "
           "(eqs. 23-25) |", "+-((z - z_hub) / D)(2.5 m/s + 0.2 beta sigma_1 (D / Lambda_1)^(1/4))(1 - cos(2 pi t / "
           "T)),", "| 6.3.2.6 (eq. 26) |", "speed factor 1 + step at", "CS-25.341 shape", "z_hub +- D/2",
           "s = exp(q z - q^2 / 2), q^2 = ln(1 + speed_std^2)", "mean 1,", "runs 300 ten-minute episodes per value up "
           "to 2.0.", '"step": 0.02}', '"heights": [0, 300]}', "(to within 10 % of the largest deviation from the "
           "final value, at least 1 mm; nan when not settled in the last 10 % of the episode, or still drifting "
           "there:", "the suite file's SHA-256",
           "Results (60 s episodes, turbulence faded in over 10 s;", "the ECD turns 72 deg in 10 s",
           "re-run on 2026-11-30, TetheredWing-v0's on 2026-12-01 (znver3) and 2026-12-02 (znver4);",
           "+20 % speed step, 1-cosine gusts of 4 s "
           "and 20 s,", "at the reel-out trim's 296.3 m and the scene's 10.39 m/s there (D = the 20 m span)",
           "NTM IB turbulence on a grid 0-600 m high and 50 m upwind to 600 m downwind of the winch (the tether is at "
           "most 540 m). Episodes of 200 s: one pumping cycle (190.5 s from the trim,",
           "EWS (IA) arriving at p . e = -120 m (upwind of the hauled station) at 5 s,", "all at mid-mill (1748 m, "
           "10.72 m/s), on one grid 0-3700 m high (dh 25 m) and -150 to 1000 m along the wind (dxi 10 m) plus the 60 "
           "s of advection.", "over the whole 60 s", "(the suite's full durations; 1 seed, 3 for turbulence;",
           "LadderMill-v0 (60 s;", "for a 3.5 km chain", "The Gaussian 1 + speed_std z",
           "The +20 % speed step", "against the whole 60 s reference", "gusts-v1's 0.01 rad direction step"),
    timings=("read through the kernel; about 40 s)",
             "is drawn in about 3.5 ms",  # the page's own measurements on the shared 2-core machine (its load given)
             "medians of 11-15 interleaved runs of 80 steps on the 2-core machine shared with other jobs): ratio with /"
             " without 1.29 (1.015 vs 1.311 ms per step, load about 3) before the fade-in slot, 1.18 and 1.11 after it"
             " in two runs at a higher load (2.5 vs 3.0 ms, 2.2 vs 2.5 ms). Drawing the field at a reset takes 3-16 "
             "ms.", "--out runs/gust_bench_v2/pumping # 16 s", "--out runs/gust_bench_v2/mill # 2 min 50 s"),
    printed=(  # long groups: python -m docsite.readme_figures --long NAME (docsite/long_figures.py)
        Printed("grid_sampling_v1", (
            "1000 seeds, 200 nodes and 200 random points of each",
            "half-widths 0.004-0.017):",
            "| TetheredWing-v0, NTM_IB | 700 m, dxi 5 m, dh 5 m | 0.997, 1.002, 1.003 | 0.884, 0.855, 0.761 | -0.055 / "
            "-0.311; 0.418 / 0.257 |",
            "| TetheredWing-v0, dryden_light | the same | 0.997, 1.005, 1.003 | 0.926, 0.931, 0.868 | -0.049 / -0.461; "
            "0.540 / 0.292 |",
            "| LadderChain-v0, NTM_IB | 2100 m, dxi 10 m, dh 25 m | 1.000, 0.996, 1.003 | 0.818, 0.752, 0.621 | "
            "0.183 / -0.120; 0.347 / 0.195 |",
            "| LadderChain-v0, dryden_light | the same | 1.000, 1.001, 1.000 | 0.891, 0.891, 0.878 | 0.294 / -0.127; "
            "0.436 / 0.190 |",
            "between them the chain's wings meet 62 % of the NTM's w variance",
            "and the wing 76 %.",
            "where the unbounded model's correlation is 0.26-0.29.")),
        Printed("grid_sampling_record", (
            "wing's NTM_IB grid is 0.419 / 0.242 against the model's 0.418 / 0.257,",
            "record 1) give 0.463 / 0.358")),
        Printed("turbulence_level", ("| TetheredWing-v0 | NTM IB | 700 | 0.49 | 2.03 | 0.45 |",
                                     "| TetheredWing-v0 | Dryden moderate | 700 | 0.35-0.89 | 1.12-2.85 | 0.07-0.60 |",
                                     "| LadderChain-v0 | NTM IB | 2100 | 0.71 | 1.41 | 0.23 |",
                                     "| Rotorcraft-v0 | NTM IB | 740 | 0.59 | 1.71 | 0.37 |",
                                     "| Rotorcraft-v0 | Dryden moderate | 740 | 0.42-0.92 | 1.09-2.41 | 0.06-0.53 |")),
        # MillTask.loop_extent() at LadderMill-v0's operating point, which tests/test_gusts_v2.py's slow grid test
        # checks against the NTM grid and prints (-s) (was not_rerun)
        Printed('mill_loop_extent_test', ('The loop spans 50 m (the stations) to 3440 m and p . e -100 to 689 m:',)),
        # tests/test_mill_gust_slots.py -s (--long mill_gust_slots_tests, 2026-12-01, as written): the slots'
        # heights at the operating point (slot 0 57.9 m, slot 23 1611.8 m, slots 99-100 199.4 / 129.0 m, the top
        # 3437.9 m), the EWS_IA grid's peak rows -+10.867 m/s at 58.0 / 3438.0 m (IEC eq. 26 in the test) and the
        # scene's 8.013 m/s at 58 m, slot 0's largest roll rate in NTM_IB seed 0's first second (2.995 rad/s at
        # 0.95 s, lateral gust 0.038 m/s); were not_rerun (figures of the gusts-v2 session; until 2026-12-01 the page
        # said "after 1 s" of the roll, whose peak is at 0.95 s: now "within 1 s")
        Printed('mill_gust_slots_tests', (
            '58-1612 m at the operating point),',
            'open loop, slot 0 (just above the veered station) rolls at 3 rad/s within 1 s in a faded-in lateral gust '
            'of 0.04 m/s (NTM seed 0)',
            "takes up to 10.9 m/s off the wind at the bottom of the loop (58 m, where the scene's wind is 8 m/s) and "
            'adds as much at the top (3438 m):', '129-199 m)',
        )),
        Printed('gusts_v1_ladder_chain', ('in turbulence both leave the aerodynamic tables after 7-11 s',)),
        # the mill's failures in the gust bench's CSV (--long gusts_v2_mill_printed, 2026-11-30, 392 s: as written)
        Printed('gusts_v2_mill_printed', (
            '(until the LQR-controlled mill fails, near 7 s)', '(slots 0-23,',
            # the failed seeds' largest lateral excursions (max_lateral_m; the open loop's at 6.1-8.25 s beyond 3 m)
            'lateral offsets of only 1-3 m (largest excursions 0.8-3.2 m;',
            "6.4-18.6 m in the open loop's three later failures);",
            'delays the failure to 5-8 s,',
        )),
        # the pumping kite's held NTM_IB seeds and in-plane events (until 2026-11-30 listed under the mill's group,
        # whose command does not run the kite)
        Printed('gusts_v2_pumping_printed', (
            '(lateral excursions of 7.6-10.2 m,', 'and loses the third to sideslip at 61 s.', '(0 m lateral)',
        )),
    ),
    derived=(
        "(a standard deviation of 0.79 sigma_w:",  # the square root of grid_sampling's printed 0.621
        # the pumping kite's held NTM_IB seeds' energy ratios less 1 (gust_bench.csv prints the ratios)
        '14-30 % more energy from the gusts)',
        # bounds over gust_bench.csv's causes (--long gusts_v2_mill_printed): every failing sideslip is 60.6-81.6 deg
        # in magnitude; the EWS failures at 14.75 and 12.35 s less the event's start at 5 s
        'by sideslip beyond 60 deg', 'leave the aerodynamic range 7-10 s after',
        # the fade-in's closed form 0.5 (1 - cos(pi t / 10 s)) at the LQR's failures, 5 and 8 s: 0.50, 0.90
        'when the fade-in has brought the field to 50-90 % of its strength',
    ),
    history=(
        History('2026-11-24', 'laddermill gust-bench --suite gusts-v1 --env ID --controllers open_loop lqr (ee8a806; '
                'the fade-in came with 34c3c4d the same day)', "the first gusts-v1 runs: TetheredWing-v0 at RK4 50 ms, "
                "Rotorcraft-v0 on the suite's eight scenarios of the day, turbulence at full strength from t = 0", (
            'before the fade-in, the open-loop and LQR chains then left the aerodynamic tables within 0.2-5 s)',
            'read 3 / 12 and 8 / 12 for TetheredWing-v0 at RK4 50 ms and 3 / 8 and 7 / 8 for Rotorcraft-v0, then on '
            'eight scenarios):',
            '(after 0.2-5 s without the fade-in)',
        )),
        History('2026-11-24', 'gymnasium resets of the envs with the Gaussian speed factor (its code is gone)',
                'the failure rates measured when the speed factor was replaced', (
            'made 1.1 % of resets fail at speed_std 0.25 (9 % at 0.3, 93 % at 0.5)',
        )),
    ),
)
