"""The scenes the numerical studies (work-precision, stress, stable step) run on, built the same way: the rigid
wing-and-cable scenes of ``configs/scenes/`` and Roberts' flying model (``configs/rotorcraft/``), each as a
simulator at its initial equilibrium; and copies of a simulator with other integrator settings or wind."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np

from laddermill_gym.sim.simulator import Simulator
from laddermill_gym.studies.commands import UsageError

#: the rotorcraft configs a study accepts by name (everything else is a scene): ``configs/rotorcraft/``
CRAFT_NAMES = ("roberts_flying_model", "roberts_35m_15kft", "roberts_35m_30kft")
#: the scenes the studies run by default
DEFAULT_SCENES = ("tethered_wing", "ladder_chain", "roberts_flying_model", "laddermill")


def file_stem(name) -> str:
    """A scene's name for its output files: the path's last part without a ``.yaml`` / ``.yml`` suffix only (a bare
    name ``wing_v2.5`` keeps its dot)."""
    last = Path(str(name)).name
    return last.rsplit(".", 1)[0] if last.endswith((".yaml", ".yml")) else last


def check_scene_names(names, option: str = "scene", crafts: bool = True) -> None:
    """UsageError naming ``option`` and the first of ``names`` that is neither a rotorcraft config name
    (:data:`CRAFT_NAMES`, with ``crafts``) nor a scene file (a path or a shipped name), or a name given twice (its
    rows would be measured and printed twice): checked before a study starts."""
    from laddermill_gym.model.configio import ConfigError, find_config

    twice = sorted({n for n in names if list(names).count(n) > 1})
    if twice:
        raise UsageError(f"{option} {twice}: named twice")
    stems = [file_stem(n) for n in names]  # the studies name their output files by it
    same = sorted({str(n) for n, st in zip(names, stems, strict=True) if stems.count(st) > 1})
    if same:
        raise UsageError(f"{option} {same}: the same file name, so their output files would overwrite each other "
                         "(copy one under another name)")

    for name in names:
        if crafts and name in CRAFT_NAMES:
            continue
        try:
            find_config("scenes", name, option)
        except ConfigError as err:
            raise UsageError(f"{err}" + (f"; or a rotorcraft: {', '.join(CRAFT_NAMES)}" if crafts else "")) from None


def refuse_scene_kinds(names, option: str, elsewhere: dict[str, str]) -> None:
    """UsageError naming ``option`` and the first of ``names`` (scene names or files, already checked to exist) of a
    kind the command does not measure: ``"pointmass"`` (a point-mass scene, its fidelity's ``wing: pointmass``) or
    ``"moving"`` (a moving cable through a station, the mill), the keys of ``elsewhere``, each with where the kind
    is measured instead. Reads the scene files only (no scene is built)."""
    from laddermill_gym.model.configio import find_config, load_yaml_text

    for name in names:
        if name in CRAFT_NAMES:
            continue
        path = find_config("scenes", name, option)
        data = load_yaml_text(path.read_text(encoding="utf-8"), str(path)) or {}
        kind = ("pointmass" if (data.get("fidelity") or {}).get("wing") == "pointmass"
                else "moving" if "station" in data else "")
        if kind in elsewhere:
            what = "a point-mass scene" if kind == "pointmass" else "a moving-cable scene (the mill)"
            raise UsageError(f"{option} {name!r}: {what}, which this command does not measure; {elsewhere[kind]}")


def build_simulator(name: str, elements_per_piece: int | None = None, scene_method: str | None = None,
                    **settings) -> Simulator:
    """A simulator of scene (or craft config) ``name`` at its initial equilibrium, with integrator ``settings``
    replaced (``dt``, ``method``, ``breakpoints``, ...). ``elements_per_piece`` re-divides a scene's cable;
    ``scene_method`` loads the scene with that method (a scene file's RK4 step too long for a finer cable is refused
    at load, before ``settings`` could replace it)."""
    if name in CRAFT_NAMES:
        if elements_per_piece is not None:
            raise UsageError(f"{name}: elements_per_piece applies to scenes, not to the rotorcraft")
        from laddermill_gym.rotorcraft.craft import load_craft

        sim = load_craft(name).simulator()
    else:
        from laddermill_gym.ladder.scene import load_scene

        sim = load_scene(name, elements_per_piece=elements_per_piece, method=scene_method).simulator()
    return with_settings(sim, **settings) if settings else sim


def with_settings(sim: Simulator, state: np.ndarray | None = None, controls: np.ndarray | None = None,
                  wind=None, **changes) -> Simulator:
    """A new simulator of the same system as ``sim`` (same class, assembly and vehicle) started from ``state``
    and ``controls`` (default the initial ones), integrator settings with ``changes``, and ``wind`` (a
    ``WindParams``) replacing the assembly's wind when given."""
    settings = dataclasses.replace(sim.settings, **changes)
    asm = sim.assembly if wind is None else dataclasses.replace(sim.assembly, wind=wind)
    x = sim.initial_state if state is None else state
    u = sim.initial_controls if controls is None else controls
    config = getattr(sim, "config", None)
    if config is not None:  # the rotorcraft's simulator takes its settings from its config
        return type(sim)(dataclasses.replace(config, settings=settings), asm, sim.layout, x, u)
    return type(sim)(asm, x, settings, u)
