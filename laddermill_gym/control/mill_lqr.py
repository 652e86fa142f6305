"""Lateral LQR of the moving-cable laddermill (``LadderMill-v0``): a frozen-phase design on the slot layout,
checked over the whole period by the closed loop's monodromy matrix.

The operating point is periodic, not an equilibrium: the wings climb one slot per period l0 / V_c (35 s for the
default mill), and at the end of the period a transfer relabels the slots. Three facts make a time-invariant
lateral design on the slot layout reasonable, and the monodromy check makes it a statement rather than a hope:

1. **Decoupling along the whole orbit.** The periodic motion lies in the x-z plane (the in-plane operating
   point, mapped to 3D, stays in plane to round-off), so at every phase the mirror symmetry of
   ``control.linearize`` holds: the lateral states (y, vy, phi, psi, p, r per slot) and inputs (rudder, aileron)
   decouple from the longitudinal ones to first order, and their reference values are zero at every phase. The
   lateral linearisation about the orbit is therefore a linear time-periodic system dz' = A(s) dz + B(s) du in the
   slot coordinates, with the cable phase s / l0 as its clock.
2. **Slow variation.** In slot coordinates a wing moves one piece (70 m of a 3.5 km loop) per period, so A(s)
   changes on the 35 s scale, while the lateral modes double in about 0.5 s open loop and the closed loop decays
   in a few seconds: a gain designed at one phase (``design_phase``) is a frozen-time design of a slowly varying
   system. The config's ``design_model`` picks the model: ``transfer_phase`` (the phase just after a transfer,
   LadderMill-v0's) or ``period_mean`` (the mean of the models at the checked phases). On LadderMill-v1's mill
   the transfer phase's gain is stable at that phase only (frozen |z| up to 1.115 at the others; the least stable
   mode at the loop's top, slot 51); the mean model's gain is stable at 7 of the 8 phases and over the period
   (configs/agents/lqr_laddermill_v1.yaml).
3. **The check.** :func:`design_mill_lqr` linearises at ``n_phases`` phases of the recorded orbit, closes the loop
   with the one gain at each (``frozen_radius``: largest |z| of the ZOH-discretised closed loop), and composes the
   period's transition matrix Phi = S prod_j (Ad_j - Bd_j K)^(n_j) with the transfer's own Jacobian S (finite
   differences of the simulator's transfer kernel, ``kernels/moving_cable.transfer_3d``: slots shift by one, the
   new wing is interpolated on the first element). The spectral radius of Phi (``monodromy_radius``) below 1 is
   Floquet stability of the piecewise-frozen linear closed loop.

The model is the moving mill's own right-hand side (:class:`~laddermill_gym.sim.simulator.Simulator` of the
env's assembly, station held at the operating point's cable speed) in the minimal coordinates of
:mod:`.linearize`, differentiated only in the lateral columns (central differences).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import control
import numpy as np

from laddermill_gym.atmosphere.field import WindField
from laddermill_gym.control.base import batch_observations
from laddermill_gym.control.discrete_lqr import discrete_lqr
from laddermill_gym.control.linearize import (
    LATERAL_INPUTS,
    WING_LATERAL,
    euler_from_quaternions,
    full_from_minimal,
    lateral_indices,
    minimal_from_full,
    minimal_rhs,
)
from laddermill_gym.control.lqr_config import LATERAL_STATE_NAMES, LQRConfig, bryson_weights
from laddermill_gym.envs.laddermill.observation import N_OBS_PER_SLOT, N_STATION_OBS, OBS_INDEX
from laddermill_gym.kernels.contract import B3_POS, B3_QUAT, B3_SIZE, SX_MOVED
from laddermill_gym.kernels.moving_cable import transfer_3d
from laddermill_gym.model.params import N_CONTROLS

__all__ = ["MillLQRDesign", "MillLQRController", "mill_lateral_model", "orbit_states", "transfer_jacobian",
           "design_mill_lqr"]

_NLAT, _NIN = len(WING_LATERAL), len(LATERAL_INPUTS)


def _check_slots_only(asm) -> None:
    if asm.n_nodes:
        raise ValueError(f"the mill has {asm.n_nodes} free cable nodes whose lateral states the env does not "
                         "observe: the mill LQR needs one element per piece (elements_per_piece = 1)")


def mill_lateral_model(sim, x: np.ndarray, u: np.ndarray, t: float = 0.0, eps: float = 1e-6, rhs=None
                       ) -> tuple[np.ndarray, np.ndarray]:
    """Lateral (A (6n, 6n) [1/s], B (6n, 2n) [per rad]) of the mill at state ``x`` and controls ``u`` (slot order;
    per slot y, vy, phi, psi, p, r and rudder, aileron), station state frozen: central differences of the minimal-
    coordinate right-hand side in the lateral columns only (2 (6n + 2n) right-hand sides). ``rhs``: another
    ``rhs(t, x, u) -> dx`` to differentiate instead of the simulator's (e.g. the numpy reference, for tests)."""
    asm = sim.assembly
    _check_slots_only(asm)
    x = np.asarray(x, dtype=float)
    u = np.asarray(u, dtype=float).reshape(-1)
    f = minimal_rhs(sim, rhs=rhs, tail=x[asm.body_state_size:])
    z0 = minimal_from_full(asm, x)
    lat = lateral_indices(asm.n_wings, 0)
    ilat = np.array([N_CONTROLS * k + i for k in range(asm.n_wings) for i in LATERAL_INPUTS], dtype=np.int64)
    A = np.empty((lat.size, lat.size))
    B = np.empty((lat.size, ilat.size))
    for c, j in enumerate(lat):
        zp, zm = z0.copy(), z0.copy()
        zp[j] += eps
        zm[j] -= eps
        A[:, c] = (f(t, zp, u)[lat] - f(t, zm, u)[lat]) / (2 * eps)
    for c, j in enumerate(ilat):
        up, um = u.copy(), u.copy()
        up[j] += eps
        um[j] -= eps
        B[:, c] = (f(t, z0, up)[lat] - f(t, z0, um)[lat]) / (2 * eps)
    return A, B


