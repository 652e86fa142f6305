"""The point-mass fidelity: its benchmark (memory, cost per element, thread scaling; part of ``laddermill
bench``), the rigid and point-mass fidelities side by side (``pointmass_fidelity``) and the moving cable at this
fidelity (``pointmass_mill``). May import the layers below studies; no topic of studies, never ``harness``."""
