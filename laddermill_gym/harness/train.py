"""Train a Stable-Baselines3 agent (PPO or SAC) on a laddermill_gym environment from a config file.

    laddermill train configs/agents/ppo_tethered_wing.yaml [--out runs/ppo] [--seed 1]
                           [--timesteps N] [--minutes M] [--torch-threads T]

The run folder gets: ``config.yaml`` (the config used), ``algorithm.txt``, ``run.yaml`` (the command line, seed,
torch threads and package versions: :mod:`~laddermill_gym.harness.run_record`), TensorBoard logs (``tb/``),
checkpoints (``checkpoints/``), ``evaluations.csv`` (deterministic returns on the registered evaluation
scenario, seeds 0 .. n - 1, against wall time and env steps), ``best_model.zip`` (the best evaluation; with a
``validation`` section, the policy that validated best) with ``best_vecnormalize.pkl``, ``model.zip`` (last) with
``vecnormalize.pkl`` (observation statistics) and ``training_curve.png`` (with the LQR and open-loop returns on
the same episodes, also in ``references.csv``).
Training stops at ``total_timesteps`` or ``time_limit_minutes``, whichever comes first. A progress bar shows
steps, episodes and the latest evaluation. Every environment (the wings and Rotorcraft-v0,
configs/agents/ppo_rotorcraft.yaml) trains and evaluates on its batched kernel (:mod:`laddermill_gym.envs.sb3`,
the native vector env).

torch runs on one thread unless ``--torch-threads`` or the environment variable ``LADDERMILL_TORCH_THREADS``
says otherwise: the networks are small (two layers of 64 or 256) and torch's default, one thread per core, spends
more time synchronising its threads than computing (measured by
``python -m laddermill_gym.studies.benchmarks.torch_threads``, docs/rl_zoo3.md).
"""

from __future__ import annotations

import csv
import dataclasses
import os
import sys
import time
from pathlib import Path

import numpy as np
from tqdm import tqdm

from laddermill_gym.control.rl_config import RLConfig, load_rl_config, read_hyperparameters
from laddermill_gym.model.configio import ConfigError, Section
from laddermill_gym.sim.interrupt import stop_requests
from laddermill_gym.studies.commands import Parser, UsageError, check_number, writable_folder


def _evaluate(policy, env, n_episodes: int) -> tuple[np.ndarray, np.ndarray]:
    """Deterministic returns and lengths [s] of ``n_episodes`` copies of the evaluation env (seeds 0..n-1),
    each run to its first end."""
    from laddermill_gym.harness.evaluate import run_episodes

    res = run_episodes(policy, env, n_episodes, record=False)
    return res.returns, res.lengths_s


