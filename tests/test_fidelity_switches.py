"""The cable fidelity switches in 3D are values, not types (docs/numerics.md, "Fidelity switches cost nothing when
off"): every setting runs the one compiled kernel, so a switched-off part is skipped work and cannot be compiled
into a slower variant (as the cable-aerodynamics-off specialisation was, 30 % slower than the full model).

Oracle: numba's own typing of the packed fields (the compiled kernel is chosen by the argument types)."""

from __future__ import annotations

import numba

from laddermill_gym import load_scene

SETTINGS = ({}, {"sag": False}, {"cable_aero": False}, {"sag": False, "cable_aero": False})


def test_every_3d_switch_setting_has_the_same_kernel_types():
    types = set()
    for opts in SETTINGS:
        m = load_scene("tethered_wing", **opts).simulator().model
        types.add((numba.typeof(m.sag), numba.typeof(m.caero)))
    assert len(types) == 1, types
    m2 = load_scene("tethered_wing", dimension=2, cable_aero=False).simulator().model
    assert m2.caero is None  # the in-plane kernel keeps its compile-time specialisation
