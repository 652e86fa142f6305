"""Shared construction helpers for the verification tests (plain functions, no fixtures with state).

Everything here only *builds* models through the public API (params, builders, simulator); no test
answer is computed here. The independent answers live in the tests (see shared/design/oracles.md).
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.model.builders import CableSpec
from laddermill_gym.model.params import AERO_COLUMNS, AERO_INDEX, AeroTable, Assembly, Elements, WindParams, WingType

#: Standard gravity [m/s^2].
G0 = 9.80665

#: Uniform alpha grid from -pi to pi, 10-degree spacing [rad].
ALPHA_GRID = np.linspace(-np.pi, np.pi, 37)


def vacuum() -> WindParams:
    """Wind parameters with zero air density: no aerodynamic load of any kind."""
    return WindParams(rho0=0.0)


def zero_aero_table() -> AeroTable:
    """An aerodynamic table with every coefficient zero (a body without aerodynamics)."""
    return AeroTable(alpha=ALPHA_GRID.copy(), values=np.zeros((ALPHA_GRID.size, len(AERO_COLUMNS))),
                     source="tests: zero table")


def smooth_aero_table() -> AeroTable:
    """A smooth, periodic synthetic table with every column non-zero (for convergence-order tests).

    Values are analytic functions of alpha sampled on the grid; the periodic spline through them is
    smooth (C2), which is all an order test needs. Signs are those of a conventional stable wing.
    """
    a = ALPHA_GRID
    s, c = np.sin(a), np.cos(a)
    cols = {
        "CL": 2.0 * np.pi * s * c / (1.0 + 2.0 * s * s) + 0.3 * c * c,
        "CD": 0.05 + 1.0 * s * s,
        "Cm": -0.5 * s + 0.02 * c,
        "CLq": 4.0 * c, "CLad": 1.0 * c, "CLde": 0.4 * c,
        "Cmq": -10.0 + 0.0 * a, "Cmad": -3.0 * c, "Cmde": -1.0 * c,
        "CYb": -0.3 * c, "CYp": -0.05 * c, "CYr": 0.1 * c, "CYdr": 0.1 * c,
        "Clb": -0.05 * c, "Clp": -0.4 * c, "Clr": 0.1 * c, "Clda": 0.1 * c, "Cldr": 0.01 * c,
        "Cnb": 0.05 * c, "Cnp": -0.03 * c, "Cnr": -0.1 * c, "Cnda": -0.01 * c, "Cndr": -0.05 * c,
    }
    values = np.zeros((a.size, len(AERO_COLUMNS)))
    for name, col in cols.items():
        values[:, AERO_INDEX[name]] = col
    values[-1] = values[0]  # exact periodicity (sin(pi) is not exactly 0 in floating point)
    return AeroTable(alpha=a.copy(), values=values, source="tests: smooth synthetic table")


def make_wing_type(mass: float = 1.0, inertia=(1.0, 2.0, 3.0, 0.0), attachment=(0.0, 0.0, 0.0),
                   aero: AeroTable | None = None, area: float = 1.0, span: float = 1.0, chord: float = 1.0,
                   r_ref=(0.0, 0.0, 0.0), name: str = "test") -> WingType:
    """A wing type with the given mass [kg], inertia (Jxx, Jyy, Jzz, Jxz) [kg m^2] and attachment [m];
    no aerodynamics unless a table is given."""
    return WingType(name=name, mass=float(mass), inertia=tuple(float(v) for v in inertia), area=float(area),
                    span=float(span), chord=float(chord), r_ref=np.asarray(r_ref, dtype=float),
                    attachment=np.asarray(attachment, dtype=float),
                    control_limits=np.array([[-0.5, 0.5]] * 3), aero=aero or zero_aero_table())


def free_body_assembly(wing_type: WingType, gravity: float = 0.0, wind: WindParams | None = None) -> Assembly:
    """One wing and no cable at all (a free rigid body)."""
    empty = Elements(end_kind=np.zeros((0, 2), dtype=np.int64), end_index=np.zeros((0, 2), dtype=np.int64),
                     attach=np.zeros((0, 2, 3)), l0=np.zeros(0), mu=np.zeros(0), EA=np.zeros(0),
                     DA=np.zeros(0), diameter=np.zeros(0))
    return Assembly(dim=3, gravity=float(gravity), wind=wind or vacuum(), wing_types=(wing_type,),
                    wing_type_index=np.zeros(1, dtype=np.int64), node_mass=np.zeros(0),
                    fixed_points=np.zeros((0, 3)), elements=empty, sag=False, cable_aero=False)


def cable_spec(mass_per_length: float, EA: float, DA: float = 0.0, diameter: float = 0.01) -> CableSpec:
    """A cable of the given mass per unstretched length [kg/m], axial stiffness [N], damping [N s]."""
    return CableSpec(diameter=diameter, mass_per_length=mass_per_length, EA=EA, DA=DA)


def node_slice(n_wings: int, j: int) -> slice:
    """State slice of free node j's position and velocity (6 floats) in a 3D state."""
    o = 13 * n_wings + 6 * j
    return slice(o, o + 6)


def pytest_configure(config):
    """SB3 writes an (empty) log folder to the system's temporary directory for every model learnt without a log
    folder; the tests' go to one folder, removed when the session ends (SB3 reads ``SB3_LOGDIR``)."""
    import os
    import shutil
    import tempfile

    if "SB3_LOGDIR" not in os.environ:
        folder = tempfile.mkdtemp(prefix="laddermill-tests-sb3-")
        os.environ["SB3_LOGDIR"] = folder
        config.add_cleanup(lambda: shutil.rmtree(folder, ignore_errors=True))


#: LadderMill's arguments for an 11-wing mill (the fallback start after 100 s of settling: not periodic, so every
#: lateral LQR designed on it grows over the period), short episodes
SMALL_MILL = dict(scene="laddermill", scene_options={"n_wings": 11}, settle={"max_time": 100.0}, control_dt=0.05,
                  episode_time=5.0)


def small_mill_task():
    """A one-copy ``MillTask`` of :data:`SMALL_MILL` (the not-periodic start's warning is not shown)."""
    import warnings

    from laddermill_gym.envs.laddermill.task import MillTask

    with warnings.catch_warnings():  # said once per process, when the start is computed
        warnings.simplefilter("ignore", RuntimeWarning)
        return MillTask(1, **SMALL_MILL)