def make_callback(cfg: RLConfig, out: Path, eval_env, pbar: tqdm, stop=None):
    from stable_baselines3.common.callbacks import BaseCallback

    from laddermill_gym.control.sb3_policy import SB3Controller
    from laddermill_gym.harness.validation import TrainingPhases

    class Harness(TrainingPhases, BaseCallback):
        """Progress bar, time limit, periodic evaluation (best model kept), checkpoints, the config's phases
        (critic warm-up, validation: :class:`~laddermill_gym.harness.validation.TrainingPhases`); training ends at
        the next step after a Ctrl-C (``stop``: a ``sim.interrupt.StopRequest``)."""

        def __init__(self):
            super().__init__()
            self.cfg, self.out, self.pbar = cfg, out, pbar
            self.t0 = time.perf_counter()
            self.next_eval = 0
            self.next_ckpt = cfg.checkpoint_every
            self.best = -np.inf
            self.rows = []
            self.halted = False  # the time limit stopped the training (no update after the last callback)

        def _vecnorm(self):
            from stable_baselines3.common.vec_env import VecNormalize

            return self.model.get_env() if isinstance(self.model.get_env(), VecNormalize) else None

        def evaluate(self):
            vn = self._vecnorm()
            ctrl = SB3Controller(self.model, *((vn.obs_rms.mean, vn.obs_rms.var, vn.clip_obs, vn.epsilon)
                                               if vn is not None else ()))
            returns, lengths = _evaluate(ctrl, eval_env, cfg.eval_episodes)
            minutes = (time.perf_counter() - self.t0) / 60
            row = dict(steps=self.num_timesteps, minutes=round(minutes, 3), mean_return=float(np.mean(returns)),
                       min_return=float(np.min(returns)), mean_length_s=float(np.mean(lengths)))
            if self.rows and self.rows[-1]["steps"] == row["steps"]:  # the final model (SB3's last update after
                self.rows.pop()  # the last step's callback) replaces the row of the same step count
            self.rows.append(row)
            self.logger.record("eval/mean_return", row["mean_return"])
            self.logger.record("eval/mean_length_s", row["mean_length_s"])
            if row["mean_return"] > self.best:
                self.best = row["mean_return"]
                if cfg.validation is None:  # with a validation the best model is the validated one
                    self._save_best(vn)
            with open(out / "evaluations.csv", "w", newline="") as fh:
                w = csv.DictWriter(fh, fieldnames=list(row))
                w.writeheader()
                w.writerows(self.rows)
            pbar.set_postfix(eval_return=f"{row['mean_return']:.1f}", best=f"{self.best:.1f}")

        def _save_best(self, vn):
            self.model.save(out / "best_model.zip")
            if vn is not None:
                vn.save(str(out / "best_vecnormalize.pkl"))

        def _save_checkpoint(self, force: bool = False):
            """The policy now as ``checkpoints/step_<n>.zip`` with the statistics it acts with (once per step n unless
            ``force``: a validation saves the policy it validates, so every validated policy is a checkpoint reselect
            reads)."""
            if self.num_timesteps == getattr(self, "checkpoint_step", None) and not force:
                return
            self.model.save(out / "checkpoints" / f"step_{self.num_timesteps}.zip")
            if (vn := self._vecnorm()) is not None:  # the statistics the checkpoint acts with
                vn.save(str(out / "checkpoints" / f"step_{self.num_timesteps}_vecnormalize.pkl"))
            self.checkpoint_step = self.num_timesteps

        def _on_step(self) -> bool:
            pbar.update(self.num_timesteps - pbar.n)
            self._phases()
            if self.num_timesteps >= self.next_eval:
                self.evaluate()
                self.next_eval = self.num_timesteps + cfg.eval_every
            if self.num_timesteps >= self.next_ckpt:
                self._save_checkpoint()
                self.next_ckpt += cfg.checkpoint_every
            if stop is not None and stop.requested:
                return False
            self.halted = (time.perf_counter() - self.t0) >= 60.0 * cfg.time_limit_minutes  # SB3 then stops at once
            return not self.halted

    return Harness()


def plot_curve(out: Path, rows: list[dict], reference: dict[str, float] | None = None) -> Path:
    """Evaluation return against wall time, with horizontal reference lines (e.g. LQR, open loop)."""
    from laddermill_gym.figure_files import subplots
    from laddermill_gym.plotting import save_figure

    fig, ax = subplots(figsize=(6.5, 4))
    ax.plot([r["minutes"] for r in rows], [r["mean_return"] for r in rows], "o-", label="agent (deterministic)")
    for i, (name, value) in enumerate((reference or {}).items()):
        ax.axhline(value, ls="--", color=f"C{i + 1}", label=name)
    ax.set_xlabel("wall time [min]")
    ax.set_ylabel("evaluation return [-]")
    ax.grid(alpha=0.3)
    ax.legend()
    return save_figure(fig, out / "training_curve.png")


def reference_returns(cfg: RLConfig, eval_env) -> dict[str, float]:
    """Mean returns of the model-based controllers (LQR, open loop) on the evaluation episodes, for the
    training curve; empty where the action layout does not suit them (grouped or angle-of-attack actions)."""
    from laddermill_gym.control.factory import make_controller

    kw = cfg.carried_env_kwargs()
    refs = {}
    for spec in ("lqr", "open_loop"):
        try:
            ctrl = make_controller(spec, cfg.env_id, kw)
        except ValueError as err:
            print(f"no {spec} reference: {err}")
            continue
        refs[spec] = float(np.mean(_evaluate(ctrl, eval_env, cfg.eval_episodes)[0]))
    return refs


