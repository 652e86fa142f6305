"""The optional training phases of :mod:`laddermill_gym.control.rl_phases` as the training loop applies them.

* :func:`freeze_actor`: the critic-only phase (``critic_warmup``) sets the actor's weights and its action noise
  (``log_std``) to need no gradient, so PPO's optimiser (Adam skips parameters without a gradient) updates the
  critic alone; the learning rate of that phase replaces the config's until it ends.
* :func:`validate`: the deterministic policy on every validation set (``run_episodes`` of the gust benchmark: one
  vector-env copy per episode, copy i seeded ``seed + i``), scored by the episodes survived, then by the smaller
  RMS lateral excursion (:func:`score`).
"""

from __future__ import annotations

import csv
import math
import time

import numpy as np

__all__ = ["TrainingPhases", "freeze_actor", "set_learning_rate", "validate", "score", "VALIDATION_FIELDS"]

#: columns of a run's ``validation.csv``
VALIDATION_FIELDS = ("steps", "minutes", "survived", "episodes", "rms_lateral_m", "per_set", "selected")


def freeze_actor(model, frozen: bool) -> None:
    """Make the actor of ``model`` (an SB3 PPO: ``policy.action_net``, ``policy.log_std`` and, when it has hidden
    layers, ``mlp_extractor.policy_net``) need no gradient (``frozen``) or need one again."""
    policy = model.policy
    params = list(policy.action_net.parameters()) + list(policy.mlp_extractor.policy_net.parameters())
    if hasattr(policy, "actor_parameters"):  # control/residual_policy.py: its skip layer too
        params = policy.actor_parameters()
    elif hasattr(policy, "log_std"):
        params.append(policy.log_std)
    for p in params:
        p.requires_grad_(not frozen)


def set_learning_rate(model, rate: float) -> None:
    """A constant learning rate for ``model``'s next updates (SB3 reads ``lr_schedule`` before each update)."""
    model.learning_rate = float(rate)
    model.lr_schedule = lambda _progress: float(rate)


def validate(controller, env_id: str, env_kwargs: dict, validation) -> dict:
    """Episodes survived by ``controller`` (``predict`` on raw observations) on every set of ``validation``
    (:class:`~laddermill_gym.control.rl_phases.Validation`) on ``env_id`` with ``env_kwargs`` (the training's
    carried arguments). Returns ``survived``, ``episodes``, ``rms_lateral_m`` (over all episodes' steps) and
    ``per_set`` (name -> survived)."""
    from laddermill_gym.studies.gusts.gust_bench import run_episodes

    survived, episodes, sq, steps, per_set = 0, 0, 0.0, 0, {}
    for vs in validation.sets:
        seeds = list(range(validation.seed, validation.seed + vs.episodes))
        rec = run_episodes(controller, env_id, env_kwargs, seeds, validation.episode_time, vs.disturbances)
        ok = int(np.sum(np.asarray(rec["failure"]) == 0))
        per_set[vs.name] = ok
        survived, episodes = survived + ok, episodes + vs.episodes
        sq, steps = sq + float(np.sum(rec["lateral_sq"])), steps + int(np.sum(rec["steps"]))
    return dict(survived=survived, episodes=episodes, rms_lateral_m=math.sqrt(sq / max(steps, 1)), per_set=per_set)


def score(result: dict) -> tuple[int, float]:
    """The order of validation results: more episodes survived, then a smaller RMS lateral excursion."""
    return result["survived"], -result["rms_lateral_m"]


class TrainingPhases:
    """The phases as methods of the training's SB3 callback (which sets ``cfg``, ``out``, ``pbar`` and ``t0`` and
    provides ``_vecnorm()`` and ``_save_best(vecnormalize)``): the critic warm-up from the first step, the
    validations every ``validation.every`` steps (``validation.csv``; the best so far saved as the best model)."""

    best_val: dict | None = None
    next_val: int = 0
    actor_free: bool = False

    def _on_training_start(self) -> None:
        if self.cfg.critic_warmup is not None:  # the critic alone first (control/rl_phases.py)
            freeze_actor(self.model, True)
            self.saved_rate = (self.model.learning_rate, self.model.lr_schedule)
            set_learning_rate(self.model, self.cfg.critic_warmup.learning_rate)

    def validate(self):
        """The validation sets (control/rl_phases.py); the best policy so far kept as best_model.zip."""
        from laddermill_gym.control.sb3_policy import SB3Controller

        vn = self._vecnorm()
        ctrl = SB3Controller(self.model, *((vn.obs_rms.mean, vn.obs_rms.var, vn.clip_obs, vn.epsilon)
                                           if vn is not None else ()))
        res = validate(ctrl, self.cfg.env_id, self.cfg.carried_env_kwargs(), self.cfg.validation)
        selected = self.best_val is None or score(res) > score(self.best_val)
        if selected:
            self.best_val = res
            self._save_best(vn)
        self.val_rows = getattr(self, "val_rows", [])
        self.val_rows.append(dict(steps=self.num_timesteps, minutes=round((time.perf_counter() - self.t0) / 60, 3),
                                  **res, selected=int(selected)))
        with open(self.out / "validation.csv", "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(VALIDATION_FIELDS))
            w.writeheader()
            w.writerows(self.val_rows)
        self.pbar.write(f"validation at {self.num_timesteps} steps: {res['survived']}/{res['episodes']} survived "
                        f"{res['per_set']}, RMS lateral {res['rms_lateral_m']:.2f} m{' (kept)' if selected else ''}")

    def _phases(self) -> None:
        warm = self.cfg.critic_warmup
        if warm is not None and not self.actor_free and self.num_timesteps >= warm.steps:
            freeze_actor(self.model, False)
            self.model.learning_rate, self.model.lr_schedule = self.saved_rate
            self.actor_free = True
        if self.cfg.validation is not None and self.num_timesteps >= self.next_val:
            self.validate()
            self.next_val = self.num_timesteps + self.cfg.validation.every
