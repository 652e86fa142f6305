"""Scenes: YAML files in configs/scenes/ loaded into frozen parameters and built into a simulator.

A scene file names its wing type and cable files, the wind, the ground points, a chain of wings on
cable pieces, the fidelity switches, how the initial state is found, and the integrator. See
configs/scenes/tethered_wing.yaml for a commented example and README.md ("Adding a scene").

:func:`load_scene` reads any scene file at its fidelity: the rigid one (``ladder/rigid_scene.py``, a
:class:`~laddermill_gym.ladder.rigid_scene.Scene`) or the point-mass one (``ladder/pointmass_scene.py``); the parts
both read alike are in ``ladder/scene_files.py``. This module imports them (the point-mass one only for a
point-mass file); none of them imports it.
"""

from __future__ import annotations

from pathlib import Path

from laddermill_gym.ladder.rigid_scene import Scene, read_rigid
from laddermill_gym.ladder.scene_files import FIDELITIES, available_scenes, open_scene, scene_path
from laddermill_gym.model.configio import ConfigError

#: The names a user of scenes needs (``Scene``, ``scene_path`` and ``available_scenes`` are defined beside this).
__all__ = ["FIDELITIES", "Scene", "available_scenes", "load_scene", "options_key", "options_kwargs", "scene_path"]


def options_key(options: dict | None) -> tuple:
    """A hashable key of ``load_scene`` keyword overrides (sorted pairs; a nested mapping such as ``overrides`` as
    canonical JSON), for caches of loaded scenes; :func:`options_kwargs` turns it back."""
    import json

    return tuple(sorted((k, json.dumps(v, sort_keys=True) if isinstance(v, (dict, list)) else v)
                        for k, v in dict(options or {}).items()))


def options_kwargs(key: tuple) -> dict:
    """The ``load_scene`` keyword arguments of an :func:`options_key`."""
    import json

    return {k: json.loads(v) if k == "overrides" and isinstance(v, str) else v for k, v in key}


#: The rigid fidelity's keyword overrides that the point-mass string has nothing to apply to, and why.
_RIGID_ONLY = {"dimension": "the point-mass fidelity is 3D only",
               "sag": "the point-mass string has no sag correction to switch (its elements resolve the sag)",
               "elements_per_piece": "the point-mass string's resolution is element_length [m]"}


def _refuse_rigid_only(path: Path, **given) -> None:
    """ConfigError naming a keyword override of the rigid fidelity that a point-mass scene would ignore (``dimension``
    3 is the point-mass string's own and passes)."""
    for key, value in given.items():
        if value is not None and not (key == "dimension" and value == 3):
            raise ConfigError(f"{path}: {key} = {value!r} (override): not at the point-mass fidelity: "
                              f"{_RIGID_ONLY[key]}")


def load_scene(name_or_path: str | Path, *, dimension: int | None = None, sag: bool | None = None,
               cable_aero: bool | None = None, elements_per_piece: int | None = None,
               n_wings: int | None = None, dt: float | None = None, method: str | None = None,
               fidelity: str | None = None, element_length: float | None = None, overrides: dict | None = None):
    """Load a scene YAML; keyword overrides replace the file's values (for benchmarks and studies).

    The fidelity is the file's ``fidelity.wing`` ('rigid', the default, or 'pointmass') unless ``fidelity``
    overrides it; at 'pointmass' the result is a :class:`~laddermill_gym.ladder.pointmass_scene.PointMassScene`
    (its string at ``fidelity.element_length`` or ``element_length`` [m]; ``n_wings``, ``dt``, ``method``
    ('explicit' or 'implicit') and ``cable_aero`` (False: no drag on the string) apply; ``dimension`` other than 3,
    ``sag`` and ``elements_per_piece`` are refused), and nothing of the rigid model is built. At 'rigid'
    ``element_length`` is refused (the cable's resolution is ``elements_per_piece``).

    ``overrides``: a nested mapping merged into the file's fields before they are read, e.g.
    ``{"wind": {"v0": 10.0}, "chain": {"piece_length": 120.0}}`` (parameters as data); checked like the file, errors
    naming the field and "(with overrides)"."""
    path, s = open_scene(name_or_path, overrides, n_wings=n_wings, elements_per_piece=elements_per_piece)
    fdata = s.data.get("fidelity")
    wing_fid = fidelity or (fdata.get("wing", "rigid") if isinstance(fdata, dict) else "rigid")
    if wing_fid not in FIDELITIES:
        raise ConfigError(f"{path}: fidelity.wing = {wing_fid!r}: must be one of {FIDELITIES}")
    if wing_fid == "pointmass":  # imported here: a rigid scene loads no point-mass code
        from laddermill_gym.ladder.pointmass_scene import read_pointmass

        _refuse_rigid_only(path, dimension=dimension, sag=sag, elements_per_piece=elements_per_piece)
        return read_pointmass(s, s.section("fidelity"), path, element_length=element_length, n_kites=n_wings,
                              dt=dt, method=method, cable_aero=cable_aero, overrides=overrides)
    if element_length is not None:  # the rigid model's elements are elements_per_piece per piece: it was ignored
        raise ConfigError(f"{path}: element_length = {element_length!r} (override): not at the rigid fidelity: its "
                          "cable's resolution is elements_per_piece (element_length applies with fidelity "
                          "'pointmass')")
    try:
        return read_rigid(s, path, dimension=dimension, sag=sag, cable_aero=cable_aero,
                          elements_per_piece=elements_per_piece, n_wings=n_wings, dt=dt, method=method)
    except ConfigError as err:  # a point-mass file without its fidelity.wing reads as a rigid one: say so
        idata = s.data.get("initial")
        marks = ((isinstance(fdata, dict) and "element_length" in fdata)
                 or (isinstance(idata, dict) and {"pitch_deg", "roll_deg", "yaw_deg"} & set(idata)))
        if (fidelity is None and not (isinstance(fdata, dict) and "wing" in fdata) and marks
                and str(err).startswith(f"{path}") and "missing field" in str(err)):
            raise ConfigError(f"{err} (the file names no fidelity.wing, so it is read at the rigid fidelity; a "
                              "point-mass scene says fidelity: {wing: pointmass})") from None
        raise
