"""The point-mass task shared by the single and the vector environments: B copies of a scene at the point-mass
fidelity (Podgaets & Ockels 2007, laddermill_gym/docs/pointmass.md) whose kites' attitude is the action, with the
observation, the rewards of the rigid envs' :class:`~laddermill_gym.envs.task.RewardConfig`, terminations and
wind disturbances around them.

A single environment is the task with B = 1, so single and vector environments run the same code. The copies are
stepped one after another by the compiled multi-step kernels (:class:`~laddermill_gym.envs.pointmass.batch.
PointMassBatch`: one kernel call per copy and control period, not one call for all copies).
"""

from __future__ import annotations

import math
import numbers
import warnings

import numpy as np

from laddermill_gym.atmosphere.disturbances import sample_wind_field
from laddermill_gym.envs.actions import clip_actions
from laddermill_gym.envs.gust_cover import START, check_turbulence_cover
from laddermill_gym.envs.physics_step import ENV_STEP_MARGIN, periods_below
from laddermill_gym.envs.pointmass.batch import (
    POINTMASS_FAILURES,
    PointMassBatch,
    check_fork_safe,
    freeze,
    pointmass_start,
    thaw,
)
from laddermill_gym.envs.pointmass.mill import PointMassMillBatch, mill_task_start
from laddermill_gym.envs.task import RewardConfig, config_from
from laddermill_gym.envs.task_base import TaskCore, check_copies, clip_observations, env_disturbances, positive
from laddermill_gym.kernels.contract import (
    N3_POS,
    N3_SIZE,
    N3_VEL,
    PKO_OFFSET,
    PKO_SIZE,
    PKO_TENSION,
    PKO_VELOCITY,
    PM_GROUND,
    PM_OK,
    PU_PITCH,
    PU_ROLL,
    PU_SIZE,
)
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.ladder.scene_files import open_scene
from laddermill_gym.model.input_cache import input_cache
from laddermill_gym.sim.pointmass import STATUS_TEXT, explicit_stable_dt
from laddermill_gym.sim.stable_step import UnstableStepWarning
from laddermill_gym.warning_site import user_stacklevel

__all__ = ["PointMassTask", "OBS_PER_KITE"]

#: Observation entries per kite (slots ``PKO_*`` of ``kernels/contract.py``): position offset from the start (3)
#: [m], velocity (3) [m/s], tension of the element below the kite [N]; then the tension at each ground point (start,
#: and end for a chain) [N].
OBS_PER_KITE = PKO_SIZE


@input_cache(maxsize=8)
def _scene(scene: str, options):
    """``scene`` loaded at the point-mass fidelity with the ``load_scene`` options ``options``
    (:func:`~laddermill_gym.envs.pointmass.batch.freeze`)."""
    return load_scene(scene, fidelity="pointmass", **thaw(options))


def _with_resolution(scene: str, scene_options: dict | None) -> dict:
    """``scene_options`` with ``element_length`` 1 m unless they or the scene file (with their ``overrides``) name
    one: the file's own ``fidelity.element_length`` (``podgaets_5km``'s 1 cm) stands."""
    options = dict(scene_options or {})
    if "element_length" not in options:
        _, s = open_scene(scene, options.get("overrides"))
        fid = s.data.get("fidelity")
        if not (isinstance(fid, dict) and fid.get("element_length") is not None):
            options["element_length"] = 1.0
    return options


def _has_station(scene: str, options) -> bool:
    """Whether ``scene`` with the frozen ``load_scene`` options ``options`` is a moving cable (has a station)."""
    return _scene(scene, options).station is not None


def _check_step(scene: str, dt) -> None:
    if isinstance(dt, bool) or not (isinstance(dt, numbers.Real) and math.isfinite(dt) and dt > 0):
        raise ValueError(f"scene {scene}: its step dt = {dt!r} s (scene_options or the file's integrator.dt) must be a "
                         "finite number > 0")


