"""The air: wind profile, direction and density, and the wind's variation in time and space (``field.py``:
``WindField`` = time modulation + frozen gust grid; ``kernels/wind.py``: their numba evaluation at any point),
the disturbance models that produce it (``disturbances.py``, ``iec_gusts.py``, ``turbulence*.py``; read from plain
data by ``disturbance_spec.py``), and site wind data for quasi-steady studies (``site_wind.py``,
``site_wind_formats.py``: plain numpy, no kernels). Imports only ``kernels.contract`` (its slot names)."""
