"""laddermill_gym: a numba-compiled 3D laddermill simulator (Meijaard, Ockels & Schwab 1999) for control
and reinforcement-learning research.

Typical use::

    from laddermill_gym import load_scene
    scene = load_scene("tethered_wing")
    sim = scene.simulator()
    sim.step(n_steps=1000)
"""

from laddermill_gym.kernels import cache_guard as _cache_guard

_cache_guard.guard()  # before any kernel runs: numba's entries compiled from other sources are removed

from laddermill_gym.kernels import thread_wait as _thread_wait  # noqa: E402

_thread_wait.passive_openmp_wait()  # before numba's OpenMP pool starts: its workers sleep, not spin (issue 32)

from laddermill_gym.model.params import AERO_COLUMNS  # noqa: E402, Assembly, WindParams, WingType
from laddermill_gym.sim.simulator import IntegratorSettings, SimulationError, Simulator  # noqa: E402

__all__ = [
    "AERO_COLUMNS",
    "Assembly",
    "IntegratorSettings",
    "SimulationError",
    "Simulator",
    "WindParams",
    "WingType",
    "load_scene",
]
__version__ = "0.1.0"

from laddermill_gym.envs import register_envs as _register_envs  # noqa: E402

_register_envs()


def load_scene(name_or_path, **overrides):
    """Load a scene by name (configs/scenes/NAME.yaml) or path; see :func:`laddermill_gym.ladder.scene.load_scene`."""
    from laddermill_gym.ladder.scene import load_scene as _load

    return _load(name_or_path, **overrides)
