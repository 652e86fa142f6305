"""The data contract between the Python layer and the numba kernels: every packed slot and state offset by name.

No other module writes a literal slot index or a ``13*k``: the kernels, the packer (``model/packing.py``) and
the Python views all read the names below. numba treats these module globals as compile-time constants, so a
named slot costs nothing.

Packed model ``KModel`` (one per built system; arrays float64 unless said):

====================  ============================================================================
field                 content
====================  ============================================================================
kind                  model kind marker (a namedtuple whose *type* selects the right-hand side, see
                      ``kernels/dispatch.py``): ``RIGID_3D`` or ``RIGID_2D`` (``kernels/rigid/kinds.py``)
wf                    wind parameters, slots ``WF_*``
tmod, ms, md          wind modulation: ``tmod[TM_T0]`` start [s], ``tmod[TM_DT]`` spacing [s]; speed factor [-]
                      and direction offset [rad] samples
gp, gv                None and None (no gust grid) or the frozen gust grid: header (slots ``GP_*``) and samples
                      (n_xi n_h GV_SIZE,) [m/s] (``atmosphere/field.py``)
glob                  global constants, slots ``GL_*``
wtype (int64)         wing type index of each rigid body (n_bodies,)
tf                    wing-type table (n_types, TF_SIZE), slots ``TF_*``
ac                    aerodynamic spline coefficients (n_types, n_intervals, 4, n_columns)
node_mass             lumped mass of each free node [kg] (n_nodes,)
fixed                 fixed (ground) points [m] (n_fixed, 3)
ek, ei (int64)        element end kinds (``END_*``) and indices (n_e, 2)
ea                    body-frame attachment vectors of element ends [m] (n_e, 2, 3)
ef                    element table (n_e, EF_SIZE), slots ``EF_*``
ekd                   T^T T of every element end (n_e, 2, 6, 6)
echild, order, parent, bsz (int64)  block-elimination tree (``model/packing.py``)
sag                   3D: float64[1], 1 = sag correction on, 0 = plain tension-only truss (branched on by value);
                      in-plane: None (off) or float64[1] (on), the type selecting the compiled path
caero                 3D: float64[2] = (C_N0, C_T0), zeros = no cable aerodynamics (by value); in-plane: None or that
vehicle               body-loads plug-in (``kernels/dispatch.py``): ``WING`` for winged bodies, the
                      rotorcraft's namedtuple for Roberts' craft
====================  ============================================================================

The point-mass fidelity, the rotorcraft vehicle and the aerodynamic tables keep their slots here too (sections
below), so this is the one module that names every packed slot, state offset and status code.

The ``None``-or-array fields are compile-time switches: numba compiles one specialisation per combination of
field types and prunes the switched-off code, so a part that is off costs nothing at run time.
"""

from collections import namedtuple

# ------------------------------------------------------------------------------------------- state layout
#: 3D rigid body (13): CG position (global) [m], unit quaternion body -> global, CG velocity (body) [m/s],
#: body rates (p, q, r) [rad/s].
B3_POS, B3_QUAT, B3_VEL, B3_RATE, B3_SIZE = 0, 3, 7, 10, 13
#: 3D free cable node (6): position (global) [m], velocity (global) [m/s].
N3_POS, N3_VEL, N3_SIZE = 0, 3, 6
#: In-plane rigid body (6): x, z [m], pitch theta [rad], body velocity u, w [m/s], pitch rate q [rad/s].
B2_X, B2_Z, B2_THETA, B2_U, B2_W, B2_Q, B2_SIZE = 0, 1, 2, 3, 4, 5, 6
#: In-plane free node (4): x, z [m], x', z' [m/s].
N2_POS, N2_VEL, N2_SIZE = 0, 2, 4
#: Velocity-block sizes (degrees of freedom) of a body and a node, 3D and in-plane.
DOF_B3, DOF_N3, DOF_B2, DOF_N2 = 6, 3, 3, 2

# ------------------------------------------------------------------------------------------- controls
#: Controls per winged body [rad]: elevator, rudder, aileron.
CTRL_ELEVATOR, CTRL_RUDDER, CTRL_AILERON, N_CONTROLS = 0, 1, 2, 3

