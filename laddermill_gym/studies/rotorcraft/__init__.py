"""Roberts' tethered twin-rotor craft: roll / lateral stability against eq. (6) (``craft_stability``), his power
chart (``rotor_chart``) and the 35 m design study (``rotor_design`` with its data, physics, operating points,
sweeps and output), and the blade-tip guard's margin (``tip_guard_margin``). May import the layers below studies,
``studies.commands`` and ``studies.gusts`` (the gust suites' turbulence); no other topic of studies, never
``harness``."""
