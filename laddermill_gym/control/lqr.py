"""Discrete-time LQR of the wings' lateral motion about the trim, and its controller.

Design: linearise at the scene's trim in minimal coordinates (:mod:`.linearize`), keep the lateral subsystem
dz = (y, vy, phi, psi, p, r), du = (rudder, aileron), discretise with a zero-order hold at the control period
(``control.c2d(..., "zoh")``) and solve the discrete Riccati equation (``control.dlqr``) with Bryson's-rule
weights from ``configs/agents/lqr_*.yaml``. The controller applies u = u_trim - K dz to rudder and aileron and
keeps the elevator at trim.

For a chain (``ladder_chain``) each wing gets its own gain from its own lateral block of the chain's
Jacobian (all other wings and nodes held at trim): a decentralised design; :func:`chain_closed_loop` checks
it on the full coupled lateral model.

The configuration (:class:`LQRConfig`, Bryson's weights) lives in ``lqr_config`` and the discrete LQR itself in
``discrete_lqr``; both are re-exported here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import control
import numpy as np

from laddermill_gym.control.base import (
    OBS_INDEX,
    OBS_PER_WING,
    actions_from_controls,
    batch_observations,
    control_ranges,
)
from laddermill_gym.control.discrete_lqr import DiscreteLQR, continuous_equivalent, discrete_lqr, mode_table
from laddermill_gym.control.linearize import (
    LATERAL_INPUTS,
    Linearization,
    coupling_norms,
    lateral_subsystem,
    linearize,
    wing_lateral_blocks,
)
from laddermill_gym.control.lqr_config import (
    DEFAULT_CHAIN_CONFIG,
    DEFAULT_CONFIG,
    LATERAL_INPUT_NAMES,
    LATERAL_STATE_NAMES,
    STRUCTURES,
    LQRConfig,
    bryson_weights,
    load_lqr_config,
)
from laddermill_gym.ladder.scene import Scene, load_scene
from laddermill_gym.model.params import N_CONTROLS

__all__ = [
    "LATERAL_STATE_NAMES",
    "LATERAL_INPUT_NAMES",
    "LQRConfig",
    "load_lqr_config",
    "bryson_weights",
    "DiscreteLQR",
    "discrete_lqr",
    "continuous_equivalent",
    "mode_table",
    "LateralDesign",
    "design_tethered_wing",
    "ChainDesign",
    "design_ladder_chain",
    "chain_closed_loop",
    "LQRController",
    "DEFAULT_CONFIG",
    "DEFAULT_CHAIN_CONFIG",
    "STRUCTURES",
]


# ------------------------------------------------------------------------------------ tethered wing
@dataclass(frozen=True)
class LateralDesign:
    """The lateral LQR of a single tethered wing: trim, linearisation, lateral model and gain.

    ``A_lat``, ``B_lat``: the wing's own lateral model (6 states) the gain is designed on; ``full_closed_loop``: with
    cable nodes along the tether (more than one element), the discrete closed-loop eigenvalues of the gain on the
    full lateral model (the nodes' lateral states unobserved, zero gain), else None."""

    config: LQRConfig
    scene: Scene
    x_trim: np.ndarray
    u_trim: np.ndarray
    linearization: Linearization
    A_lat: np.ndarray
    B_lat: np.ndarray
    coupling: dict[str, float]
    lqr: DiscreteLQR
    full_closed_loop: np.ndarray | None = None

    def controller(self, action_dtype=np.float32) -> LQRController:
        """The design's :class:`LQRController`."""
        return LQRController.from_gains(self.scene, self.x_trim, self.u_trim, self.lqr.K[None], action_dtype)


def _scene_for(config: LQRConfig, scene: Scene | None) -> Scene:
    """``scene``, or the config's (its ``scene``, resolved against the config's folder by the loader)."""
    return scene if scene is not None else load_scene(config.scene, elements_per_piece=config.elements_per_piece)


def _check_fixed_scene_fields(cfg: LQRConfig, single: bool) -> None:
    """ValueError naming the config's file and field where a fixed scene's design (a single wing: ``single``, or a
    chain) would ignore it: ``design_model`` other than the transfer phase (the mill's orbit only), ``structure:
    centralised`` for one wing."""
    if cfg.design_model != "transfer_phase":
        raise ValueError(f"{cfg.file}: design_model = {cfg.design_model!r} is the moving-cable mill's "
                         "(control.mill_lqr); a fixed scene's design has one trim: leave the field out")
    if single and cfg.structure != "decentralised":
        raise ValueError(f"{cfg.file}: structure = {cfg.structure!r}: a single wing's design is one gain on its own "
                         "lateral model (the field is for chains and the mill): leave the field out")


def _full_lateral_check(sc: Scene, lin: Linearization, K: np.ndarray, dt: float) -> np.ndarray:
    """Discrete closed-loop eigenvalues of the wing's gain ``K`` (2, 6) on the full lateral model of ``lin`` (the
    cable nodes' lateral states unobserved: zero gain), ZOH at ``dt``; ValueError when that loop is not stable (the
    design on the wing's own block would hide it)."""
    A, B, _, _ = lateral_subsystem(lin)
    n_lat = len(LATERAL_STATE_NAMES)
    sysd = control.c2d(control.ss(A, B, np.eye(A.shape[0]), np.zeros(B.shape)), dt, "zoh")
    Kf = np.zeros((B.shape[1], A.shape[0]))
    Kf[:, :n_lat] = K
    eig = np.linalg.eigvals(np.asarray(sysd.A) - np.asarray(sysd.B) @ Kf)
    if not np.max(np.abs(eig)) < 1.0:
        raise ValueError(f"scene {sc.name}: the lateral model has {A.shape[0]} states, not 6: the tether's cable "
                         f"nodes are not observed, and the wing's gain leaves the full lateral model unstable (max |z| "
                         f"= {np.max(np.abs(eig)):.5f}); use elements_per_piece = 1")
    return eig


def design_tethered_wing(config: LQRConfig | str | Path = DEFAULT_CONFIG, scene: Scene | None = None,
                         trim: tuple[np.ndarray, np.ndarray] | None = None) -> LateralDesign:
    """Trim the single-wing scene, linearise, and design the discrete lateral LQR.

    Parameters
    ----------
    config : LQRConfig or path of its YAML
    scene : Scene, optional      overrides the config's scene (e.g. a modified wing for a study)
    trim : (x, u), optional      a known trim of ``scene`` (found with ``scene.initial_state()`` otherwise)

    A tether of more than one element adds its nodes' lateral states, which the controller does not observe: the gain
    is designed on the wing's own lateral block and checked on the full lateral model (``full_closed_loop``);
    ValueError when it does not hold it (:func:`_full_lateral_check`; ``make_controller`` designs through here). The
    configs' loader refuses ``elements_per_piece`` > 1 in a single-wing config.
    """
    cfg = config if isinstance(config, LQRConfig) else load_lqr_config(config)
    _check_fixed_scene_fields(cfg, single=True)
    sc = _scene_for(cfg, scene)
    if sc.assembly.n_wings != 1:
        raise ValueError(f"design_tethered_wing: scene {sc.name} has {sc.assembly.n_wings} wings; "
                         "use design_ladder_chain for chains")
    x, u = trim if trim is not None else sc.initial_state()
    sim = sc.simulator(x, u)
    lin = linearize(sim, x, u)
    A, B, _, _ = lateral_subsystem(lin)
    n_lat = len(LATERAL_STATE_NAMES)
    nodes = A.shape[0] != n_lat
    if nodes:  # cable nodes add lateral states the controller does not observe: the wing's own block
        A, B = A[:n_lat, :n_lat], B[:n_lat]
    Q, R = bryson_weights(cfg.max_state, cfg.max_input)
    lqr = discrete_lqr(A, B, Q, R, cfg.control_period)
    full = _full_lateral_check(sc, lin, lqr.K, cfg.control_period) if nodes else None
    return LateralDesign(config=cfg, scene=sc, x_trim=x, u_trim=u, linearization=lin, A_lat=A, B_lat=B,
                         coupling=coupling_norms(lin), lqr=lqr, full_closed_loop=full)


# ------------------------------------------------------------------------------------ chain
@dataclass(frozen=True)
class ChainDesign:
    """Lateral LQR of a chain, decentralised (one gain per wing from its own lateral block) or centralised
    (one gain on the full coupled lateral model; every wing's commands use every wing's states).

    A_blocks (n_wings, 6, 6), B_blocks (n_wings, 6, 2): each wing's own lateral block of the Jacobian;
    gains: (n_wings, 2, 6) decentralised or (2 n_wings, 6 n_wings) centralised [rad per unit state];
    closed_loop: discrete eigenvalues of the design model's closed loop (per-wing blocks (n_wings, 6), or the
    full model (6 n_wings,)).
    """

    config: LQRConfig
    scene: Scene
    x_trim: np.ndarray
    u_trim: np.ndarray
    A_blocks: np.ndarray
    B_blocks: np.ndarray
    gains: np.ndarray
    closed_loop: np.ndarray

    def controller(self, action_dtype=np.float32) -> LQRController:
        return LQRController.from_gains(self.scene, self.x_trim, self.u_trim, self.gains, action_dtype)


def _chain_lateral_model(sc: Scene, x: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Full lateral (A, B) of a chain at (x, u); raises if cable nodes add lateral states a controller of
    the environments cannot observe."""
    lin = linearize(sc.simulator(x, u), x, u)
    A, B, _, _ = lateral_subsystem(lin)
    if A.shape[0] != len(LATERAL_STATE_NAMES) * lin.n_wings:
        raise ValueError(f"scene {sc.name}: the lateral model has {A.shape[0]} states, not 6 per wing: cable nodes "
                         "between wings are not observed; use elements_per_piece = 1 for a centralised design")
    return A, B


def design_ladder_chain(config: LQRConfig | str | Path = DEFAULT_CHAIN_CONFIG, scene: Scene | None = None,
                        trim: tuple[np.ndarray, np.ndarray] | None = None) -> ChainDesign:
    """Lateral LQR of a chain (``config.structure``).

    Decentralised: per-wing gains from the diagonal lateral blocks; only the 8 columns per wing that the
    blocks need are differentiated (:func:`wing_lateral_blocks`), about 1.6 thousand right-hand sides for
    101 wings. Centralised: the Riccati equation of the full lateral model (606 states for 101 wings, about
    20 s), with block-diagonal Bryson weights."""
    cfg = config if isinstance(config, LQRConfig) else load_lqr_config(config)
    _check_fixed_scene_fields(cfg, single=False)
    sc = _scene_for(cfg, scene)
    x, u = trim if trim is not None else sc.initial_state()
    sim = sc.simulator(x, u)
    A_blocks, B_blocks = wing_lateral_blocks(sim, x, u)
    Q, R = bryson_weights(cfg.max_state, cfg.max_input)
    if cfg.structure == "centralised":
        A, B = _chain_lateral_model(sc, x, u)
        nw = sc.assembly.n_wings
        d = discrete_lqr(A, B, np.kron(np.eye(nw), Q), np.kron(np.eye(nw), R), cfg.control_period)
        gains, eigs = d.K, d.closed_loop
    else:
        blocks = [discrete_lqr(A, B, Q, R, cfg.control_period) for A, B in zip(A_blocks, B_blocks, strict=True)]
        gains, eigs = np.array([d.K for d in blocks]), np.array([d.closed_loop for d in blocks])
    return ChainDesign(config=cfg, scene=sc, x_trim=x, u_trim=u, A_blocks=A_blocks, B_blocks=B_blocks,
                       gains=gains, closed_loop=eigs)


def full_gain(gains: np.ndarray) -> np.ndarray:
    """(2 n_wings, 6 n_wings) gain matrix of per-wing gains (n_wings, 2, 6) (block diagonal) or of a full one."""
    g = np.asarray(gains, dtype=float)
    if g.ndim == 2:
        return g
    nw, ni, ns = g.shape
    K = np.zeros((ni * nw, ns * nw))
    for k in range(nw):
        K[ni * k: ni * k + ni, ns * k: ns * k + ns] = g[k]
    return K


def chain_closed_loop(design: ChainDesign) -> tuple[np.ndarray, np.ndarray]:
    """Check a chain design on the full coupled lateral model: linearise the whole chain, discretise its
    lateral subsystem with a ZOH at the control period, close the loop with the design's gain (block
    diagonal for a decentralised design) and return (open-loop continuous eigenvalues, closed-loop discrete
    eigenvalues)."""
    A, B = _chain_lateral_model(design.scene, design.x_trim, design.u_trim)
    sysd = control.c2d(control.ss(A, B, np.eye(A.shape[0]), np.zeros(B.shape)), design.config.control_period, "zoh")
    Ad, Bd = np.asarray(sysd.A), np.asarray(sysd.B)
    return np.linalg.eigvals(A), np.linalg.eigvals(Ad - Bd @ full_gain(design.gains))


# ------------------------------------------------------------------------------------ controller
class LQRController:
    """Linear state feedback on the lateral deviations, in the environments' observation and action spaces.

    For every wing k: dz_k = (dy, vy, phi - phi_trim, wrap(psi - psi_trim), p, r) from its observation block
    (layout :data:`~laddermill_gym.control.base.OBS_NAMES`), (rudder, aileron)_k = trim - K_k dz_k, elevator_k =
    trim; actions a = (u - mid) / half_range clipped to [-1, 1]. Implements Stable-Baselines3's ``predict``.

    Parameters
    ----------
    gains : ndarray (n_wings, 2, 6) or (2 n_wings, 6 n_wings)
        Per-wing gains on the wing's own (y, vy, phi, psi, p, r) giving its (rudder, aileron) [rad], or one
        full gain from all wings' states (wing-major) to all wings' (rudder, aileron).
    u_trim : ndarray (3 n_wings,)
        Trim controls [rad].
    trim_attitude : ndarray (n_wings, 2)
        Trim (phi, psi) of every wing [rad].
    mid, half_range : ndarray (3 n_wings,)
        Control range centre and half width [rad] (:func:`~laddermill_gym.control.base.control_ranges`).
    action_dtype : numpy dtype of the returned actions (float32 as in the environments' Box).

    Attributes
    ----------
    n_clipped, n_actions : int
        Number of action entries clipped to [-1, 1] and of action entries produced since the last
        :meth:`reset_clip_count`.
    last_clipped : ndarray of bool
        Which entries of the last returned actions were clipped.
    """

    def __init__(self, gains: np.ndarray, u_trim: np.ndarray, trim_attitude: np.ndarray, mid: np.ndarray,
                 half_range: np.ndarray, action_dtype=np.float32):
        self.gains = np.asarray(gains, dtype=float)
        ni, ns = len(LATERAL_INPUT_NAMES), len(LATERAL_STATE_NAMES)
        g = self.gains
        if g.ndim == 3 and g.shape[1:] == (ni, ns):
            nw = g.shape[0]
        elif g.ndim == 2 and g.shape[0] % ni == 0 and g.shape[1] == g.shape[0] // ni * ns:
            nw = g.shape[0] // ni
        else:
            raise ValueError(f"gains: expected shape (n_wings, 2, 6) or (2 n_wings, 6 n_wings), got {g.shape}")
        self.n_wings = nw
        self.u_trim = np.asarray(u_trim, dtype=float).reshape(nw, N_CONTROLS)
        self.trim_attitude = np.asarray(trim_attitude, dtype=float).reshape(nw, 2)
        self.mid = np.asarray(mid, dtype=float).reshape(nw, N_CONTROLS)
        self.half_range = np.asarray(half_range, dtype=float).reshape(nw, N_CONTROLS)
        self.action_dtype = action_dtype
        self.obs_dim = OBS_PER_WING * nw
        self.act_dim = N_CONTROLS * nw
        self.reset_clip_count()

    @classmethod
    def from_gains(cls, scene: Scene, x_trim: np.ndarray, u_trim: np.ndarray, gains: np.ndarray,
                   action_dtype=np.float32) -> LQRController:
        """Controller for ``scene`` at the trim (x_trim, u_trim) with ``gains`` (see the class)."""
        sim = scene.simulator(x_trim, u_trim)
        euler = sim.wing_euler()
        mid, half = control_ranges(scene.assembly)
        return cls(gains, u_trim, euler[:, [0, 2]], mid, half, action_dtype)

    @classmethod
    def from_config(cls, path: str | Path = DEFAULT_CONFIG, action_dtype=np.float32) -> LQRController:
        """Design from a config file (single wing or chain, chosen by the scene's number of wings); ValueError for a
        moving-cable mill, whose LQR is :func:`~laddermill_gym.control.mill_lqr.design_mill_lqr` on the env's task."""
        cfg = load_lqr_config(path)
        sc = _scene_for(cfg, None)
        if sc.assembly.station is not None:
            raise ValueError(f"{cfg.file}: scene {cfg.scene} is a moving-cable mill: its lateral LQR is designed on "
                             "an environment's orbit (control.mill_lqr.design_mill_lqr; make_controller('lqr:CONFIG', "
                             "a LadderMill id); laddermill lqr --config CONFIG), not by LQRController.from_config")
        design = (design_tethered_wing(cfg, sc) if sc.assembly.n_wings == 1 else design_ladder_chain(cfg, sc))
        return design.controller(action_dtype)

    def reset_clip_count(self) -> None:
        self.n_clipped = 0
        self.n_actions = 0
        self.last_clipped = np.zeros(0, dtype=bool)

    def lateral_deviation(self, observation: np.ndarray) -> np.ndarray:
        """(n_envs, n_wings, 6) lateral deviations from trim of batched observations (n_envs, obs_dim)."""
        obs = np.asarray(observation, dtype=float).reshape(-1, self.n_wings, OBS_PER_WING)
        i = OBS_INDEX
        dpsi = obs[..., i["psi"]] - self.trim_attitude[:, 1]
        dpsi = (dpsi + math.pi) % (2 * math.pi) - math.pi
        return np.stack([obs[..., i["dy"]], obs[..., i["vy"]], obs[..., i["phi"]] - self.trim_attitude[:, 0],
                         dpsi, obs[..., i["p"]], obs[..., i["r"]]], axis=-1)

    def controls(self, observation: np.ndarray) -> np.ndarray:
        """Physical controls [rad], shape (n_envs, n_wings, 3), before clipping to the limits."""
        obs, _ = batch_observations(observation, self.obs_dim)
        dz = self.lateral_deviation(obs)
        u = np.broadcast_to(self.u_trim, (len(obs), self.n_wings, N_CONTROLS)).copy()
        if self.gains.ndim == 3:
            u[..., list(LATERAL_INPUTS)] -= np.einsum("kij,nkj->nki", self.gains, dz)
        else:
            du = dz.reshape(len(obs), -1) @ self.gains.T
            u[..., list(LATERAL_INPUTS)] -= du.reshape(len(obs), self.n_wings, len(LATERAL_INPUT_NAMES))
        return u

    def predict(self, observation: np.ndarray, state: Any = None, episode_start: np.ndarray | None = None,
                deterministic: bool = False) -> tuple[np.ndarray, Any]:
        """Normalised actions for batched (n_envs, obs_dim) or single (obs_dim,) observations."""
        _, single = batch_observations(observation, self.obs_dim)
        a = actions_from_controls(self.controls(observation), self.mid, self.half_range)
        clipped = np.abs(a) > 1.0
        self.last_clipped = clipped.reshape(len(a), -1)
        self.n_clipped += int(clipped.sum())
        self.n_actions += clipped.size
        a = np.clip(a, -1.0, 1.0).reshape(len(a), self.act_dim).astype(self.action_dtype)
        if single:
            self.last_clipped = self.last_clipped[0]
            return a[0], state
        return a, state
