"""Drawing Roberts' craft for the rotorcraft environments (``rgb_array`` and ``human``): the wing scenes' renderer
with the craft drawn as its frame and two rotor disks."""

from __future__ import annotations

import math

import numpy as np


def craft_renderer(task, interactive: bool):
    """A :class:`~laddermill_gym.envs.render.SceneRenderer` of the copies of ``task`` (a
    :class:`~laddermill_gym.envs.rotorcraft.task.CraftTask`: its ``scene``, ``x_trim``, ``nominal`` and ``batch``)
    that draws the craft as its frame (a line between the hubs, red) and two rotor disks (circles in the body
    x-y plane, blue) instead of a wing."""
    from laddermill_gym.envs.render import SceneRenderer

    cfg = task.craft.config

    class CraftRenderer(SceneRenderer):
        def draw_bodies(self, pos, rot, up):
            ax = self.ax
            c, R = pos[0], rot[0]
            hubs = [c + R @ np.array([cfg.hub_x, s * 0.5 * cfg.hub_spacing, -cfg.hub_height]) for s in (1.0, -1.0)]
            frame = np.array(hubs) * up
            ax.plot(frame[:, 0], frame[:, 1], frame[:, 2], color="tab:red", lw=2.0)
            ang = np.linspace(0.0, 2.0 * math.pi, 49)
            ring = cfg.rotor_radius * np.stack([np.cos(ang), np.sin(ang), np.zeros_like(ang)], axis=1)
            for h in hubs:
                disk = (h + ring @ R.T) * up
                ax.plot(disk[:, 0], disk[:, 1], disk[:, 2], color="tab:blue", lw=1.5)

    return CraftRenderer(task, interactive=interactive)
