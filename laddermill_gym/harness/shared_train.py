"""Train a parameter-shared per-wing policy of the mill (issue 31 point 2) from one config:

    laddermill train configs/agents/ppo_mill_v1.yaml [--out runs/ppo_mill_v1] [--minutes M]

Two phases, one policy (:mod:`laddermill_gym.control.shared_policy`: a gain-scheduled linear actor on each slot's
local observation, the same weights for every slot):

1. **Imitation (DAgger; Ross et al. 2011, AISTATS)**: the LQR (``make_controller("lqr", env)``, the centralised
   design that sees every slot) labels every slot's rudder and aileron at the states visited; iteration 0 flies
   the LQR, later iterations fly the learner, and the labels of all iterations are aggregated; each iteration
   fits the actor's weights by ridge regression (least squares of the features, whose normal equations are
   accumulated). What is learnt here is learnt from the LQR's actions, not from reward.
2. **PPO (Schulman et al. 2017) fine-tuning** of that policy on the per-wing reward (``multiagent.agents``:
   shared power and failure terms, local lateral, rate and effort terms) with the shared-policy VecEnv (every
   slot of ``n_copies`` copies one env), starting from the cloned weights with a small action noise.

Every ``eval.every`` steps (and after each DAgger iteration) the policy is flown deterministically on the
single-agent env's registered scenario (the paper's 0.01 rad step at 1 s) for ``eval.episode_time`` seconds,
seeds 0 .. n - 1; ``model.zip`` is the best evaluation (most episodes held, then longest, then smallest
lateral excursion), ``last_model.zip`` the last, ``bc_model.zip`` the best cloned policy (PPO's start),
``checkpoints/<phase>_<step>.zip`` every evaluated one. The run folder also gets ``training_curve.csv`` / ``.png``
(with the LQR's figures on the same episodes), ``config.yaml`` and ``shared_policy.yaml`` (what
``make_controller(<run folder>, env)`` needs). Observations are not normalised by running statistics: the actor
divides the lateral deviations by the LQR config's fixed Bryson scales, so no VecNormalize file is written.
"""

from __future__ import annotations

import csv
import shutil
import sys
import time
from pathlib import Path

import numpy as np
import yaml
from tqdm import tqdm

from laddermill_gym.control.rl_config import carried_settings
from laddermill_gym.harness.run_record import write_run_record
from laddermill_gym.harness.shared_config import SharedTrainConfig, load_shared_config
from laddermill_gym.harness.shared_fit import band_weights, bryson_scales
from laddermill_gym.harness.shared_teacher import linear_teacher, make_teacher
from laddermill_gym.studies.commands import Parser

__all__ = ["train_shared", "main", "CURVE_FIELDS"]

CURVE_FIELDS = ("phase", "step", "minutes", "held", "mean_length_s", "mean_power_kW", "max_lateral_m",
                "mean_return")


def _policy_kwargs(cfg: SharedTrainConfig, view, trim, scales) -> dict:
    from laddermill_gym.control.shared_policy import GainScheduledExtractor

    return dict(features_extractor_class=GainScheduledExtractor,
                features_extractor_kwargs=dict(n_agents=view.n_agents, k=cfg.k, block=view.block,
                                               n_basis=cfg.n_basis, trim=np.asarray(trim).tolist(),
                                               scales=np.asarray(scales).tolist()),
                net_arch=dict(pi=[], vf=list(cfg.value_net)), log_std_init=cfg.log_std_init, ortho_init=False)


