"""Variants of the tethered-wing scene for the lateral study: the seven sweeps (:class:`SweepSpec`) and the
scene rebuilt with one parameter changed (attachment point, aerodynamic column scales, wind, tether length).

The scene caches the attachment point in its cable elements when it is built, so variants are rebuilt with
:func:`laddermill_gym.model.builders.build_chain`, never patched."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.ladder.scene import Scene, load_scene
from laddermill_gym.model.builders import build_chain
from laddermill_gym.model.params import AERO_INDEX

SCENE = "tethered_wing"
#: Aerodynamic columns scaled by the vertical-tail sweep (fin-dominated side force and yaw derivatives).
FIN_COLUMNS: tuple[str, ...] = ("CYb", "CYr", "Cnb", "Cnr")
#: Aerodynamic column scaled by the weathercock sweep (yaw moment due to sideslip alone).
WEATHERCOCK_COLUMNS: tuple[str, ...] = ("Cnb",)
#: Aerodynamic columns scaled by the dihedral sweep (roll moment due to sideslip).
DIHEDRAL_COLUMNS: tuple[str, ...] = ("Clb",)
#: Names of the sweeps, in the order they are run and drawn.
SWEEP_NAMES: tuple[str, ...] = ("attach_x", "attach_z", "weathercock", "fin", "dihedral", "wind", "tether")


# ------------------------------------------------------------------------------------ sweep definitions
@dataclass(frozen=True)
class SweepSpec:
    """One parameter sweep.

    Attributes
    ----------
    name : str           short key, one of SWEEP_NAMES
    label : str          axis label with unit
    default : float      the default scene's value (same unit as ``values``)
    values : ndarray     the swept values (unit of ``label``)
    """

    name: str
    label: str
    default: float
    values: np.ndarray


def sweep_specs(scene: Scene, quick: bool = False) -> dict[str, SweepSpec]:
    """The seven sweeps around ``scene``'s defaults: 7 points each (4 with ``quick``), default included."""
    wing = scene.assembly.wing_types[0]
    ax, az = float(wing.attachment[0]), float(wing.attachment[2])
    v0 = float(scene.assembly.wind.v0)
    length = float(scene.piece_length)
    specs = [
        SweepSpec("attach_x", "attachment x, ahead of CG [m]", ax,
                  ax + np.array([-1.0, -0.5, -0.25, 0.0, 0.5, 1.0, 1.5])),
        SweepSpec("attach_z", "attachment z, below CG [m]", az, az * np.array([-1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0])),
        SweepSpec("weathercock", "weathercock scale (Cnb) [-]", 1.0, np.array([0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.5])),
        SweepSpec("fin", "vertical-tail scale (CYb, CYr, Cnb, Cnr) [-]", 1.0,
                  np.array([0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0])),
        SweepSpec("dihedral", "dihedral-effect scale (Clb) [-]", 1.0, np.array([0.0, 1.0, 2.0, 4.0, 6.0, 8.0, 10.0])),
        SweepSpec("wind", "wind speed v0 [m/s]", v0, np.array([5.0, 6.0, 7.0, 8.0, 10.0, 12.0, 16.0])),
        SweepSpec("tether", "tether length [m]", length, np.array([10.0, 25.0, 50.0, 100.0, 200.0, 300.0, 400.0])),
    ]
    if quick:
        specs = [dataclasses.replace(s, values=_quick_values(s)) for s in specs]
    return {s.name: s for s in specs}


def _quick_values(spec: SweepSpec) -> np.ndarray:
    """Four points of a sweep: both ends, the default and the point next to it."""
    v = spec.values
    i = int(np.argmin(np.abs(v - spec.default)))
    keep = sorted({0, len(v) - 1, i, min(i + 1, len(v) - 1)})
    return v[keep]


# ------------------------------------------------------------------------------------ variants
def base_scene() -> Scene:
    """The default ``tethered_wing`` scene with a one-element tether (the LQR's and environments' model)."""
    return load_scene(SCENE, elements_per_piece=1)


