"""Saved periodic cases of the Meijaard study (``studies/mill/meijaard.py``): each periodic search costs minutes, so
its result and the simulator's state at its end are written once to the run's output folder (``states/``, one
``.npz`` per case) and read back by a later run with the same settings.

A file is reused only when its ``key`` (scene, dimension, V_c, number of wings, ramp, search time and tolerance, the
width-sampling span, and a :func:`fingerprint` of the scene file, the mill's state at rest, its controls and the
integrator settings, which changes with any edit of the scene, wing or cable data that moves the rest state) equals
the one asked for; any other file is ignored and overwritten. What is stored: the state,
time and controls at the end of the search (the simulator is reset to them), the two ground points, every field of
:class:`~laddermill_gym.ladder.periodic.PeriodicResult` and the study's table row.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np

from laddermill_gym.ladder.periodic import PeriodicResult
from laddermill_gym.sim.overload import Overload

#: PeriodicResult's array fields, stored as arrays of the same name
ARRAYS = ("tension_mean_N", "tension_min_N", "tension_max_N", "shape_m")
#: its scalar fields, stored in the JSON header
SCALARS = ("converged", "period_s", "t_s", "mean_power_W", "mean_electrical_power_W", "breakdown",
           "peak_tension_ratio")


def fingerprint(scene_file: Path, sim) -> str:
    """SHA-256 of the scene file's text, the simulator's initial state and controls and its integrator settings."""
    h = hashlib.sha256(Path(scene_file).read_bytes())
    for a in (sim.initial_state, sim.initial_controls):
        h.update(np.ascontiguousarray(a, dtype=np.float64).tobytes())
    h.update(repr(sim.settings).encode())
    return h.hexdigest()


def case_key(scene: str, dim: int, v_c: float, n_wings: int | None, ramp_s: float, max_time: float, tol: float,
             extra_s: float, print_: str = "") -> dict:
    """The settings a saved case must match to be reused (units: V_c [m/s], times [s], tol [-]; ``print_`` the
    :func:`fingerprint`)."""
    return {"scene": scene, "dimension": int(dim), "V_c_m_s": float(v_c), "n_wings": n_wings,
            "ramp_s": float(ramp_s), "max_time_s": float(max_time), "tol": float(tol), "extra_s": float(extra_s),
            "fingerprint": print_}


def case_path(folder: Path, key: dict) -> Path:
    """The file of a case under ``folder``: the scene's name (a path's file stem), dimension and V_c in the name."""
    return Path(folder) / f"{Path(key['scene']).stem}_{key['dimension']}D_Vc{key['V_c_m_s']:g}.npz"


def save_case(path: Path, key: dict, state: np.ndarray, t: float, controls: np.ndarray,
              ground: tuple[np.ndarray, np.ndarray], res: PeriodicResult, row: dict) -> None:
    """Write one case (see the module docstring) to ``path``."""
    path.parent.mkdir(parents=True, exist_ok=True)
    head = {"key": key, "t_s": float(t), "row": row, "history": res.history,
            "overload": list(res.overload) if res.overload else None,
            **{k: getattr(res, k) for k in SCALARS}}
    np.savez_compressed(path, header=np.array(json.dumps(head, default=float)), state=state, controls=controls,
                        ground0=ground[0], ground1=ground[1], **{k: getattr(res, k) for k in ARRAYS})


def load_case(path: Path, key: dict):
    """The case saved at ``path`` as (state, t [s], controls, ground points, PeriodicResult, row), or None when the
    file is missing or was made with other settings than ``key``."""
    if not Path(path).is_file():
        return None
    with np.load(path) as f:
        head = json.loads(str(f["header"]))
        if head["key"] != key:
            return None
        arrays = {k: f[k].copy() for k in ARRAYS}
        state, controls, ground = f["state"].copy(), f["controls"].copy(), (f["ground0"].copy(), f["ground1"].copy())
    res = PeriodicResult(**{k: head[k] for k in SCALARS}, **arrays, history=head["history"],
                         overload=Overload(*head["overload"]) if head["overload"] else None)
    return state, head["t_s"], controls, ground, res, head["row"]
