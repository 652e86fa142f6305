"""Offline studies and benchmarks by topic, each a command (``python -m laddermill_gym.studies.TOPIC.NAME``) that
prints its figures and writes its plots. May import anything in the package but ``harness``; the topics import the
shared modules here (``parallel``, the executor for many independent runs; ``commands``, a command's parser;
``controller_specs``, the commands' controllers built and checked before any episode) and each other one way only
(``mill`` -> ``benchmarks`` -> ``gusts``), as each topic's ``__init__`` says; imported by the CLI and by ``harness``
(``parallel``, ``commands`` and ``controller_specs``).

Topics: ``benchmarks/`` (``laddermill bench``, ``bench-envs``, timing), ``gusts/`` (the gust benchmark,
turbulence), ``lateral/`` (the tethered wing's lateral stability), ``mill/`` (the moving-cable laddermill),
``numerics/`` (stable step, work-precision, stress), ``pointmass/`` (the point-mass fidelity), ``pumping/``
(the pumping kite's cycle), ``rotorcraft/`` (Roberts' craft: stability, rotor chart, 35 m design)."""
