"""The ledger entry (:mod:`docsite.page_ledger`) of docs/rotorcraft_design.md: the study's printed output and prose
results against ``rotor_design``, its inputs against the configs and its hand arithmetic in closed form
(:func:`docsite.design_figures.design_data`)."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, History, Printed

RDS = "{rotor_design[%s]}"
RP = "{rotor_design[prose][%s]}"
SENS = (("no profile drag", "no_drag"), ("weightless tethers", "weightless"), ("tethers at 20 deg", "elev20"),
        ("craft mass x0.7", "mass07"))
STUDY_CHECKS = (  # the study's printed output and prose against rotor_design (54 s)
    ((r"(Craft estimate \(drive rated .*?) wrote runs/rotor_design/design_study\.csv", (RDS % "printed",)),
            (r"Result: ([\d.]+) t at 15,000 ft \(180 m/s\) and ([\d.]+) t at 30,000 ft \(230 m/s\)",
             (RP % "craft_t][tip180", RP % "craft_t][tip230")),
            (r"top of the range: ([\d.]+) MW at 15,000 ft and ([\d.]+) MW at 30,000 ft at 45 m/s",
             (RP % "15kft][peak_MW", RP % "30kft][peak_MW")),
            (r"reach their allowed tension at (\d+) m/s \(([\d.]+) MW\)",
             (RP % "15kft][stress_wind", RP % "15kft][stress_MW")),
            (r"\*\*3\.13 MW is reached at ([\d.]+) m/s at 15,000 ft and at ([\d.]+) m/s at 30,000 ft",
             (RDS % "15kft][wind", RDS % "30kft][wind")),
            (r"rated winds of ([\d.]+) m/s and ([\d.]+) m/s fit", (RDS % "15kft][wind", RDS % "30kft][wind")),
            (r"The power coefficient there is ([\d.]+) and ([\d.]+)\.",
             (RP % "15kft][cp_rated", RP % "30kft][cp_rated")),
            (r"The required C_p is ([\d.]+) at 20 m/s and ([\d.]+) at 25 m/s at 15,000 ft, and ([\d.]+) at 25 m/s "
             r"and ([\d.]+) at 30 m/s", (RP % "15kft][need_cp][at20", RP % "15kft][need_cp][at25",
                                         RP % "30kft][need_cp][at25", RP % "30kft][need_cp][at30")),
            (r"C_p = ([\d.]+) \(([\d.]+) deg\) and ([\d.]+) \(([\d.]+) deg\)\.",
             ("{rotor_design[15kft][ideal_cp]:.3f}", "{rotor_design[15kft][alpha_c]}",
              "{rotor_design[30kft][ideal_cp]:.3f}", "{rotor_design[30kft][alpha_c]}")),
            (r"3\.13 MW would still need ([\d.]+) m/s and ([\d.]+) m/s", (RP % "15kft][ideal_wind",
                                                                         RP % "30kft][ideal_wind")),
            (r"no stress limit: ([\d.]+) m/s at 15,000 ft", (RP % "15kft][sensitivity][no_limit",)),
            (r"is worse: ([\d.]+) / ([\d.]+) m/s", (RP % "15kft][sensitivity][solidity",
                                                  RP % "30kft][sensitivity][solidity")))
    + tuple((rf"{label}: ([\d.]+) / ([\d.]+) m/s", (RP % f"15kft][sensitivity][{key}",
                                                    RP % f"30kft][sensitivity][{key}")) for label, key in SENS))

SC = "{rotor_design[scan][%s]}"
SCAN_CHECKS = (  # worked from the study's scan and sensitivity lines (docsite.rotor_figures.scan_figures)
    (r"With no limit at all, 3\.13 MW would come ([\d.]+) m/s earlier at 15,000 ft", (SC % "15kft][earlier",)),
    (r"(\d+ and \d+) m/s are the best, within about (\d+) % of each other\. Below (\d+) m/s",
     (SC % "15kft][best", SC % "15kft][apart_pct", SC % "15kft][low_best")),
    (r"the power drops by (\d+) % at 160 m/s, so (\d+) m/s keeps a margin\. - \*\*30,000 ft: (\d+) m/s\*\*",
     (SC % "15kft][drop160_pct", SC % "15kft][design_tip", SC % "30kft][design_tip")),
    (r"Below (\d+) m/s the craft cannot hold 30,000 ft on 30 deg tethers at 33 m/s at all",
     (SC % "30kft][lowest_tip",)),
    (r"They cover the study's collectives \(([-\d.]+\.\.[-\d.]+) deg at 15,000 ft, ([-\d.]+\.\.[-\d.]+) deg at "
     r"30,000 ft\)", (SC % "15kft][theta", SC % "30kft][theta")),
    (r"From 24 m/s on, each tether is within (\d+-\d+) % of its allowed tension", (SC % "30kft][short_pct",)),
    (r"At 30,000 ft the air is ([\d.]+) times as dense and the tethers weigh ([\d.]+) t\. The rated wind is "
     r"therefore about (\d+) m/s higher", ("{rotor_design[scan][rho_ratio]}", "{rotor_design[scan][tethers_t]}",
                           "{rotor_design[scan][rated_gap]}")))

DW, DC = "{design_data[worked][%s]}", "{design_data[config][%s]}"
DESIGN_CHECKS = (
    (r"13\.3 GWh / 6910 kWh/m\^2 = (\d+) m\^2 = 2 pi 17\.5\^2", (DW % "disk_m2",)),
    (r"3\.13 MW x 8760 h x 0\.48 = ([\d.]+) GWh and x 0\.67 = ([\d.]+) GWh", (DW % "energy48", DW % "energy67")),
    (r"rho = p/\(R T\): ([\d.]+) kg/m\^3 at (\d+) m and ([\d.]+) kg/m\^3 at (\d+) m",
     (DW % "15kft][rho", DW % "15kft][h", DW % "30kft][rho", DW % "30kft][h")),
    (r"ISA formula gives ([\d.]+) and ([\d.]+) kg/m\^3", (DW % "15kft][rho", DW % "30kft][rho")),
    (r"is ([\d.e-]+) m\^2 of fibre\. - EA = 112 GPa x [\d.e-]+ m\^2 = ([\d.e]+) N\.", (DW % "kevlar_m2", DW % "EA_N")),
    (r"- EA = 112 GPa x [\d.e-]+ m\^2 = ([\d.e]+) N\.", (DC % "cable][EA_N",)),
    (r"x 0\.67 = (\d+) kN, the same strength", (DW % "breaking_kN",)),
    (r"x 0\.67 = (\d+) kN, the same strength", (DC % "cable][breaking_kN",)),
    (r"at 2705 kg/m\^3 is ([\d.e-]+) m\^2\.", (DW % "alu_m2",)),
    (r"\*\*Diameter: (\d+) mm, not 10 mm\.\*\* The solid cross-section, ([\d.e-]+) m\^2, alone is a ([\d.]+) mm "
     r"circle\. At a fill factor of 0\.8 the cable is (\d+) mm", (DW % "cable_mm", DW % "solid_m2", DW % "solid_mm",
                                                         DW % "cable_mm")),
    (r"\*\*Diameter: (\d+) mm", (DC % "cable][cable_mm",)), (r"cable can weigh ([\d.]+) kg/m", (DC % "cable][mu",)),
    (r"aluminium of 10 mm is only ([\d.]+) kg/m", (DW % "alu10_kg_m",)),
    (r"Design factor 2: ([\d.]+) kN, which is (\d+) MPa", (DW % "allowed_kN", DW % "allowed_MPa")),
    (r"The aluminium has ([\d.e-]+) ohm/m", (DW % "ohm_m",)),
    (r"on ([\d.]+) km and 28 kV on ([\d.]+) km of tether", (DW % "15kft][length_km", DW % "30kft][length_km")),
    (r"beta = (\d+) deg at both altitudes", (DC % "15kft][elevation",)),
    (r"L = h / sin\(beta\): ([\d,]+) m at 15,000 ft and ([\d,]+) m at 30,000 ft",
     ("~" + DW % "15kft][length", "~" + DW % "30kft][length")),
    (r"L = h / sin\(beta\): ([\d,]+) m at 15,000 ft and ([\d,]+) m at 30,000 ft",
     ("~" + DC % "15kft][length", "~" + DC % "30kft][length")),
    (r"That is ([\d.]+) t and ([\d.]+) t per tether", (DW % "15kft][tether_t", DW % "30kft][tether_t")),
    (r"\(([\d.]+) rad/s\)\. 170 and 180", (DW % "15kft][omega",)), (r"\(([\d.]+) rad/s\)\. 170 and 180",
                                                                    (DC % "15kft][omega",)),
    (r"\(([\d.]+) rad/s\)\. At the thinner air", (DW % "30kft][omega",)),
    (r"\(([\d.]+) rad/s\)\. At the thinner air", (DC % "30kft][omega",)),
    (r"must lift ([\d.]+) t of tether", (DW % "30kft][tethers_t",)),
    (r"runs at about (\d+) m/s\.", (DW % "mi26_tip",)),
    (r"\(Omega R \+ V cos alpha_c\)/a = ([\d.]+) at 15,000 ft and ([\d.]+) at 30,000 ft",
     (DW % "15kft][mach", DW % "30kft][mach")),
    (r"3\.13 MW / 0\.95 / 2 = ([\d.]+) MW of shaft power", (DW % "drive_MW",)),
    (r"sigma pi R / 4 = ([\d.]+) m", (DW % "chord",)),
    (r"kg \(Fingersh, Hand & Laxson, NREL/TP-500-40566, 2006\), ([\d.]+) kg/kW", (DW % "gen_kg_kW",)),
    (r"SP260D aircraft motor is ([\d.]+) kg/kW", (DW % "motor_kg_kW",)),
    (r"Result: ([\d.]+) t at 15,000 ft \(180 m/s\) and ([\d.]+) t at 30,000 ft", (DC % "15kft][mass_t",
                                                                                  DC % "30kft][mass_t")),
    (r"\(17\.5/1\.85\)\^3 would weigh ([\d.]+) t", (DW % "scaled_t",)),
    (r"Scale k = 17\.5/1\.85 = ([\d.]+),", (DW % "scale",)),
    (r"fin area 0\.15 k\^2 = ([\d.]+) m\^2", (DW % "fin_area",)), (r"fin area 0\.15 k\^2 = ([\d.]+) m\^2",
                                                                  (DC % "15kft][fin_area",)),
    (r"fin position \(-1\.5, -0\.3\) k = \((-[\d.]+), (-[\d.]+)\) m", (DW % "fin_x", DW % "fin_z")),
    (r"fin position \(-1\.5, -0\.3\) k = \((-[\d.]+), (-[\d.]+)\) m", (DC % "15kft][fin_x", DC % "15kft][fin_z")),
    (r"frame drag area 0\.3 k\^2 = ([\d.]+) m\^2", (DW % "drag_area",)),
    (r"frame drag area 0\.3 k\^2 = ([\d.]+) m\^2", (DC % "15kft][drag_area",)),
    (r"\(v1 = 16/(\d+) = ([\d.e-]+) 1/s\)", (DW % "15kft][v1_den", DW % "15kft][v1")),
    (r"\(v1 = 16/\d+ = ([\d.e-]+) 1/s\)", (DC % "15kft][v1",)),
    (r"\(v1 = 23/(\d+) = ([\d.e-]+) 1/s\)", (DW % "30kft][v1_den", DW % "30kft][v1")),
    (r"\(v1 = 23/\d+ = ([\d.e-]+) 1/s\)", (DC % "30kft][v1",)),
    (r"\| \| 15,000 ft, 26 m/s, ([\d.]+) deg \| 30,000 ft, 33 m/s, ([\d.]+) deg \|",
     (DC % "15kft][collective", DC % "30kft][collective")))
ROTOR_DESIGN = Covered(  # the study above (rotor_design) and its inputs (design_data), every other number listed
    groups=("rotor_design", "design_data"),
    checks=STUDY_CHECKS + DESIGN_CHECKS + SCAN_CHECKS,
    given=(
        # the bound tests/test_craft.py's trim test asserts (it prints the trims' 12.9 % beside it)
        'the altitude is within 15 % of the design;',
        # the rating and the altitudes around the checked rated winds, required C_p and sensitivity winds
        "Our drives are rated for 3.13 MW (mass estimate), so the craft's peak equals Roberts' 3.13 MW at both "
        'altitudes, and these are its rated winds.', '30 m/s at 30,000 ft.',
        '- What moves the rated wind is anything that lets the craft fly at a larger incidence or lift more '
        '(sensitivity table, wind for 3.13 MW):',
        '# Twin 35 m rotorcraft at 15,000 ft and 30,000 ft: steady design study',
        'Roberts (sec. 6 and Table 1)',
        'sizes a twin-rotor craft with 35 m rotors for 15,000 ft and 30,000 ft and quotes a peak output of 3.13 '
        'MW at both altitudes.',
        'This note builds that craft from his data and our estimates, runs a steady-state study of its power '
        "against wind speed with the project's rotor model, and compares the result with his 3.13 MW.",
        'Given (sec. 6):',
        'twin 35 m rotors, so R = 17.5 m;',
        'the altitudes 15,000 ft (4572 m) and 30,000 ft (9144 m);',
        'tethers of 0.23 kg/m, half of it in the Kevlar tensile member and the rest in aluminium strands, "around'
        ' 10mm in diameter";',
        '95 % electrical transmission efficiency. From sec. 2 and Fig. 2:',
        'three tethers, two rear and one forward, all at the angle beta. From sec. 4:',
        'the 13 deg blade-incidence limit.',
        'Table 1 checks out against itself.',
        'the wind speed at which 3.13 MW is reached, how the rating was chosen, the rotor speed, solidity and '
        'blade data, the craft mass, the tether length and elevation, and the allowed cable stress ("an adequate '
        'and safe tensile stress").',
        'For each altitude and each wind speed V at the craft (5 to 45 m/s in 1 m/s steps)',
        'T = 288.15 K - 0.0065 K/m h, p = p0 (T/T0)^5.256, rho = p/(R T):',
        'with the blade data of (sigma 0.049, a 5.73, delta 0.01, B 0.97, gamma 8).',
        'mu = V cos(alpha_c)/(Omega R). - **Power.** P = 2 (-Q Omega)',
        '0.95 = 0.95 x 2 x C_p x 1/2 rho pi R^2 V^3 (Roberts eq. 4).',
        '- **Forces.** Per rotor, T along the shaft and H in the disk plane, resolved as in Roberts eq. 3:',
        'downwind 2 (T sin alpha_c + H cos alpha_c)',
        'plus the frame drag 1/2 rho V^2 C_D A, upwards 2 (T cos alpha_c - H sin alpha_c) - m g.',
        '- **Tethers.** Each is a heavy inextensible catenary of the config length L, with weight w = 0.23 g N/m '
        'per metre, loaded at the craft end by (H, V_t), a third of the net force.',
        '- **Blade limit.** Retreating-tip incidence <= 13 deg ( ).',
        '- **Lift.** The tethers must reach the design altitude, z >= L sin(beta), and leave their anchors '
        'upwards, V_a >= 0.',
        '3 with a positive cable angle, tether weight added). The first is stronger:',
        '- **Stress.** Top tension (the largest along a hanging cable) <= 0.5 x breaking load.',
        '- **Optimiser.** At each incidence on a 1 deg grid (1-88 deg)',
        'the best collective is found among 61 values in the 30 deg below the collective that puts the tip at the'
        ' limit.',
        'tip compressibility (the advancing-tip Mach number is below 0.86 at the design points); variable rotor '
        'speed.',
        '- **Kevlar.** 0.115 kg/m at 1440 kg/m^3 (Kevlar 49, DuPont technical guide) is 7.99e-5 m^2 of fibre.',
        'at the working strain of the Kevlar (about 1 %)',
        '- Breaking load = 3.6 GPa x 7.99e-5 m^2 x 0.67 = 193 kN, the same strength and rope efficiency as .',
        '- **Aluminium.** 0.115 kg/m at 2705 kg/m^3 is 4.25e-5 m^2. - **Diameter:',
        'No 10 mm cable can weigh 0.23 kg/m with these materials:',
        'Roberts\' "around 10 mm" must be a round figure.',
        'The file name keeps his 10 mm as the brief asks.',
        'Aramid creeps and fails under sustained load at a fraction of its short-term strength, so a design '
        'factor of 2 on the rope strength (3 on the fibre)',
        'see the 20 deg and 40 deg rows of the sensitivity table.',
        'The tip speed is chosen by scanning 160-260 m/s at the design wind, with the craft mass re-estimated for'
        ' each (the scan line of the output).',
        '- **15,000 ft: 180 m/s** (10.286 rad/s).',
        'The Mi-26, on which Roberts bases his rotor size (sec. 6, footnote;',
        '32 m rotor, 132 rpm), runs at about 221 m/s.',
        '- **Blades, hub and drive (gearbox).** The AFDD weight equations in Johnson, *NDARC Theory* '
        '(NASA/TP-2015-218751), with flap frequency 1/rev and technology factor 1: - blades:',
        'W = 0.02606 b^0.6592 R^1.3371 c^0.9959 V_tip^0.6682; - hub:',
        'W = 0.003722 b^0.2807 R^1.5377 V_tip^0.4290 W_blades^0.5505; - drive:',
        'W = 95.76 P^0.7814 N_gen^0.0990 / N_rotor^0.8069 (lb, ft, ft/s, hp, rpm; generator at 1500 rpm). - Check'
        ' against the Mi-26:',
        '0.8 kg/kW.** An industrial wind-turbine generator with a three-stage gearbox follows 6.47 P[kW]^0.9223 '
        'kg (Fingersh, Hand & Laxson, NREL/TP-500-40566, 2006), 3.6 kg/kW at 1.65 MW.',
        'The Siemens SP260D aircraft motor is 0.19 kg/kW (260 kW, 50 kg).',
        '0.8 kg/kW is about their geometric mean. - **Frame, fins and systems:',
        '30 % of the rest.** Our choice.',
        '- **Layout for the inertia.** Blades and hub at the hubs (y = +-19 m), with the blades as uniform rods '
        '(m R^2/3 about the shaft, m R^2/6 about a diameter).',
        'Drive and generator 1.5 m below each hub. Frame 3 m below the hubs:',
        '60 % as a lateral beam between the hubs, 40 % as a keel from x = -14 to +9.5 m.',
        'the Mi-26 is 28.2 t empty with one 32 m rotor, engines and a cargo fuselage.',
        'The sensitivity table shows the effect of +-30 % craft mass.',
        "- hub spacing 38 m (the model's 4.0 m for 3.7 m disks, rounded);",
        '- tether attachments (-0.5, 0.3, 0) k and (1.0, 0, 0) k.',
        'The limits of collective (-5..15 deg)',
        'and differential collective (+-5 deg) are as for the model.',
        '- **Density:** with rho0 = 1.225 kg/m^3.',
        '- **Wind:** 10 m/s at h0 = 1000 m, the top of the boundary layer;',
        'a 0.2 power law below (IEC 61400-1 normal profile);',
        'The design wind is the first whole m/s above the wind at which the study reaches 3.13 MW:',
        '26 m/s at 15,000 ft (v1 = 16/3572 = 4.479e-3 1/s)',
        'and 33 m/s at 30,000 ft (v1 = 23/8144 = 2.824e-3 1/s).',
        'The attachments therefore sit at hub height (1.25 m and 1.17 m above the CG).',
        "## Peak power against Roberts' 3.13 MW",
        "A peak in Roberts' sense must be a generator rating, as his Table 1 shows (above).",
        'The tests check the brackets 25-26 m/s and 32-33 m/s.',
        "- The craft cannot fly at Betz's C_p = 16/27.",
        '**What we cannot check.** Roberts does not give his rated wind or how he chose 3.13 MW, and we do not '
        'have the upper-wind statistics of his refs. 3-4.',
        '1), and it suggests that his craft reached 3.13 MW at lower winds than ours:',
        '- **ISA against the standard-atmosphere table.** Density at 0, 15,000 and 30,000 ft (1.225, 0.7708, '
        '0.4583 kg/m^3, 0.5 %); temperature at 30,000 ft; speed of sound.',
        '- **Cable file against its sources.** 0.23 kg/m;',
        '- **Catenary against discrete chains.** - A 20,000-link chain marched link by link from the top:',
        'the end position agrees to 1e-6.',
        "- Shooting a 400-link chain onto the catenary's ends recovers the end forces to 1e-3.",
        '- A 60-link chain of minimum potential energy (SLSQP):',
        'every joint lies on the closed-form curve to 1e-3 L, and the end links follow the tension directions.',
        '4.** It is recomputed from and , with the table density (5e-4), and from the shaft torque (1e-9).',
        '- **Limits at the reported points, recomputed independently.** - Tip incidence <= 13 deg. - (eq. 3)',
        'with the tether weight added is >= 0.',
        '- **The optimiser against a coarse search.** It beats a 1 deg x 0.25 deg grid search written in the '
        'test.',
        '- **Brackets.** 3.13 MW is reached within the stated wind brackets, and the power keeps rising to 45 '
        'm/s.',
    ),
    timings=(
        # dated on the page (2026-11-29, load 5-6)
        'the study, (20-27 s a run on the shared 2-core machine at a load of 5-6, 2026-11-29; writes and to ). - '
        ': the checks.',
        'wrote runs/rotor_design/design_study.csv and runs/rotor_design/power_curves.png (5.2 s)',
        '## Checks (tests/test_rotor_design.py, 20 tests, about 1 s)',
    ),
    derived=(
        # Roberts' Table 1 worked by hand
        '13.3 GWh / 6910 kWh/m^2 = 1925 m^2 = 2 pi 17.5^2, the disk area of two 35 m rotors.',
        "3.13 MW x 8760 h x 0.48 = 13.2 GWh and x 0.67 = 18.4 GWh, the table's 13.3 and 18.2 GWh.",
        '- **The 95 % efficiency is plausible.** The aluminium has 6.7e-4 ohm/m (2.83e-8 ohm m).',
        'Three-phase over the three conductors, 5 % loss at 3.3 MW needs about 20 kV on 9.1 km and 28 kV on 18.3 '
        'km of tether.',
        'That is 2.1 t and 4.2 t per tether, and at 30,000 ft the three tethers together weigh as much as the '
        'craft.',
        'the drive equation gives about 4.7 t for its VR-26 gearbox (19,725 hp at 132 rpm, input speed 8,300 rpm '
        'assumed), against the actual 3,639 kg.',
        'The product of inertia Jxz (-4.4e3 kg m^2, 0.1 % of Jxx) is set to 0.',
        'Tethers of 9 and 18 km have little pitch stiffness:',
        'about EA/L x (14 m)^2, of order 0.2 MN m/rad.',
        'We therefore cannot say whether rated winds of 25.6 m/s and 32.5 m/s fit his capacity factors of 48 % '
        'and 67 %.',
        'With our craft that needs winds above about 25 m/s at 15,000 ft and about 32 m/s at 30,000 ft for much '
        'of the time.',
        # craft_trim_tests prints the 15,000 ft craft's trim at 5160 m, +588 m from the design 4572 m: the page's
        # 590 is 5160 - 4572 = 588 rounded to two figures (15,000 ft: the config's name)
        'The 15,000 ft craft trims 590 m above the design altitude,',
    ),
    printed=(  # the page group rotor_design's whole output (docsite.printed_numbers: each number printed)
        Printed("rotor_design", (
            '**No limit caps the power inside 5-45 m/s.** The power rises to the top of the range:',
            '- At 15,000 ft the tethers reach their allowed tension at 22 m/s (1.96 MW).',
            '- At 30,000 ft the blade limit and the lift bind throughout.',
            '**Why 3.13 MW needs such strong winds.**',
            'Its disk must stay inclined only about 30-35 deg to the wind to lift itself and the tethers on 30 deg '
            'cables.',
            '24.4 m/s at 15,000 ft (no change at 30,000 ft).',
            "- Roberts' other solidity reading, sigma = 0.075 ( ), is worse: 26.6 / 33.8 m/s.",
            'and the craft needs a 230 m/s tip speed to stay up at all.',
            # the study's P at the design winds: its rows 26 m/s (3.238 MW, 15,000 ft) and 33 m/s (3.257 MW, 30,000
            # ft), seven rows apart, so one snippet each (were not_rerun)
            "study's optimum at the design wind [MW] | 3.24", '3.26 | | tether tension')),
        # tests/test_craft.py -s -k 35m_crafts_trim prints each craft's trim beside what it asserts (altitude within
        # 15 % of the design, C_p below the ideal at the trimmed incidence): 5160 / 8669 m, 26.46 / 29.84 deg,
        # 2.566 / 3.011 MW, 28.63 m/s at the 15,000 ft craft (were not_rerun: no command printed them)
        Printed("craft_trim_tests", (
            'craft altitude [m] | 5160 | 8669',
            'pitch = incidence [deg] | 26.5 | 29.8',
            'electrical power [MW] | 2.57 | 3.01',
            'where it meets 28.6 m/s.',
            # and each tether's tension at the craft, printed beside them (not asserted): 71.88 / 71.88 / 71.01 kN
            # (rear right, rear left, front) at the 15,000 ft craft, 85.33 / 85.33 / 85.38 kN at the 30,000 ft
            # one (was not_rerun: a Python session's)
            'tether tension at the craft [kN] | 72 | 85')),
    ),
    history=(
        History("2026-11-29", "laddermill_gym.rotorcraft.trim of the 35 m craft configs with the tether attachments at "
                "CG height", "a trial of the craft configs before the attachments were moved (c0907b8)", (
                    "with the attachments at CG height, the rotors' 100 kN m pitch-up moment at the design pose left "
                    'no equilibrium near it, and the trim did not converge.',)),
    ),
)
