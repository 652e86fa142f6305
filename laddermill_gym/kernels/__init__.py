"""Numba kernels over flat float64 arrays (module-level ``@njit(cache=True)`` functions).

Layering: these modules import nothing from the Python API; ``laddermill_gym.sim.simulator`` packs the
parameters and allocates every array the kernels write into.
"""