class Evaluator:
    """Deterministic episodes of the single-agent env (registered scenario, ``episode_time``) for a model."""

    def __init__(self, cfg: SharedTrainConfig, meta: dict):
        import gymnasium as gym

        from laddermill_gym.multiagent.agents import WingAgents, build_task

        kw = {k: v for k, v in cfg.env_kwargs.items() if k not in ("episode_time", "initial_noise", "reward")}
        self.env = gym.make_vec(cfg.env_id, num_envs=cfg.eval_episodes, vectorization_mode="vector_entry_point",
                                episode_time=cfg.eval_time, **kw)
        self.view = WingAgents(build_task(cfg.env_id, 1, kw), cfg.env_id, cfg.k)
        self.meta, self.eval_time = meta, cfg.eval_time

    def run(self, controller) -> dict:
        from laddermill_gym.harness.evaluate import run_episodes

        r = run_episodes(controller, self.env, record=False)
        return dict(held=int(np.sum(r.lengths_s >= self.eval_time - 1e-6)), mean_length_s=float(r.lengths_s.mean()),
                    mean_power_kW=float(r.mean_power_W.mean() / 1e3), max_lateral_m=float(r.max_lateral_m.max()),
                    mean_return=float(r.returns.mean()))

    def policy(self, model):
        from laddermill_gym.control.shared_policy import SharedPolicyController

        return SharedPolicyController(model, self.view, Path("<training>"), self.meta)


def _score(row: dict) -> tuple:
    """Most episodes held, then the longest, then the smallest lateral excursion."""
    return (row["held"], row["mean_length_s"], -row["max_lateral_m"])


def teacher_labels(teacher, obs: np.ndarray) -> np.ndarray:
    """The teacher's actions (B, n_actions) at single-agent observations ``obs``: for an LQR (the mill's
    :class:`~laddermill_gym.control.mill_lqr.MillLQRController` or the chain's
    :class:`~laddermill_gym.control.lqr.LQRController`) its linear law before the clip to [-1, 1]
    (``harness.shared_teacher``: the controller and the env clip both the same way), so that the labels are the
    linear map the actor can represent; any other controller: its ``predict``."""
    lin = linear_teacher(teacher)
    if lin is None:
        return np.asarray(teacher.predict(obs, deterministic=True)[0], dtype=float)
    return lin.labels(obs)


def _fit(model, S: np.ndarray, Bz: np.ndarray, yy: np.ndarray, ridge: float) -> np.ndarray:
    """The actor's weights from the per-slot sums S_i = sum z z^T (n, f, f) and Bz_i = sum z y^T (n, f, a): the
    normal equations of the features h(i) (outer) z are G = sum_i (h_i h_i^T) (kron) S_i, b = sum_i h_i (kron) Bz_i;
    solved as (G + ridge diag(G)) W = b (a ridge relative to each feature's own second moment, so the features'
    scales do not matter), slot by slot when the hat functions are one per slot (G block diagonal). Returns the
    fit's R^2 per action entry (1 - residual / label second moment, from the same sums) and every slot's weights
    (n, f, a)."""
    import torch as th

    from laddermill_gym.control.shared_policy import hat_basis

    n, f, na = Bz.shape
    nb = model.policy.features_extractor.n_basis
    H = hat_basis(th.arange(n, dtype=th.float64) / max(n - 1, 1), nb).numpy()  # (n, nb)
    if nb == n and np.allclose(H, np.eye(n)):
        blocks = []
        for i in range(n):
            G = S[i]
            D = np.diag(np.diag(G)) + 1e-12 * max(np.trace(G), 1e-300) / f * np.eye(f)
            blocks.append(np.linalg.solve(G + ridge * D, Bz[i]))
        W = np.concatenate(blocks)
        G = None
    else:
        G = np.einsum("ib,ic,ifg->bfcg", H, H, S).reshape(nb * f, nb * f)
        b = np.einsum("ib,ifa->bfa", H, Bz).reshape(nb * f, na)
        D = np.diag(np.diag(G)) + 1e-12 * np.trace(G) / G.shape[0] * np.eye(G.shape[0])
        W = np.linalg.solve(G + ridge * D, b)
    net = model.policy.action_net
    with th.no_grad():
        net.weight.copy_(th.as_tensor(W.T, dtype=net.weight.dtype))
        net.bias.zero_()
    Wi = np.einsum("ib,bfa->ifa", H, W.reshape(nb, f, na))  # every slot's effective weights
    residual = yy - 2 * np.einsum("ifa,ifa->a", Wi, Bz) + np.einsum("ifa,ifg,iga->a", Wi, S, Wi)
    return 1.0 - residual / np.maximum(yy, 1e-300), Wi