# ------------------------------------------------------------------------------------------- wind
#: Wind parameters ``wf``: speed at the top of the boundary layer v0 [m/s], boundary-layer height h0 [m],
#: gradient above it v1 [1/s], power-law exponent [-], direction turn far aloft phi_inf [rad], its height h_s
#: [m], density at h = 0 rho0 [kg/m^3], density model (``DENSITY_BAROMETRIC`` or ``DENSITY_ISA``), scale
#: height H_b [m].
WF_V0, WF_H0, WF_V1, WF_EXPONENT, WF_DIR_INF, WF_DIR_HEIGHT, WF_RHO0, WF_DENSITY_MODEL, WF_SCALE_HEIGHT = range(9)
WF_SIZE = 10
DENSITY_BAROMETRIC, DENSITY_ISA = 0.0, 1.0
#: Wind modulation grid ``tmod``: first sample time [s], sample spacing [s].
TM_T0, TM_DT, TM_SIZE = 0, 1, 2
#: Frozen gust grid header ``gp`` (``atmosphere/field.py``): along-wind coordinate of the first grid column
#: xi0 [m] and spacing [m], height of the first grid row [m] and spacing [m], columns and rows [-] (0 columns:
#: an empty row of a batch), advection speed of the frozen field [m/s], downwind unit vector (x, y) of the grid's
#: u axis [-], fade-in time T_f [s] (the grid's values are scaled by 0.5 (1 - cos(pi t / T_f)) for 0 <= t < T_f,
#: 0 before; T_f = 0: no fade).
GP_XI0, GP_DXI, GP_H0, GP_DH, GP_NXI, GP_NH, GP_ADVECTION, GP_EX, GP_EY, GP_FADE, GP_SIZE = range(11)
#: Components of a gust grid sample ``gv`` (flat, index ((i n_h + j) GV_SIZE + c)): along the mean wind u,
#: lateral v (to the right looking downwind), vertical w (up) [m/s].
GV_U, GV_V, GV_W, GV_SIZE = 0, 1, 2, 3

# ------------------------------------------------------------------------------------------- globals
#: ``glob``: gravity [m/s^2], cable normal and tangential drag constants C_N0, C_T0 [-], first alpha of the
#: aerodynamic tables [rad] and their spacing [rad].
GL_GRAVITY, GL_CN0, GL_CT0, GL_ALPHA0, GL_DALPHA, GL_SIZE = 0, 1, 2, 3, 4, 8

# ------------------------------------------------------------------------------------------- wing types
#: Wing-type table ``tf``: mass [kg], inertia Jxx, Jyy, Jzz, Jxz [kg m^2], area [m^2], span [m], chord [m],
#: aerodynamic reference point (3) and cable attachment (3) from the CG, body axes [m].
TF_MASS, TF_JXX, TF_JYY, TF_JZZ, TF_JXZ, TF_AREA, TF_SPAN, TF_CHORD = range(8)
TF_RREF, TF_ATTACH, TF_SIZE = 8, 11, 16

# ------------------------------------------------------------------------------------------- elements
#: Element table ``ef``: unstretched length [m], mass per length [kg/m], axial stiffness EA [N], Voigt
#: damping DA [N s], diameter [m].
EF_L0, EF_MU, EF_EA, EF_DA, EF_DIAMETER, EF_SIZE = 0, 1, 2, 3, 4, 5
#: End kinds of an element (``ek``).
END_WING, END_NODE, END_FIXED = 0, 1, 2

