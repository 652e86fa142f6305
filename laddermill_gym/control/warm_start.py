"""Start a PPO policy with a linear actor at a model-based controller (``init_from: lqr`` in a training config).

The LQR of the single craft is affine in the raw observation before its clip to [-1, 1]: a = clip(W o + b). A
PPO actor without hidden layers (``policy_kwargs.net_arch.pi: []``) is affine in the normalised observation,
mean = A z + c with z = (o - m) / s; so A = W diag(s) and c = W m + b put the PPO policy's mean exactly at the
LQR's action (SB3 clips actions to the action space as the LQR clips its own). PPO then improves the policy from
there under the training disturbances, with its own exploration noise (``log_std_init``).

* :func:`affine_map` measures W and b of a controller at one observation by finite differences (exact for an
  affine map within its unclipped region: the controller is probed there only);
* :func:`observation_statistics` runs the controller on the training env and returns the mean and variance of
  the observations (the normalisation's statistics, then held fixed: the actor's gains depend on them);
* :func:`warm_start` sets a PPO model's actor and a ``VecNormalize``'s statistics and clip (:data:`CLIP_OBS`).
"""

from __future__ import annotations

import copy

import numpy as np

__all__ = ["affine_map", "observation_statistics", "warm_start", "start_residual", "start_from", "VAR_INFLATION",
           "INIT_STEPS", "CLIP_OBS"]

#: The observation variance of the controller's rollouts is multiplied by this [-] (std x 2) before it becomes the
#: normalisation's: with the normalised observation clipped to +-CLIP_OBS (100), excursions up to 200 of the
#: rollouts' standard deviations (the large gusts the LQR meets in evaluation) still reach the actor unclipped.
VAR_INFLATION = 4.0
#: The clip of the normalised observation [-] (SB3's VecNormalize default 10): with 10 the started policy left the
#: LQR where the turbulence of gusts-v1's NTM_IB moved the wing 65 m sideways (more than 10 of the rollouts'
#: doubled standard deviations) and crashed in one of its three seeds, where the LQR survives; 100 keeps it linear
CLIP_OBS = 100.0
#: Steps per copy [-] of the controller's rollouts that give the statistics: 30 s of flight at 0.05 s, more than a
#: lateral period of either craft (23 s, 15 s), so the training disturbances have moved the copies
INIT_STEPS = 600
#: Relative probe of :func:`affine_map` [-]: o_i + h_i with h_i = PROBE (1 + |o_i|)
PROBE = 1e-4


def affine_map(controller, obs0: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(W (n_actions, obs_dim), b (n_actions,)) with ``controller``'s deterministic action a = W o + b near the
    raw observation ``obs0`` (obs_dim,). ValueError when the action at obs0 is clipped (|a| >= 1): the map is
    then not measurable there."""
    obs0 = np.asarray(obs0, dtype=np.float64)
    if getattr(controller, "action_dtype", None) is not None:  # probe in float64: float32 actions would put
        controller = copy.copy(controller)  # their rounding (6e-8) / PROBE into the gains (the LQR controllers)
        controller.action_dtype = np.float64
    probes = np.repeat(obs0[None], obs0.size + 1, axis=0)
    h = PROBE * (1.0 + np.abs(obs0))
    probes[1:][np.diag_indices(obs0.size)] += h
    acts = np.asarray(controller.predict(probes, deterministic=True)[0], dtype=np.float64)
    if np.any(np.abs(acts) >= 1.0):
        raise ValueError(f"affine_map: the controller's action at the probe observations reaches the clip "
                         f"({np.abs(acts).max():.3g}); probe it nearer its trim")
    W = ((acts[1:] - acts[0]) / h[:, None]).T
    return W, acts[0] - W @ obs0


def observation_statistics(controller, venv, n_steps: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(mean, variance, first observation of copy 0) of the raw observations of ``venv`` (an SB3 VecEnv of the
    training env) over ``n_steps`` steps of every copy driven by ``controller``."""
    obs = venv.reset()
    first = np.array(obs[0], dtype=np.float64)
    total = np.zeros(obs.shape[1])
    total_sq = np.zeros(obs.shape[1])
    count = 0
    for _ in range(n_steps):
        action = controller.predict(obs, deterministic=True)[0]
        obs = venv.step(action)[0]
        total += obs.sum(axis=0)
        total_sq += (obs.astype(np.float64) ** 2).sum(axis=0)
        count += obs.shape[0]
    mean = total / count
    return mean, np.maximum(total_sq / count - mean ** 2, 0.0), first


def warm_start(model, vecnormalize, controller, raw_venv, n_steps: int) -> dict:
    """Put ``model``'s (a PPO with a linear actor) action mean at ``controller``'s action: observation statistics
    from ``n_steps`` steps of ``raw_venv`` (the training env below ``vecnormalize``) under the controller, set
    into ``vecnormalize`` and held fixed (``training = False``); the actor's weights from :func:`affine_map`.
    Returns a summary (the largest gain and the probe's trim observation)."""
    import torch

    net = model.policy.action_net
    if model.policy.mlp_extractor.latent_dim_pi != raw_venv.observation_space.shape[0]:
        raise ValueError("warm_start: the actor has hidden layers; set policy_kwargs.net_arch.pi: [] (a linear "
                         "actor) to start it at a linear controller")
    mean, var, first = observation_statistics(controller, raw_venv, n_steps)
    var = VAR_INFLATION * var
    W, b = affine_map(controller, first)
    std = np.sqrt(var + vecnormalize.epsilon)
    vecnormalize.obs_rms.mean, vecnormalize.obs_rms.var = mean, var
    vecnormalize.obs_rms.count = float(n_steps * raw_venv.num_envs)
    vecnormalize.training, vecnormalize.clip_obs = False, CLIP_OBS
    with torch.no_grad():
        net.weight.copy_(torch.as_tensor(W * std[None, :], dtype=net.weight.dtype))
        net.bias.copy_(torch.as_tensor(W @ mean + b, dtype=net.bias.dtype))
    vecnormalize.reset()
    return dict(max_gain=float(np.abs(W).max()), trim_observation=first)


def start_residual(model, controller, raw_venv, n_steps: int) -> dict:
    """Set ``model``'s ``ResidualPolicy`` (control/residual_policy.py, PPO) or ``ResidualSACPolicy``
    (control/residual_sac.py, SAC) base at ``controller`` (the LQR) and its normalisation at the statistics of
    ``n_steps`` steps of ``raw_venv`` under the controller (variance x :data:`VAR_INFLATION`, clip
    :data:`CLIP_OBS`, as :func:`warm_start`). Returns the largest gain."""
    mean, var, _ = observation_statistics(controller, raw_venv, n_steps)
    model.policy.set_base(controller, mean, VAR_INFLATION * var, CLIP_OBS)
    return dict(max_gain=float(np.abs(controller.gains).max()))


def start_from(cfg, model, vecnormalize) -> dict:
    """:func:`warm_start` of ``model`` at the controller ``cfg.init_from`` (``lqr`` or ``lqr:<config>``, built by
    ``make_controller`` for the training's env arguments) on the training env below ``vecnormalize``."""
    from laddermill_gym.control.factory import make_controller

    ctrl = make_controller(cfg.init_from, cfg.env_id, cfg.carried_env_kwargs())
    if hasattr(model.policy, "set_base"):  # a residual policy (PPO or SAC): raw observations, ``vecnormalize`` is
        # the env itself
        return start_residual(model, ctrl, vecnormalize.venv, INIT_STEPS)
    return warm_start(model, vecnormalize, ctrl, vecnormalize.venv, INIT_STEPS)