def imitation(cfg: SharedTrainConfig, model, venv, teacher, log, pbar) -> None:
    """DAgger (see the module doc): ``cfg.bc_iterations`` rounds of ``cfg.bc_steps`` control steps of every
    copy, the teacher's actions as labels, a ridge fit of the actor after each; the flown actions (the teacher's
    in round 1, the learner's after) get Gaussian noise of std ``cfg.bc_action_noise`` so that the data excite
    every direction; ``log(phase, step)`` evaluates."""
    import torch as th

    ext, task, n = model.policy.features_extractor, venv.task, venv.view.n_agents
    B, na = venv.num_envs // n, venv.view.act_dim
    f = ext.features_dim // ext.n_basis
    S, Bz, yy = np.zeros((n, f, f)), np.zeros((n, f, na)), np.zeros(na)
    rng = np.random.default_rng(cfg.seed)
    band, lin = None, linear_teacher(teacher)
    if lin is not None:
        from laddermill_gym.harness.gain_locality import banded

        band = band_weights(banded(lin.K, cfg.k), lin.half, ext.scales.numpy(), cfg.k)
    obs = venv.reset()
    for it in range(cfg.bc_iterations):
        for _ in range(cfg.bc_steps):
            labels = teacher_labels(teacher, task.obs).reshape(venv.num_envs, na)
            with th.no_grad():
                z = ext.local_features(th.as_tensor(obs))[0].double().numpy().reshape(B, n, f)
            y = labels.reshape(B, n, na)
            S += np.einsum("bif,big->ifg", z, z)
            Bz += np.einsum("bif,bia->ifa", z, y)
            yy += np.sum(labels ** 2, axis=0)
            act = labels if it == 0 else model.predict(obs, deterministic=True)[0]
            act = np.clip(act + cfg.bc_action_noise * rng.standard_normal(act.shape), -1.0, 1.0)
            obs = venv.step(act)[0]
            pbar.update(1)
        r2, Wi = _fit(model, S, Bz, yy, cfg.bc_ridge)
        msg = f"DAgger round {it + 1}: R^2 of the fit (elevator, rudder, aileron) {np.round(r2, 4)}"
        if band is not None:  # how far the fitted gains are from the LQR's own, cut to the band
            cols = list(lin.column)
            err = np.linalg.norm(Wi[:, :-1, cols] - band) / np.linalg.norm(band)
            msg += f"; gain error vs the LQR's band-{cfg.k} gain {err:.4f}"
        tqdm.write(msg)
        log("imitation", it + 1)


def _ppo_callback(cfg: SharedTrainConfig, log, pbar, t_end: float):
    from stable_baselines3.common.callbacks import BaseCallback

    class Callback(BaseCallback):
        def __init__(self):
            super().__init__()
            self.next_eval = cfg.eval_every

        def _on_step(self) -> bool:
            pbar.update(self.model.num_timesteps - pbar.n)
            if self.model.num_timesteps >= self.next_eval:
                log("ppo", int(self.model.num_timesteps))
                self.next_eval += cfg.eval_every
            return time.perf_counter() < t_end

    return Callback()


def new_model(cfg: SharedTrainConfig, venv, policy_kwargs: dict):
    """The PPO model (cfg's seed and hyperparameters, on the CPU) of the shared policy on ``venv``."""
    from stable_baselines3 import PPO

    return PPO("MlpPolicy", venv, seed=cfg.seed, policy_kwargs=policy_kwargs, device="cpu", verbose=0,
               **cfg.hyperparameters)