#: [m, m/s, rad, rad/s] the largest lateral state (y, vy, phi, psi, p, r of any slot) of an in-plane orbit: round-off
ORBIT_LATERAL_TOL = 1e-8


def _left_plane(what: str, t: float, value: float) -> ValueError:
    return ValueError(f"the mill's orbit left the x-z plane at t = {t:.2f} s: {what} = {value:.4g} (round-off is below "
                      f"{ORBIT_LATERAL_TOL:g}); the lateral design needs the in-plane periodic orbit, recorded in a "
                      "steady wind (no direction step or gusts)")


def _check_in_plane(asm, states, t: float) -> None:
    """ValueError when a recorded orbit state has left the x-z plane (a lateral state past round-off,
    :data:`ORBIT_LATERAL_TOL`): the lateral design's reference values are zero only on the in-plane orbit."""
    lat = lateral_indices(asm.n_wings, 0)
    for x in states:
        z = minimal_from_full(asm, x)[lat]
        k = int(np.argmax(np.abs(z)))
        if not abs(z[k]) <= ORBIT_LATERAL_TOL:
            raise _left_plane(f"slot {k // _NLAT}'s {LATERAL_STATE_NAMES[k % _NLAT]}", t, z[k])


def orbit_states(sim, n_phases: int) -> tuple[np.ndarray, np.ndarray]:
    """Step ``sim`` (just after a transfer, on the periodic orbit) through one period and return the states at
    the cable phases s / l0 = j / n_phases, j = 0 .. n_phases - 1 ((n_phases, n_state); the first is the start)
    and the state just before the period's transfer ((n_state,)). RuntimeError if no transfer within two periods;
    ValueError as soon as a wing's lateral position, or at the end a recorded state's lateral coordinates, leave the
    x-z plane (past round-off, :data:`ORBIT_LATERAL_TOL`: the simulator's wind must be steady, as
    :func:`design_mill_lqr` sets it)."""
    asm = sim.assembly
    lp = asm.station.piece_length
    off = asm.body_state_size + SX_MOVED
    ys = B3_SIZE * np.arange(asm.n_wings) + B3_POS + 1  # every wing's global y [m]
    n0 = sim.transfers()
    states, before = [sim.state.copy()], sim.state.copy()
    n_max = int(math.ceil(2.0 * lp / max(abs(sim.cable_speed()), 1e-9) / sim.settings.dt))
    for _ in range(n_max):
        prev = sim.state.copy()
        sim.step()
        k = int(np.argmax(np.abs(sim.state[ys])))
        if not abs(sim.state[ys[k]]) <= ORBIT_LATERAL_TOL:
            raise _left_plane(f"slot {k}'s y", sim.t, sim.state[ys[k]])
        if sim.transfers() != n0:
            _check_in_plane(asm, [*states, prev], sim.t)
            return np.array(states), prev
        if len(states) < n_phases and sim.state[off] >= len(states) * lp / n_phases:
            states.append(sim.state.copy())
        before = prev
    raise RuntimeError(f"t = {sim.t:.2f} s: no transfer within two periods (last state {before[off]:.3g} m moved)")


