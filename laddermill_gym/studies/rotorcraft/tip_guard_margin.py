"""The blade-tip guard's margin against its prediction error in turbulence (configs/agents/lqr_guard_rotorcraft.yaml).

The guard (:mod:`laddermill_gym.control.craft_tip_guard`) sets the collective from one observation so that each
retreating tip sits at or below ``limit - margin`` during the next control period. What it cannot see (the wind's
vertical and lateral parts and its direction, the change of the wind over the period, the linearisation's error in
the wind and in the pitch it moves) shows as the one-period prediction error of each rotor r

    e_r = tip_r(k + 1) - [tip_estimate_r(obs_k) + A_th (pitch_r(k + 1) - pitch_r(k))],

which the margin has to cover. This study flies the guard itself on Rotorcraft-v0, which does not end an episode at
the blade limit (so a period past it is counted, not the end), in the turbulence of gusts-v5's NTM_IB and
dryden_moderate scenarios on seeds that gusts-v5 does not use (100 and up), and prints the error's quantiles over
the rotor-periods whose predicted tip lies in the band where the guard works (``--band``; default from 1 deg below
the guard's target up to the limit).

Run ``python -m laddermill_gym.studies.rotorcraft.tip_guard_margin [--episodes 8] [--seed 100] [--guard CONFIG]
[--json FILE]`` (seconds). Results: laddermill_gym/docs/rotorcraft.md#the-blade-tip-guard.
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


def prediction_errors(field: str, seeds, guard_config: str = "lqr_guard_rotorcraft", suite: str = "gusts-v5",
                      duration: float = 60.0) -> dict:
    """One episode per seed of the guard ``guard_config`` in the turbulence of ``suite``'s scenario ``field``: per
    control period and rotor the predicted and the simulated retreating-tip incidence [rad], arrays (periods, seeds,
    2), nan after the end; and the guard's target ``limit - margin`` [rad]."""
    import gymnasium as gym

    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.kernels.contract import CA_TIP_AOA
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    env_kwargs, scenarios = load_suite(suite).envs[SUITE_ENV]
    chosen = [s for s in scenarios if s.name == field]
    if not chosen:
        raise ValueError(f"suite {suite} has no scenario {field!r} for {SUITE_ENV}")
    kw = dict(env_kwargs, episode_time=float(duration), disturbances=[dict(d) for d in chosen[0].disturbances])
    guard = make_controller(f"lqr_guard:{guard_config}", ENV_ID, kw)
    if guard.mode != "limit":
        raise UsageError(f"--guard {guard_config}: mode {guard.mode!r}; the margin belongs to a guard in limit mode")
    env = gym.make_vec(ENV_ID, num_envs=len(seeds), vectorization_mode="vector_entry_point", **kw)
    obs, _ = env.reset(seed=[int(s) for s in seeds])
    alive = np.ones(len(seeds), bool)
    predicted, simulated = [], []
    while alive.any():
        estimate = guard.estimated_tips(obs)
        pitch = np.asarray(obs, float)[:, guard.pitch_index]
        obs, _, term, trunc, _ = env.step(guard.predict(obs)[0])
        moved = np.asarray(obs, float)[:, guard.pitch_index] - pitch
        predicted.append(np.where(alive[:, None], estimate + guard.model.a_pitch * moved, np.nan))
        simulated.append(np.where(alive[:, None], env.task.aux[:, CA_TIP_AOA:CA_TIP_AOA + 2], np.nan))
        alive &= ~(term | trunc)
    env.close()
    return {"predicted": np.array(predicted), "simulated": np.array(simulated),
            "target": guard.model.limit - guard.margin, "limit": guard.model.limit}


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
    p.add_argument("--guard", default="lqr_guard_rotorcraft", help="the guard's config (a file or a shipped name; "
                   "default lqr_guard_rotorcraft)")
    p.add_argument("--band", type=float, nargs=2, default=None, metavar=("LOW", "HIGH"),
                   help="predicted tips counted [deg] (default: 1 deg below the guard's target up to the limit)")
    p.add_argument("--json", type=Path, default=None, help="also write the quantiles to this JSON file")


def _run(args) -> int:
    if args.episodes < 1:
        raise UsageError(f"--episodes {args.episodes}: must be at least 1")
    if args.band is not None and not args.band[0] < args.band[1]:
        raise UsageError(f"--band {args.band[0]} {args.band[1]}: LOW must be below HIGH")
    if args.json is not None:
        writable_folder(args.json.parent, "--json")
    seeds = list(range(args.seed, args.seed + args.episodes))
    runs = {field: prediction_errors(field, seeds, args.guard) for field in FIELDS}
    first = runs[FIELDS[0]]
    band_deg = tuple(args.band) if args.band is not None else (math.degrees(first["target"]) - 1.0,
                                                                math.degrees(first["limit"]))
    band = (math.radians(band_deg[0]), math.radians(band_deg[1]))
    print(f"one-period prediction error of the blade-tip guard {args.guard} (target "
          f"{math.degrees(first['target']):.4g} deg), {ENV_ID}, seeds {seeds[0]}-{seeds[-1]}, per rotor and period "
          f"with the predicted tip in {band_deg[0]:.4g}-{band_deg[1]:.4g} deg [deg]:")
    print("field            periods   median   q0.99  q0.999     max")
    runs["pooled"] = {k: np.concatenate([runs[f][k].ravel() for f in FIELDS]) for k in ("predicted", "simulated")}
    results = {}
    for field, run in runs.items():
        q = results[field] = error_quantiles(run["predicted"], run["simulated"], band)
        if q["n"] == 0:
            print(f"{field:16s} {0:7d}   (no period in the band)")
            continue
        print(f"{field:16s} {q['n']:7d} " + " ".join(f"{math.degrees(q[f'q{x:g}']):7.2f}" for x in QUANTILES))
    if args.json is not None:
        args.json.write_text(json.dumps({"seeds": seeds, "guard": args.guard, "band_deg": list(band_deg),
                                         "errors_rad": results}, indent=1))
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
