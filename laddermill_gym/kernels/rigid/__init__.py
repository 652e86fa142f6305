"""Rigid wings: 3D and in-plane right-hand sides, wing aerodynamics, their Jacobian blocks, the Rosenbrock-W steps
and the batched observation kernel (their plain-numpy twin is ``laddermill_gym.reference``). Imports ``kernels``
only (the wind included: ``kernels/wind.py``)."""
