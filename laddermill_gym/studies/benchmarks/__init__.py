"""Timing: the benchmark behind ``laddermill bench`` (the rigid scenes, and the timing helpers the mill's and the
point-mass' parts reuse), ``laddermill bench-envs`` (vector env against ``SyncVectorEnv``), what a worker pays
for numba (``parallel_cost``) and training time against torch's thread count (``torch_threads``). May import the
layers below studies, ``studies.parallel`` and ``studies.gusts`` (``parallel_cost`` times the gust benchmark's
task); no other topic of studies, never ``harness``."""
