"""How much of each turbulence model's variance a gust suite's grids keep, and what the default synthesis makes of it.

A frozen field on a grid of length n_xi dxi [m] resolves the wavenumbers dkappa = 1 / (n_xi dxi) to the Nyquist
wavenumber; the variance below dkappa / 2 is not in it. The default synthesis (``Turbulence.low_frequencies =
"rescale"``, the suites up to gusts-v5) scales the kept modes so each row's record has the model's sigma^2, which
raises the resolved spectrum by 1 / (kept share). ``"offset"`` keeps the spectrum's level and adds the low band as one
random offset per row (atmosphere/turbulence.py).

For every turbulence scenario of a suite this prints, per component u and w, the kept share sum S(kappa) dkappa /
sigma^2 over the grid's modes, the factor 1 / kept share by which "rescale" raises the resolved spectrum, and the
low band's share (the integral of S from 0 to dkappa / 2 over sigma^2), each as the range over the grid's rows (the
MIL models' intensities and scales vary with height). Closed forms of the models' spectra, no random draws.

Run ``python -m laddermill_gym.studies.gusts.turbulence_level [--suite gusts-v1] [--env ID ...]`` (seconds).
Results: laddermill_gym/docs/wind.md#synthesis-and-the-grids-length.
"""

from __future__ import annotations

import argparse

import numpy as np

from laddermill_gym.studies.commands import UsageError, run_guarded

COMPONENTS = ((0, "u"), (2, "w"))


def scenario_levels(turb, duration: float) -> dict:
    """The grid length [m] and, per component name, (kept share, rescale factor, low share) as (min, max) over the
    rows of ``turb`` (a Turbulence) on an episode of ``duration`` [s]."""
    from laddermill_gym.atmosphere.turbulence import low_band, turbulence_spectra

    g = turb.grid_geometry(duration)
    h = g.h0 + g.dh * np.arange(g.n_h)
    n_rec = turb.record_columns(g.n_xi)  # the synthesised record's columns (the grid's, with record 1)
    dkappa = 1.0 / (n_rec * g.dxi)
    kappa = dkappa * np.arange(1, (n_rec + 1) // 2)
    args = (turb.wind_class, turb.wind_speed, turb.hub_height, turb.severity, turb.w20)
    comps = turbulence_spectra(turb.model, kappa, h, *args)
    lows = low_band(turb.model, 0.5 * dkappa, h, *args)
    out = {"grid_m": g.n_xi * g.dxi}
    for k, name in COMPONENTS:
        spectra, sigma, _ = comps[k]
        kept = spectra.sum(axis=0) * dkappa / sigma ** 2
        low = lows[k][0] / sigma ** 2
        out[name] = {"kept": (float(kept.min()), float(kept.max())),
                     "factor": (float(1.0 / kept.max()), float(1.0 / kept.min())),
                     "low": (float(low.min()), float(low.max()))}
    return out


def suite_levels(suite_name: str, env_ids=()) -> list[dict]:
    """Rows (env, scenario, model, levels of :func:`scenario_levels`) for every Turbulence disturbance of the suite's
    scenarios (of ``env_ids``, all when empty); UsageError naming an env the suite lacks."""
    from laddermill_gym.atmosphere.disturbance_spec import disturbance_from_spec
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    suite = load_suite(suite_name)
    for env_id in env_ids:
        if env_id not in suite.envs:
            raise UsageError(f"--env {env_id!r}: suite {suite.name} has {sorted(suite.envs)}")
    rows = []
    for env_id, (_, scenarios) in suite.envs.items():
        if env_ids and env_id not in env_ids:
            continue
        for s in scenarios:
            for i, spec in enumerate(s.disturbances):
                if spec.get("type") != "Turbulence":
                    continue
                turb = disturbance_from_spec(dict(spec), f"{s.name}.disturbances[{i}]")
                rows.append({"env": env_id, "scenario": s.name, "model": turb.model,
                             **scenario_levels(turb, s.duration)})
    return rows


def _span(pair: tuple[float, float], fmt: str) -> str:
    lo, hi = (format(v, fmt) for v in pair)
    return lo if lo == hi else f"{lo}-{hi}"


def _run(args) -> int:
    rows = suite_levels(args.suite, args.env)
    print(f"turbulence kept by the grids of {args.suite}: per component the kept share of sigma^2, the factor by "
          "which the default synthesis ('rescale') raises the resolved spectrum, and the share below the first mode "
          "(ranges over the grid's rows)")
    print(f"{'env':38s} {'scenario':16s} {'model':7s} {'grid [m]':>8s}  "
          + "  ".join(f"{c}: kept / factor / low" for _, c in COMPONENTS))
    for r in rows:
        cells = "  ".join(f"{_span(r[c]['kept'], '.2f')} / x{_span(r[c]['factor'], '.2f')} / "
                          f"{_span(r[c]['low'], '.2f')}" for _, c in COMPONENTS)
        print(f"{r['env']:38s} {r['scenario']:16s} {r['model']:7s} {r['grid_m']:8.0f}  {cells}")
    if not rows:
        print("(no Turbulence disturbance in the chosen scenarios)")
    return 0


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.gusts.turbulence_level",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("--suite", default="gusts-v1", help="a suite name or file (default gusts-v1)")
    p.add_argument("--env", nargs="*", default=[], help="env ids (default: every env of the suite)")
    args = p.parse_args(argv)
    return run_guarded("turbulence-level", lambda: _run(args))


if __name__ == "__main__":
    raise SystemExit(main())
