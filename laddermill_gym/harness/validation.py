"""The optional training phases of :mod:`laddermill_gym.control.rl_phases` as the training loop applies them.

* :func:`freeze_actor`: the critic-only phase (``critic_warmup``) sets the actor's weights and its action noise
  (``log_std``) to need no gradient, so PPO's optimiser (Adam skips parameters without a gradient) updates the
  critic alone; the learning rate of that phase replaces the config's until it ends.
* :func:`validate`: the deterministic policy on every validation set (``run_episodes`` of the gust benchmark: one
  vector-env copy per episode, copy i seeded ``seed + i``, ``seed`` the set's own or the validation's,
  :func:`set_seeds`; sets of one turbulence model on shared seeds are warned of, :func:`warn_shared_fields`), each
  validated policy first saved as the checkpoint of its step; scored by the episodes survived, then by the smaller
  RMS lateral excursion (:func:`score`); with ``selection.rule: paired`` by the episodes survived minus ``penalty``
  x the episodes the reference controller (flown once per run, same seeds) survives and the policy loses
  (:func:`lost_to_reference`), then the smaller RMS.
"""

from __future__ import annotations

import csv
import math
import time

import numpy as np

__all__ = ["TrainingPhases", "freeze_actor", "set_learning_rate", "validate", "set_seeds", "shared_fields",
           "warn_shared_fields", "benchmark_overlaps", "check_held_out", "selection_overlaps", "score",
           "lost_to_reference", "VALIDATION_FIELDS"]

#: columns of a run's ``validation.csv``
VALIDATION_FIELDS = ("steps", "minutes", "survived", "episodes", "rms_lateral_m", "per_set", "lost_to_reference",
                     "score", "selected")


def freeze_actor(model, frozen: bool) -> None:
    """Make the actor of ``model`` (an SB3 PPO: ``policy.action_net``, ``policy.log_std`` and, when it has hidden
    layers, ``mlp_extractor.policy_net``; a residual policy: its ``actor_parameters()``, SAC's included) need no
    gradient (``frozen``) or need one again."""
    policy = model.policy
    if hasattr(policy, "actor_parameters"):  # control/residual_policy.py (its skip layer too), residual_sac.py
        params = policy.actor_parameters()
    else:
        params = list(policy.action_net.parameters()) + list(policy.mlp_extractor.policy_net.parameters())
        params += [policy.log_std] if hasattr(policy, "log_std") else []
    for p in params:
        p.requires_grad_(not frozen)


def set_learning_rate(model, rate: float) -> None:
    """A constant learning rate for ``model``'s next updates (SB3 reads ``lr_schedule`` before each update)."""
    model.learning_rate = float(rate)
    model.lr_schedule = lambda _progress: float(rate)


def validate(controller, env_id: str, env_kwargs: dict, validation) -> dict:
    """Episodes survived by ``controller`` (``predict`` on raw observations) on every set of ``validation``
    (:class:`~laddermill_gym.control.rl_phases.Validation`) on ``env_id`` with ``env_kwargs`` (the training's
    carried arguments). Returns ``survived``, ``episodes``, ``rms_lateral_m`` (over all episodes' steps),
    ``per_set`` (name -> survived) and ``outcomes`` (name -> tuple of 0/1 per episode, 1 survived, in seed
    order)."""
    from laddermill_gym.studies.gusts.gust_bench import run_episodes

    survived, episodes, sq, steps, per_set, outcomes = 0, 0, 0.0, 0, {}, {}
    for vs in validation.sets:
        seeds = set_seeds(validation, vs)
        rec = run_episodes(controller, env_id, env_kwargs, seeds, validation.episode_time, vs.disturbances)
        alive = tuple(int(f == 0) for f in np.asarray(rec["failure"]))
        ok = sum(alive)
        per_set[vs.name], outcomes[vs.name] = ok, alive
        survived, episodes = survived + ok, episodes + vs.episodes
        sq, steps = sq + float(np.sum(rec["lateral_sq"])), steps + int(np.sum(rec["steps"]))
    return dict(survived=survived, episodes=episodes, rms_lateral_m=math.sqrt(sq / max(steps, 1)), per_set=per_set,
                outcomes=outcomes)


def set_seeds(validation, vs) -> list[int]:
    """The episode seeds of the validation set ``vs``: from its own ``seed`` (None: the validation's), one per
    episode."""
    first = validation.seed if vs.seed is None else vs.seed
    return list(range(first, first + vs.episodes))


def _turbulence_models(vs) -> set[str]:
    return {str(d.get("model")) for d in vs.disturbances if d.get("type") == "Turbulence"}