def transfer_jacobian(sim, x_before: np.ndarray, eps: float = 1e-6) -> np.ndarray:
    """S (6n, 6n): the derivative of the slot lateral states after a transfer with respect to those before it, by
    central differences of the simulator's own transfer (``kernels.moving_cable.transfer_3d``, cable moving up)
    applied to ``x_before`` perturbed in each lateral minimal coordinate."""
    asm = sim.assembly
    _check_slots_only(asm)
    tail = np.asarray(x_before, dtype=float)[asm.body_state_size:]
    z0 = minimal_from_full(asm, x_before)
    lat = lateral_indices(asm.n_wings, 0)
    sp, M = sim.model.kind.station, sim.model

    def after(z):
        x = full_from_minimal(asm, z, tail)
        transfer_3d(sp, x, M, True)
        return minimal_from_full(asm, x)[lat]

    S = np.empty((lat.size, lat.size))
    for c, j in enumerate(lat):
        zp, zm = z0.copy(), z0.copy()
        zp[j] += eps
        zm[j] -= eps
        S[:, c] = (after(zp) - after(zm)) / (2 * eps)
    return S


@dataclass(frozen=True)
class MillLQRDesign:
    """A lateral LQR of the mill (see the module doc).

    config : the LQR config;  A (6n, 6n), B (6n, 2n) : the lateral model the gain is designed on (the config's
    ``design_model``: the operating point's phase just after a transfer, or the mean over the checked phases)
    gains : (2n, 6n) centralised, or (n, 2, 6) per slot [rad per unit lateral state]
    phases : (m,) cable phases s / l0 of the check;  frozen_radius : (m,) largest |z| of Ad_j - Bd_j K
    open_loop_growth : (m,) largest real part of the open-loop lateral eigenvalues at each phase [1/s]
    monodromy_radius : spectral radius of the closed loop's transition matrix over one period, transfer included
    flow_radius : the same without the transfer (the period's flow in fixed slots: what the shift does not remove)
    trim_attitude : (n, 2) (phi, psi) of each slot on the orbit [rad];  u_op : (n_controls,) operating controls
    """

    config: LQRConfig
    A: np.ndarray
    B: np.ndarray
    gains: np.ndarray
    phases: np.ndarray
    frozen_radius: np.ndarray
    open_loop_growth: np.ndarray
    monodromy_radius: float
    flow_radius: float
    trim_attitude: np.ndarray
    u_op: np.ndarray

    def summary(self) -> str:
        return (f"mill lateral LQR ({self.config.structure}, {self.trim_attitude.shape[0]} slots, "
                f"{self.A.shape[0]} lateral states): open-loop growth up to {self.open_loop_growth.max():.3f} "
                f"1/s; frozen closed loop max |z| {self.frozen_radius.max():.4f} over {self.phases.size} phases; "
                f"spectral radius of the period's transition matrix {self.monodromy_radius:.4f} with the transfer, "
                f"{self.flow_radius:.4f} without")

    def controller(self, task, action_dtype=np.float32) -> MillLQRController:
        """The design's controller in ``task``'s action layout (a MillTask, e.g. ``env.unwrapped.task``)."""
        return MillLQRController(self.gains, self.trim_attitude, task.actions, action_dtype)


def _full_gain(gains: np.ndarray) -> np.ndarray:
    if gains.ndim == 2:
        return gains
    n = gains.shape[0]
    K = np.zeros((_NIN * n, _NLAT * n))
    for k in range(n):
        K[_NIN * k: _NIN * (k + 1), _NLAT * k: _NLAT * (k + 1)] = gains[k]
    return K


