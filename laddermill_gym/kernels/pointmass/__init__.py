"""Point-mass fidelity (Podgaets & Ockels 2007): kites as point masses with commanded attitude on an elastic
string of many small point-mass elements; explicit and axially/transversally implicit steppers. Imports only
``kernels/`` (the wind included: ``kernels/wind.py``)."""
