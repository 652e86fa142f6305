"""The scripted gust benchmark (``laddermill gust-bench``: versioned suites, runs, scorecard), the command that
warms a node for it (``laddermill workers warm``) and the cost of sampling turbulence in the kernels. May import
the layers below studies, ``studies.parallel`` and ``studies.commands``; no topic of studies, never ``harness``."""