def _stable_options(scene: str, options, control_dt: float, control_dt_shown):
    """``options`` (frozen ``load_scene`` options) unchanged, unless the scene's step ``method`` is ``"explicit"`` and
    its ``dt`` is past ``ENV_STEP_MARGIN`` of the string's stable step (:func:`~laddermill_gym.sim.pointmass.
    explicit_stable_dt`, on the moving cable its short end elements'): then with ``dt`` the largest whole fraction of
    the control period below it, and an UnstableStepWarning naming both (as the wing envs do for RK4; past it a run
    "stopped: speed limit exceeded" within a period). ValueError unless the scene's step (checked before the scene is
    loaded when ``scene_options`` give it) is a finite number > 0 that divides ``control_dt`` [s]."""
    if dict(options).get("dt") is not None:
        _check_step(scene, dict(options)["dt"])
    sc = _scene(scene, options)
    _check_step(scene, sc.dt)
    n = int(round(control_dt / sc.dt))
    if n < 1 or abs(n * sc.dt - control_dt) > 1e-9 * control_dt:
        raise ValueError(f"control_dt = {control_dt_shown!r}: must be a whole number of scene steps ({sc.dt} s)")
    if sc.method != "explicit":
        return options
    stable = explicit_stable_dt(sc.string, sc.station)
    limit = ENV_STEP_MARGIN * stable
    if sc.dt <= limit:
        return options
    n = periods_below(control_dt, limit)
    st, l0 = sc.station, sc.string.element_length  # the moving cable's end elements may be shorter
    short = min(l0, st.first_length, st.last_length - st.element_length) if st else l0
    warnings.warn(f"scene {sc.name}: dt = {sc.dt:g} s is above {ENV_STEP_MARGIN:g} x the explicit step's stable step"
                  f" {stable:.4g} s (of {l0:g} m elements, shortest {short:.3g} m): stepping at {control_dt / n:.4g} s,"
                  f" {n} steps per control period", UnstableStepWarning, stacklevel=user_stacklevel())
    return freeze({**thaw(options), "dt": control_dt / n})


