"""Page group of docs/rotor.md: ``python -m laddermill_gym.studies.rotorcraft.rotor_chart`` (Roberts' Fig. 3 chart
and the solidity finding), run in a fresh process and parsed from what it prints."""

from __future__ import annotations

import re
import tempfile
from pathlib import Path

from docsite.paper_figures import run_command


def rotor_chart() -> dict:
    """``python -m laddermill_gym.studies.rotorcraft.rotor_chart`` (its PNG and CSV into a temporary folder; 2-25 s):
    per mu ("m0.05", ...) the autorotation angle at the limit [deg], the peak C_p, its alpha_c [deg] and the
    collective at autorotation [deg]; the solidity at the tip limit, the best collective [deg] and its solidity, the
    solidities at fixed collectives ("t0".."t6"), the autorotation angle's rise per 0.01 of sigma [deg], and the
    blade-element table's own angles per solidity and collective ("s0.05" / "s0.08": "t0".."t6"), as printed."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = ["laddermill_gym.studies.rotorcraft.rotor_chart", "--out", str(Path(tmp) / "chart.png"), "--csv",
                str(Path(tmp) / "chart.csv")]
        out = run_command(argv, 900)

    def need(pattern: str) -> re.Match:
        m = re.search(pattern, out, re.M)
        if m is None:
            raise RuntimeError(f"python -m {argv[0]} printed nothing matching {pattern!r}:\n{out[-2000:]}")
        return m

    found = {f"m{mu}": dict(zip(("autorotation", "cp", "at", "collective"), rest, strict=True)) for mu, *rest in
             re.findall(r"^([\d.]+) +([\d.]+) +([\d.]+) at +([\d.]+) +([\d.]+)$", out, re.M)}
    if len(found) != 5:
        raise RuntimeError(f"python -m {argv[0]} printed {len(found)} mu rows, not 5:\n{out[-2000:]}")
    found["sigma_limit"] = need(r"at the [\d.]+ deg tip limit \(the chart's construction\): sigma = ([\d.]+)").group(1)
    best = need(r"best theta0 = ([\d.]+) deg\): sigma = ([\d.]+)")
    found.update(best_theta=best.group(1), sigma_best=best.group(2),
                 fixed={f"t{t}": s for t, s in re.findall(r"at fixed collective theta0 = (\d+) deg: sigma = ([\d.]+)",
                                                          out)},
                 rise=need(r"\(([\d.]+) deg per 0\.01 of sigma at the limit\)").group(1))
    for sigma in ("0.05", "0.08"):
        line = need(rf"^  sigma {re.escape(sigma)} \(theta0 deg: ours/oracle\): (.*)$").group(1)
        found[f"s{sigma}"] = {f"t{t}": ours for t, ours in re.findall(r"(\d+): ([\d.]+)/[\d.]+", line)}
    return found
