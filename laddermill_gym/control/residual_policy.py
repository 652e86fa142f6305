"""A PPO policy whose action mean is a fixed linear controller plus a learned residual (``policy: ResidualPolicy``).

mean(o) = W o + b  +  r(z),   r(z) = skip(z) + mlp(z),   z = clip((o - m) / s, -CLIP_OBS, CLIP_OBS)

or, with ``policy_kwargs.residual_limit: L`` (a fraction of each control's half range, 0 < L <= 2), the bounded
residual L tanh(r(z) / L): |mean - (W o + b)| <= L in every action component (the action space is the controls'
[-1, 1], so L is the fraction of the half range), the same slope 1 at r = 0, and still exactly 0 at the start;

* W o + b is the affine map of a model-based controller (the LQR, :func:`~laddermill_gym.control.warm_start.
  affine_map`) on the RAW observation, held in float64 buffers and never trained: the untrained policy's
  deterministic action is the controller's to float64 rounding (the float32 linear actor of ``init_from: lqr``
  with normalised observations reproduces it to about 6e-6 only, and that difference alone flips gusts-v1's
  NTM_IB seed 0);
* skip (a linear layer) and mlp (``net_arch.pi`` hidden layers, then SB3's ``action_net``) see the normalised
  observation z (statistics of the controller's rollouts, held in the policy, so no ``VecNormalize``); both
  last layers start at zero, so training starts exactly at the controller and PPO learns a correction;
* the critic is SB3's (``net_arch.vf``) on z.

The buffers are part of the policy's state dict: SB3's zip format saves and loads them (``PPO.load`` imports this
class by name). :func:`~laddermill_gym.control.warm_start.start_residual` sets them (``init_from: lqr`` with
``policy: ResidualPolicy``).
"""

from __future__ import annotations

import numpy as np
import torch
from stable_baselines3.common.policies import ActorCriticPolicy
from torch import nn

from laddermill_gym.control.lqr_base import lqr_base_actions, register_lqr_base, set_lqr_base

__all__ = ["ResidualPolicy"]


class ResidualPolicy(ActorCriticPolicy):
    """SB3 ``ActorCriticPolicy`` with a fixed float64 affine base and a zero-started residual (module docstring).
    Needs a Box observation and action space; ``share_features_extractor`` as SB3's default (the identity)."""

    def __init__(self, *args, residual_limit: float | None = None, **kwargs) -> None:
        number = isinstance(residual_limit, (int, float)) and not isinstance(residual_limit, bool)
        if residual_limit is not None and not (number and 0.0 < residual_limit <= 2.0):
            raise ValueError(f"ResidualPolicy: residual_limit {residual_limit!r} must be a number in (0, 2] (a "
                             f"fraction of each control's half range) or None (no bound)")
        self.residual_limit = None if residual_limit is None else float(residual_limit)
        super().__init__(*args, **kwargs)

    def _get_constructor_parameters(self) -> dict:
        return {**super()._get_constructor_parameters(), "residual_limit": self.residual_limit}

    def _build(self, lr_schedule) -> None:
        super()._build(lr_schedule)
        n_obs, n_act = self.observation_space.shape[0], self.action_space.shape[0]
        f64 = dict(dtype=torch.float64)
        register_lqr_base(self, n_act)  # the LQR's arguments, float64 buffers (control/lqr_base.py)
        self.register_buffer("obs_mean", torch.zeros(n_obs, **f64))
        self.register_buffer("obs_std", torch.ones(n_obs, **f64))
        self.register_buffer("clip_obs", torch.tensor(100.0, **f64))  # [-] as warm_start.CLIP_OBS (set there)
        self.skip_net = nn.Linear(n_obs, n_act)
        for layer in (self.skip_net, self.action_net):
            nn.init.zeros_(layer.weight)
            nn.init.zeros_(layer.bias)
        self.optimizer = self.optimizer_class(self.parameters(), lr=lr_schedule(1), **self.optimizer_kwargs)

    def actor_parameters(self) -> list:
        """The trained parameters of the action mean and noise (the critic warm-up freezes them)."""
        return (list(self.action_net.parameters()) + list(self.mlp_extractor.policy_net.parameters())
                + list(self.skip_net.parameters()) + [self.log_std])

    def _normalised(self, obs: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        raw = obs.to(torch.float64)
        z = ((raw - self.obs_mean) / self.obs_std).clamp(-self.clip_obs, self.clip_obs)
        return raw, z.to(torch.float32)

    def _distribution(self, raw: torch.Tensor, z: torch.Tensor, latent_pi: torch.Tensor):
        residual = self.action_net(latent_pi) + self.skip_net(z)
        if self.residual_limit is not None:  # L tanh(r / L): within +-L of the base, tanh(0) = 0 exactly
            residual = self.residual_limit * torch.tanh(residual / self.residual_limit)
        mean = (self._lqr(raw) + residual.to(torch.float64)).to(torch.float32)
        return self.action_dist.proba_distribution(mean, self.log_std)

    def _lqr(self, raw: torch.Tensor) -> torch.Tensor:
        """The LQR's unclipped float64 actions of raw observations, by the LQR's code (no gradient)."""
        return lqr_base_actions(self, raw)

    def forward(self, obs: torch.Tensor, deterministic: bool = False):
        raw, z = self._normalised(obs)
        latent_pi, latent_vf = self.mlp_extractor(z)
        dist = self._distribution(raw, z, latent_pi)
        actions = dist.get_actions(deterministic=deterministic)
        log_prob = dist.log_prob(actions)
        return actions.reshape((-1, *self.action_space.shape)), self.value_net(latent_vf), log_prob

    def evaluate_actions(self, obs: torch.Tensor, actions: torch.Tensor):
        raw, z = self._normalised(obs)
        latent_pi, latent_vf = self.mlp_extractor(z)
        dist = self._distribution(raw, z, latent_pi)
        return self.value_net(latent_vf), dist.log_prob(actions), dist.entropy()

    def get_distribution(self, obs: torch.Tensor):
        raw, z = self._normalised(obs)
        return self._distribution(raw, z, self.mlp_extractor.forward_actor(z))

    def predict_values(self, obs: torch.Tensor) -> torch.Tensor:
        return self.value_net(self.mlp_extractor.forward_critic(self._normalised(obs)[1]))

    def set_base(self, lqr, obs_mean: np.ndarray, obs_var: np.ndarray, clip_obs: float) -> None:
        """The fixed base, an :class:`~laddermill_gym.control.lqr.LQRController` ``lqr`` (its gains, trim and
        ranges), and the normalisation of the residual's and the critic's input (mean, variance of the raw
        observation, clip). ValueError for another controller or another number of wings."""
        set_lqr_base(self, lqr, "ResidualPolicy")
        with torch.no_grad():
            for name, value in (("obs_mean", obs_mean),
                                ("obs_std", np.sqrt(np.asarray(obs_var, dtype=np.float64) + 1e-8)),
                                ("clip_obs", clip_obs)):
                getattr(self, name).copy_(torch.as_tensor(np.asarray(value, dtype=np.float64)))
