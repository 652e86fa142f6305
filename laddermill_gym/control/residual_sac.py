"""A SAC policy whose actor starts exactly at a fixed linear controller (``policy: ResidualSACPolicy``).

SAC's actor draws a pre-squash action u ~ N(mean(o), exp(log_std(o))^2) and acts a = tanh(u) (SB3's
``SquashedDiagGaussianDistribution``; its deterministic action is tanh(mean)). Here

mean(o) = atanh(clip(a_lqr(o), -1 + EPS, 1 - EPS))  +  r(z),   r(z) = skip(z) + mu(mlp(z)),
z = clip((o - m) / s, -CLIP_OBS, CLIP_OBS)

* a_lqr(o) is the LQR's unclipped action of the RAW observation, by the LQR's own code on float64 buffers
  (:mod:`laddermill_gym.control.lqr_base`, shared with PPO's
  :class:`~laddermill_gym.control.residual_policy.ResidualPolicy`), never trained. Clipping it to +-(1 - EPS) is the
  LQR's own clip to [-1, 1] (EPS = :data:`BASE_EPS` keeps atanh finite); the atanh, the residual's sum and the tanh
  are done in float64, so at r = 0 the deterministic action is tanh(atanh(a)) = a to float64 rounding (about
  1e-16), then cast to float32 as the env's Box: the LQR's float32 action, a saturated control included
  (1 - EPS rounds to 1.0 in float32);
* skip (a linear layer) and mu (SB3's last actor layer after ``net_arch`` hidden layers) see the normalised
  observation z (statistics of the LQR's rollouts, held in the policy's features extractor, so no
  ``VecNormalize``) and start at zero: the untrained actor's mean is the LQR's, exactly;
* with ``policy_kwargs.residual_limit: L`` (0 < L <= 2) the residual passes through L tanh(r / L), as
  :class:`~laddermill_gym.control.residual_policy.ResidualPolicy`'s: still exactly 0 at the start, slope 1 there,
  and |mean - atanh(a_lqr)| <= L; tanh is 1-Lipschitz, so the deterministic action stays within L of the LQR's
  (a fraction L of each control's half range);
* log_std(o) is SB3's linear layer with its weights zeroed and its bias ``log_std_init`` (``policy_kwargs``): the
  start's exploration noise is exp(log_std_init) in the pre-squash space, the same everywhere;
* the critics (SB3's ``ContinuousCritic``, ``n_critics`` and their targets) see z and the action.

SB3 rescales actions between the policy's [-1, 1] and the action space's bounds; the environments' action space
is [-1, 1] itself, where that map is the identity, so :class:`ResidualSACPolicy` skips it (SB3's float32
arithmetic -1 + (a + 1) would round the action by up to 6e-8) and refuses another action space.

A limit of the construction (inherent in SAC's squashing): where the LQR saturates a control, the pre-squash mean
is atanh(1 - EPS) = 10.7 and the action's slope in r is 1 - a^2 = 2e-9, so the residual cannot pull a saturated
control back quickly; it acts where the LQR is inside its range.

**The residual after the squash** (``policy_kwargs.residual_after_squash: true``, with ``residual_limit: L``; the
default false is the construction above, bit for bit). SAC's squashed action is the residual's alone and the LQR is
added after it:

u = tanh(r(z) + std(o) eps)  (deterministic u = tanh(r(z))),   a = clip(a_lqr(o) + L u, -1, 1)

with r(z) = skip(z) + mu(mlp(z)) zero-started as above (unbounded: u is within +-1, so L u within +-L). The
untrained deterministic u is tanh(0) = 0 and a = clip(a_lqr(o), -1, 1) in float64, the LQR's own clipped action bit
for bit; a moves by up to L where the LQR's unclipped action is within 1 + L, a saturated control included (where
1 <= a_lqr < 1 + L a negative u pulls it below 1): authority the construction above lacks at |a| = 1, as PPO's
:class:`~laddermill_gym.control.residual_policy.ResidualPolicy` (whose bound also acts on the action). Where
|a_lqr| > 1 + L (the LQR's unclipped action in strong turbulence often is) the clip absorbs any u: no authority
there either. ``policy_kwargs.residual_base_clipped: true`` clips the base first, a = clip(clip(a_lqr, -1, 1) + L u,
-1, 1): the same exact start (clip is idempotent) and the authority L on every control whatever the LQR's action
(default false: the form the runs of 2026-11-30 trained with, bit for bit). The actor's
``forward`` and ``action_log_prob`` return a, so SB3's replay buffer (``SAC.collect_rollouts`` stores ``predict``'s
output; the action scaling is the identity) and the critics in ``SAC.train`` see the action the env gets. The
log-probability is u's (SB3's squashed Gaussian) minus n_act log L: a = a_lqr + L u is a shift by a constant of u
and a scale by the constant L, whose Jacobian is L^n_act; the clip's mass at +-1 is ignored, as SB3 ignores the
squash's own boundary (the gradient through a clipped component is zero).

**A slower actor** (``policy_kwargs.optimizer_kwargs.actor_lr_scale: s``, 0 < s <= 1; absent, the default, leaves
the optimisers as SB3 builds them, bit for bit). The actor's optimiser steps at s times the learning rate SB3 sets
(its schedule, or the critic warm-up's) and the critics' at the rate itself: a pre-step hook multiplies each
parameter group's rate by s and a post-step hook restores it, so SB3's ``_update_learning_rate`` and the saved
state see the unscaled rate. Adam's step is linear in its rate (lr m_hat / (sqrt(v_hat) + eps)), so every actor
step is s times the one at the critics' rate: the two-timescale order of actor-critic methods (the actor slower than
its critic), so that the critics follow the moving policy's values. It is an optimiser setting, carried in
``optimizer_kwargs`` (the config reader passes that mapping through) and removed from the keyword arguments the
optimiser class gets.

The buffers are part of the state dict: SB3's zip format saves them and ``SAC.load`` imports this class by name.
:func:`~laddermill_gym.control.warm_start.start_residual` sets them (``init_from: lqr`` with
``policy: ResidualSACPolicy``).
"""