def training_env(cfg: RLConfig):
    """The SB3 VecEnv of ``cfg.n_envs`` seeded training copies on the environment's batched task."""
    from laddermill_gym.envs.sb3 import sb3_vec_env

    return sb3_vec_env(cfg.env_id, cfg.n_envs, seed=cfg.seed, **cfg.train_env_kwargs())


def evaluation_env(cfg: RLConfig):
    """``cfg.eval_episodes`` copies of the registered evaluation scenario: the native vector env."""
    import gymnasium as gym

    return gym.make_vec(cfg.env_id, num_envs=cfg.eval_episodes, vectorization_mode="vector_entry_point",
                        **cfg.eval_env_kwargs())


#: environment variable naming torch's thread count when ``--torch-threads`` is not given
TORCH_THREADS_VAR = "LADDERMILL_TORCH_THREADS"


def torch_threads(requested: int | None = None) -> int:
    """The torch thread count for training: ``requested`` (``--torch-threads``), else the environment variable
    :data:`TORCH_THREADS_VAR`, else 1. Raises ValueError naming the option or variable and a value that is not a
    whole number >= 1."""
    if requested is not None:
        source, value = "--torch-threads", requested
    elif os.environ.get(TORCH_THREADS_VAR, "").strip():
        source, value = TORCH_THREADS_VAR, os.environ[TORCH_THREADS_VAR].strip()
    else:
        return 1
    try:
        n = int(value)
    except ValueError:
        n = 0
    if n < 1 or str(n) != str(value).strip():
        raise ValueError(f"{source} = {value!r}: must be a whole number >= 1 (torch's thread count)")
    return n


#: the config fields the command line overrides: (field, option)
OVERRIDES = (("seed", "--seed"), ("total_timesteps", "--timesteps"), ("time_limit_minutes", "--minutes"),
             ("n_envs", "--n-envs"))


def saved_config(cfg: RLConfig) -> str:
    """The config file's text with the command line's overrides written in (each top-level line ``field: value``
    replaced, or added), so that the run folder's config.yaml is what was trained."""
    import re

    text = Path(cfg.file).read_text()
    original = load_rl_config(cfg.file)
    for field, option in OVERRIDES:
        value = getattr(cfg, field)
        if value == getattr(original, field):
            continue
        line = f"{field}: {value!r}  # laddermill train {option} {value!r} (the file said {getattr(original, field)!r})"
        text, n = re.subn(rf"^{field}:[^\n]*$", line, text, count=1, flags=re.M)
        if n == 0:
            text = text.rstrip("\n") + "\n" + line + "\n"
    return text


def build_model(cfg: RLConfig, out: Path):
    """(model, training VecEnv, evaluation env) of ``cfg``: the SB3 algorithm on the training copies (normalised
    when the config says), its actor started at ``init_from``; TensorBoard logs to go to ``out / tb``. Writes
    nothing: a config that fails here leaves no run folder behind."""
    import stable_baselines3 as sb3
    from stable_baselines3.common.vec_env import VecMonitor, VecNormalize

    from laddermill_gym.control.policy_names import policy_class

    venv = VecMonitor(training_env(cfg))
    if cfg.normalize_observations:
        venv = VecNormalize(venv, norm_obs=True, norm_reward=False, clip_obs=10.0)
    eval_env = evaluation_env(cfg)
    model = getattr(sb3, cfg.algorithm)(policy_class(cfg.policy), venv, seed=cfg.seed,
                                        policy_kwargs=cfg.policy_kwargs or None, tensorboard_log=str(out / "tb"),
                                        verbose=0, device="cpu", **cfg.hyperparameters)
    if cfg.init_from is not None:  # the linear actor started at the LQR (control/warm_start.py)
        from laddermill_gym.control.warm_start import start_from

        print(f"actor started at {cfg.init_from}: largest gain {start_from(cfg, model, venv)['max_gain']:.3g}")
    return model, venv, eval_env


#: files whose presence marks a folder as holding a training run already
RUN_FILES = ("config.yaml", "run.yaml", "model.zip", "best_model.zip", "evaluations.csv")


