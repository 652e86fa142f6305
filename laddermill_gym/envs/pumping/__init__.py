"""PumpingKite-v0: one wing on a tether wound on a winch (Lansdorp et al. 2008): the winch scene and simulators
(``winch_scene``), the batched task, the single and vector envs, actions, observation and settings. Imports
``envs``' shared modules (and the rotorcraft's settings) and the layers below ``envs``."""
