"""Every picture README.md and the docs pages embed, with the command that draws it, and their regeneration.

``python -m docsite.readme_figures --pictures [NAME ...]`` (part of ``make readme-figures``) runs each picture's
command, one at a time in a fresh process, into a temporary folder (or the study's own results folder where it
reuses saved work), and copies the files it draws over ``laddermill_gym/docs/figures/`` under the embedded names;
it prints, per picture, whether its pixels changed (a picture with the same pixels keeps its file: matplotlib's
metadata alone makes the bytes differ; look at a changed one before committing it).

:data:`PICTURES` lists each command once with the pictures it draws. ``kind`` says what re-running it costs:
``quick`` (seconds to a few minutes), ``long`` (the work-precision studies, about 15 minutes; the v2 mill's
power curve, 12 minutes on two workers), ``training`` (the picture shows a training run or a policy no longer
shipped: re-running means training, which ``--pictures`` skips unless the command is named). The fast test
``tests/test_page_figures.py`` checks that every embedded picture has a command here and every picture here is
embedded, so a new picture without a command fails it.
"""

from __future__ import annotations

import hashlib
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from tqdm import tqdm

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "laddermill_gym" / "docs"
FIGURES = DOCS / "figures"
IMAGE = re.compile(r"!\[[^\]]*\]\(([^)\s]+)\)|<img\s[^>]*src=[\"']([^\"']+)[\"']")  # Markdown's or HTML's
WP = "NUMBA_NUM_THREADS=1 laddermill work-precision"  # docs/work_precision.md: one thread each (the Makefile's WP)


@dataclass(frozen=True)
class Picture:
    """One command (a shell line run from the repository root; ``{out}`` is its output folder) and the pictures it
    draws: {file it writes under ``out``: name under docs/figures/}."""

    name: str
    command: str
    draws: dict
    kind: str = "quick"
    out: str = ""  # a folder under the repository root that the command reuses (saved searches); "" = a temporary one


def _wp(name: str, scenes: str, args: str) -> Picture:
    return Picture(name, f"{WP} {scenes} {args} --out {{out}}",
                   {f"{s}.png": f"work_precision_{s}{'_10s' if '--forcing step --time 10' in args else ''}.png"
                    for s in scenes.split()}, kind="long")


PICTURES = (
    Picture("demo", "laddermill demo --no-gif --no-progress --out {out}", {"demo.png": "laddermill_demo.png"}),
    Picture("simulate_laddermill", "laddermill simulate laddermill --start periodic --direction-step 0.01 --time 60 "
            "--allow-breakdown --out {out}", {"laddermill_shape.png": "laddermill_direction_step.png",
                                              "laddermill_generator.png": "laddermill_generator.png"}),
    Picture("simulate_tethered_wing", "laddermill simulate tethered_wing --time 120 --direction-step 0.01 --out {out}",
            {"tethered_wing_histories.png": "tethered_wing_direction_step.png"}),
    Picture("ladder_chain_controllers", "laddermill evaluate --env laddermill_gym/LadderChain-v0 --episodes 1 --out "
            "{out} --controllers open_loop lqr lqr:configs/agents/lqr_ladder_chain_central.yaml",
            {"lateral.png": "ladder_chain_controllers.png"}),
    Picture("craft_stability", "python -m laddermill_gym.studies.rotorcraft.craft_stability --out {out}",
            {"rotorcraft_stability.png": "rotorcraft_stability.png"}),
    Picture("rotor_chart", "python -m laddermill_gym.studies.rotorcraft.rotor_chart --out {out}/rotor_power_chart.png "
            "--csv {out}/rotor_power_chart.csv", {"rotor_power_chart.png": "rotor_power_chart.png"}),
    Picture("lateral_study", "python -m laddermill_gym.studies.lateral.lateral_study --out {out}/lateral_study.png",
            {"lateral_study.png": "lateral_study.png"}),
    Picture("meijaard_v1", "python -m laddermill_gym.studies.mill.meijaard --no-progress --out {out}",
            {f"{f}.png": f"meijaard_v1_{f}.png" for f in ("fig6_shapes", "fig7_tension", "fig8_direction_step",
                                                          "claims")}, out="results/meijaard_v1"),
    Picture("meijaard_v0", "python -m laddermill_gym.studies.mill.meijaard --scene laddermill --no-progress "
            "--out {out}",
            {f"{f}.png": f"meijaard_{f}.png" for f in ("fig6_shapes", "fig7_tension", "fig8_direction_step",
                                                       "claims")}, out="results/meijaard"),
    Picture("pumping_cycle", "python -m laddermill_gym.studies.pumping.pumping_cycle --cycles 2 --out {out}",
            {"pumping_window.png": "pumping_crosswind_window.png",
             "pumping_timeseries.png": "pumping_crosswind_timeseries.png"}),
    Picture("pumping_power", "python -m laddermill_gym.studies.pumping.power_curve --out {out}",
            {"pumping_power_curve.png": "pumping_power_curve.png"}),
    Picture("pumping_power_reeling", "python -m laddermill_gym.studies.pumping.power_curve --reel-element-length 40 "
            "--out {out}", {"pumping_power_curve.png": "pumping_power_curve_reeling.png"}),
    Picture("site", "laddermill site --sweeps --out {out}",
            {"fig14_cabauw.png": "site_fig14_cabauw.png", "table2_cabauw_figs10-13.png":
             "site_table2_cabauw_figs10-13.png", "models_cabauw.png": "site_models_cabauw.png",
             "turbine_weather2010-daily.png": "site_turbine_weather2010.png"}),
    Picture("gust_scorecard_tethered_wing", "laddermill gust-bench --suite gusts-v1 --env "
            "laddermill_gym/TetheredWing-v0 --controllers open_loop lqr ppo_tethered_wing --out {out}",
            {"scorecard_TetheredWing-v0.png": "gust_scorecard_tethered_wing.png"}, kind="long"),
    _wp("wp_chain", "ladder_chain", "--time 10 --samples 50"),
    _wp("wp_craft", "tethered_wing roberts_flying_model laddermill", "--time 5 --samples 25"),
    _wp("wp_podgaets", "podgaets_5km", "--time 10 --samples 50"),
    _wp("wp_step", "pumping_kite roberts_35m_15kft roberts_35m_30kft", "--forcing step --time 5 --samples 25"),
    _wp("wp_mill_10s", "laddermill", "--forcing step --time 10 --samples 50"),
    Picture("mill_power_curve_v2", "laddermill power-curve --workers 2 --out {out}",
            {"power_curve.png": "mill_power_curve_v2.png"}, kind="long"),
    Picture("tethered_wing_controllers", "laddermill evaluate --controllers open_loop lqr "
            "runs/ppo_tethered_wing_seed0/best_model.zip runs/ppo_tethered_wing_seed0/model.zip --episodes 1 "
            "--out {out}", {"lateral.png": "tethered_wing_controllers.png"}, kind="training"),
    Picture("ppo_training_curve", "python -m agents.train configs/agents/ppo_tethered_wing.yaml --out {out}",
            {"training_curve.png": "ppo_training_curve.png"}, kind="training"),
    Picture("learned_mill_curve", "NUMBA_NUM_THREADS=1 laddermill train ppo_mill_v1 --seed 0 --out {out}",
            {"training_curve.png": "learned_mill_curve.png"}, kind="training"),
    Picture("laddermill_controllers", "laddermill evaluate --env laddermill_gym/LadderMill-v0 --controllers open_loop "
            "lqr runs/ppo_laddermill_seed0 --episodes 1 --episode-time 300 --scenario paper_step --out {out}",
            {"lateral.png": "laddermill_controllers.png"}, kind="training"),
)