class PointMassTask(TaskCore):
    """B copies of a point-mass scene as an RL task (arguments: :class:`PointMassEnv
    <laddermill_gym.envs.pointmass.env.PointMassEnv>`; ``n_copies`` = B).

    Attributes (B copies): ``obs`` (B, obs_dim) clipped observations, ``raw_obs`` unclipped, ``obs_low`` /
    ``obs_high`` (obs_dim,) bounds, ``scene`` the :class:`~laddermill_gym.ladder.pointmass_scene.PointMassScene`,
    ``x_trim`` / ``u_trim`` the start state (6 n,) and attitude (3 n_k,) [rad], ``nominal`` (n_k, 3) the kites'
    start positions [m], ``batch`` the :class:`~laddermill_gym.envs.pointmass.batch.PointMassBatch`, ``steps``
    (B,) control periods of the episode, ``last_action`` (B, n_actions), ``p_ref`` [W] the reference power.
    """

    failure_names = POINTMASS_FAILURES
    env_name = "point-mass"

    def __init__(self, n_copies: int = 1, scene: str = "tethered_wing", scene_options: dict | None = None,
                 control_dt: float = 0.05, episode_time: float = 60.0, settle_time: float = 0.0,
                 groups: str = "all", pitch_range_deg: float = 5.0, roll_range_deg: float = 15.0,
                 disturbances=None, wind_dt: float = 0.1, reward=None, min_altitude: float = 10.0,
                 breaking_factor: float = 1.0):
        B = check_copies(n_copies)
        self._episode_times(control_dt, episode_time, wind_dt)
        if isinstance(settle_time, bool) or not (isinstance(settle_time, numbers.Real) and math.isfinite(settle_time)
                                                 and settle_time >= 0):
            raise ValueError(f"settle_time = {settle_time!r}: must be a finite number >= 0 s")
        if groups not in ("all", "per_kite"):
            raise ValueError(f"groups = {groups!r}: must be 'all' or 'per_kite'")
        self.ranges = np.radians([positive("pitch_range_deg", pitch_range_deg, "deg"),
                                  positive("roll_range_deg", roll_range_deg, "deg")])
        if isinstance(min_altitude, (bool, np.bool_)) or not (isinstance(min_altitude, numbers.Real)
                                                              and np.isfinite(min_altitude)):
            raise ValueError(f"min_altitude = {min_altitude!r}: must be a finite number [m] (NaN never terminated)")
        self.min_altitude = float(min_altitude)
        self.breaking_factor = positive("breaking_factor", breaking_factor, "(-)")
        self.disturbances = env_disturbances(disturbances, self.episode_time, self.wind_dt)
        self.reward_config = rc = config_from(reward, RewardConfig, "reward")
        options = _stable_options(str(scene), freeze(_with_resolution(str(scene), scene_options)), self.control_dt,
                                  control_dt)
        self.mill = None
        if _has_station(str(scene), options):
            if settle_time > 0:
                raise ValueError(f"settle_time = {settle_time!r}: scene {scene!r} has a moving cable, which starts "
                                 "at its periodic operating point (settle_time must be 0)")
            check_fork_safe()
            self.scene, self.mill = mill_task_start(str(scene), options)
            self.x_trim, self.u_trim = self.mill.x0, self.mill.attitudes.ravel()
        else:
            self.scene, self.x_trim, self.u_trim, start_tension = pointmass_start(str(scene), options,
                                                                                  float(settle_time))
        sc, s = self.scene, self.scene.string
        self.string = s
        if s.n_kites < 1:
            raise ValueError(f"scene {sc.name} ({sc.file}): no kites; the point-mass task flies at least one")
        self.n_substeps = int(round(self.control_dt / sc.dt))  # a whole number: _stable_options
        self.n_copies = B
        self.n_wings = s.n_kites
        self.groups = groups
        self.kite_nodes = s.kite_nodes
        self.nominal = self.x_trim.reshape(-1, 6)[self.kite_nodes, :3].copy()
        self._check_min_altitude()
        check_turbulence_cover(self.disturbances, self.x_trim.reshape(-1, 6)[:, :3], what=START)  # every node
        self.n_actions = 2 * (1 if groups == "all" else s.n_kites)
        self.trim_action = np.zeros(self.n_actions)
        self.n_ground = 1 + (s.end is not None)
        self.obs_dim = OBS_PER_KITE * s.n_kites + self.n_ground
        span = 2.0 * s.element_length * s.n_elements
        t_hi = 100.0 * s.cable.breaking_load
        self.obs_high = np.concatenate([np.tile([span] * 3 + [s.max_speed] * 3 + [t_hi], s.n_kites),
                                        [t_hi] * self.n_ground])
        self.obs_low = np.concatenate([np.tile([-span] * 3 + [-s.max_speed] * 3 + [0.0], s.n_kites),
                                       [0.0] * self.n_ground])
        self.breaking_tension = self.breaking_factor * s.cable.breaking_load
        self.v_reel = rc.reel_speed_fraction * s.wind.v0
        self.lateral_scale = rc.lateral_scale or 0.05 * sc.piece_length
        if self.mill is not None:
            self.batch = PointMassMillBatch(sc, B, self.mill)
            start_power = self.mill.mean_power_W
        else:
            self.batch = PointMassBatch(sc, B)
            self.batch.states[:] = self.x_trim
            self.batch.controls[:] = self.u_trim
            self.batch.tension[:] = start_tension  # the start's (memoised): building the env runs no kernel
            start_power = float(self._power(self.batch.tension[:1])[0])
        self.p_ref = rc.reference_power_W or start_power
        if not self.p_ref > 0:
            raise ValueError(f"scene {sc.name} ({sc.file}): the start gives no positive reference power "
                             f"({start_power:.6g} W); set reward.reference_power_W")
        self.raw_obs = np.zeros((B, self.obs_dim))
        self.obs = np.zeros((B, self.obs_dim))
        self.steps = np.zeros(B, dtype=np.int64)
        self.last_action = np.zeros((B, self.n_actions))
        self._failure_value = np.zeros(B)
        self._failure_where = np.zeros(B, dtype=np.int64)  # the kite or element named in the failure's text
        self._compose()

    # ------------------------------------------------------------------ read-outs
    def _power(self, tension: np.ndarray) -> np.ndarray:
        """Ground-generator power [W] (B,) of element tensions (B, n_e): (T_start - T_end) v_reel for a chain
        between two ground points, T_start v_reel for a free upper end; for the moving cable the generator's
        (T_first - T_last) V_c with each copy's cable speed V_c [m/s] from its station state."""
        ends = tension[:, 0] - (tension[:, -1] if self.string.end is not None else 0.0)
        return ends * (self.batch.cable_speed if self.mill is not None else self.v_reel)

    def _compose(self) -> None:
        """raw_obs from the states and tensions; obs = raw_obs clipped to the bounds (non-finite: the bound)."""
        b, nk = self.batch, self.string.n_kites
        per = self.raw_obs[:, : OBS_PER_KITE * nk].reshape(self.n_copies, nk, OBS_PER_KITE)
        per[:, :, PKO_OFFSET: PKO_OFFSET + 3] = b.kite_positions() - self.nominal
        per[:, :, PKO_VELOCITY: PKO_VELOCITY + 3] = b.kite_velocities()
        per[:, :, PKO_TENSION] = b.kite_tensions()
        self.raw_obs[:, OBS_PER_KITE * nk] = b.tension[:, 0]
        if self.n_ground == 2:
            self.raw_obs[:, -1] = b.tension[:, -1]
        clip_observations(self.raw_obs, self.obs_low, self.obs_high, self.obs)

    def observe(self) -> None:
        """Observe every copy at its current state without stepping (after restoring states by hand)."""
        self.batch.update_tensions(np.ones(self.n_copies, bool))
        self._compose()

    def commanded_attitude(self, action: np.ndarray) -> np.ndarray:
        """Controls (B, 3 n_k) [rad] of normalised actions (B, n_actions): the start attitude plus the pitch and
        roll offsets a x range (entries clipped to [-1, 1]), one pair for all kites or one per kite."""
        a = np.clip(np.asarray(action, dtype=float).reshape(self.n_copies, -1, 2), -1.0, 1.0) * self.ranges
        nk = self.string.n_kites
        u = np.broadcast_to(self.u_trim.reshape(1, nk, PU_SIZE), (self.n_copies, nk, PU_SIZE)).copy()
        u[:, :, PU_PITCH] += a[:, :, 0]
        u[:, :, PU_ROLL] += a[:, :, 1]
        return u.reshape(self.n_copies, -1)

    # ------------------------------------------------------------------ episodes
    def reset(self, mask: np.ndarray, rngs) -> None:
        """Start new episodes in the copies selected by ``mask`` (B,): the start state and attitude, t = 0, a
        fresh wind disturbance drawn with ``rngs[b]``, and observe them. Other copies are untouched."""
        b = self.batch
        idx = np.flatnonzero(mask)
        if self.mill is not None:
            for i in idx:
                b.restart(int(i), sample_wind_field(self.disturbances, self.episode_time, self.wind_dt, rngs[i]))
                self.steps[i], self.last_action[i] = 0, 0.0
            self._compose()
            return
        for i in idx:
            b.set_wind(int(i), sample_wind_field(self.disturbances, self.episode_time, self.wind_dt, rngs[i]))
        b.states[idx] = self.x_trim
        b.controls[idx] = self.u_trim
        b.t[idx] = 0.0
        b.status[idx] = PM_OK
        self.steps[idx] = 0
        self.last_action[idx] = 0.0
        b.update_tensions(np.asarray(mask, bool))
        self._compose()

    def _check_min_altitude(self) -> None:
        """ValueError unless ``min_altitude`` is below the lowest kite's start altitude (every episode would end at
        its first step)."""
        lowest = float(-np.max(self.nominal[:, 2]))
        if self.min_altitude >= lowest:
            raise ValueError(f"min_altitude = {self.min_altitude:g} m: at or above the lowest kite's start altitude "
                             f"{lowest:.4g} m")

    def _failures(self, sel: np.ndarray, low: np.ndarray, peak: np.ndarray) -> np.ndarray:
        """Failure codes (B,) (:data:`POINTMASS_FAILURES`) of the copies in ``sel``, given the lowest kite altitude
        ``low`` (B,) [m] and the largest tension ``peak`` (B,) [N]; ``_failure_value`` keeps the quantity."""
        b, code = self.batch, np.zeros(self.n_copies, dtype=np.int64)
        for i in np.flatnonzero(sel):
            if b.status[i] != PM_OK:
                code[i] = 2 if b.status[i] == PM_GROUND else 1
            elif low[i] < self.min_altitude:
                code[i], self._failure_value[i] = 2, low[i]
                self._failure_where[i] = int(np.argmax(b.kite_positions()[i, :, 2]))  # the lowest: largest z
            elif peak[i] > self.breaking_tension:
                code[i], self._failure_value[i] = 3, peak[i]
                self._failure_where[i] = int(np.argmax(b.tension[i]))
        return code

    def step(self, action: np.ndarray, mask: np.ndarray | None = None):
        """Apply normalised actions (B, n_actions) for one control period to the copies in ``mask`` (default
        all) and evaluate them: (reward (B,), terminated (B,), truncated (B,), info dict of (B,) arrays: reward
        terms, ``power_W``, ``max_tension_N``, ``min_altitude_m``, ``t`` [s], ``n_clipped``, ``failure``)."""
        a, n_clipped = clip_actions(action, self.n_copies, self.n_actions)
        b = self.batch
        sel = np.ones(self.n_copies, bool) if mask is None else np.asarray(mask, bool)
        if self.mill is not None:
            off = self.commanded_attitude(a).reshape(self.n_copies, -1, PU_SIZE) - self.u_trim.reshape(-1, PU_SIZE)
            b.offsets[sel] = off[sel]
        else:
            b.controls[sel] = self.commanded_attitude(a)[sel]
        self.last_action[sel] = a[sel]
        b.step(np.where(sel, self.n_substeps, 0))
        self.steps[sel] += 1
        self._compose()
        kites = b.kite_positions()
        low, peak = -np.max(kites[:, :, 2], axis=1), np.max(b.tension, axis=1)
        failure = self._failures(sel, low, peak)
        rc = self.reward_config
        power = self._power(b.tension)
        dy = kites[:, :, 1] - self.nominal[:, 1]
        terminated = failure > 0
        info = {"reward_power": rc.power_weight * power / self.p_ref,
                # a non-finite state (a failure) counts as the full penalty, as the shared reward counts it
                "reward_lateral": -rc.lateral_weight * -np.expm1(-np.nan_to_num(
                    np.mean((dy / self.lateral_scale) ** 2, axis=1), nan=np.inf)),
                "reward_rates": np.zeros(self.n_copies),
                "reward_effort": -rc.effort_weight * -np.expm1(-np.mean(a ** 2, axis=1)),
                "reward_failure": -rc.failure_penalty * terminated}
        reward = sum(info.values())
        truncated = ~terminated & (self.steps >= self.n_steps_max)
        t = b.t - self.mill.t0 if self.mill is not None else b.t.copy()
        info.update(power_W=power, max_tension_N=peak, min_altitude_m=low, t=t, n_clipped=n_clipped, failure=failure)
        if self.mill is not None:
            info["cable_speed_m_s"] = b.cable_speed.copy()
        return reward, terminated, truncated, info

    # ------------------------------------------------------------------ read-outs
    def reset_info(self) -> dict:
        """The single env's reset info beside ``t``: the reference power [W]."""
        return {"reference_power_W": self.p_ref}

    def renderer(self, interactive: bool = False):
        """A 3D renderer of the copies (``envs/pointmass/render.py``): the string, its kites and ground points."""
        from laddermill_gym.envs.pointmass.render import PointMassRenderer

        return PointMassRenderer(self, interactive)

    def failure_text(self, b: int, code: int) -> str:
        """A sentence on why copy ``b`` terminated with failure ``code`` (time and quantity); "" for code 0."""
        if code == 0:
            return ""
        t = float(self.batch.t[b]) - (self.mill.t0 if self.mill is not None else 0.0)
        st = int(self.batch.status[b])
        if st != PM_OK:
            return f"t = {t:.3f} s: the simulator stopped: {STATUS_TEXT.get(st, st)} ({self._stop_where(b)})"
        k = int(self._failure_where[b])
        if code == 2:
            return (f"t = {t:.3f} s: kite {k} at {self._failure_value[b]:.3f} m, below min_altitude "
                    f"{self.min_altitude} m")
        return (f"t = {t:.3f} s: element {k}'s tension {self._failure_value[b]:.6g} N over {self.breaking_factor} x "
                f"the breaking load ({self.breaking_tension:.6g} N)")

    def _stop_where(self, b: int) -> str:
        """Where copy ``b``'s stopped state is worst: its first non-finite entry, else its fastest node [m/s] and
        lowest node [m] (the string's nodes in order from the ground)."""
        x = self.batch.states[b]
        bad = np.flatnonzero(~np.isfinite(x))
        if bad.size:  # the nodes' blocks in order (kernels/contract.py N3_*), the fixed string's and the mill's
            return f"node {int(bad[0]) // N3_SIZE} not finite ({bad.size} state entries)"
        blocks = x.reshape(-1, N3_SIZE)
        pos, vel = blocks[:, N3_POS: N3_POS + 3], blocks[:, N3_VEL: N3_VEL + 3]
        fast, low = int(np.argmax(np.linalg.norm(vel, axis=1))), int(np.argmax(pos[:, 2]))
        return (f"fastest node {fast} at {np.linalg.norm(vel[fast]):.4g} m/s, lowest node {low} at "
                f"{-pos[low, 2]:.4g} m")

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral offsets dy [m] (B, n_kites) of every kite of observations (B, 7 n_kites + n_ground)."""
        nk = self.n_wings
        o = np.asarray(obs, dtype=float)[:, : OBS_PER_KITE * nk].reshape(len(obs), nk, OBS_PER_KITE)
        return o[:, :, PKO_OFFSET + 1]

    def snapshot(self) -> dict:
        """The batch's states, controls, times, status and air per copy, the step counters and last actions;
        TypeError on the moving cable (its copies' station states and slots are not saved)."""
        if self.mill is not None:
            raise TypeError(f"scene {self.scene.name}: pickling the moving-cable point-mass env is not "
                            "supported (its copies' station states and slots are not saved)")
        b = self.batch
        return {"air": [tuple(getattr(m, f) for f in ("tmod", "ms", "md", "gp", "gv")) for m in b.models],
                "arrays": (b.states.copy(), b.controls.copy(), b.t.copy(), b.status.copy(), self.steps.copy(),
                           self.last_action.copy())}

    def restore(self, snap: dict) -> None:
        b = self.batch
        b.states[:], b.controls[:], b.t[:], b.status[:], self.steps[:], self.last_action[:] = snap["arrays"]
        for i, (tmod, ms, md, gp, gv) in enumerate(snap["air"]):
            b.models[i] = b.models[i]._replace(tmod=tmod, ms=ms, md=md, gp=gp, gv=gv)

    def simulator(self, b: int = 0):
        """A :class:`~laddermill_gym.sim.pointmass.PointMassSimulator` of copy ``b`` (snapshot of its state, time,
        controls and air)."""
        return self.batch.simulator(b)
