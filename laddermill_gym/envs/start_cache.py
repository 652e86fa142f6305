"""The on-disk cache of the wing and craft envs' starting points (issue 32 point 1: the warm start).

TetheredWing-v0 and the other wing ids start from their scene's static equilibrium and trim
(``ladder/initial.py``), Rotorcraft-v0 from its craft's trim (``rotorcraft/craft.py``): a Newton search that costs
a warm start about a tenth of a second of its own, scipy's solvers (a quarter of a second to import) and the
loading of the right-hand side's kernels from numba's cache. Like the mill's operating point
(``envs/laddermill/op_cache.py``, whose folder, keys and entry format this uses), the result is kept on disk: a
start finds it in ``$LADDERMILL_CACHE_DIR/wing_starts/`` or ``craft_starts/`` (``LADDERMILL_CACHE_DIR=off``
switches it off) and skips the search.

Keyed by everything the start depends on: the scene as loaded (every field but its file's path) or the craft as built
(config, assembly, tether layout) and its trim controls, the package version, the source of the code that computes it
(:data:`WING_SOURCES`, :data:`CRAFT_SOURCES`), the versions, the CPU and the kernels numpy and OpenBLAS choose
(``disk_cache.platform_text``).
Stored as the exact float64 arrays, so a start read back is the same bits as a recomputed one; an entry that does
not read back whole under its own key is recomputed and overwritten.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.envs.laddermill import op_cache

__all__ = ["WING_SOURCES", "CRAFT_SOURCES", "cached_start", "start_on_disk"]

#: (folders, files) of the package whose source the wing's start runs: the scene readers, packing, the simulator,
#: statics and kernels (tests/test_start_cache.py checks the modules it imports lie in these)
WING_SOURCES = (("kernels", "sim", "ladder", "model", "atmosphere"),
                ("__init__.py", "envs/start_cache.py", "envs/laddermill/op_cache.py"))
#: the same for the craft's trim: its builder and trim (``rotorcraft/``) and ``envs/rotorcraft/trim.py``
CRAFT_SOURCES = (("kernels", "sim", "model", "atmosphere", "rotorcraft"),
                 ("__init__.py", "envs/start_cache.py", "envs/laddermill/op_cache.py", "envs/rotorcraft/trim.py"))


def cached_start(kind: str, label: str, inputs: tuple, sources: tuple, compute, skip: tuple = ()):
    """(x, u), float64 arrays, of ``compute()`` (which returns them) for ``inputs`` (what it depends on; fields in
    ``skip`` left out of a top-level dataclass): read from the on-disk entry of ``kind`` when it is there and
    whole, else computed and stored for the next process. Uncached when an input cannot be fingerprinted or the
    cache is off."""
    try:
        key = op_cache.entry_key(kind, *inputs, skip=skip, sources=sources)
    except TypeError:  # an input the fingerprint does not know: compute as before
        return compute()
    path = op_cache.entry_path(kind, label, key)
    data = op_cache.read_entry(path, key)
    if data is not None and set(data) == {"x", "u"}:
        return np.array(data["x"], dtype=np.float64), np.array(data["u"], dtype=np.float64)
    x, u = compute()
    op_cache.write_entry(path, key, {"x": np.asarray(x, dtype=np.float64), "u": np.asarray(u, dtype=np.float64)})
    return x, u


def start_on_disk(kind: str, label: str, inputs: tuple, sources: tuple, skip: tuple = ()) -> bool:
    """Whether :func:`cached_start` with these arguments would read its entry (whole, under its key) and compute
    nothing; False when the cache is off or an input cannot be fingerprinted."""
    try:
        key = op_cache.entry_key(kind, *inputs, skip=skip, sources=sources)
    except TypeError:
        return False
    data = op_cache.read_entry(op_cache.entry_path(kind, label, key), key)
    return data is not None and set(data) == {"x", "u"}
