"""Offline studies and benchmarks, each a command (``python -m laddermill_gym.studies.NAME``) that prints its
figures and writes its plots. May import anything in the package but ``harness``;
imported by the CLI and by ``harness`` (the executor ``parallel``)."""
