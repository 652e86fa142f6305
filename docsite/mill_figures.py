"""Page groups of docs/moving_cable.md: the insertion study at two cable speeds, the 2D mill's run to periodic motion
(the page's own command) and the mill LQR's check over the period (``laddermill lqr``), each run in a fresh process
and parsed from what it prints."""

from __future__ import annotations

import re
import subprocess
import sys

from docsite.paper_figures import ROOT, printed_match, run_command

STUDY = "laddermill_gym.studies."
INSERTION = re.compile(r"^insertion (\w+): dv = ([\d.e-]+) m/s on l1 = ([\d.]+) m; element 0 tension ([\d.]+) kN "
                       r"before, jump ([\d.e-]+) kN \(Voigt \+ one step: ([\d.e-]+) kN\), dip ([\d.e-]+) kN at "
                       r"([\d.]+) ms \(spring: ([\d.e-]+) kN at ([\d.]+) ms\), largest ([\d.e-]+) kN in (\d+) "
                       r"ms$", re.M)
KEYS = ("dv", "l1", "before", "jump", "jump_closed", "dip", "dip_ms", "spring", "quarter_ms", "largest", "window_ms")
PERIODIC = ("from laddermill_gym import load_scene; from laddermill_gym.ladder.periodic import run_to_periodic; "
            "print(run_to_periodic(load_scene('laddermill', dimension=2).simulator(), shape_tol=1e-3, "
            "power_tol=1e-3).summary())")


def _need(pattern: str, text: str, argv: list[str]) -> re.Match:
    return printed_match(pattern, text, f"python {' '.join(argv)}")


def insertion_study() -> dict:
    """``python -m laddermill_gym.studies.mill.insertion`` at its default 0.5 m/s and with ``--speed 5`` (a few
    seconds each): per speed ("v0.5", "v5") and insertion rule ("paper", "cable") the printed figures (dv [m/s], l1
    [m], element 0's tension before, the jump and its closed form, the dip [kN] and its time [ms], the spring's
    closed-form dip [kN] and quarter period [ms], the largest tension [kN] and the window [ms]), as printed."""
    found = {}
    for speed in ("0.5", "5"):
        argv = ["-m", STUDY + "mill.insertion", "--speed", speed]
        out = run_command(argv[1:], 600)
        rows = {m.group(1): dict(zip(KEYS, m.groups()[1:], strict=True)) for m in INSERTION.finditer(out)}
        if set(rows) != {"paper", "cable"}:
            raise RuntimeError(f"python {' '.join(argv)} printed rows for {sorted(rows)}, not paper and cable:\n{out}")
        found[f"v{speed}"] = rows
    return found


def mill_periodic_2d() -> dict:
    """The page's command: ``run_to_periodic`` of the in-plane default mill (``shape_tol=1e-3, power_tol=1e-3``;
    1-4 minutes): whether it converged, where [s], the period [s], the mean generator power [kW] and the last shape
    [l0] and power changes per period, as printed (and those two in units of 1e-4: ``shape_e4``,
    ``power_change_e4``)."""
    argv = ["-c", PERIODIC]
    proc = subprocess.run([sys.executable, *argv], cwd=ROOT, capture_output=True, text=True, timeout=1800)
    if proc.returncode != 0:
        raise RuntimeError(f"python -c ... exited {proc.returncode}:\n{proc.stdout[-2000:]}{proc.stderr[-3000:]}")
    out = proc.stdout
    m = _need(r"periodic motion (converged|NOT converged[^\n]*?) at t = ([\d.]+) s \(period ([\d.]+) s\): mean "
              r"generator power ([-\d.]+) kW; last shape change ([\d.e+-]+) l0, power change ([\d.e+-]+);", out, argv)
    found = dict(zip(("state", "t", "period", "power_kW", "shape", "power_change"), m.groups(), strict=True))
    for key in ("shape", "power_change"):  # in units of 1e-4, as the page quotes them
        found[f"{key}_e4"] = f"{float(found[key]) / 1e-4:.2f}"
    return found


