"""The package's main job: the laddermill from its periodic operating point through the paper's 0.01 rad
wind-direction step, open loop, under the lateral LQR and under the shipped learned policy (ppo_mill: one
policy shared by the 101 slots, run torch-free from its exported linear actor), in one figure and one GIF.

    laddermill demo [--env laddermill_gym/LadderMill-v1] [--time 60] [--controllers open_loop lqr ppo_mill]
                    [--out runs]

Every run starts from the same state (the env's operating point, seed 0) and meets the same step (Meijaard et al.
1999, Fig. 8: 0.01 rad at 1 s). The figure ``demo.png`` shows, against the time since the step, the generator's
electrical power [kW] and the largest lateral excursion of any wing [m] for each controller, and the loop seen from
above at the end of each run; ``demo.gif`` shows the runs side by side (a run that ended keeps its last frame);
``demo.csv`` holds the time series. What it prints: per controller, how long the mill flew after the step, how
the run ended (the env's failure name and reason) and the mean power.
"""

from __future__ import annotations

import csv
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from tqdm import tqdm

from laddermill_gym.studies.commands import Parser, UsageError, check_controllers, check_number, writable_folder
from laddermill_gym.studies.controller_specs import build_controllers

__all__ = ["DEFAULT_ENV", "STEP", "STEP_TIME", "ControlRun", "default_controllers", "run_demo", "plot_demo",
           "write_gif", "main"]

#: the main job's mill: v1, 153 kW at the paper's Fig. 8 speed of 2 m/s (LadderMill-v2, the wing periodic up to
#: 5 m/s, is a second design, not v1's replacement: 102 kW at 2 m/s; ``--env laddermill_gym/LadderMill-v2``)
DEFAULT_ENV = "laddermill_gym/LadderMill-v1"
#: [rad] the paper's wind-direction step (Meijaard et al. 1999, Fig. 8)
STEP = 0.01
#: [s] when it comes, after the start at the operating point
STEP_TIME = 1.0


@dataclass
class ControlRun:
    """One controller's run. ``t_s`` (T,) time since the step [s]; ``power_W`` (T,) the generator's electrical
    power [W]; ``lateral_m`` (T,) largest |lateral offset| of any wing [m]; ``positions`` (n_wings, 3) and
    ``segments`` (n_elements, 2, 3) the wings' CG and the cable at the end [m, north-east-down]; ``outcome`` how it
    ended ("ran to the end" or the env's failure name and reason); ``frames`` RGB frames (H, W, 3) for the GIF."""

    label: str
    t_s: np.ndarray
    power_W: np.ndarray
    lateral_m: np.ndarray
    positions: np.ndarray
    segments: np.ndarray
    outcome: str
    frames: list = field(default_factory=list)

    @property
    def flew_s(self) -> float:
        """Time from the step to the end of the run [s]."""
        return float(self.t_s[-1]) if len(self.t_s) else 0.0


def _run_one(env, controller, label: str, frame_every: int | None, progress: bool) -> ControlRun:
    from laddermill_gym.envs.render import scene_geometry

    task = env.task
    obs, _ = env.reset(seed=0)
    renderer = task.renderer() if frame_every else None
    t, power, lateral, frames = [], [], [], []
    steps = int(round(task.episode_time / task.control_dt))
    outcome = "ran to the end"
    for k in tqdm(range(steps), desc=f"demo {label}", unit="step", disable=not progress):
        action, _ = controller.predict(obs, deterministic=True)
        obs, _, terminated, truncated, info = env.step(action)
        t.append(float(info["t"][0]) - STEP_TIME)
        power.append(float(info["power_W"][0]))
        lateral.append(float(np.max(np.abs(env.lateral_offsets(obs)))))
        if renderer is not None and (k % frame_every == 0 or terminated[0] or truncated[0]):
            frames.append(renderer.draw(0))
        if terminated[0]:
            outcome = f"{info['failure_name'][0]}: {info['failure_reason'][0]}"
        if terminated[0] or truncated[0]:
            break
    pos, _, seg = scene_geometry(task.batch.assembly, task.batch.states[0])
    if renderer is not None:
        renderer.close()
    return ControlRun(label, np.array(t), np.array(power), np.array(lateral), pos.copy(), seg.copy(), outcome, frames)


def default_controllers(env_id: str) -> list[str]:
    """Open loop, the LQR and the policies shipped for ``env_id`` that this install can run: a shared per-wing
    policy with its exported linear actor (numpy only; ``ppo_mill`` on LadderMill-v1), any other with SB3."""
    import importlib.util

    from laddermill_gym.control.shared_controller import LinearActorController
    from laddermill_gym.control.shipped_policies import POLICY_DIR, SHIPPED_POLICIES

    sb3 = importlib.util.find_spec("stable_baselines3") is not None
    return ["open_loop", "lqr"] + [name for name, env in SHIPPED_POLICIES.items() if env == env_id and (
        sb3 or LinearActorController.available(POLICY_DIR / name))]


