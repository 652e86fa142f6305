"""The blade-tip guard's margin from its prediction error in turbulence (configs/agents/lqr_guard_rotorcraft.yaml).

The guard (:mod:`laddermill_gym.control.craft_tip_guard`) sets the collective from one observation so that each
retreating tip sits at ``limit - margin`` during the next control period. What it cannot see (the wind's vertical
and lateral parts and its direction, the change of the wind over the period, the linearisation's error) shows as the
one-period prediction error

    e = tip(k + 1) - max over the rotors of [tip_estimate(obs_k) + A_th (pitch(k + 1) - pitch(k))],

which the margin has to cover. This study flies the eq. (6) LQR (the guard's differential, the collective held at
the trim, so the tips range freely) on Rotorcraft-v0, which does not end an episode at the blade limit, in the
turbulence of gusts-v5's NTM_IB and dryden_moderate scenarios on seeds that gusts-v5 does not use (100 and up), and
prints the error's quantiles over the control periods whose predicted tip lies in the guard's working band
(``--band``, default 11 to 13 deg).

Run ``python -m laddermill_gym.studies.rotorcraft.tip_guard_margin [--episodes 8] [--seed 100] [--json FILE]``
(seconds). Results: laddermill_gym/docs/rotorcraft.md#the-blade-tip-guard.
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from laddermill_gym.studies.commands import UsageError, run_guarded, writable_folder

ENV_ID = "laddermill_gym/Rotorcraft-v0"
SUITE_ENV = "laddermill_gym/Rotorcraft-v1"  # gusts-v5's scenarios for the craft (v0's are the same)
FIELDS = ("NTM_IB", "dryden_moderate")
QUANTILES = (0.5, 0.99, 0.999, 1.0)


def prediction_errors(field: str, seeds, suite: str = "gusts-v5", duration: float = 60.0) -> dict:
    """One LQR episode per seed in the turbulence of ``suite``'s scenario ``field``: per control period the
    predicted and the simulated larger retreating-tip incidence [rad], arrays (periods x seeds), nan after the end."""
    import gymnasium as gym

    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    env_kwargs, scenarios = load_suite(suite).envs[SUITE_ENV]
    chosen = [s for s in scenarios if s.name == field]
    if not chosen:
        raise ValueError(f"suite {suite} has no scenario {field!r} for {SUITE_ENV}")
    kw = dict(env_kwargs, episode_time=float(duration), disturbances=[dict(d) for d in chosen[0].disturbances])
    guard = make_controller("lqr_guard", ENV_ID, kw)
    lqr = guard.lqr
    env = gym.make_vec(ENV_ID, num_envs=len(seeds), vectorization_mode="vector_entry_point", **kw)
    obs, _ = env.reset(seed=[int(s) for s in seeds])
    alive = np.ones(len(seeds), bool)
    predicted, simulated = [], []
    while alive.any():
        estimate = guard.estimated_tips(obs)
        pitch = np.asarray(obs, float)[:, guard.pitch_index]
        action, _ = lqr.predict(obs)
        obs, _, term, trunc, info = env.step(action)
        moved = np.asarray(obs, float)[:, guard.pitch_index] - pitch
        pred = np.max(estimate + guard.model.a_pitch * moved, axis=1)
        predicted.append(np.where(alive, pred, np.nan))
        simulated.append(np.where(alive, np.asarray(info["max_tip_incidence_rad"], float), np.nan))
        alive &= ~(term | trunc)
    env.close()
    return {"predicted": np.array(predicted), "simulated": np.array(simulated)}


def error_quantiles(predicted: np.ndarray, simulated: np.ndarray, band: tuple[float, float]) -> dict:
    """Quantiles (:data:`QUANTILES`) of simulated - predicted [rad] over the entries whose prediction lies in
    ``band`` [rad]; ``n`` counts them."""
    p, s = np.ravel(predicted), np.ravel(simulated)
    keep = np.isfinite(p) & np.isfinite(s) & (p >= band[0]) & (p <= band[1])
    e = s[keep] - p[keep]
    if e.size == 0:
        return {"n": 0}
    return {"n": int(e.size), **{f"q{q:g}": float(np.quantile(e, q)) for q in QUANTILES}}


def _arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--episodes", type=int, default=8, help="episodes per turbulence field (default 8)")
    p.add_argument("--seed", type=int, default=100, help="first seed (default 100: gusts-v5 uses 0-2)")
    p.add_argument("--band", type=float, nargs=2, default=(11.0, 13.0), metavar=("LOW", "HIGH"),
                   help="predicted tips counted [deg] (default 11 13: the guard's working band)")
    p.add_argument("--json", type=Path, default=None, help="also write the quantiles to this JSON file")


def _run(args) -> int:
    if args.episodes < 1:
        raise UsageError(f"--episodes {args.episodes}: must be at least 1")
    if not args.band[0] < args.band[1]:
        raise UsageError(f"--band {args.band[0]} {args.band[1]}: LOW must be below HIGH")
    if args.json is not None:
        writable_folder(args.json.parent, "--json")
    band = (math.radians(args.band[0]), math.radians(args.band[1]))
    seeds = list(range(args.seed, args.seed + args.episodes))
    results, pooled_p, pooled_s = {}, [], []
    print(f"one-period prediction error of the blade-tip guard, {ENV_ID}, LQR, seeds {seeds[0]}-{seeds[-1]}, "
          f"predicted tip in {args.band[0]:g}-{args.band[1]:g} deg [deg]:")
    print("field            periods   median   q0.99  q0.999     max")
    for field in (*FIELDS, "pooled"):
        if field == "pooled":
            p, s = np.concatenate(pooled_p, axis=None), np.concatenate(pooled_s, axis=None)
        else:
            run = prediction_errors(field, seeds)
            p, s = run["predicted"], run["simulated"]
            pooled_p.append(p.ravel())
            pooled_s.append(s.ravel())
        q = error_quantiles(p, s, band)
        results[field] = q
        if q["n"] == 0:
            print(f"{field:16s} {0:7d}   (no period in the band)")
            continue
        print(f"{field:16s} {q['n']:7d} " + " ".join(f"{math.degrees(q[f'q{x:g}']):7.2f}" for x in QUANTILES))
    if args.json is not None:
        args.json.write_text(json.dumps({"seeds": seeds, "band_deg": list(args.band), "errors_rad": results},
                                        indent=1))
        print(args.json)
    return 0


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.rotorcraft.tip_guard_margin",
                                description=__doc__.split("\n\n")[0])
    _arguments(p)
    args = p.parse_args(argv)
    return run_guarded("tip-guard-margin", lambda: _run(args))


if __name__ == "__main__":
    raise SystemExit(main())
