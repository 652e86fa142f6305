"""Design the lateral LQR of a config and print its modes; optionally fly it against open loop on the simulator.

    laddermill lqr [--config configs/agents/lqr_tethered_wing.yaml] [--full-check]
                         [--rollout 300] [--step 0.01] [--out results/lqr]

Prints the open-loop lateral eigenvalues of the linearised model, the gain, and the discrete closed-loop
eigenvalues (stable when every |z| < 1). For a chain it prints the per-wing design summary and, with
``--full-check``, the eigenvalues of the decentralised gains on the full coupled lateral model. For the
moving-cable mill (``configs/agents/lqr_laddermill.yaml``) it prints the check over the period
(:mod:`laddermill_gym.control.mill_lqr`); for the rotorcraft (``configs/agents/lqr_rotorcraft.yaml``) eq. (6)'s blocks
at the craft's trim, its modes, the gain and the closed loop (:mod:`laddermill_gym.control.craft_lqr`).
``--rollout T`` flies open loop and LQR for T seconds after the paper's wind-direction step on the nonlinear
simulator and writes ``lqr_rollout.png`` and ``lqr_rollout.csv``.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from laddermill_gym.control.lqr import (
    DEFAULT_CONFIG,
    LATERAL_STATE_NAMES,
    chain_closed_loop,
    design_ladder_chain,
    design_tethered_wing,
    load_lqr_config,
    mode_table,
)
from laddermill_gym.control.open_loop import OpenLoopController
from laddermill_gym.control.rollout import run_direction_step
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.studies.commands import Parser, check_number, run_guarded, writable_folder


def report_single(design) -> str:
    lq = design.lqr
    rows = [f"scene {design.scene.name}: lateral model {len(LATERAL_STATE_NAMES)} states "
            f"({', '.join(LATERAL_STATE_NAMES)}), inputs (rudder, aileron)",
            f"trim residual max |dz/dt| = {design.linearization.residual:.3g} (state units per s; 0 at an exact trim)",
            "coupling of the lateral and longitudinal blocks at trim (relative norms): "
            + ", ".join(f"{k} {v:.2e}" for k, v in design.coupling.items()),
            "open-loop lateral modes (continuous):", mode_table(lq.open_loop),
            f"gain K (rad per unit state, columns {LATERAL_STATE_NAMES}):",
            np.array2string(lq.K, precision=4, suppress_small=True),
            f"closed-loop modes (discrete, ZOH at {lq.dt} s): max |z| = {np.max(np.abs(lq.closed_loop)):.5f}",
            mode_table(lq.closed_loop, lq.dt)]
    full = design.full_closed_loop
    if full is not None:  # a tether of several elements: the gain on the full lateral model, the nodes unobserved
        rows.append(f"on the full lateral model ({full.size} states, the cable nodes' unobserved): max |z| = "
                    f"{np.max(np.abs(full)):.5f}")
    return "\n".join(rows)


def report_chain(design, full_check: bool) -> str:
    ol = np.array([np.linalg.eigvals(A) for A in design.A_blocks])
    nw = len(design.A_blocks)
    structure = design.config.structure
    rows = [f"scene {design.scene.name}: {nw} wings, {structure} design",
            f"open-loop per-wing blocks: largest real part {ol.real.max():+.4f} 1/s "
            f"(wing {int(np.argmax(ol.real.max(1)))}), {int(np.sum(ol.real.max(1) > 0))} of {nw} wings unstable on "
            "their own"]
    model = "per-wing blocks" if structure == "decentralised" else "full coupled lateral model"
    rows.append(f"design closed loop on the {model} (discrete, ZOH at {design.config.control_period} s): "
                f"max |z| = {np.abs(design.closed_loop).max():.5f}")
    if full_check:
        ev_ol, ev_cl = chain_closed_loop(design)
        worst = ev_cl[np.argmax(np.abs(ev_cl))]
        rows += [f"full coupled lateral model ({ev_ol.size} states): open loop largest real part "
                 f"{ev_ol.real.max():+.4f} 1/s; {structure} gain closes it to max |z| = {abs(worst):.5f} "
                 f"(continuous equivalent {np.log(complex(worst)).real / design.config.control_period:+.4f} 1/s: "
                 f"{'stable' if abs(worst) < 1 else 'UNSTABLE'})"]
    return "\n".join(rows)


def report_mill(cfg) -> str:
    """Design the mill's LQR (``control.mill_lqr``) on LadderMill-v0's task at the config's control period and
    describe its check over the period."""
    from laddermill_gym.control.mill_lqr import design_mill_lqr
    from laddermill_gym.envs.laddermill.task import MillTask

    task = MillTask(1, scene=cfg.scene, scene_options={"elements_per_piece": cfg.elements_per_piece},
                    control_dt=cfg.control_period)
    d = design_mill_lqr(cfg, task, progress=print)
    rows = [d.summary(), "  phase s/l0   open-loop growth [1/s]   frozen closed loop max |z|"]
    rows += [f"  {ph:9.3f}   {g:22.3f}   {z:26.5f}" for ph, g, z in
             zip(d.phases, d.open_loop_growth, d.frozen_radius, strict=True)]
    return "\n".join(rows)


def _is_craft_config(path) -> bool:
    """Whether the LQR config at ``path`` (a file or a shipped name) is a rotorcraft's (``craft:``, eq. (6))."""
    from laddermill_gym.model.configio import find_config, read_yaml

    data = read_yaml(find_config("agents", path, "--config")).data
    return isinstance(data, dict) and "craft" in data


