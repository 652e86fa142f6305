"""Builders of small assemblies for the numpy reference's self-checks (tests/test_reference_selfchecks.py,
tests/test_reference_consistency.py)."""

from __future__ import annotations

import numpy as np

from laddermill_gym.model.params import (
    AERO_COLUMNS,
    END_FIXED,
    END_NODE,
    END_WING,
    AeroTable,
    Assembly,
    Elements,
    WindParams,
    WingType,
)

G = 9.81


# --------------------------------------------------------------------------------------------------
# Builders
# --------------------------------------------------------------------------------------------------


def make_table(n: int = 37) -> AeroTable:
    """Smooth made-up periodic table on a uniform grid from -pi to pi."""
    a = np.linspace(-np.pi, np.pi, n)
    cols = {
        "CL": 2 * np.pi * np.sin(a) * np.cos(a),
        "CD": 0.05 + 1.2 * np.sin(a) ** 2,
        "Cm": -0.1 * np.sin(a),
    }
    small = {
        "CLq": 5.0, "CLad": 2.0, "CLde": 0.4,
        "Cmq": -8.0, "Cmad": -3.0, "Cmde": -1.1,
        "CYb": -0.3, "CYp": 0.05, "CYr": 0.2, "CYdr": 0.15,
        "Clb": -0.08, "Clp": -0.45, "Clr": 0.1, "Clda": 0.2, "Cldr": 0.01,
        "Cnb": 0.06, "Cnp": -0.03, "Cnr": -0.1, "Cnda": -0.01, "Cndr": -0.07,
    }
    values = np.zeros((n, len(AERO_COLUMNS)))
    for i, name in enumerate(AERO_COLUMNS):
        values[:, i] = cols[name] if name in cols else small[name] * np.cos(a)
    values[-1] = values[0]  # exactly periodic
    return AeroTable(alpha=a, values=values, source="made-up")


def make_wing_type(attachment=(0.1, 0.0, 0.2)) -> WingType:
    return WingType(
        name="test",
        mass=12.0,
        inertia=(30.0, 4.0, 33.0, 1.5),
        area=10.0,
        span=8.0,
        chord=1.25,
        r_ref=np.array([0.2, 0.0, -0.05]),
        attachment=np.array(attachment, dtype=float),
        control_limits=np.array([[-0.3, 0.3]] * 3),
        aero=make_table(),
    )


def make_elements(ends, l0, mu=0.05, EA=2.0e5, DA=50.0, diameter=0.004, attach=None) -> Elements:
    """``ends``: list of ((kind_r, index_r), (kind_s, index_s)); scalars broadcast."""
    n = len(ends)
    kind = np.array([[r[0], s[0]] for r, s in ends], dtype=np.int64).reshape(n, 2)
    index = np.array([[r[1], s[1]] for r, s in ends], dtype=np.int64).reshape(n, 2)
    att = np.zeros((n, 2, 3)) if attach is None else np.asarray(attach, dtype=float).reshape(n, 2, 3)

    def arr(v):
        return np.broadcast_to(np.asarray(v, dtype=float), (n,)).copy()

    return Elements(
        end_kind=kind, end_index=index, attach=att, l0=arr(l0), mu=arr(mu), EA=arr(EA), DA=arr(DA),
        diameter=arr(diameter),
    )


def make_assembly(
    n_wings=0, node_mass=(), fixed_points=None, elements=None, wind=None, sag=True,
    cable_aero=True, gravity=G,
) -> Assembly:
    wt = make_wing_type()
    return Assembly(
        dim=3,
        gravity=gravity,
        wind=WindParams() if wind is None else wind,
        wing_types=(wt,),
        wing_type_index=np.zeros(n_wings, dtype=np.int64),
        node_mass=np.asarray(node_mass, dtype=float),
        fixed_points=np.asarray(() if fixed_points is None else fixed_points, dtype=float).reshape(-1, 3),
        elements=make_elements([], []) if elements is None else elements,
        sag=sag,
        cable_aero=cable_aero,
    )


def random_quaternion(rng) -> np.ndarray:
    q = rng.normal(size=4)
    return 1.7 * q / np.linalg.norm(q)  # deliberately not unit


def wing_on_tether(sag=True, cable_aero=True):
    """Wing 0 tethered to a fixed ground point through a free node (two elements)."""
    wind = WindParams(v0=8.0, h0=50.0, v1=0.0016, direction_inf=0.3, direction_height=400.0).with_modulation(
        0.0, 1.0, np.array([1.0, 1.2, 0.9]), np.array([0.0, 0.1, -0.1]))
    wt = make_wing_type()
    el = make_elements([((END_FIXED, 0), (END_NODE, 0)), ((END_NODE, 0), (END_WING, 0))], l0=[50.0, 50.5],
                       attach=[[[0, 0, 0], [0, 0, 0]], [[0, 0, 0], list(wt.attachment)]])
    asm = make_assembly(n_wings=1, node_mass=[0.2], fixed_points=[[0.0, 0.0, 0.0]], elements=el, wind=wind,
                        sag=sag, cable_aero=cable_aero)
    rng = np.random.default_rng(7)
    q = np.array([0.95, 0.05, -0.2, 0.1]) * 1.01
    x = np.concatenate([[-60.0, 5.0, -75.0], q, [18.0, 0.5, 2.0], [0.2, -0.1, 0.15],
                        [-30.0, 2.0, -40.0], rng.normal(size=3)])
    u = np.array([0.05, -0.03, 0.02])
    return asm, x, u
