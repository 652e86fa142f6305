"""Run a simulator for a time span and record its named views; save as npz and CSV."""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.sim.simulator import SimulationError, Simulator


@dataclass
class Recording:
    """Time histories: ``t`` (n,) [s] and ``views[name]`` (n, ...) with units in the names; ``error`` holds
    the SimulationError message if the run broke down (the record stops at the last good state)."""

    t: np.ndarray
    views: dict[str, np.ndarray]
    error: str | None = None

    def save_npz(self, path: Path) -> Path:
        np.savez_compressed(path, t_s=self.t, error=np.array(self.error or ""), **self.views)
        return path

    def save_csv(self, path: Path) -> Path:
        """One row per sample: time and every scalar of every view (columns named view[i][j])."""
        cols, data = ["t_s"], [self.t[:, None]]
        for name, arr in self.views.items():
            flat = arr.reshape(len(self.t), -1)
            shape = arr.shape[1:]
            for idx in np.ndindex(*shape):
                cols.append(name + "".join(f"[{i}]" for i in idx))
            data.append(flat)
        table = np.hstack(data)
        with open(path, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(cols)
            w.writerows(table.tolist())
        return path


def record(sim: Simulator, duration: float, sample_dt: float, progress: bool = True) -> Recording:
    """Advance ``sim`` by ``duration`` [s] with its current controls, sampling the views every
    ``sample_dt`` [s] (rounded to whole integrator steps). A breakdown ends the record early and is kept in
    ``Recording.error``."""
    if not duration > 0 or not sample_dt > 0:
        raise ValueError(f"duration ({duration}) and sample_dt ({sample_dt}) must be > 0")
    dt = sim.settings.dt
    per = max(1, int(round(sample_dt / dt)))
    n = int(round(duration / (per * dt)))
    times, frames = [sim.t], [sim.views()]
    error = None
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=n, desc=f"simulating {duration:g} s", unit="sample", leave=False)
    try:
        for _ in range(n):
            try:
                sim.step(n_steps=per)
            except SimulationError as err:
                error = str(err)
                break
            times.append(sim.t)
            frames.append(sim.views())
            if bar:
                bar.update(1)
    finally:
        if bar:
            bar.close()
    views = {k: np.array([f[k] for f in frames]) for k in frames[0]}
    return Recording(np.array(times), views, error)
