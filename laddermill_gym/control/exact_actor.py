"""A linear actor's deterministic action in float64, summed in a fixed order: the same bits on every CPU.

Stable-Baselines3 evaluates a policy in float32 through torch, whose matrix product chooses its order of summation
by the CPU's vector width and the batch size (MKL's kernels): on 2026-11-30's machine (AMD EPYC, torch 2.13.0+cpu,
"CPU capability usage: AVX512") one observation alone and 512 at once gave actions that differ by up to 4.8e-7, and
the shipped ``ppo_tethered_wing`` survived 88 of 200 held-out turbulent episodes on one machine and 79 on another
with the same code: a wing on the edge of its lateral instability amplifies a last-bit difference into a crash or
not. numpy's matrix product (BLAS) has the same property.

The actors the package ships are linear: the mean action is ``b + W x`` (``x`` the normalised observation, or the
shared policy's features). :func:`affine_fixed_order` evaluates it in float64 (the float32 weights widened exactly)
by adding one column's products after the other in a compiled loop: each product and sum correctly rounded by IEEE
754, no fused multiply-add and no reduction whose order a library picks, so the result is the same on any CPU and
for any batch size.
:func:`sb3_linear_actor` reads ``W`` and ``b`` off an SB3 actor-critic policy whose actor has no hidden layer
(``net_arch: {pi: []}``), or returns None for any other policy (those are evaluated by torch, as trained).

Why not torch in float64 or with deterministic algorithms: ``torch.use_deterministic_algorithms`` makes a run
repeatable on one machine, not equal across CPUs, and a float64 copy of the policy still sums in MKL's order.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

__all__ = ["affine_fixed_order", "SB3LinearActor", "sb3_linear_actor"]


def affine_fixed_order(x: np.ndarray, weight: np.ndarray, bias: np.ndarray) -> np.ndarray:
    """``bias + weight @ x`` for every row of ``x``, in float64, summed over the columns in index order.

    Parameters
    ----------
    x : ndarray (N, D) inputs (any float type; widened to float64)
    weight : ndarray (M, D)
    bias : ndarray (M,)

    Returns
    -------
    ndarray (N, M) float64: ``out[n, m] = (...((bias[m] + W[m, 0] x[n, 0]) + W[m, 1] x[n, 1]) + ...)``, each
    product and each sum rounded once (no fused multiply-add), so the bits depend on the inputs only.
    """
    x = np.ascontiguousarray(x, dtype=np.float64)
    w = np.ascontiguousarray(weight, dtype=np.float64)
    b = np.ascontiguousarray(bias, dtype=np.float64)
    if x.ndim != 2 or w.ndim != 2 or x.shape[1] != w.shape[1] or b.shape != (w.shape[0],):
        raise ValueError(f"affine_fixed_order: inputs {x.shape}, weight {w.shape}, bias {b.shape} do not fit "
                         "(N, D), (M, D), (M,)")
    out = np.empty((x.shape[0], w.shape[0]), dtype=np.float64)
    _affine_in_order(x, w, b, bool(np.all(np.isfinite(w))), out)
    return out


# Compiled (no fastmath: numba emits each product and sum on its own, and LLVM fuses no multiply-add without it),
# so the shared policies' actors, whose features are mostly zeros (10,403 per wing for ppo_mill_v3, 101 wings),
# cost no numpy operation per column: ppo_mill_v3's joint action 3.9 ms instead of 24 ms (2026-12-05). A zero input adds
# a signed zero, which leaves a non-zero sum as it is: such a term is skipped unless the sum is zero (where the sign
# of the result depends on it) or a weight is not finite (inf * 0 is NaN), so the bits are the column-by-column
# sum's (tests/test_exact_actor.py: the scalar loop as the oracle).
@njit(cache=True, nogil=True, _nrt=True, fastmath=False, error_model="python")
def _affine_in_order(x, w, b, finite_w, out):
    n_rows, n_cols = x.shape
    n_out = w.shape[0]
    for n in range(n_rows):
        for m in range(n_out):
            out[n, m] = b[m]
        for i in range(n_cols):
            xi = x[n, i]
            if xi == 0.0 and finite_w:
                for m in range(n_out):
                    if out[n, m] == 0.0:
                        out[n, m] = out[n, m] + w[m, i] * xi
            else:
                for m in range(n_out):
                    out[n, m] = out[n, m] + w[m, i] * xi


@dataclass(frozen=True)
class SB3LinearActor:
    """The mean action of an SB3 policy with a linear actor: ``clip(b + W x, low, high)``.

    Attributes
    ----------
    weight : ndarray (M, D) float64, the action head's weights (float32 in the model, widened exactly)
    bias : ndarray (M,) float64
    low, high : ndarray (M,) float64, the action space's bounds (SB3's ``predict`` clips to them)
    """

    weight: np.ndarray
    bias: np.ndarray
    low: np.ndarray
    high: np.ndarray

    def actions(self, x: np.ndarray) -> np.ndarray:
        """(N, M) float64 clipped actions of normalised observations ``x`` (N, D) float64."""
        return np.clip(affine_fixed_order(x, self.weight, self.bias), self.low, self.high)


def sb3_linear_actor(policy) -> SB3LinearActor | None:
    """The linear actor of an SB3 ``ActorCriticPolicy`` (PPO's or A2C's ``MlpPolicy``) whose observations are a flat
    Box, features the flattened observation, no hidden actor layer, a diagonal Gaussian action head and no squashed
    output; None for every other policy (a subclass such as the residual policy, hidden layers, SAC's actor, ...),
    which :class:`~laddermill_gym.control.sb3_policy.SB3Controller` then evaluates with torch."""
    from gymnasium import spaces
    from stable_baselines3.common.distributions import DiagGaussianDistribution
    from stable_baselines3.common.policies import ActorCriticPolicy
    from stable_baselines3.common.torch_layers import FlattenExtractor

    if type(policy) is not ActorCriticPolicy:
        return None
    obs_space, act_space = policy.observation_space, policy.action_space
    if not (isinstance(obs_space, spaces.Box) and len(obs_space.shape) == 1 and isinstance(act_space, spaces.Box)
            and len(act_space.shape) == 1):
        return None
    extractor = getattr(policy, "pi_features_extractor", policy.features_extractor)
    if (not isinstance(extractor, FlattenExtractor) or len(policy.mlp_extractor.policy_net) != 0
            or not isinstance(policy.action_dist, DiagGaussianDistribution) or policy.squash_output):
        return None
    head = policy.action_net
    return SB3LinearActor(weight=head.weight.detach().cpu().numpy().astype(np.float64),
                          bias=head.bias.detach().cpu().numpy().astype(np.float64),
                          low=np.asarray(act_space.low, dtype=np.float64),
                          high=np.asarray(act_space.high, dtype=np.float64))