def ppo_phase_model(cfg: SharedTrainConfig, model, ppo_env, policy_kwargs: dict, env_seed: int):
    """The PPO phase's model on ``ppo_env`` when it has another number of envs than the DAgger model ``model``
    (``ppo.n_copies`` != ``imitation.n_copies``; SB3's ``set_env`` takes only the same number): a model built as
    the first (the same seed, hyperparameters and so learning-rate schedule; its rollout buffer sized for
    ``ppo_env``), carrying ``model``'s policy: the weights and buffers (the extractor's trim and scales) and the
    optimizer's state. Building it seeds python, numpy and torch with ``cfg.seed`` and draws the same initial
    weights as the first build, so torch's generator is where the DAgger model's stood (DAgger draws nothing from
    it: its fits are least squares, its actions deterministic); ``ppo_env``'s copies are seeded again from its
    ``env_seed`` (copy b from ``env_seed + b``: SB3 seeds the env with the model's seed, which would replay the
    DAgger copies' draws). No running normalisation exists to carry (module doc)."""
    new = new_model(cfg, ppo_env, policy_kwargs)
    new.policy.load_state_dict(model.policy.state_dict())
    new.policy.optimizer.load_state_dict(model.policy.optimizer.state_dict())
    ppo_env.seed(env_seed)
    return new


def plot_curve(out: Path, rows: list[dict], lqr: dict | None) -> Path:
    """Episodes held and mean power against wall time, the LQR's as dashed lines."""
    from laddermill_gym.figure_files import subplots
    from laddermill_gym.plotting import save_figure

    fig, (a1, a2) = subplots(2, 1, figsize=(6.5, 6), sharex=True)
    for phase, style in (("imitation", "o-"), ("ppo", "s-")):
        r = [x for x in rows if x["phase"] == phase]
        a1.plot([x["minutes"] for x in r], [x["mean_length_s"] for x in r], style, label=phase)
        a2.plot([x["minutes"] for x in r], [x["mean_power_kW"] for x in r], style, label=phase)
    if lqr:
        a1.axhline(lqr["mean_length_s"], ls="--", color="k", label="LQR")
        a2.axhline(lqr["mean_power_kW"], ls="--", color="k", label="LQR")
    a1.set_ylabel("mean episode length [s]")
    a2.set_ylabel("mean power [kW]")
    a2.set_xlabel("wall time [min]")
    for a in (a1, a2):
        a.grid(alpha=0.3)
        a.legend()
    return save_figure(fig, out / "training_curve.png")


