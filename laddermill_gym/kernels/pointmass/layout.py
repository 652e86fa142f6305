"""Data contract of the point-mass fidelity: state layout, packed slots, the packed model and its workspace.

The point-mass model keeps its own compact layout (the rigid ``KModel`` holds per-element tables that do not fit
500,000 elements in 40 MB). The string is a chain of ``n`` free nodes; element e joins node e - 1 (the start
anchor for e = 0) to node e; with a fixed end the last element joins node n - 1 to the end anchor. Kites sit on
nodes (``knode``). Every node has the 3D free-node layout of ``kernels/contract.py`` (``N3_POS``, ``N3_VEL``,
``N3_SIZE`` = 6 per node), so the state is (6 n,) float64.

Packed model ``PMModel``:

=========  ========================================================================================
field      content
=========  ========================================================================================
wf, tmod,  the air, exactly as in ``KModel`` (``atmosphere/wind_kernels.wind_point``)
ms, md,
gp, gv
par        scalars, slots ``PP_*``
knode      node index of each kite (n_k,) int64, ascending
kflag      1 where a node carries a kite (n,) uint8 (0.5 MB at 500,000 nodes; avoids a search per node)
kt         kite type, slots ``KT_*`` (one type for every kite)
kcl, kcd   the kite's lift and drag coefficients on the uniform alpha grid of ``KT_ALPHA0``, ``KT_DALPHA``
=========  ========================================================================================

Controls ``u``: commanded attitude of each kite, (n_k * PU_SIZE,) [rad]: roll, pitch, yaw (3-2-1 Euler angles,
z down; Podgaets & Ockels 2007, eqs. 6-9).
"""

from collections import namedtuple

#: Scalars ``par``: gravity [m/s^2]; element unstretched length l0 [m]; cable mass per length mu [kg/m]; axial
#: stiffness EA [N]; Voigt damping DA [N s]; diameter [m]; normal and tangential drag constants C_N0, C_T0 [-];
#: number of free nodes [-]; end fixed (1) or free (0); start anchor (3) [m]; end anchor (3) [m]; ground height
#: h_g [m] (-inf: no ground check); speed limit [m/s]; unstretched lengths of the first element (start anchor ->
#: node 0) and of the element to the end anchor [m] and their rates [m/s] (l0 and 0 for a fixed string; the moving
#: cable of ``kernels/pointmass/mill.py`` sets them from the cable moved at the station every step).
PP_GRAVITY, PP_L0, PP_MU, PP_EA, PP_DA, PP_DIAM, PP_CN0, PP_CT0, PP_N, PP_END_FIXED = range(10)
PP_ANCHOR, PP_END, PP_GROUND, PP_MAX_SPEED = 10, 13, 16, 17
PP_L_FIRST, PP_L_LAST, PP_RATE_FIRST, PP_RATE_LAST, PP_SIZE = 18, 19, 20, 21, 22
#: Kite type ``kt``: mass [kg]; wing area [m^2]; first alpha of the coefficient grid [rad]; its spacing [rad].
KT_MASS, KT_AREA, KT_ALPHA0, KT_DALPHA, KT_SIZE = 0, 1, 2, 3, 4
#: Controls of one kite: commanded roll, pitch, yaw [rad].
PU_ROLL, PU_PITCH, PU_YAW, PU_SIZE = 0, 1, 2, 3

#: Status codes (the same numbers as ``kernels/integrate.py``).
PM_OK, PM_NONFINITE, PM_LIMIT, PM_GROUND = 0, 2, 3, 4

#: The packed model holds no kind marker: numba's prange lowering cannot pass a namedtuple nested in the model
#: (``kernels.batch.detach_markers``), and the point-mass kernels are called directly (``sim/pointmass.py``).

PMModel = namedtuple("PMModel", ["wf", "tmod", "ms", "md", "gp", "gv", "par", "knode", "kflag", "kt",
                                 "kcl", "kcd"])
#: Workspace: element tension [N] (n_e,); for the partitioned block elimination (``kernels/pointmass/partitioned.py``)
#: checkpoints (rows, 15: inverse pivot 6, spike 9), one segment's buffer per chunk (P_max, seg, 9) and the chunks'
#: and separators' data (P_max, 48) (``model/pointmass.make_work``).
PMWork = namedtuple("PMWork", ["tension", "ckpt", "seg", "mid"])
#: Symmetric 3x3 storage order.
S_XX, S_YY, S_ZZ, S_XY, S_XZ, S_YZ, S_SIZE = 0, 1, 2, 3, 4, 5, 6
