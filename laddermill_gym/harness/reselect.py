"""Select among a training run's saved policies again, on another config's validation sets.

A run keeps its checkpoints (``checkpoints/step_<n>.zip``, every ``checkpoint_every`` steps), its last model and
its validated best; with the observation statistics held fixed (``init_from``) one ``vecnormalize.pkl`` serves them
all. This flies each of them (and, as a reference, a controller such as ``lqr``) on the validation sets of a config
(:func:`~laddermill_gym.harness.validation.validate`: drawn episodes, never a benchmark suite's) and names the one
that survives the most (then the smaller RMS lateral excursion, :func:`~laddermill_gym.harness.validation.score`),
or, when the config's ``validation.selection`` is ``rule: paired``, the one with the most survived minus ``penalty``
x the episodes its reference controller (flown once, added to the references if not named) survives and it loses.

    python -m laddermill_gym.harness.reselect --config configs/agents/ppo_tethered_wing_severe.yaml \\
        --runs runs/ppo_tethered_wing_seed0 --reference lqr --out results/reselect.csv

Every policy a training validated is on disk as the checkpoint of its step (``checkpoints/step_<n>.zip``, saved at
each validation, beside those of ``checkpoint_every``; an older run holds only the latter, which its validations,
made ``n_envs`` steps later, did not fly), so flown on the training's own config this ranks a superset of the
policies the training ranked, by the same score on the unrounded RMS: where its pick is a validated step, it is the
one ``laddermill train <config> --seed <s>`` kept (the training is deterministic for a seed up to its time limit).
"""

from __future__ import annotations

import argparse
import csv
import re
import time
from pathlib import Path

__all__ = ["candidates", "load_candidate", "reselect", "run_names", "main"]

_STEP = re.compile(r"step_(\d+)\.zip$")


def candidates(run: Path, name: str | None = None) -> list[tuple[str, Path, Path]]:
    """(label, model file, statistics file) of every policy saved in the training run folder ``run``: its
    checkpoints in step order, ``best_model.zip`` and ``model.zip``, labelled ``<name>/<stem>`` (``name``: the
    folder's name by default). FileNotFoundError naming the folder when it holds none or lacks the statistics a
    model needs (a run trained with ``normalize_observations: false``, whose policy normalises itself, has none)."""
    run = Path(run)
    name = run.name if name is None else name
    found = []
    ckpts = sorted((run / "checkpoints").glob("step_*.zip"), key=lambda p: int(_STEP.search(p.name).group(1)))
    for p in ckpts:  # the statistics saved with the checkpoint; a run from before 2026-12-06 saved only its last
        own = p.with_name(p.stem + "_vecnormalize.pkl")
        found.append((f"{name}/{p.stem}", p, own if own.is_file() else run / "vecnormalize.pkl"))
    for file, stats in (("best_model.zip", "best_vecnormalize.pkl"), ("model.zip", "vecnormalize.pkl")):
        if (run / file).is_file():
            found.append((f"{name}/{Path(file).stem}", run / file, run / stats))
    if not found:
        raise FileNotFoundError(f"{run}: no checkpoints/step_*.zip, best_model.zip or model.zip (a training run "
                                "folder of laddermill train?)")
    if _config_field(run / "config.yaml", "normalize_observations", True) is not False:
        for label, _model, stats in found:
            if not stats.is_file():
                raise FileNotFoundError(f"{stats}: missing; {label} needs its observation statistics")
    return found


def run_names(runs: list[str | Path]) -> list[str]:
    """A label prefix per run folder: its name, or where two runs share a name, the path as given (ValueError
    for a folder named twice)."""
    paths = [Path(r) for r in runs]
    resolved = [p.resolve() for p in paths]
    for i, r in enumerate(resolved):
        if r in resolved[:i]:
            raise ValueError(f"--runs: {paths[i]} is named twice (as {paths[resolved.index(r)]})")
    names = [p.name for p in paths]
    return [p.name if names.count(p.name) == 1 else str(p) for p in paths]


def load_candidate(model_file: Path, stats: Path, env_id: str, env_kwargs: dict):
    """The policy in ``model_file`` with the observation statistics ``stats`` (a path that need not exist: none),
    loaded and checked as ``make_controller`` loads a path (:func:`~laddermill_gym.control.factory.load_policy`):
    the run's algorithm.txt, its statistics' shape, and ValueError naming the file for a policy trained on another
    env than ``env_id``, with other control settings or other observation or action sizes. Its actions come through
    torch, as the training's validations fly it (``exact=False``)."""
    from laddermill_gym.control.factory import load_policy

    return load_policy(model_file, env_id, env_kwargs, statistics=stats, exact=False)