from __future__ import annotations

import math

import numpy as np
import torch
from gymnasium import spaces
from stable_baselines3.common.torch_layers import BaseFeaturesExtractor
from stable_baselines3.sac.policies import LOG_STD_MAX, LOG_STD_MIN, Actor, SACPolicy
from torch import nn

from laddermill_gym.control.lqr_base import lqr_base_actions, register_lqr_base, set_lqr_base

__all__ = ["ResidualSACPolicy", "ResidualActor", "NormalisedObservation", "BASE_EPS", "scale_steps"]

#: [-] the base action's margin from the clip before atanh: atanh(1 - 2^-30) = 10.7; 1 - 2^-30 rounds to 1.0 in
#: float32 (anything below 2^-25 does), so a saturated LQR control is reproduced exactly
BASE_EPS = 2.0 ** -30


def scale_steps(optimizer: torch.optim.Optimizer, scale: float) -> None:
    """Make every ``step`` of ``optimizer`` use ``scale`` [-] times each parameter group's learning rate: the rate is
    multiplied before the step and restored after it (torch's step hooks), so a schedule that sets the rate between
    steps, and the optimiser's saved state, see the unscaled one."""
    saved: list[float] = []

    def before(opt, _args, _kwargs) -> None:
        saved[:] = [group["lr"] for group in opt.param_groups]
        for group in opt.param_groups:
            group["lr"] = group["lr"] * scale

    def after(opt, _args, _kwargs) -> None:
        for group, rate in zip(opt.param_groups, saved, strict=True):
            group["lr"] = rate

    optimizer.register_step_pre_hook(before)
    optimizer.register_step_post_hook(after)


class NormalisedObservation(BaseFeaturesExtractor):
    """z = clip((o - m) / s, -c, c) in float64, returned as float32 (features of the actor's residual and the
    critics): m, s (obs_dim,) and c held as float64 buffers (set by :meth:`ResidualSACPolicy.set_base`)."""

    def __init__(self, observation_space: spaces.Box) -> None:
        super().__init__(observation_space, int(observation_space.shape[0]))
        n, f64 = int(observation_space.shape[0]), dict(dtype=torch.float64)
        self.register_buffer("obs_mean", torch.zeros(n, **f64))
        self.register_buffer("obs_std", torch.ones(n, **f64))
        self.register_buffer("clip_obs", torch.tensor(100.0, **f64))  # [-] as warm_start.CLIP_OBS (set there)

    def forward(self, obs: torch.Tensor) -> torch.Tensor:
        z = (obs.to(torch.float64) - self.obs_mean) / self.obs_std
        return z.clamp(-self.clip_obs, self.clip_obs).to(torch.float32)

    def set_statistics(self, mean: np.ndarray, var: np.ndarray, clip_obs: float) -> None:
        """Mean and variance (obs_dim,) of the raw observation and the clip [-] of the normalised one."""
        with torch.no_grad():
            self.obs_mean.copy_(torch.as_tensor(np.asarray(mean, dtype=np.float64)))
            self.obs_std.copy_(torch.as_tensor(np.sqrt(np.asarray(var, dtype=np.float64) + 1e-8)))
            self.clip_obs.fill_(float(clip_obs))


