"""Numba kernels over flat float64 arrays (module-level ``@njit(cache=True)`` functions): the data contract, dispatch
by model kind and vehicle, integrators, batching, cable elements, the moving-cable and winch kinds, the wind sampling
(``wind.py``); ``rigid/`` and ``pointmass/`` per model kind. Imports nothing of the package beside itself (the bottom
layer); ``model/packing.py`` packs the parameters and ``sim/`` allocates every array the kernels write into.
"""
