"""The physical bounds of the scene, wing and cable files' numbers, each with where it comes from: a value outside
them is refused at load naming the file, the field and the value (``model.configio.Section.number``'s ``low``,
``high`` and ``why``), instead of loading and failing later as a non-finite state that names no field.

The bounds are wide: every one lies beyond what any kite, laddermill or tether on Earth has, so a scene that a
physicist would write loads, and a slip of the exponent (``1.0e+12`` for ``100.0``) does not. Where a bound follows
from another field it is a consistency check (a piece that cannot carry its own weight, an inertia tensor no body
has, a cable denser than osmium). Sizes that build arrays (wings, elements, copies) are bounded by the memory they
would take (``model/memory.py``), the step of a run by its step count (``sim/recording.check_step_count``).

Field: bound (why).

* ``gravity``: (0, 25] m/s^2 (Jupiter's 24.8 m/s^2 is the largest of the solar system's planets)
* ``wind.v0``: (0, 150] m/s (above any wind measured: 113 m/s, Barrow Island 1996)
* ``wind.h0``, ``wind.direction_height``: (0, 20] km (the boundary layer and the turning lie in the troposphere)
* ``wind.v1``: [-0.1, 0.1] 1/s (100 m/s more wind per km above the boundary layer)
* ``wind.exponent``: [0, 1] (measured Hellmann exponents lie in 0.06..0.6)
* ``wind.direction_inf_rad``: [-pi, pi] rad (an angle: half a turn at most)
* ``wind.rho0``: (0, 10] kg/m^3 (8 x sea-level air; Titan's surface air is 5.4 kg/m^3)
* ``wind.scale_height``: (0, 50] km (Earth's is 8.4 km, Jupiter's, the largest, 27 km)
* ground point coordinates, ``integrator.ground_height``: [-100, 100] km (below the edge of the atmosphere, the
  Karman line)
* ``chain.piece_length``: (0, F_b / (mu g)] (a piece longer than the cable's breaking length cannot carry its
  weight); all pieces together at most 100 km of cable (the Karman line: the barometric air there is e^-12 of sea
  level's), named at ``chain.n_wings``
* ``initial.alpha_deg``: [-90, 90] deg (beyond 90 deg the wing flies backwards)
* ``initial.elevation_deg``: (0, 90] deg (the tether's elevation above the horizon, downwind of its station)
* ``initial.elevator_up_deg``, ``elevator_down_deg``, ``elevator_top_deg``: the wing file's
  ``control_limits_deg.elevator``; ``initial.top_slots``: [0, the descending slots]
* point-mass ``initial.roll_deg``, ``pitch_deg``, ``yaw_deg``: [-180, 180] deg (attitude angles)
* ``integrator.dt``: [1e-9, 1] s (below a nanosecond one simulated second takes 1e9 steps and the float64 time of an
  hour-long run rounds each step by 2e-4 of it; above 1 s a step skips the wings' pitch and roll motion); a keyword
  override of the step (``load_scene(dt=...)``) keeps the lower bound
* ``integrator.max_speed``: (0, 3000] m/s; ``integrator.max_rate``: (0, 1e4] rad/s (exploding-state guards)
* ``station.first_fraction``: (0, 1], ``last_fraction``: (1, 2] (the end elements change by one piece between
  transfers); ``station.speed_m_s``: [-150, 150] m/s (the fastest wind); ``station.efficiency``: (0, 1]
* wing ``mass``: (0, 1e6] kg (heavier than any aircraft built, the An-225 at 640 t); ``span``: (0, 1000] m (the
  largest aircraft, the Stratolaunch, spans 117 m); span x chord / area in [0.5, 2] (the mean aerodynamic chord of
  any planform is 1 to 4/3 of S/b); ``aero_reference`` and ``attachment`` within a span of the CG (points on the
  body); ``inertia``: principal moments with J1 + J2 >= J3 (every rigid body); ``control_limits_deg``: [-90, 90]
* cable density mu / (pi d^2 / 4): [100, 23000] kg/m^3 (a rope of fibre and voids, the 25 mm Dyneema one 611
  kg/m^3, to osmium, 22,590); modulus EA / (pi d^2 / 4) <= 1.2e12 Pa (diamond, graphene); strength
  F_b / (pi d^2 / 4) <= 1.3e11 Pa (graphene); retardation time DA / EA <= 1 s (the shipped cables: 1 ms);
  ``cn0`` in [0, 2] (a cylinder's cross-flow drag is at most 1.2), ``ct0`` in [0, 1] (friction about 0.02)
"""