def make_variant(base: Scene, *, attachment=None, aero_scale: dict[str, float] | None = None,
                 v0: float | None = None, piece_length: float | None = None) -> Scene:
    """``base`` rebuilt with one or more parameters changed.

    Parameters
    ----------
    base : Scene                     a single-wing scene (from :func:`base_scene` or ``load_scene``)
    attachment : array (3,), optional  cable attachment point from the CG, body axes (x fwd, z down) [m]
    aero_scale : dict, optional      column name (``params.AERO_COLUMNS``) -> factor [-] applied to the whole
                                     column of the aerodynamic table (all angles of attack)
    v0 : float, optional             wind speed at the top of the boundary layer [m/s]
    piece_length : float, optional   unstretched tether length [m]

    The assembly is built again with :func:`~laddermill_gym.model.builders.build_chain` because the cable elements
    carry their own copy of the attachment point.
    """
    asm = base.assembly
    if asm.n_wings != 1 or len(asm.wing_types) != 1:
        raise ValueError(f"make_variant: scene {base.name} must have exactly one wing, it has {asm.n_wings}")
    wing = asm.wing_types[0]
    if attachment is not None:
        att = np.asarray(attachment, dtype=float).reshape(-1)
        if att.shape != (3,) or not np.all(np.isfinite(att)):
            raise ValueError(f"make_variant: attachment must be 3 finite numbers [m], got {attachment!r}")
        wing = dataclasses.replace(wing, attachment=att)
    if aero_scale:
        values = wing.aero.values.copy()
        for col, factor in aero_scale.items():
            if col not in AERO_INDEX:
                raise ValueError(f"make_variant: unknown aerodynamic column {col!r}; known: {sorted(AERO_INDEX)}")
            if not math.isfinite(factor):
                raise ValueError(f"make_variant: scale of {col} must be finite, got {factor!r}")
            values[:, AERO_INDEX[col]] *= factor
        wing = dataclasses.replace(wing, aero=dataclasses.replace(wing.aero, values=values))
    wind = asm.wind
    if v0 is not None:
        if not (math.isfinite(v0) and v0 > 0):
            raise ValueError(f"make_variant: v0 must be a positive wind speed [m/s], got {v0!r}")
        wind = dataclasses.replace(wind, v0=float(v0))
    length = base.piece_length
    if piece_length is not None:
        if not (math.isfinite(piece_length) and piece_length > 0):
            raise ValueError(f"make_variant: piece_length must be a positive length [m], got {piece_length!r}")
        length = float(piece_length)
    names = list(base.ground_points)
    epp = len(base.layout.piece_elements[0])
    new_asm, layout = build_chain(
        (wing,), asm.wing_type_index, length, epp, base.cable, asm.fixed_points, names.index(base.start),
        None if base.end is None else names.index(base.end), wind, dim=asm.dim, sag=asm.sag,
        cable_aero=asm.cable_aero, gravity=asm.gravity)
    return base.replace(assembly=new_asm, layout=layout, piece_length=length)


def variant_for(base: Scene, name: str, value: float) -> Scene:
    """``base`` with the parameter of sweep ``name`` (one of SWEEP_NAMES) set to ``value`` (unit of that sweep)."""
    wing = base.assembly.wing_types[0]
    if name == "attach_x":
        return make_variant(base, attachment=[value, wing.attachment[1], wing.attachment[2]])
    if name == "attach_z":
        return make_variant(base, attachment=[wing.attachment[0], wing.attachment[1], value])
    if name == "weathercock":
        return make_variant(base, aero_scale=dict.fromkeys(WEATHERCOCK_COLUMNS, value))
    if name == "fin":
        return make_variant(base, aero_scale=dict.fromkeys(FIN_COLUMNS, value))
    if name == "dihedral":
        return make_variant(base, aero_scale=dict.fromkeys(DIHEDRAL_COLUMNS, value))
    if name == "wind":
        return make_variant(base, v0=value)
    if name == "tether":
        return make_variant(base, piece_length=value)
    raise ValueError(f"unknown sweep {name!r}")
