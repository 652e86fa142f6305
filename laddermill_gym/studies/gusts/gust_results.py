"""The gust benchmark's results (``laddermill gust-bench``, :mod:`laddermill_gym.studies.gusts.gust_bench`): the
per-(env, controller, scenario) summary, the files (``gust_bench.csv``, ``gust_bench.json``, ``scorecard_<env>.png``)
and what a run records beside its rows (the suite's name, version and file SHA-256, the package's version, a digest
of its source, each env's arguments).

A folder collects a suite's runs: a run into a folder that holds an earlier run's results of the same suite file,
package version and source merges its rows into them (a row per env, scenario, controller and seed; this run's
replace the earlier ones of the same key), so the benchmark run once per env into one folder (docs/wind.md) keeps
every env's rows and scorecards. Results of another suite, version, file, package version or source are refused
before any episode, unless ``--force`` replaces them. ``gust_bench.json`` is strict JSON: a value that is not a
finite number (a settling time never reached) is ``null``.
"""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np

from laddermill_gym.studies.commands import UsageError
from laddermill_gym.studies.gusts.gust_suite import Suite

__all__ = ["RESULT_FILES", "SUMMARY_METRICS", "run_provenance", "config_digest", "summarise", "json_safe",
           "earlier_rows", "merge_rows", "write_outputs"]

#: the files of a run's rows (the scorecards beside them are ``scorecard_<env>.png``)
RESULT_FILES = ("gust_bench.csv", "gust_bench.json")
#: the row metrics the summary takes the median of over seeds (nan-aware)
SUMMARY_METRICS = ("t_end_s", "max_lateral_m", "rms_lateral_m", "energy_ratio", "peak_tension_ratio",
                   "settling_time_s", "control_effort")
#: the fields of gust_bench.json that must agree for a run's rows to merge with a folder's
_SAME = ("suite", "version", "suite_sha256", "package_version", "source_digest", "config_digest")


def run_provenance(suite: Suite, env_ids) -> dict:
    """What a run's figures depend on beside the suite's scenarios: the suite file's SHA-256, per env the arguments
    it was built with (the registered ones merged with the suite's, ``envs.registered_arguments``: scene, physics
    step, control period), the package's version, a digest of its source (``studies.parallel.source_digest``) and
    one of the files every env of the suite reads (:func:`config_digest`; the suite's envs, not the run's, so runs of
    one env each merge). A suite fixes its scenarios; the physics is the env id's, so a result is read with the
    arguments it ran on."""
    from laddermill_gym import __version__
    from laddermill_gym.envs import registered_arguments
    from laddermill_gym.studies.parallel import source_digest

    every = {e: registered_arguments(e, suite.envs[e][0]) for e in suite.envs}  # the digest: the suite's, not the
    arguments = {e: every[e] for e in env_ids}  # run's envs (a run per env merges into one folder)
    return {"suite_sha256": suite.sha256, "package_version": __version__, "source_digest": source_digest(),
            "config_digest": config_digest(every), "env_arguments": arguments}


def config_digest(env_arguments: dict) -> str:
    """SHA-256 (hex) of the data the envs read beside the code: every file of the package's shipped configs (scenes,
    wings and their tables, cables, crafts, rotors) and every existing file an env argument names by path (a scene
    or craft of the user's; the files such a file names in turn are not followed)."""
    import hashlib

    from laddermill_gym.model.configio import CONFIG_DIR

    files = sorted(f for f in Path(CONFIG_DIR).rglob("*") if f.is_file() and "__pycache__" not in f.parts)
    named = sorted({str(v) for kw in env_arguments.values() for v in _values(kw)
                    if isinstance(v, (str, Path)) and str(v).endswith((".yaml", ".yml", ".csv")) and Path(v).is_file()})
    digest = hashlib.sha256()
    for f in files:
        digest.update(f.relative_to(CONFIG_DIR).as_posix().encode() + b"\0" + f.read_bytes())
    for f in named:
        digest.update(str(Path(f).resolve()).encode() + b"\0" + Path(f).read_bytes())
    return digest.hexdigest()


def _values(value):
    """Every leaf value of nested mappings and sequences."""
    if isinstance(value, dict):
        for v in value.values():
            yield from _values(v)
    elif isinstance(value, (list, tuple)):
        for v in value:
            yield from _values(v)
    else:
        yield value


