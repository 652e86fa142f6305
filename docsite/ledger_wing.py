"""The ledger entry (:mod:`docsite.page_ledger`) of docs/wing_data.md: its key numbers, mass build-up, trims on the
cable and pitch check about the attachment against ``derive_wing --check`` (:mod:`docsite.wing_figures`, about 4 s);
the page's other figures (the paper's data, the chosen constants, the in-plane runs and the power curve of the v1
mill) not yet listed."""

from __future__ import annotations

from docsite.ledger_kinds import NotYet

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


WING_DATA = NotYet(
    "the key numbers, mass build-up, trims on the cable and the pitch check are checked against derive_wing --check; "
    "the chosen constants, the surface curves' figures, the in-plane runs and the v1 power curve not yet listed",
    groups=("derive_wing",),
    checks=((rf"\| aircraft CL_alpha \(wing \+ tail, 5 deg\) \| {N} /rad \(wing alone {N}\)",
             (_p("CL_alpha"), _p("model[CLa_w]"))),
            (rf"\| C_L,max \(aircraft, d_e = 0\) \| {N} at {N} deg", (_p("CL_max[0]"), _p("CL_max[1]"))),
            (rf"\| CD0 \(C_D at C_L = 0\) \| {N} \|", (_p("CD0"),)),
            (rf"\| Oswald e \(wing\) \| {N} \|", (_p("model[e]"),)),
            (rf"\| \(L/D\)_max \| {N} at {N} deg", (_p("LD[0]"), _p("LD[1]"))),
            (rf"\| Cm_alpha about the CG \| {N} /rad", (_p("Cm_alpha"),)),
            (rf"\| static margin \(no cable\) \| {N} c = {N} m \(neutral point {N} m",
             (_p("margin[0]"), _p("margin[1]"), _p("margin[1]"))),
            (rf"\| free-flight trim, d_e = 0 \| alpha = {N} deg", (_p("free_trim"),)),
            (rf"\| CLq, Cmq \| {N}, {N} \|", (D % "CLq", D % "Cmq")),
            (rf"\| CLad, Cmad \| {N}, {N} \|", (D % "CLad", D % "Cmad")),
            (rf"\| CLde, Cmde \| {N}, {N} /rad", (D % "CLde", D % "Cmde")),
            (rf"\| CYb, Cnb, Clb \| {N}, {N}, {N} /rad", (D % "CYb", D % "Cnb", D % "Clb")),
            (rf"\| Clp, Cnp, Clr, Cnr \| {N}, {N}, {N}, {N} \|", (D % "Clp", D % "Cnp", D % "Clr", D % "Cnr")),
            (rf"\| Clda, Cnda \| {N}, {N} \(body", (D % "Clda", D % "Cnda")),
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
            (rf"free-flight static margin {N} c \(neutral point {N} m behind the CG\), pitch damping C_mq = {N}, "
             rf"C_mad = {N} \(above\)", (_p("margin[0]"), _p("margin[1]"), D % "Cmq", D % "Cmad")),
            (rf"\(here {N} /rad from 3 deg dihedral", (D % "Clb",)),
            (rf"\(V_V = {N}; Cnb = {N}, Cnr = {N}\)", (_p("V_V"), D % "Cnb", D % "Cnr")),
            (rf"its height below the CG \({N} m\) .* its position ahead \({N} m\)",
             (_p("attachment[2]"), _p("attachment[0]"))), (rf"\(Clp = {N}, Cnr\)", (D % "Clp",)),
            _pitch("v0", "ascending"), _pitch("v0", "descending"), _pitch("v1", "ascending"),
            _pitch("v1", "descending")),
)
