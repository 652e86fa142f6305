"""Re-run the figures README.md (and the controllers page) quote, write them to a JSON, and compare them with the text.

``make readme-figures`` (``python -m docsite.readme_figures --out results/readme_figures.json``) measures:

* the main job, README's first command without the GIF (``laddermill demo``): how long the open-loop mill flies
  after the step, and the LQR's and the shipped ``ppo_mill``'s largest lateral excursion and mean power;
* every env id's action and observation sizes (``gymnasium.make(id)``; LadderMill-v0 finds its periodic operating
  point first, 2-3 minutes);
* TetheredWing-v0's open-loop and LQR rows of ``laddermill_gym/docs/controllers.md`` (``laddermill evaluate
  --controllers open_loop lqr --episodes 1``);
* with ``--policies`` (about 25 minutes more on a loaded 2-core machine): the shipped policies' gusts-v1 scorecards
  beside the LQR's, the rows of README's shipped-policy table (``laddermill gust-bench --suite gusts-v1 --env ID
  --controllers lqr ppo_<name>``; a scenario counts when every seed survives); its ppo_mill and ppo_chain rows
  (``laddermill evaluate --env ID --controllers ppo_<name> <its LQR> --episodes 1 --episode-time 301``: 300 s after
  the step at 1 s; the LQR designed on the linearised mill or chain first: minutes); the wing policy against the LQR
  on 200 held-out NTM-IB fields (``python -m laddermill_gym.harness.paired_survival``, :data:`HELD_OUT`);
* with ``--papers`` (:mod:`docsite.paper_figures`, 6.5 minutes at a load of 2-4, 12 at 5-7, about 11 more before
  Meijaard's searches are saved in results/meijaard_v1): the figures of README's "Papers reproduced"
  rows, each from the study command the row names.

* with ``--pages [PAGE ...]`` (:mod:`docsite.page_figures`): the checked numbers of the docs pages the ledger
  (:mod:`docsite.page_ledger`) covers, each group's command re-run once (``--skip-readme --pages NAME`` re-runs one
  page alone);
* with ``--long NAME ...`` (:mod:`docsite.long_figures`; ``--long --list`` lists them with their commands): the
  long tier, commands of minutes to an hour behind the pages' :class:`~docsite.ledger_kinds.Printed` snippets;
* with ``--pictures [NAME ...]`` (:mod:`docsite.pictures`): every embedded picture drawn again into docs/figures/
  (printing which changed);

and then checks that README.md, the controllers page and the covered docs pages print those numbers (exit 1 naming
each that differs).
The slow test ``tests/test_docs.py::test_readme_figures_are_what_their_commands_print`` does the same with both
groups. Not covered: machine-dependent timings (env steps/s, real-time factors: the benchmark pages say where and
when they were measured) and the longest studies (the power curve, 12 minutes on two workers).
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from docsite.host_cpu import host_cpu, quoted_profile

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
CONTROLLERS = ROOT / "laddermill_gym" / "docs" / "controllers.md"
MAIN_JOB = ["demo", "--no-gif", "--no-progress"]


def main_job() -> dict:
    """The main job's table: {controller: [flew after the step [s], mean power [kW], max |dy| [m], end]}: open loop,
    the LQR and, where this install can fly it, the shipped mill policy (the demo's default set)."""
    from laddermill_gym.cli import main

    out = io.StringIO()
    with tempfile.TemporaryDirectory() as tmp, contextlib.redirect_stdout(out):
        main(MAIN_JOB + ["--out", tmp])
    rows = dict((m.group(1), [m.group(2), m.group(3), m.group(4), m.group(5)]) for m in re.finditer(
        r"^(open_loop|lqr|ppo_mill)\s+([\d.]+)\s+([-\d.]+)\s+([\d.]+)\s+(.*)$", out.getvalue(), re.M))
    if not {"open_loop", "lqr"} <= set(rows):
        raise RuntimeError(f"laddermill {' '.join(MAIN_JOB)} printed no open_loop and lqr rows:\n{out.getvalue()}")
    return {"main_job": rows}


def env_sizes() -> dict:
    """{name: [n_actions, n_observations]} of every registered id."""
    import gymnasium as gym

    from laddermill_gym.envs import ENV_IDS

    sizes = {}
    for env_id in ENV_IDS:
        env = gym.make(env_id)
        sizes[env_id.split("/", 1)[1]] = [int(env.action_space.shape[0]), int(env.observation_space.shape[0])]
        env.close()
    return {"env_sizes": sizes}


def tethered_wing_rows() -> dict:
    """TetheredWing-v0, one seeded episode: open loop and LQR (return, flown time, largest offset, mean power)."""
    from laddermill_gym.envs import FAILURES
    from laddermill_gym.harness.evaluate import evaluate

    with tempfile.TemporaryDirectory() as tmp:
        res = evaluate("laddermill_gym/TetheredWing-v0", ["open_loop", "lqr"], 1, {}, Path(tmp), progress=False)
    rows = {}
    for label, r in res.items():
        code = int(r.failures[0])
        rows[label] = {"return": f"{r.returns[0]:.0f}", "flew_s": f"{r.lengths_s[0]:.1f}",
                       "failure": r.failure_names.get(code, FAILURES.get(code, str(code))) if code else "",
                       "max_lateral_m": float(r.max_lateral_m[0].max()), "power_W": f"{r.mean_power_W[0]:.0f}"}
    return {"tethered_wing": rows}


#: The shipped policies README scores on gusts-v1, each with its env id, in the order README quotes them.
SHIPPED = (("ppo_rotorcraft", "laddermill_gym/Rotorcraft-v0"), ("ppo_tethered_wing", "laddermill_gym/TetheredWing-v0"))


def policy_scorecards() -> dict:
    """{policy: [its scenarios survived, the LQR's, the suite's scenario count]} on gusts-v1 (every seed survives)."""
    from laddermill_gym.studies.gusts.gust_bench import run_suite, summarise
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    suite, cards = load_suite("gusts-v1"), {}
    for name, env_id in SHIPPED:
        summary = summarise(run_suite(suite, [env_id], ["lqr", name], progress=False))
        won = {c: sum(s["survived"] == 1.0 for s in summary if s["controller"] == c) for c in ("lqr", name)}
        cards[name] = [won[name], won["lqr"], sum(s["controller"] == name for s in summary)]
    return {"policy_scorecards": cards}


#: README's held-out comparison of the wing policy with the LQR (``python -m laddermill_gym.harness.paired_survival``
#: with these arguments): config, validation set, episodes, first seed, controllers.
HELD_OUT = ("configs/agents/ppo_tethered_wing_severe.yaml", "ntm_ib", 200, 5000, ["lqr", "ppo_tethered_wing"])


def wing_held_out() -> dict:
    """{"wing_held_out": [the LQR's survivors, the policy's, the sign test's p]} on README's held-out fields."""
    from laddermill_gym.harness.paired_survival import paired_survival

    config, set_name, episodes, seed, controllers = HELD_OUT
    res = paired_survival(str(ROOT / config), set_name, episodes, seed, controllers)
    return {"wing_held_out": [int(res["alive"][c].sum()) for c in controllers] + [f"{res['p_value']:.4f}"]}


def held_out_differences(figures: dict, readme: str) -> list[str]:
    """README's held-out sentence against ``figures["wing_held_out"]``, at the figures of the CPU they were measured
    on (``figures["cpu"]``; the counts are knife edges, :mod:`docsite.host_cpu`): "the wing policy survives P, the LQR
    L (sign test p = X) on CPU" or "; P and L (p = X) on CPU"; [] when it agrees or was not measured."""
    if "wing_held_out" not in figures:
        return []
    lqr, policy, p = figures["wing_held_out"]
    cpu = figures.get("cpu") or host_cpu()
    quoted = (f"the wing policy survives {policy}, the LQR {lqr} (sign test p = {p}) on {cpu}",
              f"; {policy} and {lqr} (p = {p}) on {cpu}")
    return [] if any(q in readme for q in quoted) else [f"README lacks '{quoted[0]}' or '{quoted[1]}' (paired_survival "
                                                        f"{HELD_OUT})"]


#: README's shared-policy rows: ``laddermill evaluate --env ID --controllers POLICY LQR --episodes 1 --episode-time
#: 301`` (the paper's direction step at 1 s, so 300 s after it; seed 0: the registered scenario is deterministic, every
#: seed flies the same episode, docs/learned_mill.md): policy -> (env id, the LQR it is set beside, the words before
#: the LQR's figures in its row).
SHARED_ROWS = {"ppo_mill": ("laddermill_gym/LadderMill-v1", "lqr", ""),
               "ppo_chain": ("laddermill_gym/LadderChain-v0", "lqr:lqr_ladder_chain_central", "centralised "),
               "ppo_mill_v3": ("laddermill_gym/LadderMill-v3", "lqr", "")}
SHARED_EPISODES, SHARED_EPISODE_S = 1, 301.0


def mill_policy_row() -> dict:
    """{policy: {controller: [episodes held to the end, episodes, largest |dy| [m], mean power [kW], all episodes
    alike]}} of each shared policy and its LQR (the LQR designs on the linearised mill or chain first: minutes)."""
    import numpy as np

    from laddermill_gym.harness.evaluate import evaluate

    out = {}
    for policy, (env_id, lqr, _) in SHARED_ROWS.items():
        with tempfile.TemporaryDirectory() as tmp:
            res = evaluate(env_id, [policy, lqr], SHARED_EPISODES, {"episode_time": SHARED_EPISODE_S}, Path(tmp),
                           progress=False)
        out[policy] = {"policy" if label == policy else "lqr": [
            int((r.failures == 0).sum()), len(r.failures), f"{r.max_lateral_m.max():.4f}",
            f"{r.mean_power_W.mean() / 1e3:.1f}", bool(np.allclose(r.returns, r.returns[0], rtol=1e-9, atol=0.0))]
            for label, r in res.items()}
    return {"mill_policy": out}


def shared_row(policy: str, rows: dict) -> str:
    """README's row cells of a shared policy's evaluation ``rows`` ({"policy": [...], "lqr": [...]})."""
    (held, n, dy, kw, _), lqr = rows["policy"], rows["lqr"]
    said = {(n, n): "held", (0, n): "failed"}
    return (f"| {said.get((held, n), f'{held} / {n} held')} {SHARED_EPISODE_S - 1:.0f} s after the step (seed 0: the "
            f"scenario is deterministic), {float(dy):.4f} m, {kw} kW | {SHARED_ROWS[policy][2]}"
            f"{said.get((lqr[0], lqr[1]), f'{lqr[0]} / {lqr[1]} held')}, {float(lqr[2]):.4f} m, {lqr[3]} kW")


def mill_policy_differences(figures: dict, readme: str) -> list[str]:
    """README's shared-policy rows and the main job's ppo_mill sentences against the evaluations and the demo; []
    when nothing was measured."""
    bad, rows, demo = [], figures.get("mill_policy"), figures["main_job"].get("ppo_mill")
    for policy, measured in (rows or {}).items():
        want = shared_row(policy, measured)
        if want not in readme or not (measured["policy"][4] and measured["lqr"][4]):
            bad.append(f"README's shipped-policy table: {policy} measured {measured} ([held, episodes, max |dy| m, "
                       f"kW, episodes alike]); README lacks '{want}'")
    if demo:
        flew, kw, dy, end = demo
        quotes = (f"so does `ppo_mill`, one policy shared by the 101 slots ({dy} m, {kw} kW)",
                  f"runs it: {float(flew):.0f} s after the step, {kw} kW, {dy} m, as the LQR")
        same = demo == figures["main_job"]["lqr"]  # "as the LQR"
        for quoted in quotes:
            if quoted not in readme or end != "ran to the end" or not same:
                bad.append(f"README: the main job prints ppo_mill {demo} (the LQR {figures['main_job']['lqr']}); "
                           f"README lacks '{quoted}' or it no longer holds")
    return bad


def measure(policies: bool = False, papers: bool = False) -> dict:
    """Every figure; ``policies`` and ``papers`` add the slow groups (see the module's docstring)."""
    from docsite.paper_figures import measure_papers

    return {**main_job(), **env_sizes(), **tethered_wing_rows(),
            **({**policy_scorecards(), **mill_policy_row(), **wing_held_out()} if policies else {}),
            "cpu": host_cpu(),
            **(measure_papers() if papers else {})}


def _flat(text: str) -> str:
    return " ".join(text.split())


def _env_rows(readme: str) -> dict[str, list[str]]:
    """README's env table: name -> its cells."""
    rows = {}
    for line in readme.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 6 and re.fullmatch(r"`\w+-v\d+`", cells[0]):
            rows[cells[0].strip("`")] = cells
    return rows


def differences(figures: dict) -> list[str]:
    """Each quoted figure that is not what was measured, as a sentence; [] when all agree."""
    readme, controllers = _flat(README.read_text()), _flat(CONTROLLERS.read_text())
    bad = []
    ol, lqr = figures["main_job"]["open_loop"], figures["main_job"]["lqr"]
    for quoted in (f"leaves the wing data {ol[0]} s after the step", f"excursion {lqr[2]} m, at {lqr[1]} kW mean"):
        if quoted not in readme:
            bad.append(f"README: the main job prints open loop {ol}, LQR {lqr}; README lacks '{quoted}'")
    if lqr[3] != "ran to the end":
        bad.append(f"README: the LQR no longer holds the mill through the main job ({lqr[3]})")
    rows = _env_rows(README.read_text())
    for name, (n_act, n_obs) in figures["env_sizes"].items():
        cells = rows.get(name)
        if cells is None or cells[2:4] != [str(n_act), str(n_obs)]:
            bad.append(f"README's env table: {name} has {n_act} actions and {n_obs} observations, table row {cells}")
    labels = {"open loop": "open_loop", "LQR": "lqr"}
    for shown, key in labels.items():
        r = figures["tethered_wing"][key]
        flew = f"{r['flew_s']} s ({r['failure']})" if r["failure"] else f"{float(r['flew_s']):.0f} s"
        m = re.search(rf"\| {re.escape(shown)} \| (\S+) \| ([^|]+) \| ([\d.]+) m \| (\d+) W \|", controllers)
        if m is None:
            bad.append(f"controllers.md: no TetheredWing-v0 row for {shown}")
            continue
        quoted_lat = float(m.group(3))
        digits = len(m.group(3).split(".")[1]) if "." in m.group(3) else 0
        ok = (m.group(1) == r["return"] and m.group(2).strip() == flew and m.group(4) == r["power_W"]
              and round(r["max_lateral_m"], digits) == quoted_lat)
        if not ok:
            bad.append(f"controllers.md, TetheredWing-v0 {shown}: measured {r['return']}, {flew}, "
                       f"{r['max_lateral_m']:.4g} m, {r['power_W']} W; quoted {m.group(0)}")
    from docsite.paper_figures import papers_differences

    text = README.read_text()
    return (bad + policy_differences(figures.get("policy_scorecards", {}), text, figures.get("cpu") or host_cpu())
            + mill_policy_differences(figures, readme) + held_out_differences(figures, readme)
            + papers_differences(figures.get("papers", {}), readme))


def policy_differences(cards: dict, readme: str, cpu: str) -> list[str]:
    """README's table of the shipped policies against ``cards`` ({policy: [won, the LQR's, scenarios]}) measured on
    CPU ``cpu``: each row must read "survive gusts-v1's scenarios won / n | LQR / n", the LQR's cell either one count
    or one per CPU ("11 / 12 on znver4, 10 / 12 on znver3", :mod:`docsite.host_cpu`: then ``cpu``'s is compared);
    [] when every row agrees or nothing was measured."""
    bad = []
    for name, (won, lqr, n) in cards.items():
        row = rf"^\| `{re.escape(name)}` \|.*\| survive gusts-v1's scenarios (\d+) / (\d+) \| ([^|]*) \|$"
        m = re.search(row, readme, re.M)
        cell = m and (re.fullmatch(r"(\d+) / (\d+)", m.group(3))
                      or re.search(rf"(\d+) / (\d+) on {re.escape(cpu)}\b", m.group(3)))
        quoted = m and cell and [int(m.group(1)), int(m.group(2)), *map(int, cell.groups())]
        if quoted != [won, n, lqr, n]:
            bad.append(f"README's shipped-policy table: {name} survives {won} / {n} of gusts-v1 (the LQR {lqr} / {n} "
                       f"on {cpu}); the table's row says {m.group(0) if m else 'nothing'}")
    return bad


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m docsite.readme_figures", description=__doc__.split("\n\n")[0])
    p.add_argument("--out", default="results/readme_figures.json", help="the JSON of the measured figures")
    p.add_argument("--check-only", action="store_true", help="compare the text with an existing --out JSON")
    p.add_argument("--policies", action="store_true", help="also the shipped policies' gusts-v1 scorecards and "
                   "ppo_mill's evaluation on LadderMill-v1 (~17 min)")
    p.add_argument("--papers", action="store_true", help="also the figures of the Papers-reproduced rows, each study "
                   "in turn (~12 min; 23 before Meijaard's searches are saved)")
    p.add_argument("--pages", nargs="*", metavar="PAGE", help="also the checked numbers of these docs pages "
                   "(docsite/page_ledger.py; no name: every page with checks)")
    p.add_argument("--pictures", nargs="*", metavar="NAME", help="also draw the embedded pictures again into "
                   "docs/figures/ (docsite/pictures.py; no name: every command but the training runs)")
    p.add_argument("--long", nargs="*", metavar="NAME", help="also the long tier's commands (docsite/long_figures.py; "
                   "minutes to an hour each; the slow set runs them too: tests/test_long_tier.py): their output "
                   "against the pages' Printed snippets")
    p.add_argument("--list", action="store_true", help="with --long: list the long groups and their commands, run "
                   "nothing")
    p.add_argument("--skip-readme", action="store_true", help="leave out README's own groups and checks (re-run "
                   "--pages or --pictures alone)")
    args = p.parse_args(argv)
    if args.long == [] and not args.list:
        p.error("--long needs the names of long groups (each runs minutes to hours); --long --list names them")
    if args.list:
        from docsite.long_figures import listing

        print(listing())
        return 0
    profile, settings = quoted_profile()
    if settings and not args.check_only:  # numpy and OpenBLAS choose their kernels at load: a fresh process
        print(f"this machine's numeric profile ({host_cpu()}) is not one the pages quote: measuring under "
              f"{profile}'s kernels ({settings}; docsite/host_cpu.py)", flush=True)
        return subprocess.call([sys.executable, "-m", "docsite.readme_figures",
                                *(sys.argv[1:] if argv is None else argv)],
                               env={**os.environ, **settings, "PYTHONPATH": os.pathsep.join(
                                   [str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])])})
    out = Path(args.out)
    if args.check_only:
        figures = json.loads(out.read_text())
    else:
        figures = {} if args.skip_readme else measure(policies=args.policies, papers=args.papers)
        if args.pages is not None:
            from docsite.page_figures import measure_pages

            figures.update(measure_pages(args.pages, have=figures, more={"main_job": main_job}))
        if args.long:
            from docsite.long_figures import measure_long

            figures.update(measure_long(args.long))
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_text(json.dumps(figures, indent=1))
        print(f"wrote {out}")
    if args.pictures is not None:
        from docsite.pictures import regenerate

        changed = {k: v for k, v in regenerate(args.pictures or None).items() if v != "same"}
        print(f"pictures changed: {changed or 'none'}")
    from docsite.page_figures import long_differences, pages_differences

    bad = (([] if args.skip_readme else differences(figures)) + pages_differences(figures.get("pages", {}))
           + long_differences(figures.get("long", {})))
    for line in bad:
        print(f"stale: {line}")
    print("every checked figure is what its command prints" if not bad else f"{len(bad)} stale figures")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
