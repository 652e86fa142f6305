"""What a point between a turbulence grid's nodes meets: the variance the kernels read, and the field's long lags.

A gust grid (``atmosphere/turbulence.py``) holds the drawn field at its nodes, every ``dxi`` along the wind and every
``dh`` in height, and the kernels read it between them by bilinear interpolation (``kernels/wind.gust_at``). At a
node each component has its synthesis' variance; between nodes the reading is a weighted mean of nodes that are
only partly correlated, so its variance is smaller. And the field is periodic over the grid's length n_xi dxi (one
inverse FFT along the wind), so the correlation at lags beyond about half of it is not the model's.

For every turbulence scenario of a suite (of the envs named) this draws the scenario's grid for ``seeds`` seeds and
prints, per component u, v, w, the mean of g^2 / sigma_k^2 (sigma_k the model's standard deviation at the point's
height, linear between rows) at ``points`` random nodes per seed and at as many random points of the grid, read
through ``gust_at`` after the fade-in, each with its 95 % half-width over the seeds; then u's correlation over the
seeds between the times 0 and the lags ``lags`` at a fixed point (p . e = 0, the row nearest the scenario's
reference height) against the model's for an unbounded field, the integral of S(kappa) cos(2 pi kappa U lag) over
that of S(kappa) (trapezoids from 1e-6 to 2 1/m).

Run ``python -m laddermill_gym.studies.gusts.grid_sampling [--suite gusts-v1] [--env ID ...]`` (about a minute per
scenario). Results: laddermill_gym/docs/wind.md#what-a-point-between-the-nodes-meets.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["grid_sampling", "read_grid", "main"]

_KAPPA = np.linspace(1e-6, 2.0, 400_001)  # [1/m] the closed form's quadrature nodes


def _model_correlation(turb, height: float, lags: np.ndarray) -> np.ndarray:
    """u's correlation of an unbounded field of ``turb``'s model at ``height`` [m] over the time ``lags`` [s] at a
    fixed point (Taylor: distance U lag)."""
    from laddermill_gym.atmosphere.turbulence import turbulence_spectra

    args = (turb.wind_class, turb.wind_speed, turb.hub_height, turb.severity, turb.w20)
    s = turbulence_spectra(turb.model, _KAPPA, np.array([height]), *args)[0][0][:, 0]
    total = np.trapezoid(s, _KAPPA)
    return np.array([np.trapezoid(s * np.cos(2 * math.pi * _KAPPA * turb.wind_speed * lag), _KAPPA) / total
                     for lag in lags])


def read_grid(g, xi: np.ndarray, h: np.ndarray, t: float) -> np.ndarray:
    """(n, 3) (u, v, w) [m/s] of the grid ``g`` read by the kernel at the along-wind coordinates ``xi`` and heights
    ``h`` [m] at the time ``t`` [s] (after the fade-in), in the wind's axes."""
    from laddermill_gym.kernels.contract import GP_EX, GP_EY
    from laddermill_gym.kernels.wind import gust_at

    gp, gv = g.header(), g.values.reshape(-1)
    ex, ey = gp[GP_EX], gp[GP_EY]  # the wind's direction e, along which xi = p . e - U t
    out = np.empty((xi.size, 3))
    for i, (x, z) in enumerate(zip(xi, h, strict=True)):
        d = x + g.advection * t
        gx, gy, gz = gust_at(d * ex, d * ey, -z, t, gp, gv)
        out[i] = (gx * ex + gy * ey, -gx * ey + gy * ex, -gz)
    return out


