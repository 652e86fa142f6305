"""The page groups of docs/controllers.md: TetheredWing-v0's and LadderChain-v0's controller runs and LQR designs, each
command in a fresh process as the page (and the Makefile's ``figures`` target) names it.

``wing_controllers``: ``laddermill evaluate --controllers open_loop lqr --episodes 1`` on TetheredWing-v0 (300 s) and
``laddermill lqr`` (the wing's default config); ``chain_controllers``: ``laddermill evaluate --env
laddermill_gym/LadderChain-v0 --episodes 1 --controllers open_loop lqr
lqr:configs/agents/lqr_ladder_chain_central.yaml`` (120 s) and ``laddermill lqr --config`` of the decentralised
(``--full-check``) and the centralised chain design; ``mill_v1_controllers``: ``laddermill evaluate --env
laddermill_gym/LadderMill-v1 --controllers open_loop lqr --episodes 1 --episode-time 300``."""

from __future__ import annotations

import re
import tempfile
from pathlib import Path

from docsite.paper_figures import printed_match, run_command

CLI = "laddermill_gym.cli"
CENTRAL = "lqr:configs/agents/lqr_ladder_chain_central.yaml"
ROW = r"^{label} +([-\d.]+) +([\d.]+) +([\d.]+) +([-\d.]+)  (.*)$"


def evaluate_rows(env: str, controllers: list[str], episode_time: str | None = None) -> dict:
    """``laddermill evaluate --env ENV --controllers ... --episodes 1 [--episode-time T]``: per controller its printed
    row (return, length [s], max |dy| [m], mean power [W] and [kW], failures; "" for none), as printed."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = [CLI, "evaluate", "--env", env, "--controllers", *controllers, "--episodes", "1", "--out", tmp,
                *(["--episode-time", episode_time] if episode_time else [])]
        out = run_command(argv, 1800)
    rows = {}
    for label in controllers:  # an LQR config prints as lqr:<its file's stem>
        shown = f"lqr:{Path(label[4:]).stem}" if label.startswith("lqr:") else label
        m = printed_match(ROW.format(label=re.escape(shown)), out, f"python -m {' '.join(argv)}")
        rows[label] = {"return": m.group(1), "length": m.group(2), "dy": m.group(3), "power": m.group(4),
                       "failures": "" if m.group(5).strip() == "-" else m.group(5).strip(),
                       "power_kW": f"{float(m.group(4)) / 1e3:.4f}"}
    return rows


def lqr_report(config: str | None = None, full_check: bool = False) -> str:
    """What ``laddermill lqr [--config CONFIG] [--full-check]`` prints."""
    argv = [CLI, "lqr", *(["--config", config] if config else []), *(["--full-check"] if full_check else [])]
    return run_command(argv, 1800)


def _z(text: str, pattern: str, where: str) -> str:
    return printed_match(pattern, text, where).group(1)


def wing_controllers() -> dict:
    """TetheredWing-v0: the open-loop and LQR rows (the paper's 0.01 rad step at 1 s, 300 s) and the LQR's discrete
    closed-loop max |z| as printed (5 decimals)."""
    rows = evaluate_rows("laddermill_gym/TetheredWing-v0", ["open_loop", "lqr"])
    z = _z(lqr_report(), r"closed-loop modes \(discrete, ZOH at [\d.]+ s\): max \|z\| = ([\d.]+)", "laddermill lqr")
    return {**rows, "z": z}


def chain_controllers() -> dict:
    """LadderChain-v0 (0.01 rad step, 120 s): the rows of open loop, the default decentralised LQR and the centralised
    one; the full coupled lateral model's states and largest open-loop real part [1/s] and the decentralised gain's
    max |z| on it; the centralised design's max |z| (5 decimals, as printed)."""
    rows = evaluate_rows("laddermill_gym/LadderChain-v0", ["open_loop", "lqr", CENTRAL])
    where = "laddermill lqr --config configs/agents/lqr_ladder_chain.yaml --full-check"
    full = printed_match(r"full coupled lateral model \((\d+) states\): open loop largest real part ([-+\d.]+) 1/s; "
                         r"\w+ gain closes it to max \|z\| = ([\d.]+)",
                         lqr_report("configs/agents/lqr_ladder_chain.yaml", True), where)
    central = _z(lqr_report("configs/agents/lqr_ladder_chain_central.yaml"), r"design closed loop on the full coupled "
                 r"lateral model \(discrete, ZOH at [\d.]+ s\): max \|z\| = ([\d.]+)",
                 "laddermill lqr --config configs/agents/lqr_ladder_chain_central.yaml")
    return {"open_loop": rows["open_loop"], "lqr": rows["lqr"], "central": rows[CENTRAL], "states": full.group(1),
            "real_part": full.group(2), "decentral_z": full.group(3), "central_z": central}


def mill_v1_controllers() -> dict:
    """LadderMill-v1 (the paper's 0.01 rad step at 1 s, 300 s): the open-loop and LQR rows of ``laddermill evaluate
    --env laddermill_gym/LadderMill-v1 --controllers open_loop lqr --episodes 1 --episode-time 300`` (the LQR designed
    on the linearised mill first: minutes)."""
    return evaluate_rows("laddermill_gym/LadderMill-v1", ["open_loop", "lqr"], "300")


#: docs/controllers.md's groups for :data:`docsite.page_figures.GROUPS`.
CONTROLLER_GROUPS = {"wing_controllers": wing_controllers, "chain_controllers": chain_controllers,
                     "mill_v1_controllers": mill_v1_controllers}
