"""Quasi-steady pumping-cycle power (Lansdorp et al. 2008 eqs. 1-15; Schmehl et al. 2013 / van der Vlugt et al.
2019) vectorised over many wind states, and the site optimisation of Lansdorp et al. eqs. 16-20. Plain numpy and
scipy; imports only ``model`` and ``atmosphere`` of this package, and ``figure_files`` for the figures (tqdm in
``cli.py``, windpowerlib, an optional extra, only in ``turbine.py``)."""