# ------------------------------------------------------------------------------------------- moving cable
#: Ground station of the moving cable (``kernels/moving_cable.py``; parameters in ``model/station.py``), packed in
#: the kind marker's array ``station``: piece length l0 [m]; the first (veered) and last (hauled) elements'
#: unstretched lengths as fractions of l0 when the cable has moved 0 since the last transfer (Meijaard: 1/10,
#: 11/10) [-] (the first element is element 0, the last element n_e - 1); the offset of the station block in the
#: state; mode (``MODE_PRESCRIBED``:
#: the cable speed follows the schedule, ``MODE_DRUM``: the speed is a state driven by the tension difference
#: against the generator torque, ``MODE_COMMANDED``: the speed is a state that follows a commanded speed, a
#: control, with the time constant tau of the generator's speed controller); drum radius [m] and inertia referred
#: to the drum axis [kg m^2]; offset of the station's control (torque [N m] or commanded speed [m/s]) in the
#: controls; tau [s]; the insertion rule of a transferred wing (``INSERT_PAPER``: its velocity interpolated between
#: the ground point at rest and its neighbour, Meijaard et al. 1999; ``INSERT_CABLE``: between the cable's own
#: velocity at the ground point and its neighbour, so that it moves with the cable it joins); number of schedule
#: points; the schedule: times [s], then speeds [m/s].
SP_PIECE, SP_F_FIRST, SP_F_LAST, SP_XOFF, SP_MODE = range(5)
SP_RADIUS, SP_INERTIA, SP_UOFF, SP_TAU, SP_INSERT, SP_NSCHED, SP_SCHED = 5, 6, 7, 8, 9, 10, 11
MODE_PRESCRIBED, MODE_DRUM, MODE_COMMANDED = 0.0, 1.0, 2.0
INSERT_PAPER, INSERT_CABLE = 0.0, 1.0
#: Station block of the state (after the bodies and nodes): cable moved since the last transfer s [m] (the
#: first element's unstretched length is f_first l0 + s, the last one's f_last l0 - s), number of transfers
#: [-] (signed; wing slots shift by one at each), cable speed V_c [m/s] (> 0: the cable leaves the station on
#: the first, veered side and returns on the last, hauled side), generator energy E [J] (the integral of the
#: generator's mechanical power: (T_first - T_last) V_c with a prescribed speed, (torque / radius) V_c with a
#: drum).
SX_MOVED, SX_TRANSFERS, SX_SPEED, SX_ENERGY, SX_SIZE = 0, 1, 2, 3, 4

# ------------------------------------------------------------------------------------------- reeling tether
#: The reeling multi-element tether of a winch (``kernels/reel.py``; packed by ``model/reel.py``), the kind
#: marker's array ``reel``: nominal element length l_n [m]; split the drum element when its rest length reaches
#: RL_SPLIT l_n, merge it with the element above below RL_MERGE l_n [-]; free nodes in the air at t = 0 [-] (the
#: nodes 0 .. n - 1 - that count lie on the drum, held at the ground point); ground contact of a tether node: natural
#: frequency omega [rad/s] and damping ratio zeta [-] of the penalty spring on the node's lumped mass, Coulomb
#: friction coefficient [-] and the sliding speed [m/s] below which it is viscous; the ground height h_g [m].
#: The state's ``SX_TRANSFERS`` counts the nodes paid out into the air since t = 0 (splits less merges).
RL_LNOM, RL_SPLIT, RL_MERGE, RL_ACTIVE0, RL_OMEGA, RL_ZETA, RL_MU, RL_VSLIP, RL_GROUND, RL_SIZE = range(10)

# ------------------------------------------------------------------------------------------- loads output
#: Wing aerodynamics output ``W.aout`` (3D): force (3) [N] and moment (3) [N m] in body axes, the
#: alpha-rate coefficients of the six equations (6) and the direction g along which they act (3).
AO_FORCE, AO_MOMENT, AO_KAPPA, AO_G, AO_SIZE = 0, 3, 6, 12, 15
#: In-plane wing aerodynamics output: fx, fz, my, the three alpha-rate coefficients and g (x, z).
AO2_FORCE_X, AO2_FORCE_Z, AO2_MOMENT, AO2_KAPPA, AO2_G = 0, 1, 2, 3, 6

# ------------------------------------------------------------------------------------------- observation
#: Observation of one winged body (``kernels/rigid/observe.py``; names and units in ``envs/observation.py``):
#: CG offset from the nominal position (global, 3) [m], CG velocity (global, 3) [m/s], 3-2-1 Euler angles
#: roll, pitch, yaw (3) [rad], body rates (3) [rad/s], angle of attack [rad], sideslip [rad], tension of the
#: element below the body [N].
OBS_OFFSET, OBS_VELOCITY, OBS_EULER, OBS_RATES, OBS_ALPHA, OBS_BETA, OBS_TENSION, OBS_SIZE = 0, 3, 6, 9, 12, 13, 14, 15

#: Auxiliary output of the batched wing step ``aux`` (B, N_AUX), ``kernels/rigid/observe.py``: largest element
#: tension [N], tension of the element at the start ground point [N], at the end ground point [N] (0 without an
#: end), lowest wing CG altitude -z [m].
AUX_MAX_TENSION, AUX_GROUND_START, AUX_GROUND_END, AUX_MIN_ALTITUDE, N_AUX = 0, 1, 2, 3, 4

