"""Controllers behind SB3's ``predict``: open loop, linearisation at trim, LQR (wing, chain, mill, craft), SB3
policies and the factory. Imports ``envs`` (observation layouts, tasks, trims) and the layers below it."""