def _make_env(env_id: str, kw: dict):
    import warnings

    import gymnasium as gym

    with warnings.catch_warnings():  # Gymnasium calls v1 "out of date" once v2 exists; here both are designs
        warnings.filterwarnings("ignore", message=".*is out of date", category=DeprecationWarning)
        return gym.make_vec(env_id, 1, vectorization_mode="vector_entry_point", **kw)


def run_demo(env_id: str = DEFAULT_ENV, controllers=("open_loop", "lqr"), duration: float = 60.0,
             env_kwargs: dict | None = None, frames_per_s: float = 1.0, progress: bool = True,
             built: dict | None = None) -> list[ControlRun]:
    """Run each controller spec (:func:`~laddermill_gym.control.factory.make_controller`) on ``env_id`` from its
    operating point through the paper's step for ``duration`` [s] after it; ``frames_per_s`` GIF frames per
    simulated second (0: none). ``env_kwargs`` override the env's arguments (``scene_options`` for a smaller mill).
    Every controller is built first (:func:`~laddermill_gym.studies.controller_specs.build_controllers`: a spec the
    env refuses raises before any mill is built or flown), each on ``env_kwargs`` with its trained policy's control
    settings (action groups, bands) over them, and flies an env with those settings: one env per distinct set,
    shared by the controllers that carry none (open loop, the LQR, the shipped policies). ``built``: the controllers
    already built by ``build_controllers(controllers, env_id, env_kwargs)`` (the command line builds them first)."""
    from laddermill_gym.atmosphere.disturbances import DirectionStep

    if built is None:
        built = build_controllers(controllers, env_id, env_kwargs)
    episode = dict(episode_time=float(duration) + STEP_TIME, disturbances=[DirectionStep(step=STEP, time=STEP_TIME)])
    envs: dict[str, object] = {}
    runs = []
    for spec in controllers:
        controller, kw = built[spec]
        key = repr(sorted(kw.items()))
        if key not in envs:
            envs[key] = _make_env(env_id, dict(kw, **episode))
        env = envs[key]
        every = max(1, int(round(1.0 / (frames_per_s * env.task.control_dt)))) if frames_per_s > 0 else None
        runs.append(_run_one(env, controller, spec if len(spec) < 24 else Path(spec).name, every, progress))
    for env in envs.values():
        env.close()
    return runs


def plot_demo(runs: list[ControlRun], path: Path, title: str) -> Path:
    """``demo.png``: power and largest lateral excursion against the time since the step, and the loop from above
    at the end of each run."""
    from laddermill_gym.figure_files import new_figure

    fig = new_figure(figsize=(4.0 * max(2, len(runs)), 7.5))
    grid = fig.add_gridspec(2, max(2, len(runs)))
    ax_p, ax_y = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1])
    for i, r in enumerate(runs):  # dashed and dotted after the first: a run that flies as another stays visible
        style = ("-", "--", ":", "-.")[i % 4]
        line, = ax_p.plot(r.t_s, r.power_W / 1e3, style, label=r.label)
        ax_y.semilogy(r.t_s, np.maximum(r.lateral_m, 1e-3), style, color=line.get_color(), label=r.label)
        if r.outcome != "ran to the end":
            ax_y.plot(r.t_s[-1], max(r.lateral_m[-1], 1e-3), "x", color=line.get_color(), ms=10)
    ax_p.set(xlabel="time since the 0.01 rad direction step [s]", ylabel="electrical power [kW]")
    ax_y.set(xlabel="time since the step [s]", ylabel="largest lateral excursion [m]")
    for ax in (ax_p, ax_y):
        ax.set_xlim(left=0.0)  # the runs start STEP_TIME before the step, at the operating point
    ax_p.legend()
    ax_y.legend(title="x: the run ended")
    east = max(1.0, 1.1 * max(float(np.max(np.abs(r.positions[:, 1]))) for r in runs))  # one scale for all
    for i, r in enumerate(runs):
        ax = fig.add_subplot(grid[1, i])
        for a, b in r.segments:
            ax.plot([a[1], b[1]], [a[0], b[0]], color="0.6", lw=0.6)
        dots = ax.scatter(r.positions[:, 1], r.positions[:, 0], s=6, c=-r.positions[:, 2], cmap="viridis")
        ax.set(xlabel="east [m]", ylabel="north (upwind) [m]", xlim=(-east, east),
               title=f"{r.label}: {r.flew_s:.1f} s after the step\n{_short(r.outcome)}")
        fig.colorbar(dots, ax=ax, label="altitude [m]")
        ax.title.set_fontsize(9)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return path


def _short(text: str, n: int = 60) -> str:
    return text if len(text) <= n else text[: n - 3] + "..."


#: Height of the GIF's label band above each run's frames [px].
LABEL_BAND_PX = 22


