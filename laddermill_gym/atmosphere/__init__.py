"""The air: wind profile, direction, density and the time modulation through which gusts and perturbations
enter (numba kernels and the disturbance models). Imports nothing above ``model``."""
