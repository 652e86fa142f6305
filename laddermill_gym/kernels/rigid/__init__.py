"""Rigid wings: 3D and in-plane right-hand sides, wing aerodynamics, the batched observation kernel, and their
plain-numpy twin ``reference`` (the oracle the kernels are tested against). Imports ``kernels``, ``atmosphere``
and ``model``."""