def report_craft(path) -> str:
    """The craft's eq. (6) LQR (``control.craft_lqr``): the blocks M, D, K and (alpha, beta) of the config's craft at
    its trim in the config's wind, eq. (6)'s modes, the gain, the discrete closed loop, and the gain's closed loop on
    the whole craft's linear model with that model's trim residual."""
    from laddermill_gym.control.craft_lqr import design_craft_lqr

    d = design_craft_lqr(path)
    m, lq, cfg = d.model, d.lqr, d.config
    tethers = d.sim.config.tethers

    def block(a):  # rows as lists, 4 decimals
        return str((np.round(np.asarray(a, dtype=float), 4) + 0.0).tolist())

    rows = [f"craft {cfg.craft} at v0 = {cfg.wind_speed:g} m/s, collective {np.degrees(d.u_trim[0]):.2f} deg, "
            f"{tethers.elements} elements per tether: eq. (6) (rows: force [N], moment [N m]; columns y, phi)",
            f"   M = {block(m.M)}", f"   D = {block(m.D)}", f"   K = {block(m.K)}",
            f"   (alpha, beta) = {block(m.b)} per rad",
            "eq. (6)'s modes (continuous):", mode_table(lq.open_loop),
            f"gain K (rad per unit state, columns (y, phi, vy, p)): {block(lq.K[0])}",
            f"closed-loop modes (discrete, ZOH at {lq.dt} s): max |z| = {np.max(np.abs(lq.closed_loop)):.5f}",
            mode_table(lq.closed_loop, lq.dt),
            f"on the whole craft's linear model ({d.full_closed_loop.size} states, the tethers' nodes included): "
            f"max |z| = {np.max(np.abs(d.full_closed_loop)):.5f}; its trim residual max |dz/dt| = "
            f"{d.trim_residual:.3g} (state units per s)"]
    return "\n".join(rows)