def apply_overrides(cfg: RLConfig, over: dict) -> RLConfig:
    """``cfg`` with the command line's overrides ``over`` (fields of :data:`OVERRIDES` -> values), each checked:
    ``--seed`` 0 .. 2**32 - 1, ``--n-envs`` 1 .. 4096, ``--timesteps`` a whole number > 0, ``--minutes`` > 0, and
    the config's limits that depend on them (a PPO minibatch within a rollout of n_steps x n_envs, learning_starts
    within total_timesteps, the critic warm-up below total_timesteps). UsageError naming the option and value."""
    for k, option in OVERRIDES:
        if k in over:
            check_number(option, over[k], low=0, strict=k != "seed", integer=k != "time_limit_minutes",
                         high=2 ** 32 - 1 if k == "seed" else 4096 if k == "n_envs" else None)
    if not over:
        return cfg
    cfg = dataclasses.replace(cfg, **over)
    given = " ".join(f"{o} {over[k]}" for k, o in OVERRIDES if k in over)
    try:
        read_hyperparameters(Section({"hyperparameters": dict(cfg.hyperparameters)}, cfg.file), cfg.algorithm,
                             cfg.n_envs, cfg.total_timesteps)
    except ConfigError as err:
        raise UsageError(f"{err}, with {given}") from None
    if cfg.critic_warmup is not None and cfg.critic_warmup.steps >= cfg.total_timesteps:
        raise UsageError(f"{cfg.file}: field 'critic_warmup.steps' = {cfg.critic_warmup.steps} must be below "
                         f"total_timesteps = {cfg.total_timesteps} (the actor would never train), with {given}")
    return cfg


def train(cfg: RLConfig, out: Path, threads: int | None = None, command: list[str] | None = None) -> dict:
    """Train according to ``cfg`` into the folder ``out`` with ``threads`` torch threads (None:
    :func:`torch_threads`); ``command``: the command line recorded in ``run.yaml`` (default ``sys.argv``). The
    model is built before anything is written, so a config SB3 refuses leaves ``out`` free. Returns a summary dict."""
    import torch

    from laddermill_gym.harness.run_record import write_run_record
    from laddermill_gym.harness.validation import check_held_out

    torch.set_num_threads(torch_threads(threads))
    held = [f for f in RUN_FILES if (out / f).exists()]
    if held:  # a second run there would mix its files with the first's (statistics included)
        raise FileExistsError(f"{out}: holds a training run already ({', '.join(held)}); give another --out or "
                              "delete it")
    check_held_out(cfg)  # a validation on a benchmark's own episodes is refused before anything is built
    model, venv, eval_env = build_model(cfg, out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "checkpoints").mkdir(exist_ok=True)
    (out / "config.yaml").write_text(saved_config(cfg))
    (out / "algorithm.txt").write_text(cfg.algorithm + "\n")
    write_run_record(out, cfg.seed, command)
    t0 = time.perf_counter()
    with (tqdm(total=cfg.total_timesteps, unit="step", desc=f"{cfg.algorithm} {cfg.env_id}", smoothing=0.05) as pbar,
          stop_requests("Ctrl-C: ending the training after the current step and saving the model (Ctrl-C again to "
                        "abort)") as stop):
        cb = make_callback(cfg, out, eval_env, pbar, stop)
        model.learn(total_timesteps=cfg.total_timesteps, callback=cb, tb_log_name=cfg.algorithm)
        if not stop.requested:  # the final model, unless the callback evaluated it and stopped the training there (a
            # time limit); at total_timesteps SB3 updates the model once more after the last step's callback
            at_end = lambda rows: cb.halted and rows and rows[-1]["steps"] == model.num_timesteps  # noqa: E731
            if not at_end(cb.rows):
                cb.evaluate()
            if cfg.validation is not None and not at_end(getattr(cb, "val_rows", None)):
                cb.validate(final=True)
    minutes = (time.perf_counter() - t0) / 60
    model.save(out / "model.zip")
    if cfg.normalize_observations:
        venv.save(str(out / "vecnormalize.pkl"))
    if stop.requested:  # the model so far is saved; no reference runs
        if cb.rows:
            plot_curve(out, cb.rows)
        return dict(steps=int(model.num_timesteps), minutes=round(minutes, 2), best_eval_return=cb.best,
                    last_eval_return=cb.rows[-1]["mean_return"] if cb.rows else float("nan"), references={},
                    torch_threads=torch.get_num_threads(), interrupted=True)
    refs = reference_returns(cfg, eval_env)
    with open(out / "references.csv", "w") as fh:
        fh.write("controller,mean_return\n" + "".join(f"{k},{v:.4f}\n" for k, v in refs.items()))
    plot_curve(out, cb.rows, refs)
    summary = dict(steps=int(model.num_timesteps), minutes=round(minutes, 2), best_eval_return=cb.best,
                   last_eval_return=cb.rows[-1]["mean_return"], references=refs, torch_threads=torch.get_num_threads())
    return summary


