"""Parameters of the Meijaard et al. (1999) wing's component build-up: geometry (from the paper or chosen),
the design point, the attached-flow/flat-plate blending and the mass build-up. Sources and choices:
``laddermill_gym/docs/wing_data.md``."""

from __future__ import annotations

import numpy as np

# ------------------------------------------------------------------------------------------- geometry
# Paper (Meijaard, Ockels & Schwab 1999, "Results"): S, b, m, CG-ac 0.75 m, CG-attachment 1.5 m, booms 5 m.
S_W = 54.0            # [m^2]  main-wing area, paper
B_W = 20.0            # [m]    main-wing span, paper
MASS = 54.0           # [kg]   total mass, paper
D_AC = 0.75           # [m]    CG to aerodynamic centre of the main wing, paper (we put the ac AHEAD of the CG)
D_ATT = 1.50          # [m]    CG to cable attachment, paper
L_BOOM = 5.0          # [m]    tail-boom length, paper (from the wing's quarter-chord spar to the tail pivot/ac)
C_W = S_W / B_W       # [m]    chord of the rectangular, untapered, unswept main wing (choice) = MAC
A_W = B_W**2 / S_W    # [-]    aspect ratio 7.41
DIHEDRAL = np.radians(3.0)   # [rad] main-wing dihedral, choice (Raymer Ch. 4 guideline for a mid wing, 2-4 deg)
TC_W = 0.14           # [-]    wing thickness ratio, choice (cambered kite/glider section)
A0_SECTION = 6.0      # [1/rad] section lift slope, choice (kappa = a0/2pi = 0.955, DATCOM/Helmbold input)
ALPHA0_W = np.radians(-3.0)  # [rad] zero-lift angle of the cambered section, choice
CM0_W = -0.07         # [-]    section moment about the quarter chord, choice (moderate camber)
AIL_ETA = (0.55, 0.95)       # [-] aileron span stations (fraction of semispan), choice
AIL_CF = 0.25         # [-]    aileron chord / wing chord, choice

# [m^2] horizontal tail area, choice: static margin about 0.08 c with the CG 0.75 m behind the wing ac
DEG = np.pi / 180.0  # [rad/deg]
S_H = 25.0
B_H = 11.2            # [m]    horizontal tail span, choice (aspect ratio 5.0)
TC_H = 0.10           # [-]    tail thickness ratio, choice (symmetric section)
ETA_H = 0.95          # [-]    tail dynamic-pressure ratio q_t/q, typical value (Etkin & Reid Ch. 2)
S_V1 = 3.0            # [m^2]  area of ONE of the twin fins, choice (vertical tail volume 0.024)
H_V = 1.8             # [m]    fin height above the boom, choice (chord 1.67 m)
AR_V_EFF = 2.0        # [-]    effective fin aspect ratio (geometric 1.08 raised by the tail plane end plate), choice
TC_V = 0.10           # [-]    fin thickness ratio, choice
Y_BOOM = 1.0          # [m]    lateral position of the two booms (at the wing's central splitting), choice
D_BOOM = 0.08         # [m]    boom diameter, choice
RUD_CF = 0.35         # [-]    rudder chord / fin chord, choice

ATT_ANGLE = np.radians(80.0)  # [rad] attachment direction below the body x axis (ahead of and below the CG), choice
# [rad] the v1 wing (issue 30, docs/wing_data.md "Design study: a stable in-plane mill"): the same airframe and
# table, the cable attachment 1.5 m (paper) at 60 deg below body x, i.e. 0.75 m ahead of the CG, directly below the
# main wing's ac: the cable's pull then grows the pitch stiffness about the attachment with the lift (a kite's
# tow point ahead of the neutral point); chosen by the pitch check of derivations/pitch_stability.py and in-plane
# runs of the mill (80 deg: not periodic at a descending elevator of 0 deg; 60 deg: periodic, see the doc)
ATT_ANGLE_V1 = np.radians(60.0)
RHO_REF, V_REF, NU = 1.225, 10.0, 1.5e-5   # [kg/m^3], [m/s], [m^2/s] design point for Reynolds numbers and trim
G = 9.81              # [m/s^2]

# blending of attached flow into the flat plate (logistic weights), stall angles and sharpness
# [rad] wing: blend midpoints (CL peaks about 3.5 deg earlier), choice
STALL_W = (np.radians(18.0), np.radians(-16.0))
STALL_H = (np.radians(17.0), np.radians(-17.0))    # [rad] horizontal tail, choice
STALL_V = (np.radians(21.0), np.radians(-21.0))    # [rad] fins (low aspect ratio stall later), choice
M_BLEND = 25.0        # [1/rad] sharpness of the blend (10-90 % over 10 deg), choice: smooth on a 2 deg grid

# mass build-up [kg]
M_WING = 38.0         # main wing structure and skin (0.70 kg/m^2), choice
AREAL_TAIL = 0.20     # [kg/m^2] tail surfaces, choice (light kite-type construction)
M_BOOM = 1.2          # [kg] each carbon boom, choice
N_STRIP = 200         # strips per wing semispan / tail span (numerical resolution)