def mill_lqr_check() -> dict:
    """``laddermill lqr --config configs/agents/lqr_laddermill.yaml`` (about a minute, most of it the operating
    point, 100 s of CPU; 274 s at a load of 15): the open-loop growth [1/s], the frozen closed loops' largest |z|, the
    phases checked, and the spectral radius of the period's transition matrix with and without the transfer, as
    printed; from its per-phase table the smallest growth and |z| and the phases s / l0 whose |z| exceeds 1."""
    argv = ["laddermill_gym.cli", "lqr", "--config", "configs/agents/lqr_laddermill.yaml"]
    out = run_command(argv, 1800)
    argv = ["-m", *argv]
    m = _need(r"open-loop growth up to ([\d.]+) 1/s; frozen closed loop max \|z\| ([\d.]+) over (\d+) phases; spectral "
              r"radius of the period's transition matrix ([\d.]+) with the transfer, ([\d.]+) without", out, argv)
    found = dict(zip(("growth", "max_z", "phases", "radius", "flow_radius"), m.groups(), strict=True))
    rows = re.findall(r"^ +(\d\.\d{3}) +(\d+\.\d+) +(\d\.\d+)$", out, re.M)
    if len(rows) != int(found["phases"]):
        raise RuntimeError(f"python -m {' '.join(argv)} printed {len(rows)} phase rows, not {found['phases']}")
    found["growth_min"] = min(rows, key=lambda r: float(r[1]))[1]
    found["z_min"] = min(rows, key=lambda r: float(r[2]))[2]
    found["z_above_1"] = [phase for phase, _, z in rows if float(z) > 1.0]
    return found



def pointmass_mill() -> dict:
    """``python -m laddermill_gym.studies.pointmass.pointmass_mill`` (the rigid mill's in-plane run to periodic
    motion, then the point-mass mill at 70 m and 1 m elements on one thread; 173 s at a load of 3, over 25 minutes at
    a load of 13): the rigid run's periodic
    time [s], mean power, first and last element's and smallest mean tension [kN] and its element; per element
    length ("l70", "l1") the nodes, whether its search converged, where [s], its mean power [kW], the first and last
    element's and the smallest mean tension [kN] and the slot above it, as printed; ``vs_rigid``: the page's ratios
    of these (:func:`vs_rigid`)."""
    argv = [STUDY + "pointmass.pointmass_mill"]
    out = run_command(argv, 3600, threads=1)
    m = _need(r"^rigid \(one element per piece, RK4 dt [\d.]+ s\): periodic at t = (\d+) s, mean power ([\d.]+) kW, "
              r"first element ([\d.]+) kN, last ([\d.]+) kN, smallest mean tension ([\d.]+) kN \(element (\d+)\)", out,
              ["-m", *argv])
    found = {"rigid": dict(zip(("t", "power_kW", "first_kN", "last_kN", "min_kN", "min_element"), m.groups(),
                               strict=True))}
    keys = ("nodes", "state", "t", "power_kW", "first_kN", "last_kN", "min_kN", "min_slot")
    for m in re.finditer(r"^point mass l_e = (\d+) m \((\d+) nodes, .*?; point-mass periodic motion (converged|NOT "
                         r"converged[^\n]*?) at t = ([\d.]+) s \(period [\d.]+ s\): mean power ([-\d.]+) kW, first "
                         r"element ([\d.]+) kN, last ([\d.]+) kN, smallest mean tension ([\d.]+) kN \(below slot "
                         r"(\d+)\)",
                         out, re.M):
        found[f"l{m.group(1)}"] = dict(zip(keys, m.groups()[1:], strict=True))
    if "l70" not in found or "l1" not in found:
        raise RuntimeError(f"python -m {argv[0]} printed no periodic search for 70 m or 1 m elements:\n{out[-3000:]}")
    return {**found, "vs_rigid": vs_rigid(found)}


def vs_rigid(found: dict) -> dict:
    """docs/pointmass_mill.md's ratios of :func:`pointmass_mill`'s printed figures: per element length ("l70", "l1")
    its mean power, first, last and smallest mean tension over the rigid mill's, less 1 [%]; ``resolution``: the 1 m
    string's power less the 70 m one's [kW] and over it, less 1 [%] (``kW``, ``pct``), and the smaller and larger
    change of the end tensions [kN] (``ends_lo``, ``ends_hi``)."""
    keys = {"power_pct": "power_kW", "first_pct": "first_kN", "last_pct": "last_kN", "min_pct": "min_kN"}
    rigid, l70, l1 = ({k: float(v) for k, v in found[n].items() if k in keys.values()} for n in ("rigid", "l70", "l1"))
    ratios = {n: {k: (m[v] / rigid[v] - 1.0) * 100.0 for k, v in keys.items()} for n, m in (("l70", l70), ("l1", l1))}
    ends = sorted(abs(l1[k] - l70[k]) for k in ("first_kN", "last_kN"))
    return {**ratios, "resolution": {"kW": l1["power_kW"] - l70["power_kW"],
                                     "pct": (l1["power_kW"] / l70["power_kW"] - 1.0) * 100.0,
                                     "ends_lo": ends[0], "ends_hi": ends[1]}}


#: This module's page groups (merged into docsite.page_figures.GROUPS).
MILL_GROUPS = {"insertion_study": insertion_study, "mill_periodic_2d": mill_periodic_2d,
               "mill_lqr_check": mill_lqr_check, "pointmass_mill": pointmass_mill}
