"""A scene at the point-mass fidelity as a Gymnasium environment whose actions command the kites' attitude
(``laddermill_gym/PointMassChain-v0``): the single env, a :class:`~laddermill_gym.envs.pointmass.task.PointMassTask`
with one copy, and the native vector env, the same task with many."""

from __future__ import annotations

import numpy as np

from laddermill_gym.envs.pointmass.task import OBS_PER_KITE, PointMassTask
from laddermill_gym.envs.task_env import TaskEnv
from laddermill_gym.envs.vector import TaskVectorEnv

__all__ = ["PointMassEnv", "PointMassVectorEnv", "OBS_PER_KITE"]


class PointMassEnv(TaskEnv):
    """Point-mass kites of a scene (``fidelity: pointmass``) controlled through their commanded attitude.

    ## Description

    Any scene read at the point-mass fidelity (``ladder.scene.load_scene(scene, fidelity="pointmass")``,
    Podgaets & Ockels 2007): kites are point masses whose attitude is set directly by the actions, on an elastic
    string (laddermill_gym/docs/pointmass.md). The task: pull on the ground point(s) while holding the kites
    near the plane of the wind (default disturbance: the wing envs' 0.01 rad wind-direction step at t = 1 s). The
    kites have no rotational dynamics: an action is the attitude, at once. Registered as
    ``laddermill_gym/PointMassChain-v0`` (the scene ``ladder_chain``); many copies:
    ``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")`` (the copies are stepped one after
    another by the compiled kernels, not by one batched kernel call).

    ## Action Space

    Box [-1, 1]^(2 n_groups) float32; per group of kites (``groups``: "all" one group, "per_kite" one each),
    entry 2g the pitch and 2g + 1 the roll offset from the scene's start attitude, ``a * range``;
    entries outside [-1, 1] are clipped and counted in ``info["n_clipped"]``.

    | Num | Action | Min | Max | Unit |
    |---|---|---|---|---|
    | 2g | pitch offset (alpha offset at rest in a level wind) | -pitch_range_deg | pitch_range_deg | deg |
    | 2g + 1 | roll offset | -roll_range_deg | roll_range_deg | deg |

    ## Observation Space

    Box (7 n_kites + n_ground,) float32, per kite (kite 0 nearest the start ground point): offset of its position
    from the start (x, y, z) [m], velocity (x, y, z) [m/s], tension of the cable element below it (towards the
    start) [N]; then the tension of the element at the start ground point [N] and, for a chain between two
    ground points, at the end ground point [N] (n_ground = 1 or 2). Bounds +-(2 x cable length) for offsets,
    +-max_speed for velocities, 0 to 100 x breaking load for tensions.

    ## Rewards

    r = w_P P / P_ref - w_y S(x_y) - w_u S(x_u) - failure_penalty [terminated], S(x) = 1 - exp(-x), with the
    fields of :class:`~laddermill_gym.envs.task.RewardConfig`: P = T_ground v_reel (single tether) or
    (T_start - T_end) v_reel (chain between two ground points), the ground tensions being the observation's last
    entries, v_reel = reel_speed_fraction x v0, P_ref the power at the start (or ``reference_power_W``);
    x_y = mean over kites of (dy / lateral_scale)^2 (default 5 % of the piece length); x_u = mean of a^2. The rate
    term of the rigid envs is absent (a point mass has no body rates; ``info["reward_rates"]`` is 0).

    ## Starting State

    The scene's point-mass start (quasi-static for a free upper end, the rigid static equilibrium for a chain
    between two ground points), then ``settle_time`` [s] in the steady wind with the start attitude held
    (default 0), computed once per process; every reset returns to it with a fresh wind disturbance drawn from
    ``np_random``. The reset info holds ``t`` (0 s) and ``reference_power_W`` (P_ref).

    ## Episode End

    terminated: the simulator stops (non-finite state, a node faster than ``integrator.max_speed``, a node at the
    ground), a kite below ``min_altitude`` [m], or an element above ``breaking_factor`` x the breaking load
    (``info["failure"]``, ``info["failure_name"]``, ``info["failure_reason"]``).
    truncated: ``episode_time`` [s] reached.

    ## Arguments

    scene, scene_options (keyword overrides of ``load_scene``: ``element_length`` [m], default the file's
    ``fidelity.element_length`` or else 1 m, ``dt`` [s], ``method``, ``n_wings``; an ``"explicit"`` step past 0.9 of
    the string's stable step (``sim.pointmass.explicit_stable_dt``: (dt / t_c)^2 + dt / t_d < 1, t_c = l0 / c, t_d =
    mu l0^2 / (2 DA)) is replaced by the largest whole fraction of the control period below it, with an
    UnstableStepWarning), control_dt [s] (a whole number of the scene's steps), episode_time [s], settle_time [s],
    groups, pitch_range_deg, roll_range_deg, disturbances, wind_dt [s], reward (RewardConfig or dict), min_altitude
    [m], breaking_factor [-]; ``render_mode`` ("rgb_array" or "human": the string, its kites and ground points in 3D,
    ``envs/pointmass/render.py``).

    ## Processes

    The point-mass kernels are numba parallel loops. A process forked (multiprocessing's "fork", the default of
    ``gymnasium.make_vec(..., vectorization_mode="async")`` on Linux) from one whose numba threads run on GNU
    OpenMP cannot run them (numba would end it): its env raises RuntimeError saying so at its first reset. Use
    ``vector_kwargs={"context": "forkserver"}`` (or "spawn"; SB3's ``SubprocVecEnv`` does by default), the native
    ``vectorization_mode="vector_entry_point"`` or "sync".

    ## The moving cable

    A scene with a ``station`` (``scene="laddermill"``, e.g. ``scene_options={"element_length": 70.0}``) runs
    the moving cable (:mod:`laddermill_gym.envs.pointmass.mill`): every copy a
    :class:`~laddermill_gym.sim.pointmass_mill.PointMassMillSimulator` started at the rigid mill's periodic
    operating point mapped to the point-mass mill (computed once per process, about 30 s), its kites' attitude
    following the slots' schedule. Kites are relabelled as the cable moves, so everything is per slot (slot k:
    the k-th kite from the veered ground point): the action's offsets add to the slot's scheduled attitude, the
    observation's per-kite entries are the slot's kite, its last two entries the tensions of the first and last
    element [N]. P = (T_first - T_last) V_c, V_c [m/s] the copy's station speed (``info["cable_speed_m_s"]``);
    P_ref the mean generator power over the first period from the start (or ``reference_power_W``).
    ``info["t"]`` counts from the start's time on the speed schedule; ``settle_time`` must be 0 and a gust grid
    is refused.

    ## Version History

    * v0 (``laddermill_gym/PointMassChain-v0``): initial version. Later, with the same observations, rewards and
      dynamics: rendering ("rgb_array", "human"), ``reference_power_W`` in the reset info, and arguments merged into
      the registered defaults key by key (``scene_options``).
    """

    task_class = PointMassTask

    @property
    def scene(self):
        """The :class:`~laddermill_gym.ladder.pointmass_scene.PointMassScene`."""
        return self.task.scene

    def commanded_attitude(self, action: np.ndarray) -> np.ndarray:
        """Controls (n_k * 3,) [rad] of a normalised action: the start attitude plus pitch and roll offsets."""
        return self.task.commanded_attitude(np.asarray(action, dtype=float)[None])[0]


class PointMassVectorEnv(TaskVectorEnv):
    """``num_envs`` copies of :class:`PointMassEnv` in one task (:class:`~laddermill_gym.envs.vector.TaskVectorEnv`;
    copy i behaves exactly like a single env seeded seed + i; NextStep, SameStep or Disabled autoreset). The copies are
    stepped one after another by the compiled point-mass kernels within one Python call (no Python env object per
    copy, no batched kernel yet).

    Observations (num_envs, 7 n_kites + n_ground) float32; ``info`` holds (num_envs,) arrays of every reward term,
    power [W], largest tension [N], lowest kite altitude [m], t [s], n_clipped and the failure code
    (:data:`~laddermill_gym.envs.pointmass.batch.POINTMASS_FAILURES`), each with its ``_name`` mask.
    ``lateral_offsets(obs)``: dy [m] of every kite (num_envs, n_kites).

    Parameters: ``num_envs``, ``render_mode`` ("rgb_array": one frame per copy, or None), ``autoreset_mode``
    ("NextStep", "SameStep" or "Disabled") and the arguments of the single env; others raise ValueError.
    """

    task_class = PointMassTask
