"""Frozen, typed parameter objects: the built model that kernels and the numpy reference consume.

Everything here is plain data in SI units and radians. `scene.py` builds these from YAML files;
`simulator.py` packs them into flat float64 arrays for the numba kernels. The model they describe is
specified in ``laddermill_gym/docs/model.md``.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from laddermill_gym.atmosphere.field import GustGrid, WindField
from laddermill_gym.kernels.contract import B2_SIZE, B3_SIZE, N2_SIZE, N3_SIZE, SX_SIZE
from laddermill_gym.kernels.contract import END_FIXED as END_FIXED
from laddermill_gym.kernels.contract import END_NODE as END_NODE
from laddermill_gym.kernels.contract import END_WING as END_WING
from laddermill_gym.kernels.contract import N_CONTROLS as N_CONTROLS
from laddermill_gym.model.station import StationParams

#: Column names of a wing's aerodynamic table, in kernel order (see docs/model.md, "Wing aerodynamics").
AERO_COLUMNS: tuple[str, ...] = (
    "CL", "CD", "Cm",
    "CLq", "CLad", "CLde",
    "Cmq", "Cmad", "Cmde",
    "CYb", "CYp", "CYr", "CYdr",
    "Clb", "Clp", "Clr", "Clda", "Cldr",
    "Cnb", "Cnp", "Cnr", "Cnda", "Cndr",
)
AERO_INDEX: dict[str, int] = {name: i for i, name in enumerate(AERO_COLUMNS)}

# End kinds of a cable element (END_WING, END_NODE, END_FIXED) and controls per wing (N_CONTROLS: elevator,
# rudder, aileron [rad]) are the contract's names, re-exported above.
CONTROL_NAMES: tuple[str, ...] = ("elevator", "rudder", "aileron")


@dataclass(frozen=True)
class WindParams:
    """Wind profile, direction, density and time modulation (Meijaard eqs. 1-3).

    Attributes
    ----------
    v0 : float
        Wind speed at the top of the boundary layer [m/s].
    h0 : float
        Boundary-layer thickness [m].
    v1 : float
        Speed gradient above the boundary layer [1/s].
    exponent : float
        Power-law exponent inside the boundary layer [-].
    direction_inf : float
        Direction turn far aloft phi_s(inf) [rad] (eq. 2); 0 for a fixed direction.
    direction_height : float
        Characteristic height h_s of the turn [m].
    rho0 : float
        Air density at h = 0 [kg/m^3]; 0 gives vacuum.
    density_model : str
        ``"barometric"`` (eq. 3) or ``"isa"``.
    scale_height : float
        H_b of the barometric formula [m].
    mod_t0, mod_dt : float
        Start time and spacing of the modulation samples [s].
    mod_speed : ndarray, shape (n_mod,)
        Speed factor samples [-] (1 = undisturbed).
    mod_direction : ndarray, shape (n_mod,)
        Direction offset samples [rad].
    gust : GustGrid or None
        Frozen gust grid added to the profile (``atmosphere/field.py``); None for none.

    The modulation and the gust grid together are the wind's :attr:`field`; set them with :meth:`with_field`
    (or, on a built simulator, ``Simulator.set_wind`` / ``BatchSimulator.set_wind``).
    """

    v0: float = 8.0
    h0: float = 50.0
    v1: float = 0.0016
    exponent: float = 0.2
    direction_inf: float = 0.0
    direction_height: float = 500.0
    rho0: float = 1.225
    density_model: str = "barometric"
    scale_height: float = 8400.0
    mod_t0: float = 0.0
    mod_dt: float = 1.0
    mod_speed: np.ndarray = field(default_factory=lambda: np.ones(1))
    mod_direction: np.ndarray = field(default_factory=lambda: np.zeros(1))
    gust: GustGrid | None = None

    @property
    def field(self) -> WindField:
        """The wind's variation in time and space (modulation and gust grid) as one :class:`WindField`."""
        return WindField(self.mod_t0, self.mod_dt, self.mod_speed, self.mod_direction, self.gust)

    def with_field(self, f: WindField) -> WindParams:
        """Return a copy whose variation in time and space is the :class:`WindField` ``f``."""
        if not isinstance(f, WindField):
            raise ValueError(f"wind field = {f!r}: must be a laddermill_gym.atmosphere.field.WindField")
        return dataclasses.replace(self, mod_t0=f.t0, mod_dt=f.dt, mod_speed=f.speed, mod_direction=f.direction,
                                   gust=f.grid)

    def with_modulation(self, t0: float, dt: float, speed: np.ndarray, direction: np.ndarray) -> WindParams:
        """Return a copy with a new time modulation (speed factor [-] and direction offset [rad] samples at
        t0 + k dt [s]); the gust grid is kept. Shorthand for :meth:`with_field`."""
        return self.with_field(WindField(t0, dt, speed, direction, self.gust))