def design_mill_lqr(config: LQRConfig, task, n_phases: int = 8, progress=None) -> MillLQRDesign:
    """Design the lateral LQR of ``task``'s mill (a MillTask: its assembly, operating point and control period; the
    orbit is recorded in a steady wind, speed factor 1 and no direction offset or gust grid, whatever the task's
    copy 0 drew at a reset) with Bryson's weights of ``config`` on its ``design_model`` (the operating point's
    phase just after a transfer, or the mean of the phases' models), and check it at ``n_phases`` phases of the
    orbit and over the period (see the module doc). ``progress``: a callable taking a
    line of text (e.g. ``print``), or None."""
    say = progress or (lambda _msg: None)
    if config.control_period != task.control_dt:
        raise ValueError(f"{config.file}: control_period = {config.control_period} s differs from the environment's "
                         f"control_dt = {task.control_dt} s")
    sim = task.simulator(0)
    sim.set_wind(WindField())  # the orbit's own air: steady, whatever the task's copy drew at its reset
    sim.reset(state=np.array(task.op.state), t=0.0, controls=np.array(task.u_op))
    u = np.array(task.u_op)
    n = sim.assembly.n_wings
    states, before = orbit_states(sim, n_phases)
    Q, R = bryson_weights(config.max_state, config.max_input)
    say(f"linearising the {n}-slot mill at {len(states)} phases of its orbit")
    models = [mill_lateral_model(sim, x, u) for x in states]
    A0, B0 = models[0]
    if config.design_model == "period_mean":  # the orbit's mean model: one gain for every phase, not the transfer's
        A0, B0 = np.mean([m[0] for m in models], axis=0), np.mean([m[1] for m in models], axis=0)
    say(f"solving the {config.structure} Riccati equation ({A0.shape[0]} lateral states)")
    if config.structure == "centralised":
        gains = discrete_lqr(A0, B0, np.kron(np.eye(n), Q), np.kron(np.eye(n), R), config.control_period).K
    else:  # each slot's gain from its own lateral block (all other slots held on the orbit)
        gains = np.array([discrete_lqr(A0[_NLAT * k: _NLAT * (k + 1), _NLAT * k: _NLAT * (k + 1)],
                                       B0[_NLAT * k: _NLAT * (k + 1), _NIN * k: _NIN * (k + 1)], Q, R,
                                       config.control_period).K for k in range(n)])
    say("checking the closed loop over the period (frozen phases and the monodromy matrix)")
    asm = sim.assembly
    phases = np.array([x[asm.body_state_size + SX_MOVED] for x in states]) / asm.station.piece_length
    n_steps = int(round(asm.station.piece_length / task.op.cable_speed / config.control_period))
    frozen, growth, phi = _period_check(models, _full_gain(np.asarray(gains)), config.control_period, n_steps)
    flow = float(np.max(np.abs(np.linalg.eigvals(phi))))
    monodromy = float(np.max(np.abs(np.linalg.eigvals(transfer_jacobian(sim, before) @ phi))))
    euler = euler_from_quaternions(states[0][: B3_SIZE * n].reshape(n, B3_SIZE)[:, B3_QUAT: B3_QUAT + 4])
    return MillLQRDesign(config=config, A=A0, B=B0, gains=np.asarray(gains), phases=phases, frozen_radius=frozen,
                         open_loop_growth=growth, monodromy_radius=monodromy, flow_radius=flow,
                         trim_attitude=euler[:, [0, 2]], u_op=u)


