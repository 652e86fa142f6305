"""The fixed float64 LQR base that the residual policies add a learned correction to (PPO's
:class:`~laddermill_gym.control.residual_policy.ResidualPolicy`, SAC's
:class:`~laddermill_gym.control.residual_sac.ResidualSACPolicy`).

The base is held as float64 buffers of a torch module (the :class:`~laddermill_gym.control.lqr.LQRController`'s
arguments: gains (n_wings, 2, 6), trim controls (n_wings, 3) [rad], trim attitude (n_wings, 2) [rad], the controls'
mid points and half ranges (n_wings, 3) [rad]), never trained, saved and loaded with the module's state dict (SB3's
zip format). Its actions are computed by the LQR's own code (:meth:`LQRController.controls`), so a policy started at
the base reproduces the controller to float64 rounding.
"""

from __future__ import annotations

import numpy as np
import torch

__all__ = ["BASE_BUFFERS", "register_lqr_base", "lqr_base_actions", "set_lqr_base"]

#: buffer names and (per wing) shapes of the base; "lqr_gains" is (n_wings, 2, 6)
BASE_BUFFERS = (("lqr_u_trim", 3), ("lqr_trim_attitude", 2), ("lqr_mid", 3), ("lqr_half_range", 3))


def register_lqr_base(module: torch.nn.Module, n_actions: int) -> None:
    """Register the base's float64 buffers on ``module`` for ``n_actions`` actions (3 controls per wing,
    model.params.N_CONTROLS); gains zero and the rest one until :func:`set_lqr_base`."""
    if n_actions <= 0 or n_actions % 3:
        raise ValueError(f"{type(module).__name__}: {n_actions} actions is not 3 controls per wing (the LQR base "
                         f"needs the wing envs' per-wing action groups, model.params.N_CONTROLS)")
    f64, nw = dict(dtype=torch.float64), n_actions // 3
    module.register_buffer("lqr_gains", torch.zeros((nw, 2, 6), **f64))  # LQRController's arguments
    for name, width in BASE_BUFFERS:
        module.register_buffer(name, torch.ones((nw, width), **f64))


def lqr_base_actions(module: torch.nn.Module, raw: torch.Tensor) -> torch.Tensor:
    """The LQR's unclipped float64 actions (N, n_actions) of raw observations ``raw`` (N, obs_dim), by the LQR's
    code, from the buffers of ``module`` (no gradient)."""
    from laddermill_gym.control.base import actions_from_controls
    from laddermill_gym.control.lqr import LQRController

    arrays = [getattr(module, f"lqr_{n}").cpu().numpy() for n in ("gains", "u_trim", "trim_attitude", "mid",
                                                                   "half_range")]
    ctrl = LQRController(*arrays, action_dtype=np.float64)
    obs = raw.detach().cpu().numpy()
    a = actions_from_controls(ctrl.controls(obs), ctrl.mid, ctrl.half_range).reshape(len(obs), -1)
    return torch.as_tensor(a, dtype=torch.float64, device=raw.device)


def set_lqr_base(module: torch.nn.Module, lqr, owner: str) -> None:
    """Copy the :class:`~laddermill_gym.control.lqr.LQRController` ``lqr``'s gains, trim and ranges into the
    buffers of ``module``. ValueError naming ``owner`` (the calling class) for another controller or another
    number of wings than the buffers'."""
    from laddermill_gym.control.lqr import LQRController

    if not isinstance(lqr, LQRController) or lqr.gains.shape != tuple(module.lqr_gains.shape):
        raise ValueError(f"{owner}.set_base: needs the LQRController of {module.lqr_gains.shape[0]} "
                         f"wing(s) (gains {tuple(module.lqr_gains.shape)}), got {type(lqr).__name__} "
                         f"{getattr(getattr(lqr, 'gains', None), 'shape', '')}")
    with torch.no_grad():
        for name, value in (("lqr_gains", lqr.gains), ("lqr_u_trim", lqr.u_trim),
                            ("lqr_trim_attitude", lqr.trim_attitude), ("lqr_mid", lqr.mid),
                            ("lqr_half_range", lqr.half_range)):
            getattr(module, name).copy_(torch.as_tensor(np.asarray(value, dtype=np.float64)))
