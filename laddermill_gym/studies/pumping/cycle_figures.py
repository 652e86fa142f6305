"""Figures of a flown pumping cycle (``laddermill pumping-cycle``): the flight path on the wind window (azimuth,
elevation) and in 3D, coloured by phase, over the last complete cycle, and tension, reel speed, electrical power and
phase against time over the whole run. Input: the record of ``studies.pumping.pumping_cycle.run_cycles``."""

from __future__ import annotations

from pathlib import Path

import numpy as np

__all__ = ["window_angles", "cycle_figures"]

_COLOURS = ("tab:red", "tab:orange", "tab:blue", "tab:green")


def window_angles(rec: dict[str, np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """(azimuth, elevation) [rad] of the recorded wing positions (winch at the origin, wind towards -x;
    ``envs.pumping.wind_window``'s angles)."""
    x, y, z = rec["x"], rec["y"], rec["z"]
    return np.arctan2(y, -x), np.arctan2(-z, np.hypot(x, y))


def _last_cycle(rec: dict[str, np.ndarray], reel_in: int) -> slice:
    ph = rec["phase"]
    ends = np.flatnonzero((ph[:-1] == reel_in) & (ph[1:] != reel_in)) + 1
    return slice(ends[-2], ends[-1]) if len(ends) >= 2 else slice(0, len(ph))


def _by_phase(ax, a, b, phase, names, c=None):
    for k, name in enumerate(names):
        m = phase == k
        if m.any():
            args = (a[m], b[m]) if c is None else (a[m], b[m], c[m])
            ax.scatter(*args, s=2, color=_COLOURS[k % len(_COLOURS)], label=name)


def cycle_figures(rec: dict[str, np.ndarray], dt: float, names: tuple[str, ...], reel_in: int, title: str,
                  out: Path) -> list[Path]:
    """Write ``pumping_window.png``, ``pumping_path3d.png`` and ``pumping_timeseries.png`` into ``out``; phase
    ``names`` by code, ``reel_in`` the reel-in phase's code (a cycle ends when it does)."""
    from laddermill_gym.figure_files import new_figure, subplots

    az, el = window_angles(rec)
    sl = _last_cycle(rec, reel_in)
    paths = []
    fig, ax = subplots(figsize=(7, 4.5))
    _by_phase(ax, np.degrees(az[sl]), np.degrees(el[sl]), rec["phase"][sl], names)
    ax.set_xlabel("azimuth [deg] (+: towards +y)")
    ax.set_ylabel("elevation [deg]")
    ax.set_title(f"{title}\nthe wind window, t = {rec['t'][sl][0]:.0f}-{rec['t'][sl][-1]:.0f} s", fontsize=10)
    ax.legend(markerscale=5)
    ax.set_aspect("equal")
    fig.tight_layout()
    paths.append(out / "pumping_window.png")
    fig.savefig(paths[-1], dpi=100)

    fig = new_figure(figsize=(7, 6))
    ax = fig.add_subplot(projection="3d")
    _by_phase(ax, -rec["x"][sl], rec["y"][sl], rec["phase"][sl], names, c=-rec["z"][sl])
    ax.plot([0.0], [0.0], [0.0], "k^")
    ax.set_xlabel("downwind [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("altitude [m]")
    ax.set_title(f"{title}\nthe last complete cycle (winch: black)", fontsize=10)
    ax.legend(markerscale=5)
    fig.tight_layout()
    paths.append(out / "pumping_path3d.png")
    fig.savefig(paths[-1], dpi=100)

    fig, axs = subplots(4, 1, figsize=(8, 8), sharex=True)
    t = rec["t"]
    axs[0].plot(t, rec["tension"] / 1e3)
    axs[0].set_ylabel("drum tension [kN]")
    axs[1].plot(t, rec["v"])
    axs[1].set_ylabel("reel speed [m/s]")
    axs[2].plot(t, rec["e_el"] / dt / 1e3)
    axs[2].set_ylabel("electrical power [kW]")
    axs[3].plot(t, rec["phase"], drawstyle="steps-post")
    axs[3].set_yticks(range(len(names)), names)
    axs[3].set_xlabel("t [s]")
    axs[0].set_title(title)
    fig.tight_layout()
    paths.append(out / "pumping_timeseries.png")
    fig.savefig(paths[-1], dpi=100)
    return paths