# ------------------------------------------------------------------------------------------- limits
#: Integrator safety limits ``limits``: largest speed [m/s], largest angular rate [rad/s], ground height h_g [m]
#: (height h = -z): a wing CG or free node at h <= h_g after a step stops the run; -inf when the kernels are not
#: to stop on the ground (``ground_contact`` "flag" or "off", ``sim/simulator.py``).
LIM_SPEED, LIM_RATE, LIM_GROUND, LIM_SIZE = 0, 1, 2, 3

# ------------------------------------------------------------------------------------------- element stiffness
#: Element stiffness ``W.ke`` (symmetric 3 x 3, global axes, [N/m]): entries xx, yy, zz, xy, xz, yz.
KE_XX, KE_YY, KE_ZZ, KE_XY, KE_XZ, KE_YZ, KE_SIZE = 0, 1, 2, 3, 4, 5, 6

# ------------------------------------------------------------------------------------------- status codes
#: Status of an integrator step or a post-step check (``kernels/integrate.py``, ``kernels/rigid/kinds.py``,
#: ``kernels/rigid/rosenbrock.py``): success, singular block, non-finite state, speed or rate limit, ground
#: contact, DP5(4)'s step collapsed, step budget spent.
OK, SINGULAR, NONFINITE, LIMIT, GROUND, STALLED, BUDGET = 0, 1, 2, 3, 4, 5, 6

# ------------------------------------------------------------------------------------------- aerodynamic tables
#: Columns of a wing type's aerodynamic table ``ac[k, i, p, j]`` (the order of ``model.params.AERO_COLUMNS``).
CL, CD, CM, CLQ, CLAD, CLDE, CMQ, CMAD, CMDE = 0, 1, 2, 3, 4, 5, 6, 7, 8
CYB, CYP, CYR, CYDR, CLB, CLP, CLR, CLDA, CLDR = 9, 10, 11, 12, 13, 14, 15, 16, 17
CNB, CNP, CNR, CNDA, CNDR = 18, 19, 20, 21, 22
N_COLUMNS = 23

#: The longitudinal columns (CL, CD, Cm, their rate and elevator derivatives) come first: the in-plane kernel
#: evaluates only these.
N_LONGITUDINAL = CMDE + 1

# ------------------------------------------------------------------------------------------- point-mass fidelity
#: The point-mass fidelity (Podgaets & Ockels 2007, ``kernels/pointmass/``): state layout, packed slots, the packed
#: model and its workspace.
#:
#: The point-mass model keeps its own compact layout (the rigid ``KModel`` holds per-element tables that do not fit
#: 500,000 elements in 40 MB). The string is a chain of ``n`` free nodes; element e joins node e - 1 (the start
#: anchor for e = 0) to node e; with a fixed end the last element joins node n - 1 to the end anchor. Kites sit on
#: nodes (``knode``). Every node has the 3D free-node layout above (``N3_POS``, ``N3_VEL``,
#: ``N3_SIZE`` = 6 per node), so the state is (6 n,) float64.
#:
#: Packed model ``PMModel``:
#:
#: =========  ========================================================================================
#: field      content
#: =========  ========================================================================================
#: wf, tmod,  the air, exactly as in ``KModel`` (``kernels/wind.wind_point``)
#: ms, md,
#: gp, gv
#: par        scalars, slots ``PP_*``
#: knode      node index of each kite (n_k,) int64, ascending
#: kflag      1 where a node carries a kite (n,) uint8 (0.5 MB at 500,000 nodes; avoids a search per node)
#: kt         kite type, slots ``KT_*`` (one type for every kite)
#: kcl, kcd   the kite's lift and drag coefficients on the uniform alpha grid of ``KT_ALPHA0``, ``KT_DALPHA``
#: =========  ========================================================================================
#:
#: Controls ``u``: commanded attitude of each kite, (n_k * PU_SIZE,) [rad]: roll, pitch, yaw (3-2-1 Euler angles,
#: z down; Podgaets & Ockels 2007, eqs. 6-9).
#:
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

#: Status codes of the point-mass kernels (the integrators' codes).
PM_OK, PM_NONFINITE, PM_LIMIT, PM_GROUND = OK, NONFINITE, LIMIT, GROUND

#: Symmetric 3x3 storage order.
S_XX, S_YY, S_ZZ, S_XY, S_XZ, S_YZ, S_SIZE = 0, 1, 2, 3, 4, 5, 6

