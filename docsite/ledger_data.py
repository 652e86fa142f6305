"""The ledger entries (:mod:`docsite.page_ledger`) of the data pages: the cable's derivation checked against its
configuration file and the page's hand arithmetic reworked in closed form (:mod:`docsite.config_figures`)."""

from __future__ import annotations

from docsite.ledger_kinds import Covered

CW, CC = "{cable_dyneema[page][%s]}", "~{cable_dyneema[config][%s]}"
N = r"([\d.]+(?:e-?\d+)?)"  # a number as the page writes it: 0.30, 3.0e5, 3.08e-4
CABLE_DATA = Covered(
    groups=("cable_dyneema",),
    checks=((rf"mu = 21/70 = \*\*{N} kg/m\*\*", (CC % "mass_per_length",)),
            (rf"C_N0 = \*\*{N}\*\*, C_T0 = \*\*{N}\*\*", (CC % "cn0", CC % "ct0")),
            (rf"mu = 0\.30 kg/m = {N} tex", (CW % "tex",)),
            (rf"A_f = mu/rho_f = 0\.30/975 = {N} m\^2, i\.e\. a fill factor of {N} of the 25 mm circle \({N} m\^2\)",
             (CW % "fibre_area", CW % "fill", CW % "circle")),
            (rf"x 3\.0e5 tex = {N} N \(= {N} GPa x 3\.08e-4 m\^2\)", (CW % "ea_fibre", CW % "fibre_GPa")),
            (rf"\*\*EA = 0\.6 x 3\.6e7 N = {N} N\*\* \(effective modulus {N} GPa", (CC % "EA", CW % "rope_GPa")),
            (rf"under 10 kN then stretches {N} cm \({N} %\)", (CW % "stretch_cm", CW % "strain_pct")),
            (rf"3\.5 N/tex \(lower mid-range\) x 3\.0e5 tex = {N} N", (CW % "strength",)),
            (rf"\*\*breaking_load = {N} N\.\*\*", (CC % "breaking_load",)),
            (rf"\*\*tau = {N} s\*\*: \*\*DA = {N} N s\*\*", (CC % "tau", CC % "DA")),
            (rf"sqrt\({N}/{N}\) ~ {N} rad/s, giving a loss factor of {N}",
             (CW % "k70", CW % "mass", CW % "omega", CW % "loss")),
            (rf"k = 4: \|lambda\| = {N} 1/s, dt < {N} s", (CW % "lam70", CW % "dt70")),
            (rf"\|lambda\| = {N} 1/s, dt < {N} ms", (CW % "lam7", CW % "dt7_ms")),
            (rf"\| diameter \| {N} m \| paper \| \| mass_per_length \| {N} kg/m", (CC % "diameter",
                                                                               CC % "mass_per_length")),
            (rf"\| EA \| {N} N \| DSM", (CC % "EA",)), (rf"\| DA \| {N} N s \| EA x {N} s", (CC % "DA", CC % "tau")),
            (rf"\| breaking_load \| {N} N \| DSM", (CC % "breaking_load",)),
            (rf"\| cn0, ct0 \| {N}, {N} \|", (CC % "cn0", CC % "ct0"))),
    given=("25 mm Dyneema rope", "Schwab (1999)", "diameter d = 2.5 cm; a 70 m piece weighs 21 kg, so mu = 21/70",
           "(paper eq. 24,", "(ref. CIS YA100, 2010), grades", "modulus 112-137 N/tex (109-132 GPa), tenacity 3.4-4.0 "
           "N/tex (3.3-3.9 GPa), elongation at break 3-4 %. Fibre density 975 kg/m^3", "(1 tex = 1 g/km)",
           "= 0.30/975 =", "25 mm circle", "EA_fibre = 120 N/tex (mid-range) x 3.0e5", "x 3.08e-4 m^2",
           "efficiency of **0.6**", "EA = 0.6 x 3.6e7 N", "A 70 m piece under 10 kN", "Fibre: 3.5 N/tex",
           "x 3.0e5 tex =", "efficiency of **0.5**", "for a 2.5 cm rope", "a 70 m piece carrying a 54 kg wing",
           "(k = 3 for one end fixed with consistent mass, 12 for the free-free", "about 4 in between",
           "dt < 2.78. For l = 70 m and k = 4", "(l = 7 m at the start, 1/10 of a piece)", "set DA = 0",
           "paper (21 kg / 70 m)", "modulus 120 N/tex x 3.0e5 tex x 0.6", "tenacity 3.5 N/tex x 3.0e5 tex x 0.5",
           "paper eq. 24"),
)