def main(argv: list[str] | None = None) -> int:
    p = Parser(prog="laddermill train", description=__doc__.split("\n\n")[0])
    p.add_argument("config", help="configs/agents/ppo_*.yaml or sac_*.yaml, or a shipped config's name "
                   "(ppo_tethered_wing)")
    p.add_argument("--out", type=Path, help="run folder (default runs/<config name>_seed<seed>)")
    p.add_argument("--seed", type=int, help="override the config's seed")
    p.add_argument("--timesteps", type=int, help="override total_timesteps")
    p.add_argument("--minutes", type=float, help="override time_limit_minutes")
    p.add_argument("--n-envs", type=int, help="override n_envs")
    p.add_argument("--torch-threads", type=int, help=f"torch threads (default: ${TORCH_THREADS_VAR}, else 1: "
                   "faster than one per core for these small networks)")
    p.add_argument("--replot", action="store_true", help="only redraw the training curve of the run folder "
                   "--out (config: its config.yaml) with the LQR and open-loop references")
    args = p.parse_args(argv)
    from laddermill_gym.harness.shared_config import is_shared_config

    if is_shared_config(args.config):  # a shared per-wing policy (configs/agents/ppo_mill_v1.yaml): its own trainer
        from laddermill_gym.harness.shared_train import main as shared_main

        return shared_main(sys.argv[1:] if argv is None else argv)
    cfg = load_rl_config(args.config)
    if args.replot:
        if args.out is None or not (args.out / "evaluations.csv").is_file():
            p.error("--replot needs --out RUN_FOLDER with an evaluations.csv")
        lines = (args.out / "evaluations.csv").read_text().splitlines()
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(lines)]
        refs = reference_returns(cfg, evaluation_env(cfg))
        print(f"wrote {plot_curve(args.out, rows, refs)}; references {refs}")
        return 0
    given = {"seed": args.seed, "total_timesteps": args.timesteps, "time_limit_minutes": args.minutes,
             "n_envs": args.n_envs}
    try:
        cfg = apply_overrides(cfg, {k: given[k] for k, _ in OVERRIDES if given[k] is not None})
    except UsageError as err:
        p.error(str(err))
    try:
        threads = torch_threads(args.torch_threads)
    except ValueError as err:
        p.error(str(err))
    out = args.out or Path("runs") / f"{Path(args.config).stem}_seed{cfg.seed}"
    try:
        writable_folder(out)  # a bad folder named now, not after the model and its envs are built
    except UsageError as err:
        p.error(str(err))
    try:
        summary = train(cfg, out, threads)
    except FileExistsError as err:
        p.error(f"--out {str(out)!r}: {err}")
    if summary.get("interrupted"):
        print(f"laddermill train: interrupted (Ctrl-C) after {summary['steps']} steps: saved {out / 'model.zip'} "
              f"(and the evaluations so far) (exit status 130)", file=sys.stderr)
        return 130
    print(f"trained {summary['steps']} steps in {summary['minutes']} min ({summary['torch_threads']} torch "
          f"thread(s)); evaluation return best {summary['best_eval_return']:.2f}, last "
          f"{summary['last_eval_return']:.2f}; run folder {out}")
    for name, value in summary["references"].items():
        print(f"  {name} on the same episodes: {value:.2f}")
    return 0


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    raise SystemExit(run_guarded("train", main))