#: Observation of one point-mass kite (``envs/pointmass/task.py``): position offset from the start (3) [m],
#: velocity (3) [m/s], tension of the element below the kite [N].
PKO_OFFSET, PKO_VELOCITY, PKO_TENSION, PKO_SIZE = 0, 3, 6, 7
#: Station state of the point-mass mill (``kernels/pointmass/mill.py``): the rigid mill's ``SX_*`` block, then the
#: kites transferred (signed) [-].
MX_KITE_TRANSFERS = SX_SIZE
MX_SIZE = SX_SIZE + 1

#: Partitioned elimination's workspace (``kernels/pointmass/partitioned.py``).
#: Columns of a checkpoint row (inverse pivot 6, spike 9), of a segment buffer row (inverse pivot 6, spike
#: times the lower separator's load 3) and of a chunk's row of ``PMWork.mid``.
CKPT_COLS, BUF_COLS, MID_COLS = 15, 9, 48
#: ``PMWork.mid`` row c: chunk c's top inverse pivot and solution, bottom inverse pivot and solution, corner
#: block q_top W_top (3x3, row-major); separator c's reduced inverse pivot, eliminated right-hand side, coupling
#: L_c to separator c - 1 (3x3) and solution z_c.
MID_TOP, MID_BOT, MID_GTB, MID_DINV, MID_GRED, MID_LBLK, MID_ZSEP = 0, 9, 18, 27, 33, 36, 45

# ------------------------------------------------------------------------------------------- rotorcraft vehicle
#: Blade parameters ``rp`` and the inflow solver's outputs and status (``rotorcraft/rotor_kernels.py``).
P_SIGMA, P_A, P_DELTA, P_B, P_GAMMA = 0, 1, 2, 3, 4
N_PARAMS = 5

#: Outputs of solve_inflow (first five) and rotor_state (all).
O_LAMBDA, O_NU, O_CT, O_ITER, O_STATUS = 0, 1, 2, 3, 4
O_CH, O_CQ, O_A0, O_A1, O_B1, O_TIP_AOA, O_CP = 5, 6, 7, 8, 9, 10, 11
N_OUT = 12

#: Inflow solver status.
STATUS_OK = 0
STATUS_NO_BRACKET = 1   # no sign change of the residual found within the search
STATUS_MAX_ITER = 2     # bracket found, but the tolerance was not met within max_iter refinements
STATUS_NOT_FINITE = 3   # a non-finite input or residual

#: Craft parameters ``cp``, per-rotor outputs and vehicle outputs (``rotorcraft/craft_kernels.py``).
C_RADIUS, C_OMEGA, C_HUB_X, C_HUB_Y, C_HUB_Z = 0, 1, 2, 3, 4
C_FIN_AREA, C_FIN_SLOPE, C_FIN_X, C_FIN_Z, C_DRAG_AREA = 5, 6, 7, 8, 9
C_ETA, C_TOL, C_MAX_ITER = 10, 11, 12
N_CP = 13

#: Per-rotor outputs.
R_THRUST, R_HFORCE, R_TORQUE, R_POWER, R_MU, R_LAMBDA, R_CT, R_TIP_AOA, R_STATUS, R_THETA = range(10)
N_RO = 10
#: Vehicle outputs ``cout`` (the workspace's ``vout``): body force (3), body moment (3), the rotors' blocks
V_FORCE, V_MOMENT, V_ROTOR = 0, 3, 6
N_COUT = V_ROTOR + 2 * N_RO

#: Controls of the craft ``u`` [rad]: collective pitch theta0, differential collective dtheta (right rotor at
#: theta0 + dtheta, left at theta0 - dtheta).
CU_COLLECTIVE, CU_DIFFERENTIAL, CU_SIZE = 0, 1, 2

#: Rows of the craft's batched observation (``rotorcraft/craft_observe.py``).
CO_OFFSET = 0      # CG position minus the nominal position (3) [m]
CO_VELOCITY = 3    # CG velocity, global (3) [m/s]
CO_EULER = 6       # roll, pitch, yaw (3) [rad]
CO_RATES = 9       # body rates p, q, r (3) [rad/s]
CO_THRUST = 12     # thrust ratio per rotor (2) [-]
CO_TENSION = 14    # tension ratio per tether (3) [-]
CO_PITCH = 17      # blade collective pitch per rotor (2) [rad]
N_CRAFT_OBS = 19