def embedded() -> dict[str, list[str]]:
    """{picture file name under docs/figures/: [the documents that embed it]} of README.md and every docs page."""
    found: dict[str, list[str]] = {}
    for doc in [ROOT / "README.md", *sorted(DOCS.rglob("*.md"))]:
        for target in (md or html for md, html in IMAGE.findall(doc.read_text())):
            path = (doc.parent / target).resolve()
            if path.parent == FIGURES.resolve():
                found.setdefault(path.name, []).append(str(doc.relative_to(ROOT)))
    return found


def drawn() -> dict[str, str]:
    """{picture file name: the name of the command that draws it}; a picture drawn twice raises."""
    out: dict[str, str] = {}
    for pic in PICTURES:
        for name in pic.draws.values():
            if name in out:
                raise ValueError(f"docsite/pictures.py: {name} is drawn by both {out[name]} and {pic.name}")
            out[name] = pic.name
    return out


def compare(new: Path, old: Path) -> str:
    """"same" when two PNGs show the same pixels (matplotlib writes its version and the like into the file, so equal
    pictures can differ in their bytes), else "changed" with how many pixels differ and by how much at most (a few
    pixels at edges is antialiasing; look before committing)."""
    import numpy as np
    from matplotlib.image import imread

    if hashlib.sha256(new.read_bytes()).digest() == hashlib.sha256(old.read_bytes()).digest():
        return "same"
    a, b = imread(new), imread(old)
    if a.shape != b.shape:
        return f"changed (size {b.shape[1]} x {b.shape[0]} -> {a.shape[1]} x {a.shape[0]})"
    diff = np.abs(a - b).max(axis=-1) if a.ndim == 3 else np.abs(a - b)
    if not diff.any():
        return "same"
    return f"changed ({int((diff > 0).sum()):,} of {diff.size:,} pixels, max {diff.max():.2f})"


def regenerate(names: list[str] | None = None, timeout_s: float = 3600.0) -> dict[str, str]:
    """Run the commands ``names`` (default: every one but the training kind) and copy their pictures into
    docs/figures/; {picture: "same" | "new" | "changed (...)"}. A command that fails raises naming it."""
    by_name = {p.name: p for p in PICTURES}
    unknown = sorted(set(names or ()) - set(by_name))
    if unknown:
        raise ValueError(f"--pictures: no picture command named {unknown}; the names: {sorted(by_name)}")
    chosen = [by_name[n] for n in names] if names else [p for p in PICTURES if p.kind != "training"]
    result = {}
    for pic in tqdm(chosen, desc="pictures", unit="command"):
        with tempfile.TemporaryDirectory() as tmp:
            out = ROOT / pic.out if pic.out else Path(tmp)
            command = pic.command.format(out=shlex.quote(str(out)))
            t0 = time.perf_counter()
            proc = subprocess.run(command, shell=True, cwd=ROOT, capture_output=True, text=True, timeout=timeout_s)
            if proc.returncode != 0:
                raise RuntimeError(f"{pic.name}: `{command}` exited {proc.returncode}:\n{proc.stderr[-3000:]}")
            for made, name in pic.draws.items():  # a picture with the same pixels keeps its file (no churn in git)
                target = FIGURES / name
                result[name] = "new" if not target.exists() else compare(out / made, target)
                if result[name] != "same":
                    shutil.copyfile(out / made, target)
            tqdm.write(f"{pic.name}: {time.perf_counter() - t0:.0f} s; "
                       + ", ".join(f"{n} {result[n]}" for n in pic.draws.values()))
    return result


if __name__ == "__main__":
    print(regenerate(sys.argv[1:] or None))