@dataclass(frozen=True)
class AeroTable:
    """Aerodynamic coefficients of one wing type versus angle of attack.

    Attributes
    ----------
    alpha : ndarray, shape (n,)
        Uniform grid from -pi to pi inclusive [rad].
    values : ndarray, shape (n, len(AERO_COLUMNS))
        Coefficient values [-]; rate derivatives per non-dimensional rate, control derivatives per rad.
        Row 0 and row n-1 must be equal (periodic).
    source : str
        Where the numbers come from (file path).
    """

    alpha: np.ndarray
    values: np.ndarray
    source: str = ""

    def column(self, name: str) -> np.ndarray:
        return self.values[:, AERO_INDEX[name]]


@dataclass(frozen=True)
class WingType:
    """One rigid wing design.

    Attributes
    ----------
    name : str
    mass : float                 [kg]
    inertia : tuple              (Jxx, Jyy, Jzz, Jxz) about the CG, body axes [kg m^2]
    area, span, chord : float    reference area [m^2], span [m], mean aerodynamic chord [m]
    r_ref : ndarray (3,)         aerodynamic reference point from the CG, body axes [m]
    attachment : ndarray (3,)    cable attachment point from the CG, body axes [m]
    control_limits : ndarray (3, 2)  lower/upper limits of elevator, rudder, aileron [rad]
    aero : AeroTable or None     tables; None for a body whose loads come from elsewhere (the rotorcraft)
    """

    name: str
    mass: float
    inertia: tuple[float, float, float, float]
    area: float
    span: float
    chord: float
    r_ref: np.ndarray
    attachment: np.ndarray
    control_limits: np.ndarray
    aero: AeroTable | None


@dataclass(frozen=True)
class Elements:
    """Cable truss elements of a built scene (n_e elements).

    end_kind : int array (n_e, 2)    END_WING, END_NODE or END_FIXED for end r (0) and end s (1)
    end_index : int array (n_e, 2)   index of the wing, free node or fixed point
    attach : float array (n_e, 2, 3) body-frame attachment vector for wing ends [m] (0 otherwise)
    l0 : (n_e,)  unstretched length [m];   mu : (n_e,) mass per unstretched length [kg/m]
    EA : (n_e,)  axial stiffness [N];      DA : (n_e,) Voigt damping coefficient [N s]
    diameter : (n_e,) [m]
    breaking_load : (n_e,) tension at which the element breaks [N] (the cable file's ``breaking_load``), or None:
        not known (no tension is an overload; ``sim/overload.py``)
    """

    end_kind: np.ndarray
    end_index: np.ndarray
    attach: np.ndarray
    l0: np.ndarray
    mu: np.ndarray
    EA: np.ndarray
    DA: np.ndarray
    diameter: np.ndarray
    breaking_load: np.ndarray | None = None

    @property
    def count(self) -> int:
        return int(self.l0.size)


@dataclass(frozen=True)
class Assembly:
    """A built scene: bodies, nodes, elements, wind and fidelity switches.

    dim : 3 or 2 (in-plane).  gravity [m/s^2].  sag, cable_aero : fidelity switches.
    wing_type_index : int array (n_w,) into wing_types.  node_mass : (n_nodes,) lumped extra mass [kg].
    fixed_points : (n_fixed, 3) global positions [m].  cable_cn0, cable_ct0 : cable aerodynamic constants [-].
    station : the moving cable's ground station (``model/station.py``), or None for a cable that does not move;
    with a station the state ends with its block (``SX_*``, kernels/contract.py).
    """

    dim: int
    gravity: float
    wind: WindParams
    wing_types: tuple[WingType, ...]
    wing_type_index: np.ndarray
    node_mass: np.ndarray
    fixed_points: np.ndarray
    elements: Elements
    sag: bool = True
    cable_aero: bool = True
    cable_cn0: float = 1.1
    cable_ct0: float = 0.02
    station: StationParams | None = None

    @property
    def n_wings(self) -> int:
        return int(self.wing_type_index.size)

    @property
    def n_nodes(self) -> int:
        return int(self.node_mass.size)

    @property
    def wing_state_size(self) -> int:
        return B3_SIZE if self.dim == 3 else B2_SIZE

    @property
    def node_state_size(self) -> int:
        return N3_SIZE if self.dim == 3 else N2_SIZE

    @property
    def state_size(self) -> int:
        return self.body_state_size + (SX_SIZE if self.station is not None else 0)

    @property
    def body_state_size(self) -> int:
        """Entries of the wings and nodes (the station block, if any, follows them)."""
        return self.n_wings * self.wing_state_size + self.n_nodes * self.node_state_size

    @property
    def n_controls(self) -> int:
        """Controls: N_CONTROLS per wing, then the station's (the generator torque of a drum)."""
        return N_CONTROLS * self.n_wings + (self.station.n_controls if self.station is not None else 0)

    def wing(self, k: int) -> WingType:
        return self.wing_types[int(self.wing_type_index[k])]