#: Auxiliary row.
CA_POWER = 0           # net electrical power [W] (eta P generating, P / eta driven; nan if an inflow failed)
CA_MAX_TENSION = 1     # largest element tension [N]
CA_MAX_ELEMENT = 2     # index of that element (a whole number)
CA_ALTITUDE = 3        # CG altitude -z [m]
CA_INFLOW_OK = 4       # 1.0 when both rotors' inflow converged, else 0.0
CA_THRUST = 5          # rotor thrusts (2) [N]
CA_TENSION = 7         # craft-end tether tensions (3) [N]
CA_TIP_AOA = 10        # retreating-tip incidences (2) [rad]
N_CRAFT_AUX = 12

#: References ``ref``.
REF_POSITION = 0   # nominal CG position (3) [m]
REF_THRUST = 3     # trim thrust per rotor (2) [N]
REF_TENSION = 5    # trim craft-end tension per tether (3) [N]
REF_SIZE = 8

# ------------------------------------------------------------------------------------------- records
KModel = namedtuple(
    "KModel",
    ["kind", "wf", "tmod", "ms", "md", "gp", "gv", "glob", "wtype", "tf", "ac", "node_mass", "fixed",
     "ek", "ei", "ea", "ef", "ekd", "echild", "order", "parent", "bsz", "sag", "caero", "vehicle"],
)
#: Per-copy air of a batch (each array with a leading copy axis; rows as the KModel fields of the same name; gp and
#: gv None when no copy has a gust grid):
#: the batch kernels take it as one argument, so adding a part of the air does not change their signatures.
KAir = namedtuple("KAir", ["tmod", "ms", "md", "gp", "gv"])
#: Kernel workspace: block matrices and pivots of the elimination, scratch of the element ends, tensions [N]
#: (``tension``), body rotations (``Rw``), aerodynamic scratch, the vehicle's outputs and scratch (``vout``,
#: ``vscratch``: per copy, so batched copies never share them), the integrators' stage vectors, and the linearly
#: implicit integrator's (``kernels/rigid/rosenbrock.py``) mass matrix at the step's start (``Dm``, ``Um``), its
#: iteration matrix (``Ds``, ``Us``), the body rotations at the step's start (``Rn``) and each element's stiffness
#: (``ke`` (n_e, KE_SIZE): the symmetric 3 x 3 axial and geometric stiffness [N/m], slots ``KE_*``) and each body's
#: load derivatives with its attitude (``kb`` (n_bodies, 6, 3) [N/rad, N m/rad], ``kernels/rigid/body_jacobian.py``),
#: the wind modulation's line on a step between kinks (``seg_tmod`` (TM_SIZE,), ``seg_ms``, ``seg_md`` (4,):
#: ``kernels/fixed_steps.py``), and the factored iteration matrix's coupling blocks and pivots (``Yw``, ``pivw``;
#: its factored diagonal blocks in ``Ds``: ``kernels/rigid/blocks.py`` ``tree_factor``), and ``wjac`` (1,): h gamma [s]
#: of the iteration matrix those hold (0: none yet), read only when a W-method reuses it over steps
#: (``kernels/rigid/rosenbrock.py`` ``with_jacobian_reuse``).
KWork = namedtuple(
    "KWork",
    ["D", "U", "Y", "piv", "bv", "Rw", "tension", "Tr", "Ts", "er", "es", "coef", "aout", "vout", "vscratch",
     "k1", "k2", "k3", "k4", "k5", "k6", "k7", "xt", "xp", "Dm", "Um", "Ds", "Us", "Rn", "ke", "kb",
     "seg_tmod", "seg_ms", "seg_md", "Yw", "pivw", "wjac"],
)

#: The packed model holds no kind marker: numba's prange lowering cannot pass a namedtuple nested in the model
#: (``kernels.batch.detach_markers``), and the point-mass kernels are called directly (``sim/pointmass.py``).
PMModel = namedtuple("PMModel", ["wf", "tmod", "ms", "md", "gp", "gv", "par", "knode", "kflag", "kt",
                                 "kcl", "kcd"])
#: Workspace: element tension [N] (n_e,); for the partitioned block elimination (``kernels/pointmass/partitioned.py``)
#: checkpoints (rows, 15: inverse pivot 6, spike 9), one segment's buffer per chunk (P_max, seg, 9) and the chunks'
#: and separators' data (P_max, 48) (``model/pointmass.make_work``).
PMWork = namedtuple("PMWork", ["tension", "ckpt", "seg", "mid"])
