"""Drawing Roberts' craft for :class:`~laddermill_gym.envs.rotorcraft_env.RotorcraftEnv` (``rgb_array`` and
``human``): the wing scenes' renderer with the craft drawn as its frame and two rotor disks."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np


class _RenderSource:
    """What :class:`~laddermill_gym.envs.render.SceneRenderer` reads from a task, taken from the env's
    simulator (one copy)."""

    def __init__(self, env):
        self.env = env
        self.scene = SimpleNamespace(assembly=env.craft.assembly, name=env.craft.config.name)
        self.x_trim = env.x_trim
        self.nominal = env.nominal_position[None]

    @property
    def batch(self):
        return SimpleNamespace(states=self.env.sim.state[None], t=np.array([self.env.sim.t]))


def craft_renderer(env, interactive: bool):
    """A :class:`~laddermill_gym.envs.render.SceneRenderer` that draws the craft as its frame (a line between
    the hubs, red) and two rotor disks (circles in the body x-y plane, blue) instead of a wing."""
    from .render import SceneRenderer

    class CraftRenderer(SceneRenderer):
        def draw(self, b: int = 0):
            ax = self.ax
            ax.cla()
            pos, rot, segments = self._geometry(b)
            up = np.array([1.0, 1.0, -1.0])  # plot altitude = -z
            for p, q in segments:
                seg = np.array([p, q]) * up
                ax.plot(seg[:, 0], seg[:, 1], seg[:, 2], color="0.35", lw=1.0)
            cfg = env.craft.config
            c, R = pos[0], rot[0]
            hubs = [c + R @ np.array([cfg.hub_x, s * 0.5 * cfg.hub_spacing, -cfg.hub_height]) for s in (1.0, -1.0)]
            frame = np.array(hubs) * up
            ax.plot(frame[:, 0], frame[:, 1], frame[:, 2], color="tab:red", lw=2.0)
            ang = np.linspace(0.0, 2.0 * math.pi, 49)
            ring = cfg.rotor_radius * np.stack([np.cos(ang), np.sin(ang), np.zeros_like(ang)], axis=1)
            for h in hubs:
                disk = (h + ring @ R.T) * up
                ax.plot(disk[:, 0], disk[:, 1], disk[:, 2], color="tab:blue", lw=1.5)
            fp = self.asm.fixed_points * up
            ax.scatter(fp[:, 0], fp[:, 1], fp[:, 2], color="k", marker="^", s=30)
            lo, hi = self.box
            ax.set_xlim(lo[0], hi[0])
            ax.set_ylim(lo[1] - 0.5 * (hi[0] - lo[0]), hi[1] + 0.5 * (hi[0] - lo[0]))
            ax.set_zlim(max(0.0, -hi[2]), -lo[2])
            ax.set_xlabel("x north [m]")
            ax.set_ylabel("y east [m]")
            ax.set_zlabel("altitude [m]")
            ax.set_title(f"{cfg.name}  t = {env.sim.t:6.2f} s")
            self.fig.canvas.draw()
            if self._plt is not None:
                self._plt.pause(1e-3)
                return None
            return np.asarray(self.fig.canvas.buffer_rgba())[:, :, :3].copy()

    return CraftRenderer(_RenderSource(env), interactive=interactive)