def _config_field(config: Path, field: str, default):
    """A top-level field of a run folder's ``config.yaml`` (``default`` without the file or the field)."""
    from laddermill_gym.model.configio import load_yaml_text

    data = load_yaml_text(config.read_text(), str(config)) if config.is_file() else None  # YAML 1.2, as training
    return data.get(field, default) if isinstance(data, dict) else default


def reselect(config: str | Path, runs: list[str | Path], reference: list[str] = (), out: str | Path | None = None,
             log=print) -> list[dict]:
    """Rows (label, survived, episodes, per-set counts, RMS lateral, seconds, selected) of every policy saved in
    ``runs`` and of the ``reference`` controllers (factory specs), on ``config``'s validation sets; the selected
    row is the best policy of the runs (references are never selected) by the config's ``validation.selection``
    (:func:`~laddermill_gym.harness.validation.score`; rows carry ``lost_to_reference``, blank under the default
    rule, and ``score``). Written to ``out`` (CSV) when given."""
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.harness.validation import (
        check_held_out,
        lost_to_reference,
        score,
        validate,
        warn_shared_fields,
    )

    if not runs and not reference:
        raise ValueError("nothing to fly: name training run folders (--runs) or reference controllers (--reference)")
    cfg = load_rl_config(config)
    if cfg.validation is None:
        raise ValueError(f"{config}: no validation section (the sets to select on)")
    check_held_out(cfg)
    warn_shared_fields(cfg)
    kw = cfg.carried_env_kwargs()
    sel = cfg.validation.selection
    reference = list(reference) + ([sel.reference] if sel.rule == "paired" and sel.reference not in reference else [])
    jobs = [(spec, None, None) for spec in reference]
    for run, name in zip(runs, run_names(runs), strict=True):
        jobs += candidates(Path(run), name)
    loaded = []
    for label, model_file, stats in jobs:  # every one loaded and checked before any flies (a bad file fails at once)
        t0 = time.process_time()
        ctrl = make_controller(label, cfg.env_id, kw) if model_file is None else \
            load_candidate(model_file, stats, cfg.env_id, kw)
        loaded.append((label, ctrl, model_file is None, time.process_time() - t0))
    rows, results = [], []  # results[i]: row i's, as validated
    for label, ctrl, is_reference, load_s in loaded:
        t0 = time.process_time() - load_s
        res = validate(ctrl, cfg.env_id, kw, cfg.validation)
        results.append(res)
        rows.append(dict(label=label, survived=res["survived"], episodes=res["episodes"], per_set=res["per_set"],
                         rms_lateral_m=round(res["rms_lateral_m"], 3), cpu_s=round(time.process_time() - t0, 1),
                         reference=int(is_reference), selected=0))
        log(f"{label}: {res['survived']}/{res['episodes']} {res['per_set']} RMS lateral "
            f"{res['rms_lateral_m']:.2f} m ({rows[-1]['cpu_s']} CPU s)")
    paired_with = results[reference.index(sel.reference)] if sel.rule == "paired" else None
    ranked = []  # row i's result as scored: the raw RMS (the rows show it rounded), as the training ranks
    for r, res in zip(rows, results, strict=True):
        r["lost_to_reference"] = lost_to_reference(res, paired_with) if sel.rule == "paired" else ""
        ranked.append(dict(res, lost_to_reference=r["lost_to_reference"]))
        r["score"] = score(ranked[-1], sel)[0]
        r["selected"] = r.pop("selected")  # the last column
    policies = [i for i, r in enumerate(rows) if not r["reference"]]
    if policies:  # the first of equal scores, in step order: the training keeps a later one only if it is better
        best = rows[max(policies, key=lambda i: score(ranked[i], sel))]
        best["selected"] = 1
        log(f"selected: {best['label']} ({best['survived']}/{best['episodes']}"
            + (f", {best['lost_to_reference']} lost that {sel.reference} holds, score {best['score']:g}"
               if sel.rule == "paired" else "") + ")")
    if out is not None:
        Path(out).parent.mkdir(parents=True, exist_ok=True)
        with open(out, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)
    return rows


def main(argv: list[str] | None = None) -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--config", required=True, help="training config whose validation sets select")
    p.add_argument("--runs", nargs="+", default=[], help="training run folders (checkpoints/, best_model.zip)")
    p.add_argument("--reference", nargs="*", default=[], help="controllers flown as references (lqr, ...)")
    p.add_argument("--out", default=None, help="CSV of the rows")
    a = p.parse_args(argv)
    try:
        reselect(a.config, a.runs, a.reference, a.out)
    except (ValueError, OSError) as e:
        p.error(str(e))


if __name__ == "__main__":
    main()