def rollout_figure(scene, x, u, controllers: dict, t_end: float, step: float, period: float, out: Path) -> None:
    from laddermill_gym.figure_files import subplots
    from laddermill_gym.plotting import save_figure

    out.mkdir(parents=True, exist_ok=True)
    runs = {name: run_direction_step(scene, x, u, c, t_end, period, step) for name, c in controllers.items()}
    fig, ax = subplots(figsize=(6.5, 4))
    for name, r in runs.items():
        dy = r.positions[:, :, 1] - r.positions[0, :, 1]
        ax.plot(r.t, dy, lw=0.8, label=f"{name}" + (f" (stopped: {r.error[:40]})" if r.error else ""))
        print(f"{name:10s}: ran {r.t[-1]:.1f} s, largest lateral offset {np.abs(dy).max():.4f} m"
              + (f", stopped: {r.error}" if r.error else ""))
    ax.set_yscale("symlog", linthresh=0.01)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("lateral CG offset [m]")
    ax.set_title(f"{scene.name}: {step} rad wind-direction step at 1 s", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save_figure(fig, out / "lqr_rollout.png")
    with open(out / "lqr_rollout.csv", "w") as fh:
        fh.write("controller,t_s,wing,y_m\n")
        for name, r in runs.items():
            for j, t in enumerate(r.t):
                for k in range(r.positions.shape[1]):
                    fh.write(f"{name},{t:.3f},{k},{r.positions[j, k, 1]:.6g}\n")
    print(f"wrote {out / 'lqr_rollout.png'} and {out / 'lqr_rollout.csv'}")


def main(argv: list[str] | None = None) -> int:
    p = Parser(prog="laddermill lqr", description=__doc__.split("\n\n")[0])
    p.add_argument("--config", default=str(DEFAULT_CONFIG), help="configs/agents/lqr_*.yaml")
    p.add_argument("--full-check", action="store_true", help="chain: close the loop on the full coupled model")
    p.add_argument("--rollout", type=float, metavar="T", help="[s] fly open loop and LQR on the simulator")
    p.add_argument("--step", type=float, default=None, help="[rad] with --rollout: wind-direction step at 1 s "
                   "(default 0.01)")
    p.add_argument("--out", type=Path, default=None, help="with --rollout: folder for lqr_rollout.png and .csv "
                   "(default results/lqr)")
    args = p.parse_args(argv)
    check_number("--rollout", args.rollout, low=0, high=86400, unit="s")
    check_number("--step", args.step, low=-3.15, high=3.15, unit="rad")
    if args.rollout is None and (args.step is not None or args.out is not None):
        p.error(f"{'--step' if args.step is not None else '--out'} is --rollout's: without it nothing is flown")
    args.step = 0.01 if args.step is None else args.step
    args.out = Path("results") / "lqr" if args.out is None else args.out
    if _is_craft_config(args.config):
        if args.rollout or args.full_check:
            p.error("a rotorcraft's LQR: --rollout and --full-check are the wings'; fly it with laddermill evaluate "
                    "--env laddermill_gym/Rotorcraft-v0 --controllers open_loop lqr")
        print(report_craft(args.config))
        return 0
    cfg = load_lqr_config(args.config)
    sc = load_scene(cfg.scene, elements_per_piece=cfg.elements_per_piece)
    if sc.assembly.station is not None:
        if args.rollout or args.full_check:
            p.error("a moving-cable mill: the design is checked over the period anyway; fly it with "
                    "laddermill evaluate --env laddermill_gym/LadderMill-v0 --controllers open_loop lqr")
        print(report_mill(cfg))
        return 0
    chain = sc.assembly.n_wings > 1
    if args.full_check and not chain:
        p.error(f"--full-check closes a chain's loop on its full coupled model; {args.config} designs one wing, whose "
                "report is its full model's already")
    if args.rollout:
        writable_folder(args.out)  # a bad folder named before the design and the runs
    design = design_ladder_chain(cfg, sc) if chain else design_tethered_wing(cfg, sc)
    print(report_chain(design, args.full_check) if chain else report_single(design))
    if args.rollout:
        if not args.rollout > 0:
            p.error(f"--rollout = {args.rollout}: must be > 0 s")
        ctrls = {"open loop": OpenLoopController.from_scene(sc, design.u_trim), "LQR": design.controller()}
        rollout_figure(sc, design.x_trim, design.u_trim, ctrls, args.rollout, args.step, cfg.control_period,
                       args.out)
    return 0


if __name__ == "__main__":
    sys.exit(run_guarded("lqr", main))
