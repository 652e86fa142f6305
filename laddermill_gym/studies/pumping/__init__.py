"""The pumping kite: the scripted dynamic cycle against the quasi-steady prediction (``laddermill
pumping-cycle``). May import the layers below studies and ``studies.commands``; no topic of studies, never
``harness``."""