class ResidualActor(Actor):
    """SB3's SAC ``Actor`` whose pre-squash mean is the LQR's atanh-ed action plus a zero-started residual
    (module docstring). Needs SB3's unstructured noise (``use_sde: false``)."""

    def __init__(self, *args, residual_limit: float | None = None, residual_after_squash: bool = False,
                 residual_base_clipped: bool = False, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.residual_limit = residual_limit
        self.residual_after_squash = residual_after_squash
        self.residual_base_clipped = residual_base_clipped
        if self.use_sde:
            raise ValueError("ResidualSACPolicy: use_sde must be false (the residual actor uses SAC's own noise)")
        n_obs, n_act = self.observation_space.shape[0], self.action_space.shape[0]
        register_lqr_base(self, n_act)
        self.skip_net = nn.Linear(n_obs, n_act)
        for layer in (self.skip_net, self.mu):
            nn.init.zeros_(layer.weight)
            nn.init.zeros_(layer.bias)
        nn.init.zeros_(self.log_std.weight)
        nn.init.constant_(self.log_std.bias, self.log_std_init)

    def get_action_dist_params(self, obs: torch.Tensor):
        """(pre-squash mean (N, n_act) float64, log std (N, n_act) float64, {}) of raw observations ``obs``: the
        LQR's atanh-ed action plus the residual, or the residual alone after the squash (module docstring)."""
        z = self.extract_features(obs, self.features_extractor)
        latent = self.latent_pi(z)
        residual = (self.mu(latent) + self.skip_net(z)).to(torch.float64)
        log_std = torch.clamp(self.log_std(latent), LOG_STD_MIN, LOG_STD_MAX).to(torch.float64)
        if self.residual_after_squash:  # u = tanh(r + std eps): the LQR is added after it (after_squash)
            return residual, log_std, {}
        if self.residual_limit is not None:  # L tanh(r / L): within +-L, tanh(0) = 0 exactly
            residual = self.residual_limit * torch.tanh(residual / self.residual_limit)
        base = lqr_base_actions(self, obs.to(torch.float64)).clamp(-1.0 + BASE_EPS, 1.0 - BASE_EPS)
        return torch.atanh(base) + residual, log_std, {}

    def after_squash(self, obs: torch.Tensor, squashed: torch.Tensor) -> torch.Tensor:
        """The env action clip(a_lqr(obs) + L u, -1, 1) (N, n_act) float64 of SAC's squashed residual action u
        ``squashed`` (N, n_act) and raw observations ``obs`` (a_lqr clipped to [-1, 1] first with
        ``residual_base_clipped``), or u itself without ``residual_after_squash``."""
        if not self.residual_after_squash:
            return squashed
        base = lqr_base_actions(self, obs.to(torch.float64))
        if self.residual_base_clipped:
            base = base.clamp(-1.0, 1.0)
        return (base + self.residual_limit * squashed.to(torch.float64)).clamp(-1.0, 1.0)

    def forward(self, obs: torch.Tensor, deterministic: bool = False) -> torch.Tensor:
        return self.after_squash(obs, super().forward(obs, deterministic)).to(torch.float32)

    def action_log_prob(self, obs: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        """(env actions (N, n_act), their log-probabilities (N,)), float32: after the squash, u's log-probability
        minus n_act log L (the scale L's Jacobian; the clip's mass at the bounds is ignored)."""
        actions, log_prob = super().action_log_prob(obs)
        if self.residual_after_squash:
            log_prob = log_prob - actions.shape[1] * math.log(self.residual_limit)
        return self.after_squash(obs, actions).to(torch.float32), log_prob.to(torch.float32)

    def actor_parameters(self) -> list:
        """The trained parameters of the actor (the critic warm-up freezes them)."""
        return list(self.parameters())


class ResidualSACPolicy(SACPolicy):
    """SB3 ``SACPolicy`` with :class:`ResidualActor` and :class:`NormalisedObservation` features for the actor's
    residual and the critics. Needs a Box observation space and the action space [-1, 1]^n."""

    def __init__(self, observation_space, action_space, lr_schedule, residual_limit: float | None = None,
                 residual_after_squash: bool = False, residual_base_clipped: bool = False, **kwargs) -> None:
        number = isinstance(residual_limit, (int, float)) and not isinstance(residual_limit, bool)
        if residual_limit is not None and not (number and 0.0 < residual_limit <= 2.0):
            raise ValueError(f"ResidualSACPolicy: residual_limit {residual_limit!r} must be a number in (0, 2] "
                             f"(a bound of the pre-squash residual, so of the action's change) or None (no bound)")
        if not isinstance(residual_after_squash, bool):
            raise ValueError(f"ResidualSACPolicy: residual_after_squash {residual_after_squash!r} must be true or "
                             f"false")
        if residual_after_squash and residual_limit is None:
            raise ValueError("ResidualSACPolicy: residual_after_squash needs residual_limit L (the env action is "
                             "clip(a_lqr + L u, -1, 1), u SAC's squashed action)")
        if not isinstance(residual_base_clipped, bool) or (residual_base_clipped and not residual_after_squash):
            raise ValueError(f"ResidualSACPolicy: residual_base_clipped {residual_base_clipped!r} must be true or "
                             f"false, and true only with residual_after_squash (it clips the LQR's action before L u "
                             f"is added)")
        self.residual_limit = None if residual_limit is None else float(residual_limit)
        self.residual_after_squash = residual_after_squash
        self.residual_base_clipped = residual_base_clipped
        for name, space in (("observation", observation_space), ("action", action_space)):
            if not isinstance(space, spaces.Box) or len(space.shape) != 1:
                raise ValueError(f"ResidualSACPolicy: needs a flat Box {name} space (the wing envs'), got {space}")
        low, high = np.asarray(action_space.low), np.asarray(action_space.high)
        if not (np.all(low == -1.0) and np.all(high == 1.0)):
            raise ValueError(f"ResidualSACPolicy: needs the action space [-1, 1]^n (the LQR's normalised actions), "
                             f"got low {low.min()}..{low.max()}, high {high.min()}..{high.max()}")
        kwargs.setdefault("features_extractor_class", NormalisedObservation)
        optimizer_kwargs = dict(kwargs.get("optimizer_kwargs") or {})
        self.actor_lr_scale = optimizer_kwargs.pop("actor_lr_scale", None)
        if self.actor_lr_scale is not None:
            scale = self.actor_lr_scale
            if isinstance(scale, bool) or not isinstance(scale, (int, float)) or not 0.0 < scale <= 1.0:
                raise ValueError(f"ResidualSACPolicy: optimizer_kwargs.actor_lr_scale {scale!r} must be a number in "
                                 f"(0, 1] (the actor's learning rate as a fraction of the critics')")
            self.actor_lr_scale = float(scale)
            kwargs["optimizer_kwargs"] = optimizer_kwargs
        super().__init__(observation_space, action_space, lr_schedule, **kwargs)
        if self.actor_lr_scale is not None:
            scale_steps(self.actor.optimizer, self.actor_lr_scale)

    def _get_constructor_parameters(self) -> dict:
        params = super()._get_constructor_parameters()
        if self.actor_lr_scale is not None:  # SAC.load rebuilds the slower actor's optimiser
            params["optimizer_kwargs"] = {**params["optimizer_kwargs"], "actor_lr_scale": self.actor_lr_scale}
        return {**params, "residual_limit": self.residual_limit,
                "residual_after_squash": self.residual_after_squash,
                "residual_base_clipped": self.residual_base_clipped}

    def make_actor(self, features_extractor=None) -> ResidualActor:
        kwargs = self._update_features_extractor(self.actor_kwargs, features_extractor)
        return ResidualActor(**kwargs, residual_limit=self.residual_limit,
                             residual_after_squash=self.residual_after_squash,
                             residual_base_clipped=self.residual_base_clipped).to(self.device)

    def scale_action(self, action: np.ndarray) -> np.ndarray:
        """The identity: the action space is [-1, 1] (checked at construction), SB3's map is the identity there."""
        return action

    def unscale_action(self, scaled_action: np.ndarray) -> np.ndarray:
        """The identity (see :meth:`scale_action`)."""
        return scaled_action

    def actor_parameters(self) -> list:
        """The actor's trained parameters (mean, residual, noise): the critic warm-up freezes them."""
        return self.actor.actor_parameters()

    def set_base(self, lqr, obs_mean: np.ndarray, obs_var: np.ndarray, clip_obs: float) -> None:
        """The fixed base, an :class:`~laddermill_gym.control.lqr.LQRController` ``lqr``, and the normalisation
        (mean, variance (obs_dim,) of the raw observation, clip [-]) of the actor's and the critics' inputs.
        ValueError for another controller or another number of wings."""
        set_lqr_base(self.actor, lqr, "ResidualSACPolicy")
        for net in (self.actor, self.critic, self.critic_target):
            net.features_extractor.set_statistics(obs_mean, obs_var, clip_obs)