from __future__ import annotations

import math

#: (low, high, why) of a field: ``Section.number(key, **BOUNDS[field])``.
BOUNDS: dict[str, dict] = {
    "gravity": dict(high=25.0, why="Jupiter's 24.8 m/s^2 is the largest of the solar system's planets"),
    "wind.v0": dict(high=150.0, why="m/s: above any wind measured, 113 m/s at Barrow Island in 1996"),
    "wind.h0": dict(high=20000.0, why="m: the boundary layer lies in the troposphere"),
    "wind.direction_height": dict(high=20000.0, why="m: the wind turns within the troposphere"),
    "wind.v1": dict(low=-0.1, high=0.1, why="1/s: 100 m/s more wind per km above the boundary layer"),
    "wind.exponent": dict(low=0.0, high=1.0, why="measured Hellmann exponents lie in 0.06..0.6"),
    "wind.direction_inf_rad": dict(low=-math.pi, high=math.pi, why="rad: a turn of half a circle at most"),
    "wind.rho0": dict(high=10.0, why="kg/m^3: 8 x sea-level air; Titan's surface air is 5.4 kg/m^3"),
    "wind.scale_height": dict(high=50000.0, why="m: Earth's is 8.4 km, Jupiter's (the largest) 27 km"),
    "coordinate": dict(low=-1e5, high=1e5, why="m: the cable stays below the edge of the atmosphere, 100 km"),
    "initial.alpha_deg": dict(low=-90.0, high=90.0, why="deg: beyond 90 deg the wing flies backwards"),
    "initial.elevation_deg": dict(high=90.0, why="deg: the tether's elevation above the horizon, downwind of its "
                                                 "station"),
    "attitude_deg": dict(low=-180.0, high=180.0, why="deg: an attitude angle"),
    "integrator.dt": dict(low=1e-9, high=1.0, why="s: below a nanosecond one simulated second takes 1e9 steps; above "
                                                  "1 s a step skips the wings' pitch and roll motion"),
    "integrator.max_speed": dict(high=3000.0, why="m/s: the exploding-state guard, ten times the speed of sound"),
    "integrator.max_rate": dict(high=1e4, why="rad/s: the exploding-state guard, about 1600 turns per second"),
    "wing.mass": dict(high=1e6, why="kg: heavier than any aircraft built, the An-225 at 640 t"),
    "wing.span": dict(high=1000.0, why="m: the largest aircraft, the Stratolaunch, spans 117 m"),
    "wing.control_limit_deg": dict(low=-90.0, high=90.0, why="deg: a control-surface deflection"),
    "cable.cn0": dict(high=2.0, why="a cylinder's cross-flow drag coefficient is 1.2 at most (Hoerner)"),
    "cable.ct0": dict(high=1.0, why="a cable's friction coefficient is about 0.02 (Hoerner)"),
}

#: The most cable a scene may hold [m]: the Karman line, 100 km, where the barometric air (scale height 8.4 km) is
#: e^-12 of sea level's and no wing flies.
MAX_CABLE_LENGTH = 1e5
#: Cable density bounds [kg/m^3]: a rope of fibre and voids (the 25 mm Dyneema rope: 611 kg/m^3) to osmium (22,590).
CABLE_DENSITY = (100.0, 23000.0)
#: The stiffest material [Pa]: diamond and graphene, about 1 TPa (E = EA / (pi d^2 / 4) may not exceed it).
MAX_MODULUS = 1.2e12
#: The strongest material [Pa]: graphene's 130 GPa (breaking_load / (pi d^2 / 4) may not exceed it).
MAX_STRENGTH = 1.3e11
#: The largest Voigt retardation time DA / EA [s] (the shipped cables: 1 ms); beyond, the cable creeps.
MAX_RETARDATION = 1.0
#: Bounds of span x chord / area: the mean aerodynamic chord of a planform is 1 (rectangle) to 4/3 (delta) of S/b.
CHORD_RATIO = (0.5, 2.0)
