"""The dated History records of docs/controllers.md (:data:`docsite.ledger_controllers.CONTROLLERS`'s history)."""

from __future__ import annotations

from docsite.ledger_kinds import History
from docsite.ledger_residual_sac import RESIDUAL_SAC_NOISE

CONTROLLERS_HISTORY = (
    # the float32 actions' batch dependence as first measured, in a Python session on the machine of 2026-11-30
    # (MKL, AVX512), whose observations the session did not keep (until 2026-12-01 not_rerun)
    History('2026-11-30', "a Python session: the shipped ppo_tethered_wing's SB3 predict on one observation "
            'alone and on 512 at once (fe300dd)', 'the torch float32 actions on the AVX512 machine of 2026-11-30',
            ('against 512 at once: up to 4.8e-7 apart with MKL on AVX512, 2026-11-30;',)),
    # the hand-over on 2026-11-30's CPU (znver4) with the code of that day (--long switch_ntm_ib_0 until 2026-12-01;
    # on 2026-12-02 the same CPU kind printed the Printed entry, as znver3 did on 2026-12-01)
    History('2026-11-30', 'python -m laddermill_gym.studies.gusts.switch_controllers --scenario NTM_IB --seed 0 '
            '--controllers lqr ppo_tethered_wing --times 10 18 20 21 21.5 22 22.5 (0dc3b47)',
            "the hand-over runs on 2026-11-30's AVX-512 CPU, not kept",
            ("On 2026-11-30's AVX512 CPU, with the code of that day, the hand-over at 22.5 s failed (44.80 s).",)),
    # TetheredWing-v0's PPO rows and scenario table
    History('2026-11-23',
            'laddermill train configs/agents/ppo_tethered_wing.yaml, then laddermill evaluate --controllers lqr '
            'RUN --scenario S (make figures of 70f4094)',
            'the PPO run of 12.0 M steps in 25.0 min (best and last policies, not kept) and the LQR beside it on '
            'three scenarios',
            ('PPO trained with on 2026-11-23 (12.0 million steps in 25.0 minutes, randomised direction steps up '
             "to 0.1 rad and slow turbulence during training) beats the LQR's return after 4.1 minutes of "
             'training:',
             '| PPO, best evaluation (6.9 min) | 15782 | 300 s | 37.1 m | 12478 W | | PPO, last (25 min) | 7739 |'
             ' 300 s | 1.03 m | 4740 W',
             'The last policy flies near the nominal position with a small +-1 m limit cycle and 33 % more power '
             "(angle of attack 10.7 deg instead of the trim's 8.0 deg). The best-scoring checkpoint rediscovered "
             'crosswind flight: sweeps of +-37 m with a 10 s period raise the apparent wind and the mean pull to '
             '3.5 times the trim value (Loyd 1980), paying the saturated lateral penalty.',
             'direction step -0.05 rad | 5976, 0.30 m | 9587, 26.5 m | 7685, 0.66 m | | direction step +0.1 rad |'
             ' 5903, 0.60 m | 3835, crashed at 84.8 s | 7721, 2.0 m | | 1-cosine gust, +30 % speed and 0.05 rad '
             'over 10 s | 6091, 0.23 m | 15861, 36.0 m | 514, crashed at 22.0 s',
             '(runs of 2026-11-23, ):',)),
    # Rotorcraft-v0's PPO paragraph
    History('2026-11-23',
            'laddermill train configs/agents/ppo_rotorcraft.yaml, then laddermill evaluate --env '
            'laddermill_gym/Rotorcraft-v0 --controllers open_loop lqr RUN --episodes 4 (a944103)',
            'the PPO run of 1.0 M steps in 20.2 min, not kept',
            ('PPO ( , 1.0 M steps in 20.2 min, run of 2026-11-23) has a higher return than the LQR on the same '
             'four episodes: 4279 against 2399 (open loop: 583, crash at 46 s). The gain comes from the '
             'collective, not from stabilisation. PPO holds the collective at its 15 deg limit and almost doubles'
             " the power (2.9 kW against 1.6 kW). The LQR keeps the trim collective. PPO's craft wanders further,"
             ' up to 0.92 m against 0.054 m. The LQR with its collective set to 15 deg returns 4286.',)),
    # LadderMill-v0's PPO column and its run
    History('2026-11-23',
            'laddermill train configs/agents/ppo_laddermill.yaml, then laddermill evaluate --env '
            'laddermill_gym/LadderMill-v0 --controllers open_loop lqr RUN --episode-time 300 --scenario S '
            '(923fca7; its column re-flown at the 10 ms step on 2026-11-24, 2f2b941)',
            'the LadderMill-v0 PPO run of 655,000 steps in 20 min at the 12.5 ms step, not kept',
            ('655,000 steps in 20 min, run of 2026-11-23).',
             'PPO (20 min, trained at the 12.5 ms step)',
             '15, 0.7 s, 1.3 m (74.4 kW) |',
             '15, 0.7 s, 1.3 m |',
             '15, 0.7 s, 1.3 m',
             "The PPO policy was trained when the scene's physics step was 12.5 ms (since found to be just beyond"
             " RK4's stability limit, now 10 ms): then (2026-11-23) it pulled more power before failing at 9.2 s "
             '(123.6 kW; it learnt power, not the lateral mode);',)),
    # the PPO run at the 10 ms step
    History('2026-11-24',
            'laddermill evaluate --env laddermill_gym/LadderMill-v0 --controllers RUN after the physics step went'
            ' to 10 ms (2f2b941)',
            'the 2026-11-23 PPO run at the 10 ms step, not kept',
            ('at 10 ms (2026-11-24) its aggressive elevator stalls a wing at 0.7 s, before the disturbance. '
             'Retraining at 10 ms is open.',)),
    # the wing's phased training
    History('2026-11-29',
            'laddermill train configs/agents/ppo_tethered_wing.yaml --seed 0 and --seed 1, their validations and '
            'laddermill gust-bench --suite gusts-v1 (fd025ec)',
            'the phased training runs of the shipped wing policy and its second seed (the second not kept)',
            ("The wing's policy (trained on 2026-11-29) trains in phases ( , ): the critic alone for 400,000 "
             'steps ( : actor and action noise frozen), then PPO at learning rate 2e-5 with NTM turbulence among '
             'the training disturbances, and every 200,000 steps a **validation** on 64 drawn episodes (NTM-IB '
             "and light-Dryden fields, drawn steps and gusts; seeds 1000 and up, none of gusts-v1's) keeps the "
             'policy that survives the most as . gusts-v1 is never used to select: it is the test. The kept '
             'policy survives 48 of the 64 validation episodes (the LQR 42, the previous 10-minute policy 33).',
             "That scenario is chaotic for the LQR "
             'itself: Gaussian action noise of 1e-5 crashed it in one of three draws, and the LQR-started policy,'
             ' equal to the LQR up to float32 rounding (6e-6 in the action), crashed there as well. Across drawn '
             'NTM-IB fields the LQR survived about half (12 of 24), and scaling its gains by 0.7 to 2 did not '
             'change that, so three fixed seeds per turbulence scenario decide a count of 11 or 10 largely by '
             "chance. Flown side by side on NTM_IB seed 0, the shipped policy's actions stayed within 0.02-0.08 of"
             " the LQR's until, at 22 s, a gust saturated the rudder and aileron of both (|a| = 1; the LQR holds "
             "the elevator at trim, and the policy's elevator gains stay at most 0.0145 per normalised "
             "observation against 34.6 for rudder and aileron) and rolled both wings past 0.86 rad; the LQR's "
             "recovered from 0.99 rad, the policy's did not (22.95 s). A second training seed ( , validation 48 /"
             ' 64 as well) also scored 10 / 12 and lost the same episode at 23.10 s, the same way. Before these '
             'phases, PPO at learning rate 1e-4 took the LQR-started policy down to 7 / 12 (its critic explained '
             "under 15 % of the return's variance), and 1e-5 for 10 minutes to 9 / 12.",)),
    # the held-out counts through torch
    History('2026-11-29',
            'python -m laddermill_gym.harness.paired_survival --config '
            'configs/agents/ppo_tethered_wing_severe.yaml --set ntm_ib --episodes 200 --seed 5000 --controllers '
            'lqr ppo_tethered_wing, the policy flown through torch (242407d; before control/exact_actor.py)',
            "the shipped policy's actions through SB3's float32 predict, on 2026-11-30's machine and 2026-11-29's",
            ("Through torch the same command printed 79 for the policy on 2026-11-30's machine (both 45, only the "
             "LQR 25, only the policy 34, neither 96; p = 0.298) and 88 on 2026-11-29's (only the policy 43, "
             'neither 87; p = 0.0385), the LQR 70 on both: on knife-edge episodes such bits decide survival. The '
             "comparisons below against its 88 were made so. The training's own validations (and ) fly the policy"
             ' through torch, as it trains.',)),
    # selection on more turbulence, the NTM-IA run
    History('2026-11-29',
            'python -m laddermill_gym.harness.reselect ... --runs RUN...; laddermill train '
            'configs/agents/ppo_tethered_wing_ia.yaml --seed 0 (242407d)',
            'reselection over the two training seeds, the NTM-IA run (55 min), not kept',
            ('Selecting on more turbulence did not change the count (runs of 2026-11-29). validates on 184 drawn '
             'episodes (96 NTM-IB and 48 NTM-IA fields, 24 light Dryden, 16 steps and gusts); flies every '
             'checkpoint of the two training seeds on them: the LQR 78 / 184, the shipped policy 95, the best '
             'checkpoint (seed 1, 3.5 M steps) 96, which scores 10 / 12 on gusts-v1 as well (NTM_IB seed 0 at '
             '23.20 s, seed 2 at 37.65 s; dryden_moderate). Training on stronger turbulence did not either: (NTM '
             "class A, I_ref 0.16 against B's 0.14, in the training episodes; the same 184-episode selection; "
             '6,556,272 steps in 55.2 min on one core at a load of 5 to 10) kept its 6.0 M-step policy (94 / '
             '184), which scores 10 / 12 (NTM_IB seed 0 at 23.30 s, seed 1 at 29.40 s; dryden_moderate) and '
             "survives 80 of the 200 held-out fields against the shipped policy's 88 (p = 0.396): no better.",)),
    # the residual policy
    History('2026-11-29',
            'NUMBA_NUM_THREADS=1 laddermill train configs/agents/ppo_tethered_wing_residual.yaml --seed 0 '
            '(c62ac3c)',
            "the residual policy's run of 5,519,472 steps in 45.5 min, not kept",
            ('itself (run of 2026-11-29).',
             "( , ) makes the action mean the LQR's own unclipped float64 action (computed by from gains and trim"
             ' held in the policy, never trained) plus an MLP (64, 64) and a linear layer whose last layers start'
             ' at zero, rounded to float32 once as the LQR rounds its action; so the untrained policy acts as the'
             " LQR bit for bit ( , the LQR of as the oracle) and validates 78 / 184, the LQR's count; on gusts-v1"
             " the run's 250,000-step checkpoint (critic warm-up, actor frozen) scores 11 / 12 with the LQR's "
             'peak lateral excursion in all 36 episodes (difference 0.0 m). Near is not enough here: unrounded '
             'float64 actions validated 77, an affine map of the LQR measured by finite differences (1e-13 off) '
             '79. (critic warm-up, learning rate 2e-5, 0.01, the same training disturbances and 184-episode '
             'selection as above; 5,519,472 steps in 45.5 min on one core at a load of 9 to 13) validated 70 to '
             '93 / 184 and kept its 2.75 M-step policy (93: NTM-IB 47, NTM-IA 18, light Dryden 12, gusts 16). On '
             'gusts-v1 it scores 10 / 12 (NTM_IB seed 0 at 23.25 s and seed 1 at 30.40 s, beta outside the '
             'aerodynamic range; dryden_moderate, as the LQR), and on the 200 held-out NTM-IB fields it survives '
             "79 against the shipped policy's 88 (both 52, only the shipped 36, only the residual 27, neither 85;"
             ' p = 0.314; ): not shipped.',)),
    # the bounded residual
    History('2026-11-30',
            'laddermill train configs/agents/ppo_tethered_wing_residual_bounded.yaml --seed 0 (7a2e014)',
            "the bounded residual's run of 7,000,016 steps in 45.52 min, not kept",
            ('A bounded residual did not either, on gusts-v1, though it is the best policy yet on the held-out '
             'fields (run of 2026-11-30). ( , otherwise the config above) passes the residual through 0.2 tanh(r '
             "/ 0.2), so the deterministic action stays within 0.2 of the half range of the LQR's in every "
             'control and the untrained policy is still the LQR bit for bit (the tests check both, and that the '
             "bound survives SB3's zip). (7,000,016 steps in 45.52 min on one core at a load of 4 to 7) validated"
             " 78 / 184 at the start (the LQR's count), then 65 to 104, and kept its 5.25 M-step policy (104: "
             'NTM-IB 48, NTM-IA 19, light Dryden 21, gusts 16). On gusts-v1 ( ) it scores 9 / 12 against the '
             "LQR's 11 / 12: NTM_IB lost in seeds 0 (23.10 s) and 2 (38.90 s), dryden_light in seed 2 (37.80 s), "
             'dryden_moderate in seeds 0 and 2 (it holds seed 1, which the LQR loses). On the 200 held-out NTM-IB'
             " fields (the command above) it survives 110 against the shipped policy's 84 (both 63, only the "
             "shipped 21, only the bounded residual 47, neither 69; p = 0.00219; ) and against the LQR's 70 (both"
             ' 52, only the LQR 18, only the bounded residual 58, neither 72; p = 4.71e-06). (Through torch the '
             'shipped policy read 79 here, p = 0.000152 against the bounded residual: the float32 matter above; '
             'the residual policy itself, not a plain linear actor, still acts through torch.) Not shipped: '
             "gusts-v1's NTM_IB seed 0 is again lost near 23 s.",)),
    # the paired selection
    History('2026-11-30',
            'python -m laddermill_gym.harness.reselect --config '
            'configs/agents/ppo_tethered_wing_residual_paired.yaml --runs RUN; laddermill train '
            'configs/agents/ppo_tethered_wing_residual_paired.yaml --seed 0 (c9720bf)',
            'the paired reselection of the bounded run and the paired run of 4,659,328 steps in 45.75 min, not '
            'kept',
            ('Nor did selecting by pairs (runs of 2026-11-30). ( , ; default: the count, unchanged) scores a '
             'checkpoint by the validation episodes it survives minus P x the episodes the LQR (flown once per '
             'run on the same seeds) survives and it loses. sets P = 2 (chosen before any scoring) and L = 0.1. '
             'Applied post hoc to the bounded run above ( , over its 250,000-step checkpoint and the 21 with more'
             ' than 82 / 184; one with fewer cannot score above 82), it selects 3.5 M steps (102 / 184, 10 lost '
             "that the LQR holds, score 82; the others 41 to 79; the count's 5.25 M steps: 104, 17 lost, score "
             '70), which scores 10 / 12 on gusts-v1 (NTM_IB seed 0 lost at 23.40 s; dryden_moderate lost in every'
             " seed, as by the LQR) and 103 of the 200 held-out fields against the LQR's 70 (both 53, only the "
             'LQR 17, only the policy 50, neither 80; p = 6.74e-05). (4,659,328 steps in 45.75 min on one core at'
             ' a load of 5 to 10) validated 78 to 98 / 184, but every checkpoint after the critic warm-up lost 13'
             " to 21 episodes the LQR holds (paired scores 37 to 72 against the start's 78): it kept its start, "
             "the LQR bit for bit (gusts-v1 11 / 12 with the LQR's peak lateral excursion in all 18 episodes, "
             'difference 0.0 m; held-out 70 / 200, both 70), which is no learned policy. Every learned checkpoint'
             " flown gave up 10 to 21 of the LQR's 78 validation survivals while gaining others, and every "
             "residual run so far, like the NTM-IA run, loses gusts-v1's NTM_IB seed 0 near 23 s (23.25, 23.10, "
             '23.40 s; 23.30 s). ',)),
    # the second seed
    History('2026-11-30',
            'laddermill train configs/agents/ppo_tethered_wing_residual_bounded_paired.yaml --seed 1 (ec6a6ad)',
            "the second seed's run of 8,679,440 steps in 45.34 min, not kept",
            ('Nor did a second seed (run of 2026-11-30). is the bounded config above (L = 0.2) with the paired '
             'rule (P = 2, the LQR as reference) and seed 1, every setting fixed before it was trained or scored:'
             ' the combination whose post hoc selection gave the learned policy above had one seed. (8,679,440 '
             'steps in 45.34 min on one core at a load of 4 to 6) validated 78 / 184 at the start and 71 to 97 '
             'after the critic warm-up, but every checkpoint after it lost 16 to 27 episodes the LQR holds '
             "(paired scores 18 to 65 against the start's 78; the best, 6.5 M steps, survived 97 and lost 16): it"
             " kept its start, the LQR bit for bit (gusts-v1 11 / 12 with the LQR's peak lateral excursion in all"
             ' 18 episodes, difference 0.0 m; held-out 70 / 200, both 70, p = 1), which is no learned policy. Of '
             'the two seeds of L = 0.2 under the paired rule, seed 0 gave a learned policy that loses one '
             'gusts-v1 scenario the LQR holds and seed 1 gave none: every checkpoint of seed 1 gave up more of '
             "the LQR's validation survivals (16 to 27) than the one selected in seed 0 (10).",)),
    # SAC from the LQR start
    History('2026-11-30',
            'laddermill train configs/agents/sac_tethered_wing_residual.yaml --seed 0 (6734c1e); laddermill '
            'gust-bench --suite gusts-v1 ... --controllers lqr RUN; python -m '
            'laddermill_gym.harness.paired_survival ... --controllers lqr RUN',
            "the residual SAC's run of 650,008 steps in 40.29 min, not kept",
            ("Nor did SAC from the LQR start (run of 2026-11-30). ( , ) makes SAC's pre-squash mean atanh of the "
             "LQR's own action (clipped 2^-30 inside the range, the float64 base shares with ) plus a residual "
             "started at zero and bounded to 0.2 tanh(r / 0.2); the atanh, the sum and SAC's tanh are done in "
             "float64 and SB3's action rescaling (the identity on [-1, 1], rounded in float32) is skipped, so the "
             'untrained policy acts as the LQR bit for bit, saturated controls included ( , the LQR of as the '
             "oracle, through SB3's zip). The environment, training disturbances and 184-episode paired selection "
             "(P = 2, the LQR as reference) are the bounded paired config's; SAC's own settings (critics alone for "
             'the first 80,000 steps, then learning rate 3e-5 for both, fixed entropy weight 0.001, initial noise '
             'exp(-2.5), 4 gradient steps per 8 transitions, seed 0) were fixed before it was trained or scored. '
             '(650,008 steps in 40.29 min on one core at a load of 3.4 to 8.5) validated 78 / 184 at the start and '
             'at 50,008 steps (the warm-up), then 40 to 81, but every checkpoint after the warm-up lost 23 to 47 '
             "episodes the LQR holds (paired scores -54 to 35 against the start's 78; the best, 350,008 steps, "
             "survived 81 and lost 23): it kept its start, the LQR bit for bit (gusts-v1 11 / 12 with the LQR's "
             'peak lateral excursion in all 18 episodes, difference 0.0 m; held-out 70 / 200, both 70, p = 1), '
             "which is no learned policy. Its checkpoints gave up more of the LQR's validation survivals than any "
             "PPO residual's (10 to 27).",)),
    # the residual after the squash
    History('2026-11-30',
            'laddermill train configs/agents/sac_tethered_wing_residual_after.yaml --seed 0 (8bf9629); laddermill '
            'gust-bench --suite gusts-v1 --env laddermill_gym/TetheredWing-v0 --controllers lqr RUN; python -m '
            'laddermill_gym.harness.paired_survival --config configs/agents/ppo_tethered_wing_severe.yaml --set '
            'ntm_ib --episodes 200 --seed 5000 --controllers lqr RUN',
            "the after-squash residual SAC's run of 754,592 steps in 30.16 min, not kept",
            ("The residual after the squash gave a learned policy, but not the LQR's gusts-v1 count (run of "
             "2026-11-30). ( , ) adds the LQR after SAC's squash: the env action is clip(a_lqr + L u, -1, 1), u = "
             "tanh(r(z) + std eps) SAC's squashed action of the zero-started residual, L = 0.2, so the untrained "
             "deterministic action is the LQR's clipped action bit for bit and every control, a saturated one "
             "included, can move by up to 0.2 where the LQR's unclipped action is within 1.2 (beyond it, as the "
             "LQR's action in strong turbulence often is, the clip absorbs the residual; clips the base first, "
             "which keeps the start and gives the authority everywhere: not trained yet). The replay buffer and "
             "the "
             "critics get that action; the actor's "
             "log-probability is u's minus 3 log 0.2, the clip's mass at the bounds ignored as SB3 ignores the "
             "squash's own boundary ( : the LQR of as the oracle through SB3's zip, a saturated control moved, the "
             "log-density against torch.distributions). Every other setting is the previous SAC run's but the "
             "training time (30 min), fixed and committed before it was trained or scored; so the start's action "
             "noise is 0.2 x 0.08 = 0.016 of the half range, a fifth of the previous run's. (754,592 steps in "
             '30.16 min on one core at a load of 0.6 to 2.4) validated 78 / 184 at the start and at 50,008 steps '
             '(the warm-up), 34 at 100,008 steps (56 lost that the LQR holds), then 70 to 123. The paired rule '
             "kept 700,008 steps: 123 / 184 survived (NTM-IB 62 against the LQR's 33, NTM-IA 24 against 15, light "
             "Dryden 21 against 14, gusts 16 as 16), 11 lost that the LQR holds, score 101 against the start's 78. "
             "Scored once on gusts-v1 ( ): 10 / 12 against the LQR's 11 / 12. It loses NTM_IB, which the LQR holds "
             'on all three seeds (seed 0 at 23.60 s, near 23 s as every residual run so far, and seed 2 at 39.55 '
             's; it holds seed 1), and dryden_moderate on every seed as the LQR does, later (22.40, 53.50, 57.85 s '
             'against 21.45, 32.15, 18.90 s); it holds the ten others, with larger excursions in the quiet ones '
             "(direction_step 0.24 m against 0.059 m: the learned residual is not zero at trim). The validation's "
             "gain (45 more of its episodes survived) did not carry over to gusts-v1's three NTM_IB fields: issue "
             '31 point 4 is not met by this run. On the 200 held-out NTM-IB fields ( ) it survives 132 against '
             "the LQR's 70 (both 55, only the LQR 15, only the policy 77, neither 53; p = 3.26e-11), the most of "
             'any policy here.',)),
    History('2026-11-30',
            'laddermill train configs/agents/sac_tethered_wing_residual_after.yaml --seed 1 (f658f64); laddermill '
            'train configs/agents/sac_tethered_wing_residual_after_clipped.yaml --seed 0 (29d574c); laddermill '
            'gust-bench --suite gusts-v1 --env laddermill_gym/TetheredWing-v0 --controllers lqr RUN',
            "the after-squash residual SAC's seed 1 and the clipped base's seed 0, about 30 min each, not kept",
            ("Nor did a second seed or the clipped base (runs of 2026-11-30). Both were fixed and committed before "
             "they were trained, with the rule between the seeds (the higher paired validation score). (518,768 "
             "steps in 30.17 min on one core at a load of about 3, beside the next run) validated 78 / 184 at the "
             "start and the warm-up, then 22 to 93 with 21 to 58 lost that the LQR holds (paired scores at most 51 "
             "against 78): it kept its start, the LQR bit for bit (gusts-v1 11 / 12 with the LQR's peak lateral "
             "excursion in all 12 scenarios), so seed 0's policy (score 101) stays the construction's candidate, "
             "at 10 / 12. ( , otherwise the same; seed 0; 581,856 steps in 30.16 min beside seed 1) validated 25 "
             "to 94 after the warm-up with 19 to 57 lost that the LQR holds (paired scores at most 56): it kept "
             "its start too (gusts-v1 11 / 12, the LQR's excursions). Two of the three after-squash runs found no "
             "checkpoint that loses fewer than 19 of the LQR's validation survivals; seed 0's lost 11.",)),
    *RESIDUAL_SAC_NOISE)
