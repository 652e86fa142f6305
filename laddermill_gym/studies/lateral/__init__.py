"""The lateral (sideways) stability study of one wing on a tether: scene variants, trim and linearisation, sweeps,
table and figure (``python -m laddermill_gym.studies.lateral.lateral_study``). May import the layers below
studies and ``studies.parallel``; no topic of studies, never ``harness``."""