def shared_fields(validation) -> list[tuple[str, str, str]]:
    """(set, set, model) for every two validation sets with a turbulence of the same ``model`` whose episode seeds
    overlap (:func:`set_seeds`): the same seed draws the same field of a model (NTM IA's is NTM IB's, scaled), so
    those episodes test one field twice."""
    out = []
    sets = list(validation.sets)
    for i, a in enumerate(sets):
        for b in sets[i + 1:]:
            if set(set_seeds(validation, a)) & set(set_seeds(validation, b)):
                out += [(a.name, b.name, m) for m in sorted(_turbulence_models(a) & _turbulence_models(b))]
    return out


def benchmark_overlaps(cfg) -> list[str]:
    """What of ``cfg``'s validation flies a shipped gust suite's episodes (a test set selected on): for every set
    and every scenario of the suites (``configs/benchmarks``) for an id of the config's task, the seeds both use
    where the two have the same disturbances or a turbulence of the same model (the same seed draws the same field
    of a model, scaled). Each entry names the set, the scenario, the suites that hold it and the seeds."""
    from laddermill_gym.envs import same_task
    from laddermill_gym.studies.gusts.gust_suite import SHIPPED_SHA256, load_suite

    if cfg.validation is None:
        return []
    found: dict[tuple, list[str]] = {}  # (set, scenario, seeds) -> the suites
    for name in SHIPPED_SHA256:
        suite = load_suite(name)
        for env_id, (_kw, scenarios) in suite.envs.items():
            if not same_task(env_id, cfg.env_id):
                continue
            for vs in cfg.validation.sets:
                for sc in scenarios:
                    same = [dict(d) for d in sc.disturbances] == [dict(d) for d in vs.disturbances] or \
                        _turbulence_models(vs) & {str(d.get("model")) for d in sc.disturbances
                                                  if d.get("type") == "Turbulence"}
                    common = sorted(set(set_seeds(cfg.validation, vs)) & set(sc.seeds))
                    if same and common:
                        suites = found.setdefault((vs.name, sc.name, tuple(common)), [])
                        suites += [name] if name not in suites else []
    return [f"validation set {v!r} flies scenario {sc} of {', '.join(suites)} (seeds {list(seeds)})"
            for (v, sc, seeds), suites in found.items()]


def check_held_out(cfg) -> None:
    """ConfigError naming ``cfg``'s file and its validation sets that fly a shipped gust suite's episodes
    (:func:`benchmark_overlaps`): a benchmark is the test, never a selection's data."""
    from laddermill_gym.model.configio import ConfigError

    found = benchmark_overlaps(cfg)
    if found:
        raise ConfigError(f"{cfg.file}: field 'validation': " + "; ".join(found) + ": a benchmark's episodes would "
                          "select the policy it then scores (give the validation or the set another seed)")


def selection_overlaps(validation, set_name: str, seeds) -> list[str]:
    """The validation sets of ``validation`` (a config's) that fly any of ``seeds`` on the set ``set_name``'s fields:
    that set itself, and those with a turbulence of one of its models (the same fields, scaled); each entry names
    the set and the first and last seed shared."""
    sets = {vs.name: vs for vs in validation.sets}
    models = _turbulence_models(sets[set_name])
    out = []
    for vs in validation.sets:
        if vs.name == set_name or models & _turbulence_models(vs):
            common = sorted(set(set_seeds(validation, vs)) & set(seeds))
            if common:
                out.append(f"{vs.name} (seeds {common[0]} .. {common[-1]})")
    return out


def warn_shared_fields(cfg) -> None:
    """A UserWarning naming the config file (``cfg.file``) and the sets of :func:`shared_fields`, if any. The
    selection is not changed (the shipped policies were selected so); a set's own ``seed`` separates them."""
    import warnings

    if cfg.validation is None:
        return
    shared = shared_fields(cfg.validation)
    if shared:
        pairs = "; ".join(f"{a} and {b} ({m})" for a, b, m in shared)
        warnings.warn(f"{cfg.file}: validation sets {pairs} draw their turbulence with the same seeds, so they fly "
                      "the same fields scaled; give one of each pair a seed of its own (validation.sets.<name>.seed) "
                      "for other fields", UserWarning, stacklevel=2)


def lost_to_reference(result: dict, reference: dict) -> int:
    """Episodes the ``reference`` result survives and ``result`` loses: both :func:`validate` results of the same
    sets and seeds (their ``outcomes``, paired episode by episode). ValueError when the sets or counts differ."""
    ours, theirs = result["outcomes"], reference["outcomes"]
    if list(ours) != list(theirs) or any(len(ours[k]) != len(theirs[k]) for k in ours):
        raise ValueError(f"unpaired validation results: sets {[(k, len(v)) for k, v in ours.items()]} against the "
                         f"reference's {[(k, len(v)) for k, v in theirs.items()]}")
    return sum(int(r == 1 and o == 0) for k in ours for o, r in zip(ours[k], theirs[k], strict=True))