def grid_sampling(turb, duration: float, seeds: int = 100, points: int = 200, lags=(20.0, 40.0)) -> dict:
    """Variance ratios at nodes and at random points (``node`` and ``between``: (3,) means and (3,) 95 % half-widths
    over the seeds), ``lags`` [s] with u's correlation through the field (``field_corr``) and the model's
    (``model_corr``), and the grid's length ``grid_m`` [m] and row ``height`` [m] of the lags, for the Turbulence
    ``turb`` on an episode of ``duration`` [s]."""
    from laddermill_gym.atmosphere.turbulence import turbulence_spectra

    geo = turb.grid_geometry(duration)
    h_rows = geo.h0 + geo.dh * np.arange(geo.n_h)
    args = (turb.wind_class, turb.wind_speed, turb.hub_height, turb.severity, turb.w20)
    sig2 = np.stack([c[1] ** 2 for c in turbulence_spectra(turb.model, np.array([1e-3]), h_rows, *args)], axis=1)
    t = float(turb.fade_in) + 1.0
    row = int(np.argmin(np.abs(h_rows - min(max(turb.hub_height, h_rows[0]), h_rows[-1]))))
    lags = np.asarray(lags, float)
    node, between, pairs = [], [], []
    for seed in range(seeds):
        g = turb.gust_grid(duration, np.random.default_rng(seed))
        q = np.random.default_rng(1_000_000 + seed)
        i, j = q.integers(2, geo.n_xi - 3, points), q.integers(0, geo.n_h, points)
        at = read_grid(g, geo.xi0 + geo.dxi * i, h_rows[j], t)
        node.append(np.mean(at ** 2 / sig2[j], axis=0))
        xi = q.uniform(geo.xi0 + 2 * geo.dxi, geo.xi0 + (geo.n_xi - 3) * geo.dxi, points)
        h = q.uniform(h_rows[0], h_rows[-1], points)
        s2 = np.stack([np.interp(h, h_rows, sig2[:, k]) for k in range(3)], axis=1)
        between.append(np.mean(read_grid(g, xi, h, t) ** 2 / s2, axis=0))
        fixed = np.concatenate([[0.0], -turb.wind_speed * lags])  # xi of p . e = 0 at t and t + lag
        pairs.append(read_grid(g, fixed, np.full(fixed.size, h_rows[row]), t)[:, 0])
    node, between, pairs = np.array(node), np.array(between), np.array(pairs)

    def mean_hw(a):
        return a.mean(axis=0), 1.96 * a.std(axis=0, ddof=1) / math.sqrt(len(a))

    corr = [float(np.corrcoef(pairs[:, 0], pairs[:, 1 + k])[0, 1]) for k in range(lags.size)]
    return {"node": mean_hw(node), "between": mean_hw(between), "lags": lags, "field_corr": np.array(corr),
            "model_corr": _model_correlation(turb, float(h_rows[row]), lags), "grid_m": geo.n_xi * geo.dxi,
            "height": float(h_rows[row]), "dxi": geo.dxi, "dh": geo.dh}


def _print(env: str, scenario: str, turb, r: dict, seeds: int, points: int) -> None:
    def cells(pair):
        return "   ".join(f"{m:.3f} +- {w:.3f}" for m, w in zip(*pair, strict=True))

    print(f"{env} {scenario}: {turb.model} ({turb.low_frequencies}, record {turb.record:g}), grid "
          f"{r['grid_m']:.0f} m along the wind, dxi "
          f"{r['dxi']:g} m, dh {r['dh']:g} m; {seeds} seeds x {points} points")
    print(f"  g^2 / sigma_k^2 (u, v, w) at the grid's nodes:  {cells(r['node'])}")
    print(f"  g^2 / sigma_k^2 (u, v, w) at random points:     {cells(r['between'])}")
    lags = " / ".join(f"{v:g}" for v in r["lags"])
    print(f"  u correlation at lags {lags} s (p . e = 0, h = {r['height']:g} m): field "
          + " / ".join(f"{v:.3f}" for v in r["field_corr"]) + "; the model's, unbounded: "
          + " / ".join(f"{v:.3f}" for v in r["model_corr"]))


def main(argv: list[str] | None = None) -> int:
    from laddermill_gym.atmosphere.disturbance_spec import disturbance_from_spec
    from laddermill_gym.studies.commands import Parser, UsageError, check_number, run_guarded
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    p = Parser(prog="python -m laddermill_gym.studies.gusts.grid_sampling", description=__doc__.split("\n\n")[0])
    p.add_argument("--suite", default="gusts-v1", help="a suite name or file (default gusts-v1)")
    p.add_argument("--env", nargs="*", default=["laddermill_gym/TetheredWing-v0"], help="env ids of the suite")
    p.add_argument("--seeds", type=int, default=100, help="fields drawn per scenario [-]")
    p.add_argument("--points", type=int, default=200, help="nodes and random points read per field [-]")
    p.add_argument("--lags", type=float, nargs="*", default=[20.0, 40.0], help="[s] u's correlation lags")
    p.add_argument("--record", type=float, default=None, help="draw the fields with this Turbulence.record (the "
                   "synthesised record in grid lengths) instead of the suite's")
    a = p.parse_args(argv)

    def run() -> int:
        check_number("--seeds", a.seeds, low=2, high=100000, integer=True, strict=False)
        check_number("--points", a.points, low=1, high=100000, integer=True, strict=False)
        for lag in a.lags:
            check_number("--lags", lag, low=0, high=86400, unit="s", strict=False)
        suite = load_suite(a.suite)
        for env in a.env:
            if env not in suite.envs:
                raise UsageError(f"--env {env!r}: suite {suite.name} has {sorted(suite.envs)}")
            for s in suite.envs[env][1]:
                for i, spec in enumerate(s.disturbances):
                    if spec.get("type") == "Turbulence":
                        given = dict(spec) if a.record is None else dict(spec, record=a.record)
                        turb = disturbance_from_spec(given, f"{s.name}.disturbances[{i}]")
                        _print(env, s.name, turb, grid_sampling(turb, s.duration, a.seeds, a.points, a.lags),
                               a.seeds, a.points)
        return 0

    return run_guarded("grid-sampling", run)


if __name__ == "__main__":
    raise SystemExit(main())
