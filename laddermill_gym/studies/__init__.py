"""Offline studies and benchmarks, each a command (``python -m laddermill_gym.studies.NAME``) that prints its
figures and writes its plots. Top layer: may import anything in the package; nothing imports it but the CLI."""
