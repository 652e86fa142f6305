"""Build any controller of the harness for a registered environment from a short spec string:

* ``open_loop``: trim controls held (LadderMill-v0: the operating point's tail settings, zero normalised action);
* ``lqr`` (the environment's default design, configs/agents/lqr_<scene>.yaml) or ``lqr:<config.yaml>``;
* ``scripted`` (PumpingKite-v0 only): the scripted pumping cycle; there ``lqr`` is the cycle with the lateral LQR
  (``control/pumping_cycle.py``) and ``open_loop`` the reel-out trim with the winch stopped;
* ``crosswind`` or ``crosswind:<config.yaml>`` (the pumping kite): figure eights during reel-out, the lateral LQR
  in the reel-in (``control/crosswind.py``; default config ``configs/agents/crosswind_pumping.yaml``);
* PointMassChain-v0 (the point-mass fidelity): ``open_loop`` holds the start attitude; ``lqr`` raises ValueError
  (the LQR designs are the rigid wings');
* a path to a training run folder or model file: a Stable-Baselines3 policy (``rl`` extra), refused when it was
  trained on another env or its observation or action size is not the env's;
* ``ppo_tethered_wing``, ``ppo_rotorcraft``, ``ppo_mill``, ``ppo_chain``, ``ppo_mill_v3``: the policies shipped
  with the package (``control/shipped_policies.py``); a shared per-wing policy (``ppo_mill``, a ``laddermill train
  ppo_mill_v1`` run, and ``ppo_chain``, ``ppo_mill_v3``) runs from its exported ``linear_actor.npz`` when it has one
  (numpy only: no ``rl`` extra needed), else from its SB3 model (:func:`load_policy`).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np

from laddermill_gym.control.base import Controller, UnstableDesignWarning
from laddermill_gym.envs import ENV_IDS, registered_arguments, task_class
from laddermill_gym.envs.task import scene_trim
from laddermill_gym.ladder.scene import options_key
from laddermill_gym.model.configio import CONFIG_DIR

__all__ = ["make_controller", "load_policy", "DEFAULT_LQR_CONFIGS", "UnstableDesignWarning"]

#: LQR design per registered environment (the design's scene and model must be the environment's)
DEFAULT_LQR_CONFIGS: dict[str, Path] = {
    "laddermill_gym/TetheredWing-v0": CONFIG_DIR / "agents" / "lqr_tethered_wing.yaml",
    # TetheredWing-v0's scene (the ids differ in the physics step only)
    "laddermill_gym/TetheredWing-v1": CONFIG_DIR / "agents" / "lqr_tethered_wing.yaml",
    "laddermill_gym/LadderChain-v0": CONFIG_DIR / "agents" / "lqr_ladder_chain.yaml",
    # LadderChain-v0's scene (the ids differ in the physics step only)
    "laddermill_gym/LadderChain-v1": CONFIG_DIR / "agents" / "lqr_ladder_chain.yaml",
    "laddermill_gym/LadderMill-v0": CONFIG_DIR / "agents" / "lqr_laddermill.yaml",
    "laddermill_gym/LadderMill-v1": CONFIG_DIR / "agents" / "lqr_laddermill_v1.yaml",
    "laddermill_gym/LadderMill-v2": CONFIG_DIR / "agents" / "lqr_laddermill_v2.yaml",
    # LadderMill-v2's scene (the ids differ in the physics step only)
    "laddermill_gym/LadderMill-v3": CONFIG_DIR / "agents" / "lqr_laddermill_v2.yaml",
}


def _env_scene(env_kwargs: dict):
    options = dict(env_kwargs.get("scene_options") or {})
    if env_kwargs.get("physics_dt") is not None:
        options["dt"] = env_kwargs["physics_dt"]
    return scene_trim(str(env_kwargs["scene"]), options_key(options))


def _craft_controller(spec: str, kw: dict) -> Controller:
    """Rotorcraft-v0 and v1: open loop (trim collective, no differential), the eq. (6) LQR (``lqr``, ``lqr:<config>``)
    or the LQR with the blade-tip guard on the collective (``lqr_guard``, ``lqr_guard:<config>``:
    control/craft_tip_guard.py)."""
    from laddermill_gym.envs.rotorcraft import observation as ro
    from laddermill_gym.envs.rotorcraft import trim as rt

    if spec == "open_loop":
        from laddermill_gym.control.open_loop import craft_open_loop_controller

        return craft_open_loop_controller(kw)
    from laddermill_gym.control.craft_lqr import (
        DEFAULT_CRAFT_LQR,
        CraftLQRController,
        design_craft_lqr,
        load_craft_lqr_config,
    )

    guard = None
    if spec == "lqr_guard" or spec.startswith("lqr_guard:"):
        from laddermill_gym.control.craft_tip_guard import DEFAULT_TIP_GUARD, load_tip_guard_config

        guard = load_tip_guard_config(spec[10:] if spec.startswith("lqr_guard:") else DEFAULT_TIP_GUARD)
        path = guard.lqr
    else:
        path = Path(spec[4:]) if spec.startswith("lqr:") else DEFAULT_CRAFT_LQR
    cfg = load_craft_lqr_config(path)
    where = f"{guard.file} (its lqr: {path})" if guard is not None else str(path)
    craft_cfg = rt.craft_config(str(kw["craft"]))
    wind = craft_cfg.wind.v0 if kw.get("wind_speed") is None else float(kw["wind_speed"])
    for name, mine, env in (("craft", cfg.craft, kw["craft"]), ("wind_speed", cfg.wind_speed, wind),
                            ("control_period", cfg.control_period, kw["control_dt"])):
        if mine != env:
            raise ValueError(f"{where}: {name} = {mine!r} differs from the environment's {env!r}")
    design = design_craft_lqr(cfg)
    full = float(np.max(np.abs(design.full_closed_loop)))
    if not full < 1.0:  # eq. (6)'s own loop is stable by construction; the whole craft's need not be
        warnings.warn(f"{where}: its gain, designed on eq. (6), does not hold the whole craft's linear model "
                      f"({design.full_closed_loop.size} states, the tethers' nodes included): closed loop max |z| "
                      f"{full:.5f} (>= 1; eq. (6)'s own {float(np.max(np.abs(design.lqr.closed_loop))):.5f}); "
                      f"laddermill lqr --config {path} prints both", UnstableDesignWarning, stacklevel=3)
    if kw.get("collective") is not None and float(kw["collective"]) != design.u_trim[0]:
        raise ValueError(f"{where}: the design trims at the craft's collective {design.u_trim[0]!r} rad, the "
                         f"environment at collective = {kw['collective']!r} rad (the controller would hold its own)")
    mid, half = rt.control_ranges(craft_cfg)
    idx = (ro.OBS_Y, ro.OBS_PHI, ro.OBS_VY, ro.OBS_P)
    lqr = CraftLQRController(design.gain, idx, ro.N_CRAFT_OBS, design.u_trim[0], mid, half)
    if guard is None:
        return lqr
    from laddermill_gym.control.craft_tip_guard import guard_controller

    return guard_controller(guard, lqr, design, craft_cfg.collective_limits, ro.CRAFT_OBS_INDEX)


def _mill_controller(spec: str, kw: dict, env_id: str) -> Controller:
    """LadderMill-v0 and -v1: open loop (the zero normalised action, which holds the operating point's tail
    settings, the paper's fixed settings, and with a drum its generator torque; needs the scene only) or the lateral
    LQR (``control.mill_lqr``: centralised, on the env's own mill with the id's config of
    :data:`DEFAULT_LQR_CONFIGS`; needs the operating point), built with an :class:`UnstableDesignWarning` naming the
    radius when its closed loop grows over the period (the transition matrix's spectral radius >= 1)."""
    if spec == "open_loop":

        from laddermill_gym.control.open_loop import OpenLoopController
        from laddermill_gym.envs.laddermill.actions import action_count
        from laddermill_gym.envs.laddermill.observation import N_OBS_PER_SLOT, N_STATION_OBS
        from laddermill_gym.envs.laddermill.operating_point import mill_scene
        from laddermill_gym.model.params import CONTROL_NAMES

        options = dict(kw.get("scene_options") or {})
        options.pop("dimension", None)
        n = mill_scene(str(kw["scene"]), options_key(options), 3).assembly.n_wings
        n_act = action_count(n, kw.get("groups", "per_slot"), kw.get("n_bands", 4),
                             kw.get("surfaces", CONTROL_NAMES), kw.get("generator_torque", False),
                             kw.get("cable_speed_command", False))
        ctrl = OpenLoopController(np.zeros(n_act), np.zeros(n_act), np.ones(n_act))
        ctrl.obs_dim = N_OBS_PER_SLOT * n + N_STATION_OBS  # its default assumes the wing layout
        return ctrl
    from laddermill_gym.control.lqr_config import load_lqr_config
    from laddermill_gym.control.mill_lqr import design_mill_lqr
    from laddermill_gym.envs.laddermill.task import MillTask

    default = DEFAULT_LQR_CONFIGS.get(env_id, DEFAULT_LQR_CONFIGS["laddermill_gym/LadderMill-v0"])
    path = Path(spec[4:]) if spec.startswith("lqr:") else default
    cfg = load_lqr_config(path)  # its weights, designed on the environment's own mill
    task = MillTask(1, **{k: v for k, v in kw.items() if k != "parallel"})
    design = design_mill_lqr(cfg, task)
    if not design.monodromy_radius < 1.0:  # Floquet: the closed loop grows over the period, transfer included
        warnings.warn(f"{path}: its design on {env_id}'s mill does not hold the orbit: the closed loop's "
                      f"transition matrix over the period has spectral radius {design.monodromy_radius:.3g} "
                      f"(>= 1; frozen closed loop max |z| {design.frozen_radius.max():.4f} over "
                      f"{design.phases.size} phases); laddermill lqr --config {path} prints the check",
                      UnstableDesignWarning, stacklevel=3)
    return design.controller(task)


def _warn_unstable_chain(design, path: Path, env_id: str) -> None:
    """UnstableDesignWarning where a decentralised chain ``design`` leaves the chain's full coupled lateral model
    unstable (:func:`~laddermill_gym.control.lqr.chain_closed_loop`: the whole chain linearised, ZOH at the
    control period, the per-wing gains block-diagonal)."""
    from laddermill_gym.control.lqr import chain_closed_loop
    from laddermill_gym.warning_site import user_stacklevel

    full = float(np.max(np.abs(chain_closed_loop(design)[1])))
    if not full < 1.0:
        blocks = float(np.max(np.abs(design.closed_loop)))
        warnings.warn(f"{path}: its decentralised design on {env_id}'s chain does not hold the full coupled lateral "
                      f"model: closed loop max |z| {full:.4f} (>= 1; on the per-wing blocks it was designed on "
                      f"{blocks:.4f}); a centralised design (structure: centralised, lqr_ladder_chain_central.yaml) "
                      f"holds the default chain; laddermill lqr --config {path} --full-check prints the check",
                      UnstableDesignWarning, stacklevel=user_stacklevel())


def _pumping_controller(spec: str, kw: dict, task_cls: type) -> Controller:
    """PumpingKite-v0 and -v1: ``open_loop`` (the zero action: reel-out trim, winch stopped), ``scripted`` (the cycle
    with rudder and aileron at trim) or ``lqr`` / ``lqr:<config>`` (the cycle with the wing's lateral LQR; default
    config ``lqr_tethered_wing.yaml``, designed on the pumping scene: ``control.pumping_cycle``)."""

    from laddermill_gym.control.pumping_cycle import PumpingCycleController, lateral_lqr
    task = task_cls(1, **{k: v for k, v in kw.items() if k != "parallel"})
    if spec == "open_loop":
        from laddermill_gym.control.open_loop import OpenLoopController

        ctrl = OpenLoopController(np.zeros(task.n_actions), np.zeros(task.n_actions), np.ones(task.n_actions))
        ctrl.obs_dim = task.obs_dim  # its default assumes the wing layout
        return ctrl
    if spec == "scripted":
        return PumpingCycleController(task)
    if spec == "crosswind" or spec.startswith("crosswind:"):
        from laddermill_gym.control.crosswind import CrosswindController
        from laddermill_gym.control.crosswind_config import DEFAULT_CROSSWIND_CONFIG

        lqr = lateral_lqr(task, DEFAULT_LQR_CONFIGS["laddermill_gym/TetheredWing-v0"])
        return CrosswindController(task, lqr, spec[len("crosswind:"):] if ":" in spec else DEFAULT_CROSSWIND_CONFIG)
    path = Path(spec[4:]) if spec.startswith("lqr:") else DEFAULT_LQR_CONFIGS["laddermill_gym/TetheredWing-v0"]
    return PumpingCycleController(task, lateral_lqr(task, path))


def _pointmass_controller(spec: str, kw: dict) -> Controller:
    """PointMassChain-v0: ``open_loop`` (the zero action: every kite holds the start attitude). The LQR designs
    linearise the rigid wings (tail surfaces, body rates), which a point-mass kite does not have."""
    if spec != "open_loop":
        raise ValueError(f"controller {spec!r} is not available for the point-mass fidelity (its kites have no tail "
                         "surfaces and no rotational dynamics to design an LQR on): use 'open_loop' or a trained "
                         "policy")

    from laddermill_gym.control.open_loop import OpenLoopController
    from laddermill_gym.envs.pointmass.task import PointMassTask

    task = PointMassTask(1, **kw)  # its start is memoised per process
    n = task.n_actions
    ctrl = OpenLoopController(np.zeros(n), np.zeros(n), np.ones(n))
    ctrl.obs_dim = task.obs_dim  # its default assumes the wing layout
    return ctrl


def make_controller(spec: str, env_id: str, env_kwargs: dict | None = None) -> Controller:
    """The controller named by ``spec`` for environment ``env_id`` (with argument overrides ``env_kwargs``).

    Model-based controllers act on every wing (``action_mode="tail"``, ``groups="per_wing"``); other action
    layouts raise ValueError. An LQR takes its weights and control period from the config and is designed on the
    environment's own scene (a custom scene file or ``scene_options`` overrides included); a single wing on a tether
    of several elements is refused when the gain does not hold the full lateral model (the cable nodes, which the env
    does not observe: ``design_tethered_wing``), and a mill design unstable over the period is warned of."""
    if env_id not in ENV_IDS:
        raise ValueError(f"env_id = {env_id!r}: must be one of {sorted(ENV_IDS)}")
    kw = registered_arguments(env_id, env_kwargs)  # as gymnasium.make merges them, key by key at every depth
    if "craft" in kw and (spec in ("open_loop", "lqr", "lqr_guard") or spec.startswith(("lqr:", "lqr_guard:"))):
        return _craft_controller(spec, kw)
    pumping = any(c.__name__ == "PumpingTask" for c in task_class(env_id).__mro__)  # v0's task and v1's
    if pumping and (spec in ("open_loop", "scripted", "lqr", "crosswind")
                    or spec.startswith(("lqr:", "crosswind:"))):
        return _pumping_controller(spec, kw, task_class(env_id))
    if task_class(env_id).__name__ == "PointMassTask" and (spec in ("open_loop", "lqr") or spec.startswith("lqr:")):
        return _pointmass_controller(spec, kw)
    if task_class(env_id).__name__ == "MillTask" and (spec == "open_loop" or spec == "lqr" or spec.startswith("lqr:")):
        return _mill_controller(spec, kw, env_id)
    if spec in ("open_loop",) or spec == "lqr" or spec.startswith("lqr:"):
        if kw.get("action_mode", "tail") != "tail" or kw.get("groups", "per_wing") != "per_wing":
            raise ValueError(f"controller {spec!r} needs action_mode='tail' and groups='per_wing' "
                             f"(got {kw.get('action_mode')!r}, {kw.get('groups')!r})")
        sc, x_trim, u_trim = _env_scene(kw)
        if spec == "open_loop":
            from laddermill_gym.control.open_loop import OpenLoopController

            return OpenLoopController.from_scene(sc, u_trim)
        from laddermill_gym.control.lqr import design_ladder_chain, design_tethered_wing, load_lqr_config

        path = Path(spec[4:]) if spec.startswith("lqr:") else DEFAULT_LQR_CONFIGS[env_id]
        cfg = load_lqr_config(path)
        if cfg.control_period != kw["control_dt"]:
            raise ValueError(f"{path}: control_period = {cfg.control_period} s differs from the environment's "
                             f"control_dt = {kw['control_dt']} s")
        # the config gives the weights and the period; the design is made on the environment's own scene (a
        # custom file or overrides included)
        if sc.assembly.n_wings == 1:
            return design_tethered_wing(cfg, sc, (x_trim.copy(), u_trim.copy())).controller()
        design = design_ladder_chain(cfg, sc, (x_trim.copy(), u_trim.copy()))
        if cfg.structure != "centralised":  # the per-wing blocks' stability says nothing of the coupled chain
            _warn_unstable_chain(design, path, env_id)
        return design.controller()
    from laddermill_gym.control.shipped_policies import SHIPPED_POLICIES, shipped_policy_path

    path = shipped_policy_path(spec) if spec in SHIPPED_POLICIES else Path(spec)
    if not path.exists():
        raise ValueError(f"controller = {spec!r}: not 'open_loop', 'lqr', 'lqr:<config>', 'lqr_guard' (rotorcraft "
                         "envs), a shipped policy "
                         f"({', '.join(sorted(SHIPPED_POLICIES))}) or an existing model path")
    return load_policy(path, env_id, env_kwargs)


def load_policy(path: str | Path, env_id: str, env_kwargs: dict | None = None,
                statistics: str | Path | None = None, exact: bool = True) -> Controller:
    """The trained policy at ``path`` (a run folder or a model file) for ``env_id`` with argument overrides
    ``env_kwargs``, refused (ValueError naming the file) where it was trained with other control settings
    (:func:`~laddermill_gym.control.trained_settings.check_trained_settings`), on another env, or with other
    observation or action sizes. A shared per-wing policy runs from its ``linear_actor.npz`` when it has one; an SB3
    one (:meth:`~laddermill_gym.control.sb3_policy.SB3Controller.load`) with the observation statistics
    ``statistics`` when given (a path that need not exist: none), else those saved with the model; ``exact``: its
    linear actor's deterministic actions in float64, fixed order (False: through torch, as training validates)."""
    from laddermill_gym.control.shared_controller import LinearActorController, is_shared_run
    from laddermill_gym.control.trained_settings import check_trained_settings

    if env_id not in ENV_IDS:
        raise ValueError(f"env_id = {env_id!r}: must be one of {sorted(ENV_IDS)}")
    path = Path(path)
    own = {k: v for k, v in registered_arguments(env_id, env_kwargs).items() if k != "parallel"}
    check_trained_settings(path, env_id, own)  # spaces can match an env whose actions mean other things
    if is_shared_run(path):  # a shared per-wing policy (laddermill train ppo_mill_v1)
        if LinearActorController.available(path):  # its linear actor exported: numpy, no torch
            return LinearActorController.load(path, env_id, own)
        from laddermill_gym.control.shared_policy import SharedPolicyController

        return SharedPolicyController.load(path, env_id, own)
    from laddermill_gym.control.sb3_policy import SB3Controller

    ctrl = SB3Controller.load(path, exact=exact, statistics=statistics)
    ctrl.check_env(env_id)
    task = task_class(env_id)(1, **own)
    ctrl.check_spaces(task.obs.shape[-1], task.n_actions, env_id)
    return ctrl
