"""The ledger entries (:mod:`docsite.page_ledger`) of the guide pages: index, about the docs, getting started,
the model, scale-out, rl-zoo3."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, History

INDEX = Covered(given=("Schwab (1999)", "Schwab 1999", "Figs. 6-8", "Ockels 2007", "5 km string at 1 cm",
                       "Lansdorp et al. 2008", "his Fig. 3, eq. (6), the 35 m design", "after its 0.01 rad"))
ABOUT_DOCS = Covered(given=("MkDocs 1.6)", "MkDocs 1.6.1 (2024) is the last 1.x release", "May 2027", "MkDocs 1.x"),
                     timings=("about 1.5-3 minutes here",))

DEMO_ROW = r"{} +(\S+) +(\S+) +(\S+) +{}"
GETTING_STARTED = Covered(
    groups=("main_job", "simulate_laddermill", "simulate_tethered_wing"),
    checks=((DEMO_ROW.format("open_loop", r"(aerodynamic range exceeded: t = [\d.]+ s: slot \d+ alpha = [-\d.]+ deg, "
                                          r"beta = [-\d.]+ deg outside the aerodynamic range)"),
             tuple(f"{{main_job[open_loop][{i}]}}" for i in range(4))),
            (DEMO_ROW.format("lqr", "(ran to the end)"), tuple(f"{{main_job[lqr][{i}]}}" for i in range(4))),
            (DEMO_ROW.format("ppo_mill", "(ran to the end)"), tuple(f"{{main_job[ppo_mill][{i}]}}" for i in range(4))),
            (r"\((\d+\.\d+) s simulated, the step at 1 s\)", ("{simulate_laddermill[simulated]}",)),
            # the span less the step's 1 s (until 2026-11-30 derived entries)
            (r"the run stops about (\d+) s after the step \(", ("~{simulate_laddermill[after_1s]}",)),
            (r"last state before the run stops, about (\d+) s after a 0\.01 rad",
             ("~{simulate_laddermill[after_1s]}",)),
            (r"wings (\d+)-(\d+) beyond the (\d+) m/s speed guard",
             ("{simulate_laddermill[first_wing]}", "{simulate_laddermill[last_wing]}", "{simulate_laddermill[guard]}")),
            (r"at the start \((0\.\d{4}) s, above the scene's (0\.\d+) s\)",
             ("{simulate_laddermill[stable_step]:.4f}", "{simulate_laddermill[dt]}")),
            (r"The run stops at ([\d.]+) s, when", ("{simulate_tethered_wing[contact_t]}",)),
            (r"ground contact at t = ([\d.]+) s: node (\d+) at height ([-\d.e]+) m",
             tuple(f"{{simulate_tethered_wing[contact_{k}]}}" for k in ("t", "node", "height")))),
    given=("at V_c = 2 m/s", "the paper's 0.01 rad wind-direction step (at 1 s) three times, 60 s after the step",
           "the paper's laddermill (101 wings", "generator at 2 m/s", "then 60 s of the 3D mill after the paper's 0.01 "
           "rad", "after some 40 seconds", "the step at 1 s", "exits 0", "exits 3", "after a 0.01 rad wind-direction",
           "A 0.01 rad turn"),
    timings=("113 s on the 2-core machine with numba's cache filled (2026-11-29)",
             "(base install, numba's and the operating-point caches empty, load 1, 2026-11-29 evening)",
             "2 min 47 s (the demo 140 s of it", "(about 30 s of compute)", "(about a minute, plus numba's",
             "16-20 minutes on a 2-core machine from a fresh clone on\n2026-12-01"),
    derived=("(period about 20 s: zero crossings of "
             "the lateral position 9-12 s apart; the linear model's 23 s)", "dive after about 52 s"),
)


SCALE_OUT = Covered(  # every figure a dated timing on the shared 2-core machine (the page gives the load)
    given=("accept a connection within 5 s is refused in one line",  # ray_start.PROBE_TIMEOUT_S
           "cores / N, at least 1 |", "one big machine) | 1 |", "of this node) | 1 |", "that cluster ( ) | 1 |",
           "a 0.5 s episode per environment", "two seeds, a 1 - cos gust, 120 s episodes", "a 2-core machine shared",
           "on 2 local workers", "| 2 workers [s] |", "lqr (3 repeats)", "open_loop (1 repeat; )", "1. **The same code",
           "a SHA-256", "2. **A filled numba cache", "3. **Shared paths**", "Ray 2.60 turns on", "(Ray 2.60 here"),
    timings=("about 30 kB per 60 s scenario", "load average 5.2-5.7 throughout", "medians of 3 fresh processes",
             "| **94.4** (the compile) | 0.197 |", "| 0.632 (the cache load) | 0.191 |", "| 0.450 | 0.200 | 0.198 |",
             "would pay 94 s of compile without a cache and 0.43 s of cache load with one, for 0.2 s of simulation",
             "| 4.62 | 13.05 | 0.35 | 8.38 | 3.69 (the LQR", "| 41.6 | 32.2 | 1.29 | 7.19 | 2.99 |",
             "(4.6 s serially)", "about 7-8 s (spawning and importing the workers, about 4-5 s under this load",
             "(42 s serially) gains 1.29x", "This takes 37 s here with a filled cache: LadderMill-v0's operating point "
             "costs 26 s", "(6.0 s against 1.6 s serially", "a 79 MB wheel, 240 MB installed", "take about 20 s here"),
)


MODEL = Covered(given=(  # the model's equations: their constants and the state layout, nothing measured
    "Schwab 1999", "3-2-1 Euler", "wing k (13 floats at offset 13 k): x (3, global CG position), q (4), v (3,",
    "w (3, body-frame", "free node j (6 floats at offset 13 n_w + 6 j): position (3, global), velocity (3, global)",
    "q' = 1/2 q (x) (0, w)", "per wing (6 dof) and the node velocity (3 dof)", "(C_L_de > 0, C_m_de < 0)",
    "(C_n_dr < 0, C_Y_dr > 0)", "C_l_da > 0)", "for 0 < h < h0 (n = 0.2)", "0 for h <= 0", "phi_inf (1 - exp",
    "(1 - 2.2558e-5 h)", "if V < 1e-9", "V^2 / 2",
    "at sideslip beta this model's lift and drag are 1/cos^2 beta times that build-up's: a choice kept for the "
    "registered ids, found by a review of 2026-12-07)", "from -180 to 180 deg", "g = (-w_a, 0, u_a)", "the 6-vector",
    "(sin a, 0, -cos a) ; r_ref x (CLad (sin a, 0, -cos a)) + (0, c Cmad, 0)", "the node velocity, or 0",
    "(e = 0 if l < 1e-9)", "mu g (0, 0, 1)", "C_N0 = 1.1, C_T0 = 0.02", "F_r = l (2 f_r + f_s)/6",
    "F_s = l (f_r + 2 f_s)/6", "+ 7/360 p_r", "- EA eps_p/l0 = 0", "(EA eps_p/l0)^(1/3))", "below 1e-13 of s (at most "
    "60 steps)", "l0 <= 1e-300 or l < 1e-9: sigma = max(sigma0, 0)", "sigma = max(sigma0, 0) if eps > 0 else 0",
    "R^T (0, 0, m g)", "J = [[Jxx, 0, -Jxz], [0, Jyy, 0], [-Jxz, 0, Jzz]]", "State per wing (6)", "per node (4)",
    "y = 0, v = 0, p = r = 0, phi = psi = 0", "sin(phi_s(h) + delta(t)), 0)"))

RL_ZOO3 = Covered(
    groups=("tethered_wing_lqr",),
    checks=((r"lqr +(\d+\.\d\d) +(\d+\.\d) +(\d\.\d{4}) +(\d+\.\d) +(-)",
             tuple(f"{{tethered_wing_lqr[{k}]}}" for k in ("return", "length", "dy", "power", "failures"))),),
    given=("(Python 3.11, torch 2.13 CPU)", "moviepy 2.2 wants and replaced pillow 13.0 by 11.3", "rl-zoo3 2.9 (",
           "(300 s episodes, the paper's 0.01 rad step), not the file's 60 s episodes",
           "| 1 thread [s / 1000 steps] | 2 threads", "(16 x 256 steps per rollout, 2 rollouts a run)",
           "(4 x 256 steps, 4 gradient steps per 4 transitions)", "(64 x 64)", "the 200,000-step run above",
           "200,000 steps are a demonstration", "the README's PPO took 12 M steps", "(20 frames/s, 640 x 480",
           "moviepy 2.x", "(11 frames at 20 frames/s come out as 10)",
           "For the 200,000-step run it printed (two 300 s episodes of the 0.01 rad step;", "rl-zoo3 (2.x)",
           "PPO (4096 steps) and SAC (200 steps)", "along 40 steps, and the same return of a 2 s episode"),
    timings=("165 MB of the 270 MB added", "wall time per 1000 env steps, median), on this project's 2-core machine "
             "while the other engineers' jobs kept its load average at 2.7 to 5.9",
             "| 5 | 0.124 (0.085 to 0.137) | 1.59 (0.59 to 4.39) | 12.9x |",
             "| 7 | 0.094 (0.076 to 0.119) | 0.90 (0.46 to 6.03) | 9.6x |",
             "| 3 | 3.98 (2.68 to 13.9) | 239 (189 to 262) | 60x |", "The issue reported 4.7x"),
    history=(History("2026-11-24", "python -m rl_zoo3.train --algo ppo --env laddermill_gym/TetheredWing-v0 "
                     "--gym-packages laddermill_gym -n 200000 (the page's command), then laddermill evaluate "
                     "--controllers lqr runs/zoo/ppo/"
                     "laddermill_gym-TetheredWing-v0_1 --episodes 2", "an rl-zoo3 PPO run of 200,000 steps, not "
                     "kept (1fe468f)", ("(25 s of the 60 s episodes",
                                        "laddermill_gym-TetheredWing-v0_1 933.89 32.2 49.8734 7563.6")),),
)