def summarise(rows: list[dict]) -> list[dict]:
    """Per (env, controller, scenario): ``n`` seeds, ``survived`` (the share of them survived), the medians of
    :data:`SUMMARY_METRICS` over the seeds (nan-aware; ``t_end_s`` over every seed, survivors' full episodes
    included) and ``t_fail_s``, the median end time [s] over the failed seeds only (nan when none failed)."""
    groups: dict[tuple, list[dict]] = {}
    for r in rows:
        groups.setdefault((r["env"], r["controller"], r["scenario"]), []).append(r)
    out = []
    for (env_id, ctrl, scen), rs in groups.items():
        s = {"env": env_id, "controller": ctrl, "scenario": scen, "n": len(rs),
             "survived": sum(bool(r["survived"]) for r in rs) / len(rs)}
        for k in SUMMARY_METRICS:
            s[k] = _median([r[k] for r in rs])
        s["t_fail_s"] = _median([r["t_end_s"] for r in rs if not r["survived"]])
        out.append(s)
    return out


def _median(values: list) -> float:
    v = np.array([math.nan if x is None else x for x in values], dtype=float)
    return float(np.nanmedian(v)) if np.isfinite(v).any() else math.nan


def json_safe(value):
    """``value`` with every float that is not finite (nan, inf) replaced by None, at every depth (dicts, lists,
    tuples; numpy scalars as Python numbers), for ``json.dump(..., allow_nan=False)``."""
    if isinstance(value, dict):
        return {k: json_safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_safe(v) for v in value]
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def _nan(row: dict) -> dict:
    """A row read back from gust_bench.json: null (a value that was not finite) as nan again."""
    return {k: math.nan if v is None else v for k, v in row.items()}


def earlier_rows(out: Path, suite: Suite, env_ids, force: bool = False) -> list[dict]:
    """The rows an earlier run left in ``out`` to merge this run's into (:func:`merge_rows`): [] when it holds no
    results (or ``force``: this run replaces them); UsageError naming the folder, checked before any episode, when
    they are not gust_bench.json's rows of the same suite name, version and file (SHA-256), package version and
    source (``env_ids``: this run's envs, for the provenance)."""
    held = [f for f in RESULT_FILES if (out / f).exists()]
    if force or not held:
        return []
    where = f"--out = {str(out)!r}"
    again = "give another --out, or --force to replace them"
    path = out / "gust_bench.json"
    try:
        data = json.loads(path.read_text())
        rows = data["rows"]
    except (OSError, ValueError, KeyError, TypeError) as err:
        raise UsageError(f"{where}: holds {', '.join(held)} but no readable gust_bench.json rows to merge with "
                         f"({type(err).__name__}: {err}); {again}") from None
    mine = {"suite": suite.name, "version": suite.version, **run_provenance(suite, env_ids)}
    for key in _SAME:
        if data.get(key) != mine[key]:
            raise UsageError(f"{where}: holds results of {key} {data.get(key)!r}, not this run's {mine[key]!r} (a "
                             f"run's rows merge only with those of the same {', '.join(_SAME)}); {again}")
    return [_nan(r) for r in rows]


def _key(row: dict) -> tuple:
    return row["env"], row["scenario"], row["controller"], int(row["seed"])


def merge_rows(earlier: list[dict], rows: list[dict]) -> list[dict]:
    """``earlier`` rows with those of ``rows`` of the same (env, scenario, controller, seed) replaced in place, then
    the other ``rows`` in their order."""
    new = {_key(r): r for r in rows}
    old = {_key(r) for r in earlier}
    return [new.get(_key(r), r) for r in earlier] + [r for r in rows if _key(r) not in old]


def write_outputs(rows: list[dict], suite: Suite, out: Path) -> list[Path]:
    """``gust_bench.csv`` (one row per env, controller, scenario and seed), ``gust_bench.json`` (strict JSON: the
    suite's name, version and file, the provenance of :func:`run_provenance`, the rows and per-(env, controller,
    scenario) summaries of :func:`summarise`) and ``scorecard_<env>.png`` per env of the rows; returns the paths."""
    out.mkdir(parents=True, exist_ok=True)
    paths = [out / "gust_bench.csv", out / "gust_bench.json"]
    with open(paths[0], "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    summary = summarise(rows)
    data = {"suite": suite.name, "version": suite.version, "file": str(suite.path),
            **run_provenance(suite, dict.fromkeys(r["env"] for r in rows)), "rows": rows, "summary": summary}
    with open(paths[1], "w") as f:
        json.dump(json_safe(data), f, indent=1, allow_nan=False)
    from laddermill_gym.studies.gusts.gust_scorecard import plot_scorecard

    for env_id in dict.fromkeys(r["env"] for r in rows):
        paths.append(plot_scorecard([s for s in summary if s["env"] == env_id], env_id, suite.name,
                                    out / f"scorecard_{env_id.split('/')[-1]}.png"))
    return paths
