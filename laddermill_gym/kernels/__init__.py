"""Numba kernels over flat float64 arrays (module-level ``@njit(cache=True)`` functions): the data contract, dispatch
by model kind and vehicle, integrators, batching, cable elements, the moving-cable and winch kinds; ``rigid/`` and
``pointmass/`` per model kind. Imports only ``atmosphere`` (the wind kernels) beside itself; ``model/packing.py``
packs the parameters and ``sim/`` allocates every array the kernels write into.
"""