def score(result: dict, selection=None) -> tuple[float, float]:
    """The order of validation results (larger is better). ``selection`` None or ``rule: survived``
    (:class:`~laddermill_gym.control.rl_phases.Selection`): more episodes survived, then a smaller RMS lateral
    excursion. ``rule: paired``: episodes survived minus ``selection.penalty`` x ``result["lost_to_reference"]``
    (:func:`lost_to_reference`), then the smaller RMS."""
    if selection is None or selection.rule == "survived":
        return result["survived"], -result["rms_lateral_m"]
    return result["survived"] - selection.penalty * result["lost_to_reference"], -result["rms_lateral_m"]


class TrainingPhases:
    """The phases as methods of the training's SB3 callback (which sets ``cfg``, ``out``, ``pbar`` and ``t0`` and
    provides ``_vecnorm()``, ``_save_best(vecnormalize)`` and ``_save_checkpoint()``): the critic warm-up from the
    first step, the validations every ``validation.every`` steps (``validation.csv``; each validated policy saved
    as ``checkpoints/step_<n>.zip``, the best so far as the best model)."""

    best_val: dict | None = None
    next_val: int = 0
    actor_free: bool = False

    def _on_training_start(self) -> None:
        warn_shared_fields(self.cfg)
        if self.cfg.critic_warmup is not None:  # the critic alone first (control/rl_phases.py)
            freeze_actor(self.model, True)
            self.saved_rate = (self.model.learning_rate, self.model.lr_schedule)
            set_learning_rate(self.model, self.cfg.critic_warmup.learning_rate)

    def validate(self, final: bool = False):
        """The validation sets (control/rl_phases.py); the best policy so far kept as best_model.zip. ``final``: the
        model after training, which SB3 updated once more after the last step's callback: its checkpoint and row
        replace those of a validation at the same step count."""
        from laddermill_gym.control.sb3_policy import SB3Controller

        vn = self._vecnorm()
        self._save_checkpoint(force=final)  # the policy validated here, on disk as checkpoints/step_<n>.zip
        ctrl = SB3Controller(self.model, *((vn.obs_rms.mean, vn.obs_rms.var, vn.clip_obs, vn.epsilon)
                                           if vn is not None else ()))
        res = validate(ctrl, self.cfg.env_id, self.cfg.carried_env_kwargs(), self.cfg.validation)
        sel = self.cfg.validation.selection
        if sel.rule == "paired":
            res["lost_to_reference"] = lost_to_reference(res, self.reference_result())
        selected = self.best_val is None or score(res, sel) > score(self.best_val, sel)
        if selected:
            self.best_val = res
            self._save_best(vn)
        self.val_rows = getattr(self, "val_rows", [])
        if self.val_rows and self.val_rows[-1]["steps"] == self.num_timesteps:  # the final model at the same count
            self.val_rows.pop()
        shown = {k: v for k, v in res.items() if k != "outcomes"}
        shown.setdefault("lost_to_reference", "")
        self.val_rows.append(dict(steps=self.num_timesteps, minutes=round((time.perf_counter() - self.t0) / 60, 3),
                                  **shown, score=score(res, sel)[0], selected=int(selected)))
        with open(self.out / "validation.csv", "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(VALIDATION_FIELDS))
            w.writeheader()
            w.writerows(self.val_rows)
        self.pbar.write(f"validation at {self.num_timesteps} steps: {res['survived']}/{res['episodes']} survived "
                        f"{res['per_set']}, RMS lateral {res['rms_lateral_m']:.2f} m"
                        + (f", {res['lost_to_reference']} lost that {sel.reference} holds" if sel.rule == "paired"
                           else "") + (" (kept)" if selected else ""))

    def reference_result(self) -> dict:
        """The paired rule's reference controller on the validation sets, flown once per run (same seeds)."""
        if getattr(self, "_reference", None) is None:
            from laddermill_gym.control.factory import make_controller

            cfg = self.cfg
            kw = cfg.carried_env_kwargs()
            self._reference = validate(make_controller(cfg.validation.selection.reference, cfg.env_id, kw),
                                       cfg.env_id, kw, cfg.validation)
            self.pbar.write(f"reference {cfg.validation.selection.reference}: {self._reference['survived']}/"
                            f"{self._reference['episodes']} survived {self._reference['per_set']}")
        return self._reference

    def _phases(self) -> None:
        warm = self.cfg.critic_warmup
        if warm is not None and not self.actor_free and self.num_timesteps >= warm.steps:
            freeze_actor(self.model, False)
            self.model.learning_rate, self.model.lr_schedule = self.saved_rate
            self.actor_free = True
        if self.cfg.validation is not None and self.num_timesteps >= self.next_val:
            self.validate()
            self.next_val = self.num_timesteps + self.cfg.validation.every
