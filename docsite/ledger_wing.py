"""The ledger entry (:mod:`docsite.page_ledger`) of docs/wing_data.md: its key numbers, mass build-up, trims on the
cable and pitch check about the attachment against ``derive_wing --check`` (:mod:`docsite.wing_figures`, about 4 s);
the paper's data and the chosen constants given; the figures worked by hand listed; the in-plane runs of the mill,
the v1 steps and power curve Printed by long groups; the in-plane trial runs no command repeats listed as not
re-run."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, History, Printed

N = r"(-?[\d.]+)"
D = "~{derive_wing[deriv][%s][1]}"  # a derivative at 7 deg
MASS = "~{derive_wing[mass][%s][%d]}"
PITCH = r"\| (v\d) \(\d0 deg\) \| (ascending|descending) \| " + r" \| ".join([N] * 7) + r" \|"


def _p(path: str) -> str:
    """The template of a printed figure at ``path`` ("CL_alpha", "model[e]", "kite[V6.0][0]"), rounded as quoted."""
    return "~{derive_wing[" + (path.replace("[", "][", 1) if "[" in path else path + "]") + "}"


def _pitch(variant: str, leg: str) -> tuple:
    row = PITCH.replace(r"(v\d)", variant).replace("(ascending|descending)", leg)
    return row, tuple(f"{{derive_wing[pitch][{variant} {leg}][{i}]}}" for i in range(7))


#: the figures derive_wing --check prints, where the page quotes them
CHECKS = (
    (rf"\| aircraft CL_alpha \(wing \+ tail, 5 deg\) \| {N} /rad \(wing alone {N}\)",
     (_p("CL_alpha"), _p("model[CLa_w]"))),
    (rf"\| C_L,max \(aircraft, d_e = 0\) \| {N} at {N} deg", (_p("CL_max[0]"), _p("CL_max[1]"))),
    (rf"\| CD0 \(C_D at C_L = 0\) \| {N} \|", (_p("CD0"),)),
    (rf"\| Oswald e \(wing\) \| {N} \|", (_p("model[e]"),)),
    (rf"\| \(L/D\)_max \| {N} at {N} deg", (_p("LD[0]"), _p("LD[1]"))),
    (rf"\| Cm_alpha about the CG \(5 deg\) \| {N} /rad", (_p("Cm_alpha"),)),
    (rf"\| static margin \(no cable, 5 deg\) \| {N} c = {N} m \(neutral point {N} m",
     (_p("margin[0]"), _p("margin[1]"), _p("margin[1]"))),
    (rf"\| free-flight trim, d_e = 0 \| alpha = {N} deg", (_p("free_trim"),)),
    (rf"\| CLq, Cmq \| {N}, {N} \|", (D % "CLq", D % "Cmq")),
    (rf"\| CLad, Cmad \| {N}, {N} \|", (D % "CLad", D % "Cmad")),
    (rf"\| CLde, Cmde \| {N}, {N} /rad", (D % "CLde", D % "Cmde")),
    (rf"\| CYb, Cnb, Clb \| {N}, {N}, {N} /rad", (D % "CYb", D % "Cnb", D % "Clb")),
    (rf"\| Clp, Cnp, Clr, Cnr \| {N}, {N}, {N}, {N} \|", (D % "Clp", D % "Cnp", D % "Clr", D % "Cnr")),
    (rf"\| Clda, Cnda \| {N}, {N} \(body", (D % "Clda", D % "Cnda")),
    # the side-force rate derivatives and the aileron's yaw in stability axes (printed since 2026-11-30)
    (rf"\| CYp, CYr \| {N}, {N} \|", (D % "CYp", D % "CYr")),
    (rf"in stability axes Cnda = {N}, adverse yaw", (D % "Cnda_stability",)),
    (rf"\| CYdr, Cndr, Cldr \| {N}, {N}, {N} /rad", (D % "CYdr", D % "Cndr", D % "Cldr")),
    *[(rf"\| {label} \| {N} \| {N} \| {N} \|", (MASS % (part, 0), MASS % (part, 1), MASS % (part, 2)))
      for label, part in ((r"main wing \(0\.70 kg/m\^2; CG at 40 % chord\)", "main wing"),
                          (r"horizontal tail \(0\.2 kg/m\^2\)", "horizontal tail"),
                          (r"pod \(nose fairing: attachment hardware, actuators, battery\)", "pod"))],
    (rf"\| fins, 2 x \(0\.2 kg/m\^2\) \| 2 x {N} \| {N} \| {N} \|",
     (MASS % ("fin right", 0), MASS % ("fin right", 1), MASS % ("fin right", 2))),
    (rf"\| booms \(carbon tubes, 5 m, 80 mm\) \| 2 x {N} \| {N} \| {N} \|",
     (MASS % ("boom right", 0), MASS % ("boom right", 1), MASS % ("boom right", 2))),
    (rf"Result: Jxx = {N}, Jyy = {N}, Jzz = {N}, Jxz = {N} kg m\^2",
     tuple(_p(f"J[{i}]") for i in range(4))),
    (rf"statically stable \| Cm_alpha = {N} /rad, margin {N} c", (_p("Cm_alpha"), _p("margin[0]"))),
    (rf"alpha = {N} / {N} / {N} / {N} deg; cable force {N} / {N} / {N} / {N} kN "
     rf"\(lift {N} / {N} / {N} / {N} kN\)",
     tuple(_p(f"kite[V{v}][0]") for v in ("6.0", "10.0", "15.0", "20.0"))
     + tuple(f"~{{derive_wing[kite][V{v}][{i}]}}e-3" for i in (1, 2) for v in ("6.0", "10.0", "15.0", "20.0"))),
    (rf"\| d_e = \+?{N} / {N} / {N} deg \|", tuple(_p(f"elevator[a{a}]") for a in ("0.0", "7.0", "15.0"))),
    (rf"\| {N} / {N} / {N} / {N} / {N} deg \(a second, post-stall branch exists at {N} deg",
     tuple(_p(f"de_trim[de{d}][0]") for d in ("-15.0", "-5.0", "0.0", "5.0", "15.0"))
     + (_p("de_trim[de15.0][1]"),)),
    (rf"d_e = 0 trims at {N} / {N} / {N} deg; alpha = 7 deg needs d_e = {N} / {N} / {N} deg",
     tuple(_p(f"tether[e{e}][{i}]") for i in (0, 1) for e in (30, 40, 50))),
    (rf"i_t = {N} deg \(solved by the script\)", (_p("i_t"),)),
    (rf"Main wing {N} /rad, tail plane {N} /rad, fins \(A = 2\) {N} /rad",
     (_p("model[CLa_w]"), _p("model[CLa_h]"), _p("model[CLa_v]"))),
    (rf"Wing {N}, tail plane {N} \(on its own area\), fins {N};",
     (_p("model[CD0_w]"), _p("model[CD0_h]"), _p("model[CD0_v]"))),
    (rf"d eps/d alpha = 2 CLa_w/\(pi A\) = {N}\.", (_p("deps"),)),
    (rf"aileron \(c_f/c = 0\.25\) {N}, rudder \(0\.35\) {N}\.", (_p("model[tau_a]"), _p("model[tau_r]"))),
    (rf"c = S/b = {N} m \(= mean", (_p("chord"),)), (rf"V_H = S_h l_t/\(S c\) = {N} \|", (_p("V_H"),)),
    (rf"V_V = 2 S_v l_v/\(S b\) = {N} \|", (_p("V_V"),)),
    (rf"\(1 \+ cos Lambda\) \+ 0\.009 A = {N}", (_p("model[eta_v(1+ds/db)]"),)),
    (rf"Tail volume V_H = S_h l_t / \(S c\) = {N} \(from the wing's ac\), V_V = {N};", (_p("V_H"), _p("V_V"))),
    (rf"free-flight static margin {N} c at alpha = 5 deg \(neutral point {N} m behind the CG\), pitch damping "
     rf"C_mq = {N}, "
     rf"C_mad = {N} \(above\)", (_p("margin[0]"), _p("margin[1]"), D % "Cmq", D % "Cmad")),
    (rf"\(here {N} /rad from 3 deg dihedral", (D % "Clb",)),
    (rf"\(V_V = {N}; Cnb = {N}, Cnr = {N}\)", (_p("V_V"), D % "Cnb", D % "Cnr")),
    (rf"its height below the CG \({N} m\) .* its position ahead \({N} m\)",
     (_p("attachment[2]"), _p("attachment[0]"))), (rf"\(Clp = {N}, Cnr\)", (D % "Clp",)),
    (rf"- 0\.64 = {N} \(wing\)", (_p("model[e]"),)),
    (rf"\(0\.15 m\^2 x C_D 0\.15\) add {N};", (_p("model[misc]"),)),
    (rf"below body x: {N} m ahead of the CG\)", (_p("attachment[0]"),)),
    _pitch("v0", "ascending"), _pitch("v0", "descending"), _pitch("v1", "ascending"),
    _pitch("v1", "descending"),
)

#: the paper's data, the chosen constants (each a named constant of derivations/wing_parameters.py with its source),
#: the formulas and their sources, the counts of the method
GIVEN = (
    # the two profiles' runs of mill_v1_steps, both printed on one AVX-512 machine (numerics.md, Bits and machines)
    "this AVX-512 machine prints both with their settings, 2026-12-02)",
    "Meijaard, Ockels & Schwab (1999)", "S = 54 m^2, b = 20 m, m = 54 kg, |CG - aerodynamic centre of the main wing| "
    "= 0.75 m, |CG - cable attachment| = 1.5 m, booms 5 m long", "t/c = 0.14, a0 = 6.0 /rad", "alpha0 = -3 deg, Cm0 = "
    "-0.07", "| dihedral | 3 deg |", "Ch. 4, dihedral guidelines (unswept mid wing 2-4 deg)", "| 0.75 m **ahead** of",
    "put mass 4-5 m aft", "at y = +-1 m", "spar 5.0 m aft", "l_t = 5.0 m from the wing ac",
    "S_h = 25 m^2, b_h = 11.2 m",
    "symmetric t/c = 0.10", "a static margin of about 0.08 c", "alpha = 7 deg at 10 m/s |", "2 x 3.0 m^2, height 1.8 m",
    "effective A = 2.0", "| 0.55-0.95 semispan, c_a/c = 0.25 |", "| c_r/c_v = 0.35 |", "| 1.5 m from the CG at 80 deg "
    "below", "elevator +-15 deg, rudder +-25 deg, aileron +-20 deg", "(200 per semispan", "(0, +-sin Gamma, cos Gamma)",
    "(0, 0, 1) on the tail plane, (0, 1, 0) on a fin", "3-D coefficient curves", "(4/pi) sqrt(1 - eta^2)",
    "3rd ed. 1996, Ch. 5,", "Clp = -CLa/8, Cnp = -CL/8, Clb = -(8/(3 pi)) CLa Gamma/4", "Sec. 4.1.3.2",
    "CLa = 2 pi A / (2 + sqrt(A^2/kappa^2 + 4)), kappa = a0/(2 pi)", "(A = 2)", "Raymer Ch. 12: e = 1.78 (1 - 0.045 "
    "A^0.68) - 0.64", "Raymer Ch. 12 component", "Cf = 0.455/(log10 Re)^2.58 at V = 10 m/s", "FF = 1 + 2 t/c + 60 "
    "(t/c)^4", "*Fluid-Dynamic Drag*, 1965, Ch. 6), S_wet = (1.977 + 0.52 t/c) S_exposed (Raymer Ch. 7) and "
    "interference Q = 1.1", "(0.15 m^2 x C_D 0.15)", "(wing -0.07, tails 0)", "Viterna & Corrigan (1982,",
    "NASA CP-2230", "C_D,max = 1.11 + 0.018 A", "x/c = 0.5 - 0.25 cos alpha (quarter chord at 0 deg, mid-chord at 90 "
    "deg,", "(1 - s) C_plate", "[1 + e^{M (alpha - alpha_s+)}]^-1 [1 + e^{-M (alpha - alpha_s-)}]^-1, M = 25 /rad "
    "(10-90 % over 10 deg, at least five 2-deg table rows", "alpha_s = +18/-16 deg (wing), +-17 deg (tail plane), +-21 "
    "deg (fins)", "*Small Unmanned Aircraft*, 2012, Ch. 4", "Etkin & Reid Ch. 2,", "2nd ed. 1998, Ch. 2", "eps = 2 "
    "C_L,w/(pi A)", "eta_h = 0.95 (Etkin & Reid Ch. 2", "CLq,t = 2 eta a_t V_H and Cmq,t = -2 eta a_t V_H l_t/c follow "
    "(Etkin & Reid Ch. 5; Nelson Ch. 3)", "CLq,w = (1/2 + 2 xbar/c) CLa_w", "(Etkin & Reid Ch. 5)",
    "-(d eps/d alpha) (2 l_t/c) alpha_hat", "CLad >= 0", "(effectiveness 1)",
    "eta_v (1 + d sigma/d beta) = 0.724 + 3.06", "Nelson Ch. 2;", "Fin ac 0.45 of", "tau = 1 - (theta_f - sin "
    "theta_f)/pi, cos theta_f = 2 c_f/c - 1", "times 0.8 for viscous", "## Key numbers (alpha = 7 deg", "(wing + tail, "
    "5 deg)", "Cnb > 0, Clb < 0, Clp < 0, Cnr < 0, Cmq < 0, CLde > 0 > Cmde, Clda > 0, CYdr > 0 > Cndr",
    "At 90 deg the",
    "a 1.2 x 0.3 x 0.3 m box", "left of 54 kg", "(0.70 kg/m^2; CG at 40 % chord)", "(0.2 kg/m^2)",
    "fins, 2 x (0.2 kg/m^2)", "(carbon tubes, 5 m, 80 mm)", "CG only 0.75 m behind", "times 1.5 m)",
    "10 deg ahead of the "
    "vertical through the CG (80 deg below body x)", "gives alpha = 7 deg at 10 m/s", "V = 6 / 10 / 15 / 20 m/s",
    "alpha = 0 / 7 / 15 deg (10 m/s)", "d_e = -15 / -5 / 0 / +5 / +15 deg", "for d_e = +15)", "at 30 / 40 / 50 deg "
    "elevation", "along a 30-50 deg line", "even then alpha = 7 deg", "within its +-15 deg limits", "near 7 deg",
    "(the v1 wing, issue 30)", "V_c = 2 m/s is periodic", "elevator -1 deg", "At 0 deg", "CG 0.75 m behind the main",
    "over 70 m", "2 T / l0",
    "2D periodic state at 2 m/s embedded",
    "on a 1.5 m lever", "(1.5 m at 80 deg below body x:", "(60 deg below body x: x = 0.75 m, "
    "the same 1.5 m from the CG,", "steady 10 m/s wind", "V_c = 2 m/s, 101 wings,",
    "| 80 deg (v0) | -4 / -1 | paper |",
    "| 80 deg (v0) | -4 / 0 | paper |", "| 90 deg | -4 / -1 | paper |", "| 70 deg | -4 / -1 | paper |",
    "| 60 deg | -6 / -1 | paper |", "| 60 deg | -6 / -1 | cable |", "| 60 deg | -8 / -1 | cable |",
    "| 60 deg (v1) | -8 / -0.5 | cable |", "elevators -8 / -0.5 deg and", "At 1 m/s", "(issue 30 point 2), matched at "
    "V_c = 2 m/s", "at 2 m/s (the paper's Fig. 8 speed; the paper: \"of the order of 200 kW\")", "the 2.5 cm cable's",
    "F_s = 2.5 of Lansdorp", "(2008, \"Long-Term", "525 / 2.5 = 210 kN",
    # the limit, passed by the 10 m/s rows' 222.0 / 221.0 kN (Printed, power_curve_v1)
    "and at 10 m/s the period's largest tension passes 210 kN",
    "its tensions pass 210 kN in the transient", "in 30 s",
    # the runs' dates and CPUs (power_curve_v1 and mill_v1_steps re-run on 2026-12-01; Printed and History below)
    "The table is the run of 2026-12-01 on znver3 (an AMD EPYC with AVX2; the 6 m/s wind's",
    "znver4 (with AVX512: the runs of 2026-11-30 and 2026-12-02) gives the same periodic rows but for the 2 m/s search "
    "peak,",
    "at 2 m/s (t = 1,345 s): the wind "
    "8 -> 9 m/s (the whole profile scaled by 9/8 over 1 s)", "below 210 kN; the cable speed 2 -> 3 m/s (over 1 s)",
    "(issue 30 point 3)", "in the scene's 30 s", "elevators -8 / -0.5 deg for every case,",
    "\"periodic\" within 1,400 s",
    "Bryant, Brown & Sweeting 1950", "R&M 2303; DeLaurier 1972", "NASA CR-2021", "wing 40 diverges in yaw after a "
    "0.01 rad", "3 deg dihedral", "(70 m pieces;", "(3 deg dihedral,", "for 10 m/s;", "with a tail 4-5 m aft",
    "so that d_e = 0 gives", "trim, d_e = 0, V", "[the mill at 4-5 m/s", "uses 3-D wing curves")
#: worked by hand from the page's inputs (no command prints them)
DERIVED = (
    "c = S/b = 2.70 m (= mean aerodynamic chord), A = 7.41",  # 54/20; 20^2/54
    "(kappa = 0.955)",  # 6.0/(2 pi)
    "4.25 m from the CG", "(A = 5.0), c_h = 2.23 m",  # 5.0 - 0.75; 11.2^2/25, 25/11.2
    "chord 1.67 m",  # 3.0/1.8
    "the CG 0.28 c behind", "(wing 1.24)",  # 0.75/2.70; 1.11 + 0.018 x 7.41
    "kite trims from -14 to 18 deg", "over -14..18 deg", "(83-86 deg below the horizontal here)",  # the trims above
    "83-86 deg below horizontal |", "|d_e| < 11 deg", "(about -2.7 deg of alpha per deg",  # read off the trims
    "The pod sits 1.4 m ahead", "The wing root plane lies 0.22 m below",
    "(about 18-24 deg and -14..-20 deg)",  # the CSV
    "the neutral point lies 0.48 m behind P", "puts it 0.97 m behind P", "C_L 0.61 (the issue's estimate for 200 kW at "
    "2 m/s was 0.6)", "than the v0 wing at C_L 1.00", "kite trim C_L 1.00", "(142 - 65) kN x 2 m/s = 154 kW",
    "(40 kN of tension difference)", "at 5 m/s",  # the estimate: 200 kW / 40 kN
    "(79 %)",  # the rigid run's last / first element, 126.9 / 160.0 kN (pointmass_mill_study, Printed below)
    # a review of 2026-12-07: the shipped CSV's least CLad and its apparent mass, rho0 S c CLad / 4 with rho0 1.225,
    # S 54, c 2.7 (-0.627 x 44.65 = -28.0 kg), the load check's bound -4 m / (rho0 S c) = -216 / 178.6; the v2 CG shift
    # (mill_fast.md) and the rate columns' transfer (CLq 5.44 -> about 1.3, Cmq -10.5 -> about -8.4 at 7 deg)
    "(the table's least, -0.63, lies near -18 deg)",
    "rho S c CLad/4 = -28 kg at sea level against the wing's m = 54 kg",
    "-4 m/(rho S c) = -1.21 for this wing). Found by a review (2026-12-07)", "whose CG lies 0.863 m further aft",
    "(at 7 deg; the transfer CLq' = CLq - (2 dx/c) CLa)")
#: the long groups (python -m docsite.readme_figures --long NAME): the v1 steps (the slow test prints both; first run
#: 2026-11-30, 172 s at nice 15, load 2.9-3.0: as written; it also prints the start's cable overload at t = 397.05 s,
#: "peak 1.07 x the limit", until then not_rerun and derived) and the v1 power curve (the page's command, 7 min)
PRINTED = (
    # the start's overload per CPU (docsite/host_cpu.py): 396.05 s, peak 1.13 x the limit on znver3 (2026-12-01, 220 s
    # at nice 15); 397.05 s, 1.07 on znver4 (2026-11-30, 2026-12-02); the steps' figures the same on both
    Printed("mill_v1_steps", ('at t = 397 s, peaking at 1.07 times it, on znver4',), cpu="znver4"),
    Printed("mill_v1_steps", ('and at t = 396 s (', '1.13 times it) on znver3'), cpu="znver3"),
    Printed("power_curve_v1", ('(593.4 kN,',), cpu="znver3"),  # the search's peak at 2 m/s on znver3 (2026-12-01)
    Printed("mill_v1_steps", (
        'at t = 2,010 s with 202.3 kW and tensions of the period up to 197.7 kN',
        'at t = 2,348.5 s with 212.8 kW and tensions up to 153.3 kN',
    )),
    # --long power_curve_v1 (2026-11-30; with --tail-rule scene, the run's rule, 425 s at nice 15, load 1.6-3.4): every
    # row as written; its table, one snippet until then, spans more printed numbers than missing's window: one per
    # row. The 210 kN limit is the setting (525 / 2.5, given), the v2 mill's 323.9 kW power_curve_replay's. Re-run
    # 2026-12-01 by helper D13 (1205 s at nice 15, AMD EPYC AVX2): the periodic rows as before but the 2 m/s search
    # peak (561.6 -> 593.4 kN), every non-periodic row other (chaotic runs; the CPU's last bits): the page's rows now
    # this run's, 2026-11-30's peak a History record
    Printed("power_curve_v1", (
        '| 8 | 0.5 | yes | 42.3 | 42.3 | 148.5 | 150.4 |', '| 8 | 1 | yes | 82.1 | 82.1 | 147.6 | 153.6 |',
        '| 10 | 2 | yes | 228.5 | 228.5 | 222.0 | 240.7 |',
        '| 10 | 3 | yes | 321.4 | 321.4 | 221.0 | 265.7 |',
        'settles at 0.5-2 m/s only (at 3 m/s it does settle when reached by the step from 2 m/s, above), at 6 m/s '
        'wind not at all,',
        'at V0 = 6 or 10 m/s',
        # the prose beside the table: its V_c 1 and 2 m/s rows (P, T_max) and the search's peak at 2 m/s
        'periodic at 715 s with 82.1 kW', 'peak tension 148 kN', 'delivers 152.9 kW',
        'is 2 m/s (152.9 kW)',
        # the period's T_max at V_c 2 m/s (until 2026-11-30 the page said "stays below 149 kN": issue 33 point 6)
        'stays at or below 149.5 kN',
        # the 5 m/s row's T_max of the last period and search peak (its table row above, the same run); until
        # 2026-12-01 the page said "up to 390 kN", of the trial runs of 2026-11-29 (fb84e85: 350 kN first element,
        # 388 kN last), not kept and printed by no command; not_rerun until then. The 210 kN limit is given. Until
        # 2026-12-01 (the run of 2026-11-30, AVX-512) "327.7 kN in the last period of the search, 527.8 kN at its peak"
        '**At 4-5 m/s**',
    )),
    # the chaotic rows per CPU (docsite/host_cpu.py): the table's are znver3's (2026-12-01, helper D13), the second
    # table znver4's (2026-11-30 and 2026-12-02 print the same)
    Printed("power_curve_v1", (
        '| 8 | 2 | yes | 152.9 | 152.9 | 149.5 | 593.4 |', '| 8 | 3 | no | 214.5 | 214.5 | 153.6 | 574.5 |',
        '| 8 | 4 | no | 273.2 | 273.1 | 120.9 | 452.9 |', '| 8 | 5 | no | 307.8 | 307.8 | 135.3 | 488.6 |',
        '| 8 | 6 | no | 697.7 | 697.6 | 246.4 | 565.9 |', '| 6 | 2 | no | 124.7 | 124.7 | 140.8 | 367.1 |',
        '| 6 | 3 | no | 92.4 | 92.3 | 48.0 | 522.6 |',
        "(488.6 kN at the search's peak; 135.3 kN at most in its last period on znver3;",
        # the 6 m/s wind's 3 m/s case: "breakdown ground contact at t = 933.19 s: wing 100 ..." (2026-12-01)
        "3 m/s case ended by ground contact at t = 933 s on znver3",
    ), cpu="znver3"),
    Printed("power_curve_v1", (
        '| 8 | 2 | yes | 152.9 | 152.9 | 149.5 | 561.6 |', '| 8 | 3 | no | 214.6 | 214.6 | 154.0 | 477.1 |',
        '| 8 | 4 | no | 167.1 | 167.1 | 165.6 | 571.3 |', '| 8 | 5 | no | 586.7 | 586.6 | 327.7 | 527.8 |',
        '| 8 | 6 | no | 460.5 | 460.6 | 257.8 | 613.6 |', '| 6 | 2 | no | -62.9 | -62.9 | 209.4 | 575.6 |',
        '| 6 | 3 | no | 64.4 | 64.4 | 96.6 | 223.6 |',
        '527.8 kN and 327.7 kN on znver4)', 'and at 336 s on znver4)'), cpu="znver4"),
    Printed("power_curve_replay", ('at 1 to 5 m/s (323.9 kW at 5 m/s)',)),
    # tests/test_mill_v0_slack.py -s (--long mill_v0_slack_test, 2026-12-01): the v0 mill in plane at a descending
    # elevator of 0 deg, its last element's tension 0.17 kN at t = 159.96 s (first under 1 kN at 157.99 s), against
    # the scene's -1 deg (least 59.9 kN); was not_rerun (a Python session of 2026-11-29); until 2026-12-01 the page
    # said "falls to 0" (now 0.2 kN)
    Printed("mill_v0_slack_test", ('falls to 0.2 kN at t = 160 s',)),
    # the v0 mill's power at 1 m/s: the v0 study prints 36.3 kW (docs/paper_meijaard1999.md's table, Printed there)
    Printed("meijaard_v0", ('(v0: 36 kW)',)),
    # the v0 mill's power at 2 m/s in plane: the rigid run of the point-mass mill study (moving_cable.md's 66.1 kW)
    # and its ground elements' period-mean tensions ("first element 160.0 kN, last 126.9 kN"; until 2026-11-30 the
    # page said the descending leg pulls 82 % of the ascending one's pull, a figure no recorded run gives; dropped)
    Printed("pointmass_mill_study", ('and the mill delivers 66 kW', "127 kN against the ascending one's 160 kN")),
    # derive_wing --check's lines the page group does not parse: "wing alone (main wing's 3-D curve): C_L,max = 1.220
    # at alpha = 14.45 deg; boom cross-flow drag 0.0163 sin^2 alpha", "v0 attachment at elevator 0 deg (steady 10
    # m/s): trim alpha 7.00 deg, C_L 0.849" (2026-11-30; until then not_rerun)
    Printed("derive_wing_printed", ('The resulting wing-alone C_L,max is 1.22 at 14.5 deg',
                                    '(wing alone 1.22 at 14.5 deg)', 'boom cross-flow adds 0.016 sin^2 alpha',
                                    '(C_L 0.85)')),
    # the v1 study's 3D case at 2 m/s ("3D V_c=2: periodic, t = 1485 s; mean power 152.9 kW"; --long, 60 s with its
    # searches saved, 2026-11-30, nice 15, load 5.7)
    # and its peak tension ("(peak tension 0.285 x the breaking load)"; until 2026-11-30 the page quoted "a largest
    # tension of 149.5 kN", the study's CSV's 0.2847 x 525 kN, which the study prints as 0.285 x)
    Printed("meijaard_v1_printed", ('periodic at t = 1,485 s with the same 152.9 kW',
                                    'and a peak tension over its search of 0.285 x the breaking load')),
)
#: the attachment trials' in-plane runs (a Python session with overrides, 2026-11-29, fb84e85); figures of the page
#: that no recorded run gives and that today's commands print otherwise (issue 33 point 6, 2026-11-30)
HISTORY = (
    History("2026-11-29", "run_to_periodic(load_scene('laddermill', dimension=2, overrides=...).simulator(), "
            "shape_tol=1e-3, power_tol=1e-3) per attachment, elevators and insertion rule",
            "the v1 wing's attachment trials (fb84e85)", (
                '| periodic, 66.2 kW',
                '| not periodic: last period -365 kW at 365 s, period means -365..+387 kW |',
                '| not periodic: -180 kW at 575 s,',
                '| 88.9 kW at 575 s, shape still changing 3.4e-2 l0 per period |',
                '| 128.3 kW at 470 s, shape changing 4.4e-2 l0 per period |',
                '| 124.0 kW, shape change 1.7e-3 l0 at 855 s |',
                '| 135.3 kW, shape change below 1e-3 l0 at 890 and 925 s, peak tension 151 kN |',
                '| periodic at 1,345 s, 152.9 kW, tensions of the period up to 149.5 kN',
            )),
    # the v1 mill's start from rest at V_c 2 m/s on 2026-11-30's CPU (AVX-512, znver4): overload at 397.05 s, peak
    # 561.6 kN (1.07 x); today's AVX2 CPU gives 396.05 s and 593.4 kN (1.13 x), Printed above
    History("2026-11-30", "laddermill power-curve --scene laddermill_v1 --ramp scene --tail-rule scene --speeds 0.5 1 "
            "2 3 4 5 6 --winds 6 10 --wind-speeds 2 3 --max-time 1400 (--long power_curve_v1, 8e95472) and python -m "
            "pytest -m slow -s tests/test_mill_v1.py -k step (--long mill_v1_steps)",
            "the v1 mill's searches from rest on 2026-11-30's AVX-512 CPU, not kept",
            ("its run of 2026-11-30 peaked at 561.6 kN)",)),
)

WING_DATA = Covered(groups=("derive_wing",), checks=CHECKS, given=GIVEN, derived=DERIVED, printed=PRINTED,
                    history=HISTORY)
