"""The ledger entry (:mod:`docsite.page_ledger`) of docs/reeling_tether.md: the element-count convergence table
checked against ``tether_convergence`` (2-5 minutes); the model's rules and settings given; its closed forms
derived; the reeling power curve and its phase split checked against ``power_curve --reel-element-length 40``
(``reeling_power_curve``, 211 s at a load of 8); the 200-500 m runs, the model comparison and the tests' figures not
re-run (their commands named)."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, History, Printed
from docsite.ledger_papers import REELING_CHECKS
from docsite.ledger_pumping import curve_checks

WINDS = (8, 10, 12, 14, 16, 18, 20)
#: python -m laddermill_gym.studies.pumping.power_curve --reel-element-length 40 (about 6 minutes at a load of 7):
#: its power curve and its loss split, as printed.
CURVE_CHECKS = curve_checks("reeling_power_curve", WINDS) + tuple(
    (rf"\| {v} \| (-?\d+) \| (-?\d+) \| (-?\d+) \| (-?\d+) \| (\d+) / (\d+) \|",
     tuple(f"{{reeling_power_curve[v{v}][{k}]}}" for k in ("out", "in", "within", "transitions", "T_in", "model_T_in")))
    for v in WINDS)
#: the page's ratios and ranges of the reeling power curve's printed columns and of the reeling cycle's third cycle
#: (docsite/printed_ratios.py, compared by --long reeling_power_curve_printed / reeling_cycle_40; until 2026-11-30
#: derived entries): sim / matched >= 0.7 at 10-20 m/s; T_out / matched T_out 0.781-0.850; wing / drum within 1.24 %;
#: the aerodynamic force over the wing's tension 6.2-6.8 % above, over the model's 0.844-0.905
RC = "reeling_power_curve_printed"
RATIO_CHECKS = (
    (r"\*\*Within 30 % at (\d+) to (\d+) m/s\*\*", (f"{{{RC}[within30][lo]}}", f"{{{RC}[within30][hi]}}")),
    (r"on the third cycle: (\d\.\d+), where the single element gives", ("~{reeling_cycle_40[last_ratio]}",)),
    (r"is the largest share: (\d\.\d+)-(\d\.\d+) of the model's", (f"~{{{RC}[tension_model][lo]}}",
                                                                    f"~{{{RC}[tension_model][hi]}}")),
    (r"the drum and the wing feel the same tension within (\d+\.\d+) %", (f"~{{{RC}[wing_drum_pct]}}",)),
    (r"1/2 rho S C_R <v_a\^2> at the mean alpha's C_R, is (\d+)-(\d+) % above the tension at the wing",
     (f"~{{{RC}[aero_above_pct][lo]}}", f"~{{{RC}[aero_above_pct][hi]}}")),
    *((rf"{head} (\d\.\d+)-(\d\.\d+) of the model's{tail}", (f"~{{{RC}[aero_model][lo]}}",
                                                                f"~{{{RC}[aero_model][hi]}}"))
      for head, tail in (("and it is itself", r" tension \(10 m/s:"), ("a mean squared airspeed of", ""))),
)

REELING = Covered(
    groups=("tether_convergence", "reeling_power_curve"),
    checks=REELING_CHECKS + CURVE_CHECKS + RATIO_CHECKS,
    given=(
        # the element count of the tether's first version (78cc615, 2026-11-29), which stopped near that time
        '(where the 3-element chain used to stop;',
        # the static cycle's tether: the 300 m start and Delta L 200 m (configs/pumping/pumping_kite_reeling.yaml);
        # the re-run's date
        'the static wing holds up little of 300-500 m of tether,',
        'which lies on the ground near the winch; , re-run 2026-11-30;',
        '3. **Within the phases** (eqs.',  # a list's number
        '(Re-run 2026-11-30; as first written on',  # the re-run's date
        "the 40 m elements' weight and drag take almost nothing of it in crosswind flight);",  # the element length
        '# The reeling tether of the pumping kite (issue 29 point 2)',
        'the tether is a chain of elements of nominal length l_n = 40 m that are paid out from the drum and taken'
        ' back onto it as the winch reels ( , the kind ;',
        'a fixed number of nodes, a count in the air.** The assembly has the nodes of the longest tether ( = 560 '
        'm in 40 m elements: 14 elements, 13 nodes);',
        'element e joins node e - 1 (the ground point for e = 0)',
        'With a nodes in the air, nodes 0 .. k - 1 (k = n - a) lie on the drum:',
        "rest length l_d = l_p + s - m l_n (l_p its start length, s the tether paid out, the winch's state as "
        'before, m the nodes paid out since t = 0, );',
        "the drum feels its tension (reported in element slot 0, so the envs' drum tension needs no index).",
        '- *split* when l_d reaches 1.75 l_n and a node is left on the drum:',
        "node k - 1 leaves the drum onto the drum element's chord at the unstretched distance l_d - l_n from the "
        'ground (fraction f = (l_d - l_n)',
        'and the momentum of the consistent mass (sum of mu l (v_r + v_s) / 2) do not change.',
        '- *merge* when l_d falls below 0.5 l_n and two nodes or more are in the air:',
        "node k goes onto the drum and node k + 1 takes v' = ((l_d + l_a) v_k + (l_a + l_b) v_{k+1}) / (l_d + l_a"
        ' + l_b)',
        '- The drum element stays in [0.5, 1.75] l_n:',
        '0.5 after a merge is 1.5, 1.75 after a split is 0.75, so a split is not undone until 0.25 l_n = 10 m '
        'more have been reeled.',
        "A drum element of 0.25 l_n (a first version) is the chain's stiffest part:",
        '**The time step.** A taut chain of elements of length l with consistent mass has its highest axial mode '
        'at omega_max = (2 / l) sqrt(3 EA / mu)',
        'stiffness 4 EA / l against mass mu l / 3):',
        'A first version (5 ms, the drum element down to 0.25 l_n;',
        'picks the largest of 5, 2.5, 2, 1, 0.5 ms with omega_max dt <= 2:',
        '2.5 ms at 40 and 60 m, 2 ms at 30 m, 5 ms at 100 m; the config sets .',
        'in crosswind flight at 50 kN the full EA / l acts.)',
        "feels a normal force F_n = max(0, m_j (omega^2 d + 2 zeta omega d'))",
        '(d the depth, m_j = mu (l_below + l_above) / 2 its lumped mass)',
        'and a friction force mu_f F_n against its sliding velocity, viscous below 0.1 m/s.',
        'omega dt = 0.05 at 2.5 ms), zeta = 1 (no bounce), mu_f = 0.5 (assumed:',
        'rope on grass or soil, 0.3-0.7; not measured).',
        "with the nodes in the air on the elastic catenary of the tether from the drum to the wing's attachment "
        '(Irvine 1981, "Cable Structures", eqs. 2.24-2.25; )',
        'on the single element and on reeling tethers of l_n = 100, 60, 40 and 30 m (3, 5, 7.5 and 10 elements at'
        ' the 300 m start), the third cycle:',
        'l_n [m] | RK4 step [ms] | 300 m / l_n | elements over the run | net electrical mean power [W] | reel-out'
        ' tension [N] | reel-out speed [m/s] | reel-in tension [N] | cycle [s] | alpha [deg] | nodes on the '
        'ground',
        "the scene's tether 200 m at t = 0, the crosswind controller's Delta L 300 m):",
        'paying out at 2 m/s puts nodes into the air at floor((l_p + s - 1.75 l_n) / l_n)',
        "+ 1 with s the winch's closed form (a rate of V / l_n), and the lowest node meets the ground without a "
        'stop;',
        'on the same 3-element chain over 2 s of reel-out (1e-12);',
        'the catenary solver against the inextensible catenary (sqrt(L^2 - h^2) = 2 a sinh(D / 2a))',
        "and against Irvine's two elastic catenaries of the oracles (H, V to 1e-6);",
        "keep the single element (a reeling tether is a new id's business, with its 2.5 ms step, about 2.5 times "
        'the cost); the in-plane (2D)',
        '## Power curve on the reeling tether (issue 29 point 3)',
        "the same cycle on the reeling multi-element tether ( , 40 m elements), against Schmehl's model at the "
        "simulated cycle's own operating point (same wing, wind profile, elevation, reeled length, reel-out "
        "factor and reel-in speed, as [the pumping page's single-element curve]):",
        "10-14 at the simulated reel-out speed, reeled length and reel-in speed, fed the model's reel-out and "
        'reel-in tensions, then the simulated reel-out tension, then both simulated tensions;',
        "the slow test also checks each cycle's mean reel-out mechanical power against (4/27)",
        "1/2 rho S C_L (C_L / C_D)^2 w^3 at the cycle's reel-out wind and alpha;",
        'the fast checks 40 s of figure eights on the single element.',
        '1. **The reel-out tension**',
    ),
    timings=(
        # the studies' durations as the page gives them (2026-11-29)
        'about 2 minutes on a 2-core machine at a load of 2):',
        'measured 2026-11-29, 1 min 53 s;',
        '**From 200 m to 500 m and back.** (2.5 minutes;',
        '(about 6 minutes on the shared 2-core machine at a load of 7):',
    ),
    derived=(
        # 1 - t_cycle / schmehl_matched_cycle_s over the rows of --long reeling_power_curve_printed's JSON (8-20 m/s):
        # 1 - 249.95 / 263.80 = 5.3 % at 8 m/s ... 1 - 142.85 / 148.66 = 3.9 % at 20 m/s
        '4-5 % shorter,',
        # closed forms worked from the page's inputs, or from the checked table
        'the node above it oscillates at sqrt(3 EA / (mu l_d l_n)) = 735 rad/s at 10 m of 40 m.',
        '735 rad/s at 40 m of the 25 mm tether (EA 2.16e7 N, 0.3 kg/m).',
        "The scene's RK4 step of 5 ms gives omega_max dt = 3.7, beyond RK4's 2.83 on the imaginary axis.",
        'omega = 20 rad/s (a node resting under its weight sinks g / omega^2 = 2.5 cm;',
        '44787, 45582, 45719, 45880 W (steps of 795, 137 and 161 W as l_n goes 100 -> 60 -> 40 -> 30 m;',
        '40 m is within 0.4 % of 30 m, and the last step is not smaller than the one before, so the count has not'
        ' converged to better than that;',
        'The single element is 31 % below:',
        'lower reel-out tension (47.6 against 53.9 kN)',
        'and a longer cycle (276 against 219 s;',
        "The static cycle's 1.9 kW on the single element ([the pumping page])",
    ),
    printed=(  # long groups: python -m docsite.readme_figures --long NAME (docsite/long_figures.py)
        # the static LQR cycle on the reeling tether: pumping-cycle's table prints each cycle's sim W (-4631, -2487)
        # and mean reel-out tension (131, 346 N) (were not_rerun: a Python session's; its -2488 W is History)
        Printed('reeling_lqr_cycle', (
            '-4631 W and -2487 W over its first two cycles (reel-out tension 131 and 346 N:',
            # its ground-contact line (pumping-cycle prints it for a reeling tether since 2026-12-01; until then
            # not_rerun, a Python session's of 2026-11-29 that put the first contact "in the first reel-in"): "up to
            # 4 nodes on the ground at once, in 32.7 % of the 9440 control steps; the first at t = 173.45 s, 5.05 s
            # into the reel_out phase of cycle 2"
            'up to 4 nodes on the ground at once, in 33 % of the control steps, the first at t = 173.45 s, 5.05 s '
            'into the second reel-out, just after the first reel-in',)),
        # tests/test_reel_tether.py prints the two cases' errors beside its assertion
        Printed("reel_tether_tests", (
            'a hanging tether of 5 and 10 sag-corrected elements between two fixed points against the elastic '
            'catenary (horizontal tension within 0.67 % and 0.99 % at 5 elements, 0.17 % and 0.26 % at 10: second '
            "order); the stable step's omega_max; bad fields named.",)),
        Printed('reeling_cycle_40', (
            'Against Schmehl\'s model at the simulated operating point (docs/pumping.md, "Power curve"), prints '
            '45719 W simulated against 56746 W matched on the third cycle:',
        )),
        Printed('pumping_power_curve_printed', (  # the single element's sim / matched at 10 m/s
            '0.68 at this wind (10 m/s).', "The single element's 0.68 at 10 m/s",
        )),
        Printed('tether_200', (
            'the tether between 193 and 521 m, **5 to 13 elements of 40 m at every length**, 49058 W on the third '
            'cycle (the single 200 m element: 33881 W); no node touched the ground.',
        )),
        Printed('reeling_power_curve_printed', (
            'becomes 0.81 on the reeling tether:',
            ', slow, checks 10, 12 and 14 m/s).',
            '(wing / drum 0.999-1.012:',
            '56256 against 61585 N),',
            "Which of the course's parts takes how much is not yet measured. 2. **The reel-in tension**:",
            "the hang near the zenith pulls 4.4-16.7 kN while the model's depowered kite at the simulated reel-in "
            'elevation pulls 0-5.0 kN.',
            '10-14 on the simulated means less the simulated power)',
            "and **the model's transitions** (its cycle time's transition phases, which the simulated cycle,",
            'does not spend)',
            "are smaller and of the other sign: they favour the simulation. 4. **Loyd's bound**:",
        )),
    ),
    history=(
        History('2026-12-07', "a review's scripts: the crosswind cycle on the reeling tether through its splits and "
                "merges (s4_cycle_switch.py, s5_split_transient.py, s6_merge.py) and a 100 m start reeled in at 5 m/s "
                "at 2.5 and 1 ms (s7_short_drum.py)", 'the relabelling transients and the last element (4ddc82a)',
                ('in crosswind reel-out at 2.95 m/s the drum tension fell by 1.2 kN (1.5 % to 4.5 %) at every split '
                 'and rang for about 0.1 s, some 90 J per split against 11 MJ per reel-out.',
                 'the drum tension fell by 15 % to 16 % at every reel-in merge and was back within 30 ms.',
                 "0.5 l_n to the end stop at 0.05 l_n, and at 2.5 ms its mode passes RK4's limit below about 4.2 m of "
                 '40 m elements (the drum tension rang between 15 N and 6 kN from 3.4 m on; at 1 ms it held within '
                 "1192 to 1197 N: the same review's run of 2026-12-07, a 100 m start reeled in at 5 m/s).")),
        History('2026-11-29', 'python -m laddermill_gym.studies.pumping.tether_convergence --start-length 200 '
                '--lengths 200 40', 'the 200-500 m run as first written (78cc615), before the crosswind controller '
                'changed (0db432c, e1ce3ac)', ('bisected: 191-521 m, 49982 W and 34567 W.)',)),
        History('2026-11-29', 'PumpingTask(config="pumping_kite_reeling") and PumpingCycleController with the lateral '
                'LQR in a Python session, three cycles (df64aed)', 'the static LQR cycle on the reeling tether as '
                'first written (re-run 2026-11-30 by reeling_lqr_cycle: -2487 W)',
                ('-2488 W in the session of 2026-11-29)',)),
        History('2026-11-29', 'laddermill pumping-cycle --reel-element-length 40 --cycles 2 at 1cc497c and before '
                '0db432c',
                'runs of earlier code (a first version of the reeling tether; the crosswind controller before '
                '0db432c)', (
            'did not stop at 40 m but flew a different cycle (14.8 kW, alpha 6.2 deg, against 45.7 kW now) and '
            'failed at 30 m.',
            "an earlier run, before the crosswind controller's change of 0db432c, printed 44575 / 45515 / 45672 / "
            '45745 W).',
        )),
    ),
)