def train_shared(cfg: SharedTrainConfig, out: Path) -> dict:
    """Run both phases into ``out`` (see the module doc); returns the best evaluation row and the LQR's."""
    import torch as th

    from laddermill_gym.multiagent.sb3 import shared_policy_vec_env

    th.set_num_threads(1)
    t0 = time.perf_counter()
    (out / "checkpoints").mkdir(parents=True, exist_ok=True)
    shutil.copyfile(cfg.file, out / "config.yaml")
    venv = shared_policy_vec_env(cfg.env_id, cfg.bc_copies, k=cfg.k, seed=cfg.seed, **cfg.train_env_kwargs())
    view = venv.view
    teacher = make_teacher(cfg.env_id, cfg.teacher_config,
                           {k: v for k, v in cfg.env_kwargs.items() if k != "initial_noise"})
    meta = dict(env=cfg.env_id, k=cfg.k, n_agents=view.n_agents, obs_dim=view.obs_dim, algorithm="PPO",
                env_kwargs=carried_settings(cfg.env_id, cfg.env_kwargs),
                config=str(cfg.file.name), seed=cfg.seed)
    (out / "shared_policy.yaml").write_text(yaml.safe_dump(meta, sort_keys=False))
    write_run_record(out, cfg.seed)  # the command line, seed, torch threads and package versions
    pk = _policy_kwargs(cfg, view, teacher.trim_attitude, bryson_scales(cfg.env_id, cfg.teacher_config))
    model = new_model(cfg, venv, pk)
    ev = Evaluator(cfg, meta)
    lqr = ev.run(teacher)
    print(f"LQR on the evaluation episodes: {lqr}")
    rows: list[dict] = []
    best = {"row": None}

    def log(phase: str, step: int) -> None:
        row = dict(phase=phase, step=step, minutes=round((time.perf_counter() - t0) / 60, 2),
                   **ev.run(ev.policy(model)))
        rows.append(row)
        tqdm.write(f"{phase} {step}: {row}")
        model.save(out / "checkpoints" / f"{phase}_{step}.zip")
        if best["row"] is None or _score(row) > _score(best["row"]):
            best["row"] = row
            best["state"] = {key: v.clone() for key, v in model.policy.state_dict().items()}
            model.save(out / "model.zip")
        model.save(out / "last_model.zip")
        with open(out / "training_curve.csv", "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(CURVE_FIELDS))
            w.writeheader()
            w.writerows(rows)

    with tqdm(total=cfg.bc_iterations * cfg.bc_steps, unit="step", desc="imitation (DAgger)") as pbar:
        imitation(cfg, model, venv, teacher, log, pbar)
    model.policy.load_state_dict(best["state"])  # PPO starts from the best DAgger round (a later fit can be worse)
    model.save(out / "bc_model.zip")
    t_end = t0 + 60 * min(cfg.time_limit_minutes, (time.perf_counter() - t0) / 60 + cfg.ppo_minutes)
    if cfg.ppo_timesteps > 0 and time.perf_counter() < t_end:
        if cfg.ppo_copies != cfg.bc_copies:  # `log` flies and saves the PPO phase's model from here on
            ppo_env = shared_policy_vec_env(cfg.env_id, cfg.ppo_copies, k=cfg.k, **cfg.train_env_kwargs())
            model = ppo_phase_model(cfg, model, ppo_env, pk, env_seed=cfg.seed + 1000)
        with tqdm(total=cfg.ppo_timesteps, unit="step", desc="PPO fine-tuning") as pbar:
            model.learn(total_timesteps=cfg.ppo_timesteps, callback=_ppo_callback(cfg, log, pbar, t_end),
                        reset_num_timesteps=True)
        log("ppo", int(model.num_timesteps))
    plot_curve(out, rows, lqr)
    from laddermill_gym.control.shared_policy import export_linear_actor, is_linear_actor

    if is_linear_actor(model.policy):  # the kept model's actor for torch-free evaluation (control/shared_controller)
        export_linear_actor(out / "model.zip")
    with open(out / "lqr_reference.csv", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(lqr))
        w.writeheader()
        w.writerow(lqr)
    return dict(best=best["row"], lqr=lqr, minutes=round((time.perf_counter() - t0) / 60, 2))


def main(argv: list[str] | None = None) -> int:
    p = Parser(prog="laddermill train", description="train a shared per-wing policy (imitation, then PPO)")
    p.add_argument("config", help="configs/agents/ppo_mill_v1.yaml or a shipped config's name")
    p.add_argument("--out", type=Path, help="run folder (default runs/<config name>_seed<seed>)")
    p.add_argument("--minutes", type=float, help="override ppo.time_limit_minutes")
    p.add_argument("--seed", type=int, help="override the config's seed")
    args = p.parse_args(argv)
    cfg = load_shared_config(args.config)
    if args.seed is not None:
        if not 0 <= args.seed < 2 ** 31:
            p.error(f"--seed = {args.seed}: must be in 0 .. 2**31 - 1")
        import dataclasses

        cfg = dataclasses.replace(cfg, seed=int(args.seed))
    if args.minutes is not None:
        if not args.minutes >= 0:
            p.error(f"--minutes = {args.minutes}: must be >= 0")
        import dataclasses

        cfg = dataclasses.replace(cfg, ppo_minutes=float(args.minutes))
    out = args.out or Path("runs") / f"{Path(args.config).stem}_seed{cfg.seed}"
    s = train_shared(cfg, out)
    print(f"trained in {s['minutes']} min; best evaluation {s['best']}; LQR {s['lqr']}; run folder {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
