"""The memory a model would take, estimated from its sizes and checked before its arrays are allocated: a count
that builds arrays (wings, elements per piece, point-mass elements, batched copies) is refused with the field, the
value and the memory it would take, instead of filling the machine until the out-of-memory killer ends the process
(and others with it).

The limit is ``LADDERMILL_MEMORY_LIMIT_GB`` [GB] when set, else half of the machine's physical memory. The costs per
body are measured (``tests/test_memory_limits.py`` holds them to the arrays actually allocated):

* rigid model (``sim.Simulator`` with its packed model, workspace and elimination tree; the loaded assembly):
  at most :data:`RIGID_BYTES_PER_BODY` per wing or cable node (measured 5.0 kB per wing at 1000 wings, 3.9 kB per
  node at 2000 nodes);
* its start (``ladder/initial.py``: Newton on the static equilibrium, MINPACK hybrd and the forward-difference
  Jacobian of ``sim/statics.py``): three dense m x m float64 matrices, m the unknowns (3 per wing and 2 per node in
  the plane, 6 and 3 in 3D);
* point-mass string (state, tensions, packed parameters, workspace of the implicit solver; ``model/pointmass.py``
  ``held_bytes``: 58 B per node at 500,000 nodes): :data:`POINTMASS_BYTES_PER_NODE` per node, room for the
  start state, a recording and the simulator's copies.
"""

from __future__ import annotations

import os

#: Environment variable: the memory limit [GB] (default: half of the physical memory).
LIMIT_VARIABLE = "LADDERMILL_MEMORY_LIMIT_GB"
#: Bytes per wing or cable node of a rigid model held by one simulator or one batched copy (rounded up from the
#: measured 5.0 kB per wing and 3.9 kB per node).
RIGID_BYTES_PER_BODY = 6_000
#: Bytes per node of a point-mass string, its start and its simulator (4 x the arrays of ``held_bytes``).
POINTMASS_BYTES_PER_NODE = 240


def physical_memory() -> int:
    """The machine's physical memory [bytes] (``os.sysconf``; 16 GiB where the platform does not say)."""
    try:
        return int(os.sysconf("SC_PAGE_SIZE")) * int(os.sysconf("SC_PHYS_PAGES"))
    except (AttributeError, ValueError, OSError):
        return 16 * 2 ** 30


def memory_limit() -> tuple[int, str]:
    """(limit [bytes], where it comes from): ``LADDERMILL_MEMORY_LIMIT_GB`` when set to a number > 0, else half
    of the physical memory."""
    text = os.environ.get(LIMIT_VARIABLE, "").strip()
    if text:
        try:
            gb = float(text)
        except ValueError:
            gb = float("nan")
        if not gb > 0 or gb == float("inf"):
            raise ValueError(f"{LIMIT_VARIABLE} = {text!r}: must be a number of GB > 0")
        return int(gb * 1e9), f"{LIMIT_VARIABLE} = {text}"
    return physical_memory() // 2, "half of this machine's memory; set " + LIMIT_VARIABLE + " to change it"


def show_bytes(n: float) -> str:
    """``n`` bytes in kB, MB, GB, TB or PB (powers of 1000), three digits."""
    for unit, size in (("PB", 1e15), ("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{int(n)} B"


def over_limit(needed: float, what: str) -> str | None:
    """None if ``needed`` bytes fit under :func:`memory_limit`, else the reason: "``what`` would take about X of
    memory, more than the limit Y (its source)"."""
    limit, source = memory_limit()
    if needed <= limit:
        return None
    return f"{what} would take about {show_bytes(needed)} of memory, more than the limit {show_bytes(limit)} ({source})"


def rigid_bytes(n_wings: int, n_nodes: int, planar_start: bool = True, copies: int = 1) -> float:
    """Estimated bytes [B] of a rigid model of ``n_wings`` wings and ``n_nodes`` free cable nodes: ``copies``
    simulators (or batched copies) and the dense Jacobians of its start (in the plane, ``planar_start``, or in 3D)."""
    bodies = float(n_wings) + float(n_nodes)
    m = (3.0 * n_wings + 2.0 * n_nodes) if planar_start else (6.0 * n_wings + 3.0 * n_nodes)
    return RIGID_BYTES_PER_BODY * bodies * max(int(copies), 1) + 3.0 * 8.0 * m * m


def pointmass_bytes(n_nodes: int) -> float:
    """Estimated bytes [B] of a point-mass string of ``n_nodes`` nodes with its start and simulator."""
    return POINTMASS_BYTES_PER_NODE * float(n_nodes)
