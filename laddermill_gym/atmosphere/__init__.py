"""The air: wind profile, direction and density, and the wind's variation in time and space (``field.py``:
``WindField`` = time modulation + frozen gust grid; ``wind_kernels.py``: their numba evaluation at any point),
and the disturbance models that produce it. Imports only ``kernels.contract`` (its slot names)."""
