"""Component build-up of the wing's mass, CG and inertia (main wing, tail surfaces, booms, pod)."""

from __future__ import annotations

import numpy as np

from laddermill_gym.derivations.wing_model import (
    Wing,
)
from laddermill_gym.derivations.wing_parameters import (
    AREAL_TAIL,
    B_H,
    B_W,
    C_W,
    DIHEDRAL,
    H_V,
    L_BOOM,
    M_BOOM,
    M_WING,
    MASS,
    S_H,
    S_V1,
    Y_BOOM,
)


def mass_properties(wing: Wing):
    """Component build-up of mass, CG and inertia about the CG (body axes).

    Returns (components, J) where J = (Jxx, Jyy, Jzz, Jxz) [kg m^2] and components is a list of
    (name, mass, x, y-extent description) for the documentation. The pod's position is solved so the
    CG is at the origin.
    """
    # wing: uniform mass per span, strips on the dihedral line, chordwise centroid at 40 % chord
    x_wcg = wing.x_w + C_W / 4 - 0.40 * C_W
    y = wing.eta * B_W / 2
    z = wing.z_root - np.abs(y) * np.tan(DIHEDRAL)
    dm = M_WING * wing.deta / 2
    Jw = np.zeros(4)
    Jw[0] = np.sum(dm * (y**2 + z**2))
    Jw[1] = np.sum(dm * (x_wcg**2 + z**2)) + M_WING * C_W**2 / 12
    Jw[2] = np.sum(dm * (x_wcg**2 + y**2)) + M_WING * C_W**2 / 12
    Jw[3] = np.sum(dm * x_wcg * z)
    mx_w, mz_w = M_WING * x_wcg, np.sum(dm * z)
    m_h, m_v = AREAL_TAIL * S_H, AREAL_TAIL * S_V1
    c_h, c_v = wing.c_h, wing.c_v
    x_h = wing.x_h - 0.25 * c_h       # plate centroid (tail pivot at its quarter chord)
    x_v = wing.x_h - 0.25 * c_v
    z_h, z_vc = wing.z_root, wing.z_root - H_V / 2
    x_b = wing.x_w - L_BOOM / 2
    items = [  # (mass, x, y, z, own Jxx, own Jyy, own Jzz)
        (m_h, x_h, 0.0, z_h, m_h * B_H**2 / 12, m_h * c_h**2 / 12, m_h * (B_H**2 + c_h**2) / 12),
        (m_v, x_v, Y_BOOM, z_vc, m_v * H_V**2 / 12, m_v * (c_v**2 + H_V**2) / 12, m_v * c_v**2 / 12),
        (m_v, x_v, -Y_BOOM, z_vc, m_v * H_V**2 / 12, m_v * (c_v**2 + H_V**2) / 12, m_v * c_v**2 / 12),
        (M_BOOM, x_b, Y_BOOM, wing.z_root, 0.0, M_BOOM * L_BOOM**2 / 12, M_BOOM * L_BOOM**2 / 12),
        (M_BOOM, x_b, -Y_BOOM, wing.z_root, 0.0, M_BOOM * L_BOOM**2 / 12, M_BOOM * L_BOOM**2 / 12),
    ]
    m_known = M_WING + sum(it[0] for it in items)
    m_pod = MASS - m_known
    x_pod = -(mx_w + sum(it[0] * it[1] for it in items)) / m_pod
    z_pod = -(mz_w + sum(it[0] * it[3] for it in items)) / m_pod
    # pod: a 1.2 m x 0.3 m x 0.3 m box (nose fairing with attachment hardware, actuators, battery)
    lp, wp = 1.2, 0.3
    items.append((m_pod, x_pod, 0.0, z_pod, m_pod * 2 * wp**2 / 12, m_pod * (lp**2 + wp**2) / 12,
                  m_pod * (lp**2 + wp**2) / 12))
    J = Jw.copy()
    for m, x, yy, zz, jx, jy, jz in items:
        J += [jx + m * (yy**2 + zz**2), jy + m * (x**2 + zz**2), jz + m * (x**2 + yy**2), m * x * zz]
    names = ["main wing", "horizontal tail", "fin right", "fin left", "boom right", "boom left", "pod"]
    comps = [(names[0], M_WING, x_wcg, mz_w / M_WING)]
    comps += [(nm, it[0], it[1], it[3]) for nm, it in zip(names[1:], items, strict=True)]
    return comps, tuple(J)