def _label_band(text: str, width: int) -> np.ndarray:
    """A white band (LABEL_BAND_PX, width, 3) uint8 with ``text`` in black (PIL's default font)."""
    from PIL import Image, ImageDraw

    band = Image.new("RGB", (width, LABEL_BAND_PX), "white")
    ImageDraw.Draw(band).text((6, 4), _short(text, max(8, width // 7)), fill="black")
    return np.asarray(band)


def write_gif(runs: list[ControlRun], path: Path, fps: int = 8) -> Path | None:
    """``demo.gif``: the runs' frames side by side, each under a band naming its controller (a run that ended keeps
    its last frame); None without frames."""
    from PIL import Image

    if not all(r.frames for r in runs):
        return None
    n = max(len(r.frames) for r in runs)
    bands = [_label_band(r.label, r.frames[0].shape[1]) for r in runs]
    images = []
    for i in range(n):
        row = np.concatenate([np.concatenate([band, r.frames[min(i, len(r.frames) - 1)][..., :3]], axis=0)
                              for band, r in zip(bands, runs, strict=True)], axis=1)
        images.append(Image.fromarray(row).convert("P", palette=Image.Palette.ADAPTIVE))
    images[0].save(path, save_all=True, append_images=images[1:], duration=int(1000 / fps), loop=0)
    return path


def write_csv(runs: list[ControlRun], path: Path) -> Path:
    """``demo.csv``: controller, time since the step [s], power [W], largest lateral excursion [m]."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["controller", "t_since_step_s", "power_W", "max_lateral_m"])
        for r in runs:
            for row in zip(r.t_s, r.power_W, r.lateral_m, strict=True):
                w.writerow([r.label, *(f"{x:.6g}" for x in row)])
    return path


def _arguments(p) -> None:
    p.add_argument("--env", default=DEFAULT_ENV, help=f"a mill env id (default {DEFAULT_ENV})")
    p.add_argument("--controllers", nargs="+", default=None,
                   help="open_loop, lqr, lqr:CONFIG, a shipped policy or a trained one (run folder or model file); "
                        "default: open_loop, lqr and the env's shipped policy (ppo_mill on LadderMill-v1)")
    p.add_argument("--time", type=float, default=60.0, help="[s] simulated time after the step (default 60)")
    p.add_argument("--out", type=Path, default=Path("runs"), help="folder for demo.png, demo.gif, demo.csv")
    p.add_argument("--no-gif", action="store_true", help="no GIF (the runs are a little faster)")
    p.add_argument("--no-progress", action="store_true", help="no progress bars")


def _whole_periods(env_id: str, duration: float) -> None:
    """UsageError naming ``--time`` unless the episode (the step time plus ``duration`` [s]) is a whole number of the
    env's control periods (``envs/task_base.episode_periods``)."""
    import inspect

    from laddermill_gym.envs import ENV_IDS
    from laddermill_gym.envs.task import WingTask
    from laddermill_gym.envs.task_base import episode_periods

    default = inspect.signature(WingTask).parameters["control_dt"].default  # the mill ids are wing tasks
    control_dt = float(ENV_IDS[env_id].get("control_dt", default))
    try:
        episode_periods(float(duration) + STEP_TIME, control_dt)
    except ValueError:
        raise UsageError(f"--time = {duration!r}: the step at {STEP_TIME:g} s plus it must be a whole number of "
                         f"control periods ({control_dt:g} s)") from None


def main(argv: list[str] | None = None) -> int:
    p = Parser(prog="laddermill demo", description=__doc__.split("\n\n")[0])
    _arguments(p)
    args = p.parse_args(argv)
    from laddermill_gym.envs import ENV_IDS

    try:
        if args.env not in ENV_IDS or "LadderMill" not in args.env:
            raise UsageError(f"--env {args.env!r}: not a mill id ({', '.join(i for i in ENV_IDS if 'Mill-' in i)})")
        check_number("--time", args.time, low=0, high=3600, unit="s")
        _whole_periods(args.env, args.time)
        args.controllers = args.controllers or default_controllers(args.env)
        check_controllers(args.controllers)
        t0 = time.perf_counter()
        # every controller built and checked against the env before any mill is flown (a refused one: one line)
        built = build_controllers(args.controllers, args.env, option="--controllers")
        writable_folder(args.out)  # a bad folder named now, not after the runs
    except UsageError as err:
        p.error(str(err))
    runs = run_demo(args.env, args.controllers, args.time, frames_per_s=0.0 if args.no_gif else 1.0,
                    progress=not args.no_progress, built=built)
    print(f"{args.env}: the paper's {STEP} rad wind-direction step at t = {STEP_TIME:g} s, from the periodic "
          "operating point")
    print(f"{'controller':<16}{'flew after the step [s]':>24}{'mean power [kW]':>17}{'max |dy| [m]':>14}  end")
    for r in runs:
        print(f"{r.label:<16}{r.flew_s:>24.2f}{np.mean(r.power_W) / 1e3:>17.1f}{np.max(r.lateral_m):>14.2f}  "
              f"{r.outcome}")
    written = [plot_demo(runs, args.out / "demo.png", f"{args.env}: {STEP} rad direction step"),
               write_csv(runs, args.out / "demo.csv")]
    gif = None if args.no_gif else write_gif(runs, args.out / "demo.gif")
    written += [gif] if gif else []
    print(f"wrote {', '.join(str(x) for x in written)} in {time.perf_counter() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
