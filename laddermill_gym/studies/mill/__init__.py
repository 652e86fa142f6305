"""The moving-cable laddermill: Meijaard, Ockels & Schwab's examples redone (``meijaard``; its Fig. 8 divergence
followed to a physical end in ``divergence``), the two wing-insertion rules' jerk (``insertion``), the power curve
of the v2 mill, or the v1 (``power_curve``), the v1 mill at 4-5 m/s with the near-top elevator rule and the v2
mill periodic at 1-5 m/s (``fast_mill``), the cable-held wing's trim against air speed (``trim_slope``), the
mill LQR's closed loop step by step after a transfer (``transfer_transient``) and the mill's part of ``laddermill
bench`` (``mill_benchmark``). May import the layers below studies and ``studies.benchmarks`` (the timing helpers); no
other topic of studies, never ``harness``."""