def _period_check(models, K: np.ndarray, dt: float, n_steps: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(largest |z| of each phase's ZOH closed loop (m,), largest open-loop real part [1/s] (m,), the period's
    transition matrix prod_j (Ad_j - Bd_j K)^(n_j) without the transfer): phase j holds for the control steps
    round(j N / m) .. round((j + 1) N / m) of the period's N = ``n_steps``."""
    m = len(models)
    phi = np.eye(models[0][0].shape[0])
    frozen, growth = np.empty(m), np.empty(m)
    for j, (A, B) in enumerate(models):
        sysd = control.c2d(control.ss(A, B, np.eye(A.shape[0]), np.zeros(B.shape)), dt, "zoh")
        Mj = np.asarray(sysd.A) - np.asarray(sysd.B) @ K
        frozen[j] = float(np.max(np.abs(np.linalg.eigvals(Mj))))
        growth[j] = float(np.max(np.linalg.eigvals(A).real))
        phi = np.linalg.matrix_power(Mj, round((j + 1) * n_steps / m) - round(j * n_steps / m)) @ phi
    return frozen, growth, phi


class MillLQRController:
    """Lateral state feedback of the mill in LadderMill-v0's observation and action spaces (by slot).

    For every slot k: dz_k = (dy, vy, phi - phi_op, wrap(psi - psi_op), p, r) from its observation block;
    (rudder, aileron)_k = u_op - K dz (centralised: every slot's commands from every slot's states); the
    elevator and the station's control hold the operating point (a = 0). Actions a = (u - u_op) / half range,
    clipped to [-1, 1]. Implements Stable-Baselines3's ``predict``.

    Parameters
    ----------
    gains : ndarray (2n, 6n) or (n, 2, 6)    [rad per unit lateral state]
    trim_attitude : ndarray (n, 2)           (phi, psi) of each slot on the orbit [rad]
    actions : SlotActionMap                   the env's action layout: one group per slot, with rudder and aileron
    action_dtype : numpy dtype of the returned actions

    Attributes: ``n_clipped``, ``n_actions`` (entries clipped / produced since :meth:`reset_clip_count`).
    """

    def __init__(self, gains: np.ndarray, trim_attitude: np.ndarray, actions, action_dtype=np.float32):
        n = actions.n_wings
        if actions.groups != tuple((k,) for k in range(n)):
            raise ValueError("the mill LQR commands every slot: it needs groups = 'per_slot'")
        surf = list(actions.surface_index)
        if not set(LATERAL_INPUTS) <= set(surf):
            raise ValueError("the mill LQR needs the rudder and the aileron among the env's surfaces")
        self.K = _full_gain(np.asarray(gains, dtype=float))
        if self.K.shape != (_NIN * n, _NLAT * n):
            raise ValueError(f"gains: shape {self.K.shape} does not fit {n} slots ({_NIN * n}, {_NLAT * n})")
        self.n_wings = n
        self.trim_attitude = np.asarray(trim_attitude, dtype=float).reshape(n, 2)
        self.column = np.array([surf.index(i) for i in LATERAL_INPUTS])  # rudder, aileron within a group's entries
        self.n_surfaces = len(surf)
        self.half = actions._half[:, list(LATERAL_INPUTS)]  # (n, 2) [rad per unit action]
        self.act_dim = actions.n_actions
        self.obs_dim = N_OBS_PER_SLOT * n + N_STATION_OBS
        self.action_dtype = action_dtype
        self.reset_clip_count()

    def reset_clip_count(self) -> None:
        self.n_clipped = 0
        self.n_actions = 0

    def lateral_deviation(self, obs: np.ndarray) -> np.ndarray:
        """(B, n, 6) lateral deviations of batched observations (B, 15 n + 4)."""
        nb = N_OBS_PER_SLOT
        o = np.asarray(obs, dtype=float)[:, : nb * self.n_wings].reshape(len(obs), self.n_wings, nb)
        i = OBS_INDEX
        dpsi = (o[..., i["psi"]] - self.trim_attitude[:, 1] + math.pi) % (2 * math.pi) - math.pi
        return np.stack([o[..., i["dy"]], o[..., i["vy"]], o[..., i["phi"]] - self.trim_attitude[:, 0], dpsi,
                         o[..., i["p"]], o[..., i["r"]]], axis=-1)

    def predict(self, observation: np.ndarray, state: Any = None, episode_start: np.ndarray | None = None,
                deterministic: bool = False) -> tuple[np.ndarray, Any]:
        """Normalised actions for batched (B, obs_dim) or single (obs_dim,) observations."""
        obs, single = batch_observations(observation, self.obs_dim)
        du = -(self.lateral_deviation(obs).reshape(len(obs), -1) @ self.K.T).reshape(len(obs), self.n_wings, _NIN)
        a = np.zeros((len(obs), self.act_dim))
        per_slot = a[:, : self.n_wings * self.n_surfaces].reshape(len(obs), self.n_wings, self.n_surfaces)
        per_slot[:, :, self.column] = du / self.half
        clipped = np.abs(a) > 1.0
        self.n_clipped += int(clipped.sum())
        self.n_actions += clipped.size
        a = np.clip(a, -1.0, 1.0).astype(self.action_dtype)
        return (a[0] if single else a), state
