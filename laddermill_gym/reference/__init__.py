"""Plain-numpy reference (oracle) of the 3D right-hand side, written independently of the kernels: wind, rotations,
wing, state, cable and rhs. Imports only ``model`` (typed parameters) and ``kernels.contract`` (slot names); the
tests and ``studies/benchmarks/benchmark.py`` use it, the simulator never does."""

from laddermill_gym.reference.cable import (
    LENGTH_EPS,
    ElementState,
    cable_aero_load,
    element_loads_per_length,
    element_state,
    element_tensions,
    sag_elongation,
    sag_tension,
    tension,
)
from laddermill_gym.reference.rhs import mass_matrix_and_forces, reference_rhs
from laddermill_gym.reference.rotations import euler_321, quaternion_product, rotation, skew
from laddermill_gym.reference.state import end_transformation
from laddermill_gym.reference.wind import (
    air_density,
    wind_direction_profile,
    wind_modulation,
    wind_rate,
    wind_speed_profile,
    wind_velocity,
)
from laddermill_gym.reference.wing import AIRSPEED_EPS, aero_coefficients, inertia_matrix, wing_aero

__all__ = [
    "AIRSPEED_EPS",
    "LENGTH_EPS",
    "ElementState",
    "aero_coefficients",
    "air_density",
    "cable_aero_load",
    "element_loads_per_length",
    "element_state",
    "element_tensions",
    "end_transformation",
    "euler_321",
    "inertia_matrix",
    "mass_matrix_and_forces",
    "quaternion_product",
    "reference_rhs",
    "rotation",
    "sag_elongation",
    "sag_tension",
    "skew",
    "tension",
    "wind_direction_profile",
    "wind_modulation",
    "wind_rate",
    "wind_speed_profile",
    "wind_velocity",
    "wing_aero",
]
