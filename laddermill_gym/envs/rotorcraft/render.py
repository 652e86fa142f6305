"""Drawing Roberts' craft for :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv` (``rgb_array`` and
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
    from laddermill_gym.envs.render import SceneRenderer

    class CraftRenderer(SceneRenderer):
        def draw_bodies(self, pos, rot, up):
            ax = self.ax
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

    return CraftRenderer(_RenderSource(env), interactive=interactive)
