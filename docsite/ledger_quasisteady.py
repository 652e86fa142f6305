"""The ledger entry (:mod:`docsite.page_ledger`) of docs/quasisteady.md: Tables 1-2, the capacity table, the Cabauw
coverage and the f <= 1/2 means and peaks checked against ``laddermill site`` (35-85 s); the models' equations and
the paper's figures given; the sweeps, the f <= 1/3 means and the hourly set's clipped hours Printed by
``site_sweeps`` (its whole output); the page's timing table dated 2026-11-24 (git log)."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, Printed
from docsite.ledger_papers import QUASISTEADY_CHECKS

QUASISTEADY = Covered(
    groups=("site_tables", "site_sweeps"),
    checks=QUASISTEADY_CHECKS,
    given=(
        '# Quasi-steady pumping power and site optimisation (Lansdorp et al. 2008)',
        'Lansdorp, Ruiterkamp, Williams & Ockels (2008), *Long-term laddermill modeling for site selection*, size'
        ' a pumping kite system (one kite pulls a cable off a drum, then it is reeled back in at low tension) for'
        " a site's wind history.",
        '1-15, vectorised over wind states (plain numpy). - :',
        'the quasi-steady model of Schmehl et al. (2013) and van der Vlugt et al. (2019).',
        '16-20), the sweeps, and the fixed design run through the data. - , : the tables and figures ( ). - :',
        "## Lansdorp's model (eqs. 1-15)",
        "Fig. 14's altitudes are the paper's 200-600 m in 50 m steps",  # the paper's grid (cli.PAPER_FIG14_HEIGHTS)
        '1, 8 | effective wind w_e = w sin(theta)',
        '- v_out (the wind component along the cable, less the reel-out speed; floored at 0);',
        '6 | cable drag lumped at the kite:',
        "1/4 of the cable's drag, as a kite drag coefficient d L C_Dc / (4 S)",
        '| 7 | system glide ratio G = C_L / (C_D + d L C_Dc / (4 S))',
        '| 9 | T = 1/2 rho C_L S G^2 (1 + 1/G^2)^(3/2)',
        'w_e^2 = 1/2 rho S (C_L^2 + C_Dt^2)^(3/2)',
        '/ C_Dt^2 w_e^2 (the second form stays finite at C_L = 0)',
        '| 10-14 | P = T v_out, P_r = T_r v_in, t_c = dL/v_out + dL/v_in, E = eta T dL - T_r dL / eta, P_useful ='
        ' E / t_c',
        '15 | F_max = sigma_ut / F_s pi d^2 / 4',
        'The paper says (after eq. 9)',
        "This is the same as Loyd's crosswind kite at elevation 90 deg - theta.",
        "/ 3 is exactly the massless zeta_max of Schmehl's model (a test checks this).",
        'The paper fixes v_out at "1/3 of the wind speed", that is w / 3 and not w sin(theta) / 3.',
        'Two limits of eqs. 12-14:',
        '- A reel-in speed of 0 never ends the cycle, so the power is 0.',
        '- **Traction.** The kite is at elevation beta = 90 deg - theta and azimuth phi. It flies course angles '
        'chi.',
        'The tangential velocity factor is lambda = a + sqrt(a^2 + b^2 - 1 + kappa^2 (b - f)^2), with a = '
        '-sin(beta) cos(phi) cos(chi) - sin(phi) sin(chi) and b = cos(beta) cos(phi) (Schmehl et al. 2013).',
        'The kinematic ratio kappa comes from the tangential force balance with the weight: (E - kappa) sqrt(1 + '
        'kappa^2) = m g cos(beta) cos(chi)',
        '/ (1/2 rho S C_D v_w^2 (b - f)^2).',
        'The tether force is F_t = D (E kappa + 1) / sqrt(1 + kappa^2) - m g sin(beta).',
        '- **Retraction.** The kite is reeled in at a fixed elevation (60 deg by default).',
        'It is depowered to the C_L on the polar C_D = 0.03 + 0.04 C_L^2 that balances its weight across the '
        'tether.',
        'The mass is the kite, at 0.6 kg/m^2 (our assumption, about that of a leading-edge-inflatable kite with '
        'its control unit), plus half of the tether mass.',
        'The traction phase flies a loop of 8 course angles at phi = 0, even in chi.',
        'it, 1/lambda (our derivation).',
        'With weight, the reel-out power stays below the massless zeta_max at every wind.',
        'Until 2026-12-07 the model averaged the 8 courses with equal weights, and a course the kite could not fly '
        'counted as zero tension.',
        'the kite, at 0.6 kg/m^2 with half its tether, cannot climb through the top of its loop.',
        'prints the ratios): for the Table 2 design at Cabauw,',
        '/ 3 optimum and the zeta_max value are found by a scalar optimiser.',
        '## Site optimisation (eqs. 16-20)',
        'T_i = c_i g(C_L), with c_i = rho S w_e,i^2 / 2.',
        "So choosing the C_L's is choosing the tensions T_i in [T(C_L = 0), min(T(C_L,max), F_max)]. Maximising P"
        ' / (T + k1 S) (eq. 16) or P / (T S d m_c) (eq. 20)',
        'C_L,i follows from a tabulated inverse of g, which is monotone for both drag laws up to C_L = 1.2 '
        '(checked at run time).',
        'The four design variables are solved by SLSQP with finite-difference gradients, from 8 starting points.',
        'Each starting point has its kite area set by bisection so that the start is feasible. The constraints '
        'are eqs. 18-19; eq.',
        '17 holds inside the inner problem.',
        'A state where even C_L = 0 would overload the cable has its kite landed (no power, no tension).',
        '9 written out in the test, with the cap of eq. 15;',
        'every C_L a variable, SLSQP on , 8 days.',
        '- **"G = 16" in design 1.** We read this as the kite\'s own L/D (C_D = C_L / 16). The system glide ratio '
        'of eq.',
        '7 still carries the cable drag.',
        "The paper's altitude and angle sensitivity (Fig. 14)",
        '16 is not given.** We use k1 = 1000 N/m^2.',
        'k1 = 100 N/m^2 gives a larger kite flown at lower C_L ( ).',
        '- **Design 2 ("re-optimised with a slightly different cost").** Eq.',
        '20 with P >= 1 MW, theta >= 57 deg, and the polar C_D = 0.03 + 0.04 C_L^2 (kite only;',
        'the cable drag is added by eq. 7). - **Cable mass in eq.',
        '20.** Solid Dyneema, 970 kg/m^3.',
        "For the hourly data we average each day's 24 profiles. Figs.",
        '19-20 and the capacity factor run the design through the hourly profiles.',
        "The reeled 200 m changes the drag by up to 40 % of L, which the paper's model ignores too. - **Reel "
        'length.** In eqs.',
        '12-14, Delta L cancels from P_useful = E / t_c. It acts only through eq.',
        "18 (L >= 2.5 Delta L), as in the paper's Fig. 17.",
        'The shapes are 1 at 100 m.',
        'The speed is linear between 10 m and 80 m.',
        'It is extrapolated to 600 m only.',
        # the limited exponent's two calm cases (tests/test_site_wind.py checks the first against the closed form)
        'An hour calm at 10 m under wind at 80 m has an unbounded exponent and takes the upper limit, 0.6;',
        'an hour calm at both heights takes 0 (its speeds are 0 anyway).',
        'frequencies that add up to more than 100 %,',
        'For the 2010 data these are',
        "Averaging lowers the power's measure: on the 2010 data",
        "with the 2010 set extrapolated higher, design 1 climbs with it.",
        'Every output that uses heights above 80 m says so.',
        'Above 2000 distinct heights (years of soundings) they are resampled every 5 m.',
        '2020, 8 clusters x 100 bins, 10-600 m. - :',
        'windpowerlib example weather, hourly, 10 and 80 m. - : the same as daily means.',
        "## Results on the shipped data beside the paper's (De Bilt soundings 1998-2007)",
        '**Table 1** (eq.',
        '16, P = 1 MW, theta 45-80 deg, kite L/D 16):',
        'parameter | paper | 2010 daily (extrapolated)',
        '**Table 2** (eq.',
        '20, P >= 1 MW, theta >= 57 deg, polar):',
        'parameter | paper | 2010 daily (extrapolated)',
        '- **Different data.** We have no De Bilt soundings, and the 2010 set is measured only up to 80 m.',
        'Real soundings flatten above the boundary layer, and there the shortest cable (L = 2.5 Delta L = 500 m) '
        'wins, as in the paper:',
        "- **The kite-area weight.** Design 1's mean C_L of 0.5 in the paper (a large kite flown mostly "
        'depowered)',
        '- **Design 2 is close to the paper.** Its optimum is a ratio with no weight to choose.',
        "With 1 year of data, our design 2 lands near the paper's:",
        '- **Optimum altitudes at data heights.** Altitudes such as 220, 250 and 300 m are heights of the Cabauw '
        'grid.',
        '### Figs. 19-20:',
        'For the Table 2 design run through the hourly 2010 data:',
        'As in the paper, this is "close" to but below 1 MW.',
        '- f <= 1/2 gives 1.07 MW, with peaks of 2.3 MW (the paper: 1 MW, peaks of 3.5 MW).',
        'On Cabauw the two bounds give 1.01 and 1.16 MW.',
        '![Figs. 10-13 for design 2 at Cabauw]',
        '### Fig. 14 and the sweeps (Figs. 15-18)',
        'Each point is a full re-optimisation on a subset of about 130 states, as the paper did to save time.',
        '- Power per cost falls linearly with the retrieval tension fraction (Fig. 18).',
        '- Power per cost falls when more cable is reeled (Fig. 17:',
        'the kite climbs once L = 2.5 Delta L binds).',
        '- Power per cost falls as the reel-in speed drops (Fig. 16).',
        '- It falls as the kite L/D drops (Fig. 15).',
        '![Fig. 14 at Cabauw]',
        '![Lansdorp vs Schmehl model for the Table 2 design]',
        'The turbine hub is at 80 m, the top of the measured 2010 data ( ).',
        'The paper claims a capacity factor above 50 % against 22 % for turbines.',
        'This rests on the extrapolated wind at 400 m against a measured 80 m hub, and on a peak-sized generator.',
        'A laddermill rated at its mean design power would have a capacity factor near 100 %, and so would be '
        'meaningless to compare.',
        '![capacity factor, 2010 data]',
    ),
    timings=(
        # the page's own timing table (python -m laddermill_gym.quasisteady.timing, median of 5 on the shared 2-core
        # machine, 2026-12-07 22:13, znver4: 2.59 s, 13573 solves, 0.191 ms; 2.33 s, 11457, 0.203 ms; at 03:37 on
        # another machine: 1.24 s, 9786, 0.127 ms; 0.57 s, 4193, 0.135 ms); the hourly runs 2026-11-24
        '**Timing.** One year of daily states (365)',
        'on the shipped 2010 data, median of 5 runs on the shared 2-core development machine (2026-12-07 22:13, load',
        '0.8;',
        'Table 1 (eq. 16)',
        '2.59 | 13573 | 0.19',
        'Table 2 (eq. 20)',
        '2.33 | 11457 | 0.20',
        'The same code printed 9786 and 4193 inner solves (1.24 and 0.57 s) at 03:37 that day on another machine',
        'the number of solves, moves with the last bits of the machine\'s arithmetic (numpy\'s SIMD loops and',
        'With every hour a state of its own (8760 C_L variables), one run of each case took 11 s (Table 1) and '
        '16 s (Table 2) on the same machine (2026-11-24).',
        'The command (prints the median of 5 runs per case):',
    ),
    derived=(
        # read off the sweeps' and the models' figures (figs15-18_*.png, models_*.png) or worked from the checked
        # coverage (100 % less the bins' share); k1 = 100 is the sweep's input
        'C_L 1.05-1.08 against 1.01, d 29-38 mm against 32 mm, S 196-227 m^2 against 169 m^2, and the angle at '
        'its 57 deg bound for the 2010 data.',
        'Time outside the data (43.4 % for the Cabauw bins)',
        'With k1 = 100 N/m^2 our kite grows and its mean C_L falls.',
        '- The kite area has its minimum near a 60-65 deg cable angle, which the paper also found ("an optimal kite '
        'area in the region of 60 deg").',
        "Here it falls by 43 % for L/D 16 -> 5, more than the paper's 3 %, because our k1 charges more for the 3x "
        'larger kite.',
        'There the rating is set by rare strong-wind states (peak 4.3 MW for a 1.16 MW mean), and the 43 % of the '
        'time outside the bins counts',
        # the bins' range per cluster (configs/wind/cabauw_8clusters_frequency.csv: lowest bin 5.69-5.94 m/s, highest
        # 14.77-20.02 m/s at 100 m); a turbine's usual cut-in and cut-out; the paper's density against the ISA
        # troposphere, rho = 1.225 (1 - 2.25577e-5 h)^4.2559: 1.1786 at 400 m, 1.1560 at 600 m, ratios 1.039 and 1.060
        'That time is wind at 100 m below each cluster\'s cut-in (5.7-5.9 m/s) or above its cut-out (14.8-20 m/s). A '
        'turbine at '
        '80 m makes power from about 3 m/s and up to 25 m/s, so this biases the turbine\'s capacity factor low. The '
        "kite's air is the paper's 1.225 kg/m^3 at every altitude; the standard atmosphere's at 400-600 m is "
        '1.18-1.16 kg/m^3, so the comparison favours the kite by about 4-6 %.',
        # the paper's Fig. 13 read off, and the design's area
        "At the paper's Table 1 design, the mean tension (about 0.8 x 443 kN, from Fig. 13) and k1 S (312 m^2) "
        'are then of the same size. The choice moves the optimum:',
        # 1 MW over the share of time in the data
        'A 1 MW time mean therefore needs about 1.8 MW while operating, which calls for a thicker cable.',
        # the literal formulation's tolerance, rel=5e-3 in tests/test_site_optimisation.py
        # (test_whole_problem_matches_the_literal_formulation); no command prints it
        'Our optimum equals or beats it to 0.5 %;',
    ),
    printed=(  # the page group site_sweeps's whole output (laddermill site --sweeps)
        # "Our optimum equals or beats it to 0.5 %" was Printed here until 2026-11-30, matched by chance (the table's
        # "Average kite C_L | - | 0.50" read as a percent); it is the test's tolerance, given above
        Printed('site_sweeps', (
            'Its power-law extrapolation keeps the wind growing with height, so design 1 climbs to the top of the '
            'allowed range (600 m).',
            # two snippets: Table 1's paper column and Table 2's lie more than 60 printed numbers apart
            'its h = 353.6 m at 45 deg and',
            'h = 272.3 m at 57 deg are both L = 500 m.',
            'On the Cabauw profiles the shortest cable is active for design 2 (L = 500 m)',
            'and nearly so for design 1 (L = 560 m).',
            'On the 2010 data our laddermill comes close: 46.7 % against 16.8 %.',
            # laddermill site prints, per case, its design's run through the hourly data (figs. 19-20) with the
            # hourly set's SiteWind.notes: 'table2 design run through weather2010 (figs. 19-20): f <= 1/3 mean 0.972
            # MW, f <= 1/2 mean 1.074 MW; exponent limited to (0.0, 0.6) in 247 of 8760 hours' (2026-11-30; were
            # not_rerun: the figure drew the mean, the notes were printed only where no extrapolation note replaced
            # them)
            '- f <= 1/3 gives a mean of 0.97 MW.',
            # the data line: 'daily means: the time mean of w^3 at 80 m is 0.917 of the 8760 states' ...' (2026-12-07)
            "the daily means' time mean of w^3 at 80 m is 0.917 of the hourly data's",
            # the tables' row "On a bound of the search" (2026-12-07): 'h = 600 m: the upper bound, the top of the
            # data (every state has data up to 600 m)' and 'theta = 57 deg: the lower bound, the case's theta_bounds'
            "design 1's altitude, 600 m, the top of the data, and design 2's angle, 57 deg, the case's lower bound.",
            'On Cabauw their bars add up to the 56.6 % that the bins cover,',
            "Above 80 m it follows a power law whose exponent comes from each hour's two speeds, clipped to [0, 0.6] "
            '(247 of 8760 hours).',
        )),
    ),
)
