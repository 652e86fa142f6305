"""Roberts' tethered twin-rotor craft: config, rotor aerodynamics (Python and numba), the craft's loads on the
rigid body, the built craft with its trim, and the derivation of its eq. (6). Imports ``ladder``'s
wind and cable readers, ``sim`` and below."""
