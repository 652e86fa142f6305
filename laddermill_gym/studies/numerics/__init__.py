"""Numerical studies of the integrators: ``laddermill stable-step``, ``laddermill work-precision`` (rigid scenes,
the point-mass scenes in ``pointmass_precision``, what both share in ``precision``) and ``laddermill stress``, on
the scenes of ``scenes.py``. May import the layers below studies and ``studies.commands``; no topic of studies,
never ``harness``."""
