"""Thin entry points of the baseline agents for a repository checkout: ``python -m agents.train``,
``python -m agents.evaluate`` and ``python -m agents.lqr`` run ``laddermill train | evaluate | lqr``, whose code lives
in :mod:`laddermill_gym.harness` (installed with the package; this folder is not, so the name ``agents`` stays free
in site-packages)."""
