"""The documentation: README's shape and links, the quick start is the tutorial the docs build runs, every env id and
command gets its generated page (one per env id in Gymnasium's sections, the command reference), CITATION.cff names
the package and the four papers; and, in the slow set, the site builds with ``mkdocs build --strict`` (warnings,
broken links and anchors fail it; the tutorials run), within a few minutes.

Oracles: the files on disk (links), the code's own registry and parsers (the generated pages, re-derived here), the
Citation File Format's required keys, and MkDocs' validation of every link and anchor.
"""

from __future__ import annotations

import ast
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
DOCS = ROOT / "laddermill_gym" / "docs"
LINK = re.compile(r"\]\(([^)\s]+)\)")


def _readme() -> str:
    return README.read_text()


def test_readme_fits_on_two_screens():
    assert len(_readme().splitlines()) <= 200


def test_readme_keeps_the_two_setup_commands_of_ci():
    """README's main-job command, and its test command as .ci/run runs it (each install and test step of .ci/run's
    README section, less pip's -q, is in README's one-line command)."""
    text = _readme()
    assert "pip install -e . && laddermill demo --out runs" in text
    ci = (ROOT / ".ci" / "run").read_text().split("# --- README", 1)[1].split("# --- end of README", 1)[0]
    ci = ci.splitlines()[1:]
    steps = [" ".join(line.replace(" -q", "").split()) for line in ci if line.startswith(("pip ", "python -m pytest"))]
    assert steps, ".ci/run's README section has no install or test step"
    test_line = next(line for line in text.splitlines() if "python -m pytest" in line and "pip install" in line)
    for step in steps:
        assert step in test_line, f".ci/run step {step!r} is not in README's test command"


def test_readme_and_docs_relative_links_exist():
    """Every relative link (and image) of README and of the Markdown documents points at a file that exists
    (the site build checks the same for the pages and their anchors; this covers README and runs without MkDocs)."""
    files = [README] + sorted(DOCS.rglob("*.md"))
    missing = []
    for f in files:
        for target in LINK.findall(f.read_text()):
            if re.match(r"[a-z]+:", target) or target.startswith("#"):
                continue
            path = (f.parent / target.split("#", 1)[0]).resolve()
            if any(path.is_relative_to(DOCS / d) for d in ("tutorials", "envs", "commands")):
                continue  # pages the site build writes (docsite/hooks.py); MkDocs checks those links
            if not path.exists():
                missing.append(f"{f.relative_to(ROOT)} -> {target}")
    assert not missing, "\n".join(missing)


def _quickstart_code(text: str) -> str:
    block = text.split("## Quick start", 1)[1].split("```python\n", 1)[1].split("```", 1)[0]
    return block.strip()


def test_readme_quick_start_is_the_tutorial_the_docs_build_runs():
    """README's quick start is ``tutorials/quickstart.py`` after its docstring, at most 15 lines."""
    source = (ROOT / "tutorials" / "quickstart.py").read_text()
    code = "\n".join(source.splitlines()[ast.parse(source).body[0].end_lineno:]).strip()
    assert _quickstart_code(_readme()) == code, "README's quick start differs from tutorials/quickstart.py"
    assert len(code.splitlines()) <= 15


def test_every_tutorial_is_listed_for_the_docs_build():
    sys.path.insert(0, str(ROOT))
    from docsite.tutorials import ORDER, SHORT

    present = {p.name for p in (ROOT / "tutorials").glob("*.py")}
    assert present == set(ORDER) == set(SHORT)
    for name, pairs in SHORT.items():
        source = (ROOT / "tutorials" / name).read_text()
        for old, _new in pairs:
            assert source.count(old) == 1, (name, old)


def test_every_env_id_and_command_gets_its_page():
    """The site's generated pages (docsite/hooks.py): one per registered env id, with every Gymnasium section
    (an env docstring that loses one raises), and one per ``laddermill`` command with its ``--help``."""
    sys.path.insert(0, str(ROOT))
    from docsite.commands import commands_pages
    from docsite.env_pages import REQUIRED, env_pages
    from laddermill_gym.cli import FORWARDED
    from laddermill_gym.envs import ENV_IDS

    pages = dict(env_pages())
    nav = (ROOT / "mkdocs.yml").read_text()  # a page left out of the nav fails the strict build
    for env_id in ENV_IDS:
        assert f"- envs/{env_id.split('/', 1)[1]}.md" in nav, f"mkdocs.yml's nav lacks {env_id}'s page"
        text = pages[f"envs/{env_id.split('/', 1)[1]}.md"]
        assert all(s in text for s in REQUIRED + ("## Registered defaults", "## Every argument")), env_id
    commands = commands_pages()
    for name in list(FORWARDED) + ["simulate", "bench", "bench-envs", "scenes"]:
        assert f"usage: laddermill {name}" in commands[f"commands/{name}.md"], name


def test_env_pages_give_each_summary_whole():
    """A summary that runs over several docstring lines was cut at the first one on the env's page and in the index
    ("... (one Meijaard wing on a 300 m tether on"), the rest left below the table (review of 2026-12-07)."""
    sys.path.insert(0, str(ROOT))
    from docsite.env_pages import env_pages

    pages = dict(env_pages())
    whole = "while the winch reels out under high lift and in at low lift."
    assert whole in pages["envs/PumpingKite-v0.md"].split("| | |")[0]
    row = next(line for line in pages["envs/index.md"].splitlines() if "PumpingKite-v0" in line)
    assert whole in row


def test_citation_file_names_the_package_and_the_four_papers():
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    for key in ("cff-version", "message", "title", "authors"):
        assert cff.get(key), key
    titles = " | ".join(r["title"].lower() for r in cff["references"])
    for words in ("dynamic behaviour of a laddermill", "three-dimensional simulation of a laddermill",
                  "long-term laddermill modeling", "tethered rotorcraft"):
        assert words in titles
    assert "How to cite" in _readme() and "CITATION.cff" in _readme()


def test_docs_pages_are_under_400_lines():
    long = [f"{p.relative_to(ROOT)}: {n}" for p in sorted(DOCS.rglob("*.md"))
            if (n := len(p.read_text().splitlines())) > 400]
    assert not long, long


@pytest.mark.slow
def test_site_builds_strict_with_its_tutorials(tmp_path):
    """``make docs``'s command: strict (a warning, a missing page, link or anchor fails it), the tutorials run."""
    pytest.importorskip("mkdocs")
    pytest.importorskip("mkdocstrings")
    pytest.importorskip("stable_baselines3")  # the quick-start tutorial trains PPO
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1")
    env.pop("LADDERMILL_DOCS_TUTORIALS", None)
    t0 = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir", str(tmp_path / "site")],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=900)
    seconds = time.perf_counter() - t0
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-6000:]
    for page in ("index.html", "envs/TetheredWing-v0/index.html", "api/scenes_simulators/index.html",
                 "tutorials/simulate_and_plot/index.html", "commands/index.html", "commands/simulate/index.html"):
        assert (tmp_path / "site" / page).is_file(), page
    assert seconds < 600, f"the docs build took {seconds:.0f} s"


@pytest.mark.slow
def test_readme_figures_are_what_their_commands_print(tmp_path, capsys):
    """``make readme-figures`` (``--policies --papers``): the main job (with ppo_mill), every env's sizes,
    TetheredWing-v0's open-loop and LQR rows, the shipped policies' gusts-v1 scorecards and ppo_mill's row, and the
    Papers-reproduced rows' studies re-run (582 s at a load of 1-2 with Meijaard's searches saved; about 35 minutes
    at a load of 5-8) and compared with README and controllers.md."""
    sys.path.insert(0, str(ROOT))
    from docsite.readme_figures import main

    # main: under a quoted numeric profile where this machine's is not one (docsite/host_cpu.quoted_profile)
    status = main(["--policies", "--papers", "--out", str(tmp_path / "readme_figures.json")])
    assert status == 0, capsys.readouterr().out[-6000:]


def test_the_policy_table_check_names_a_changed_scorecard():
    """The check of README's shipped-policy table: the quoted scorecards pass, any other count is named; an LQR cell
    quoted per CPU is compared at the measuring CPU's count, and a CPU it does not name fails."""
    sys.path.insert(0, str(ROOT))
    from docsite.readme_figures import policy_differences

    readme = ("| `ppo_tethered_wing` | TetheredWing-v0 | PPO | survive gusts-v1's scenarios 10 / 12 | 11 / 12 |\n"
              "| `ppo_rotorcraft` | Rotorcraft-v0 | PPO | survive gusts-v1's scenarios 8 / 9 | 8 / 9 |\n")
    good = {"ppo_rotorcraft": [8, 8, 9], "ppo_tethered_wing": [10, 11, 12]}
    assert policy_differences(good, readme, "znver4") == []
    assert policy_differences({}, readme, "znver4") == []
    bad = policy_differences({**good, "ppo_tethered_wing": [10, 12, 12]}, readme, "znver4")
    assert len(bad) == 1 and "ppo_tethered_wing survives 10 / 12 of gusts-v1 (the LQR 12 / 12 on znver4)" in bad[0]
    assert len(policy_differences({"ppo_chain": [1, 1, 1]}, readme, "znver4")) == 1
    keyed = readme.replace("| 11 / 12 |", "| 11 / 12 on znver4, 10 / 12 on znver3 |")
    assert policy_differences(good, keyed, "znver4") == []
    assert policy_differences({**good, "ppo_tethered_wing": [10, 10, 12]}, keyed, "znver3") == []
    assert len(policy_differences(good, keyed, "znver3")) == 1  # znver3's LQR held 10, not 11
    assert len(policy_differences(good, keyed, "skylake-avx512")) == 1  # no count quoted for that CPU


def test_the_held_out_check_reads_the_measuring_cpus_counts():
    """README's held-out sentence, quoted per CPU (worked by hand): each CPU's counts pass on that CPU only."""
    sys.path.insert(0, str(ROOT))
    from docsite.readme_figures import held_out_differences

    readme = ("the wing policy survives 84, the LQR 70 (sign test p = 0.1034) on znver4; 82 and 72 (p = 0.2604) on "
              "znver3: no clear difference.")
    assert held_out_differences({"wing_held_out": [70, 84, "0.1034"], "cpu": "znver4"}, readme) == []
    assert held_out_differences({"wing_held_out": [72, 82, "0.2604"], "cpu": "znver3"}, readme) == []
    assert len(held_out_differences({"wing_held_out": [72, 82, "0.2604"], "cpu": "znver4"}, readme)) == 1
    assert len(held_out_differences({"wing_held_out": [70, 84, "0.1034"], "cpu": "znver5"}, readme)) == 1
    assert held_out_differences({"cpu": "znver4"}, readme) == []


def test_the_mill_policy_check_names_a_changed_figure():
    """The check of README's ppo_mill row and its demo sentence: the quoted figures pass, any other is named."""
    sys.path.insert(0, str(ROOT))
    from docsite.readme_figures import mill_policy_differences

    readme = ("| `ppo_mill` | LadderMill-v1 | DAgger | held 300 s after the step (seed 0: the scenario is "
              "deterministic), 0.0940 m, 154.0 kW | held, 0.0948 m, 154.0 kW | ... at 157.1 kW mean; so does "
              "`ppo_mill`, one policy shared by the 101 slots (0.09 m, 157.1 kW). ... so the base install runs it: "
              "60 s after the step, 157.1 kW, 0.09 m, as the LQR.")
    lqr = ["60.00", "157.1", "0.09", "ran to the end"]
    good = {"main_job": {"lqr": lqr, "ppo_mill": list(lqr)},
            "mill_policy": {"ppo_mill": {"policy": [1, 1, "0.0940", "154.0", True],
                                         "lqr": [1, 1, "0.0948", "154.0", True]}}}
    assert mill_policy_differences(good, readme) == []
    assert mill_policy_differences({"main_job": {"lqr": lqr}}, readme) == []
    fewer = {"ppo_mill": {**good["mill_policy"]["ppo_mill"], "policy": [0, 1, "0.0940", "154.0", True]}}
    assert len(mill_policy_differences({**good, "mill_policy": fewer}, readme)) == 1
    fell = {"lqr": lqr, "ppo_mill": ["12.00", *lqr[1:]]}
    assert len(mill_policy_differences({**good, "main_job": fell}, readme)) == 2
    chain = {"policy": [1, 1, "0.0813", "237.6", True], "lqr": [1, 1, "0.0803", "237.9", True]}
    row = ("| held 300 s after the step (seed 0: the scenario is deterministic), 0.0813 m, 237.6 kW | centralised "
           "held, 0.0803 m, 237.9 kW (the default ...) |")
    assert mill_policy_differences({**good, "mill_policy": {"ppo_chain": chain}}, readme + row) == []
    assert len(mill_policy_differences({**good, "mill_policy": {"ppo_chain": chain}}, readme)) == 1


def test_the_papers_check_names_a_changed_figure():
    """The check of README's Papers-reproduced rows: the quoted figures pass, a changed or non-periodic one is named."""
    sys.path.insert(0, str(ROOT))
    from docsite.paper_figures import papers_differences

    readme = ("periodic at 1 and 2 m/s (82.1, 153 kW, a wing) ... (323.9 kW at 5 m/s; its power curve), the loop "
              "widens with V_c, the smallest tension at the top, ... 5 km of cable at 1 cm (500,000 elements) in "
              "28.69 MB ... ([45.7 kW on 40 m elements, 0.4 % from 30 m](reeling_tether.md); the cycle "
              "0.75-0.86 of Schmehl's quasi-steady model at 10-20 m/s)")
    claims = [["the loop widens with V_c (1 -> 5 m/s)", "yes"], ["tension smallest near the top (V_c = 1 m/s)", "yes"],
              ["tension smallest near the top (V_c = 5 m/s)", "yes"]]
    good = {"meijaard_v1": {"1": [True, 82.1], "2": [True, 152.9]}, "v2_at_5": [True, 323.94],
            "meijaard_claims": claims,
            "podgaets": [500_000, 28.69], "tether_power_W": {"40": 45719.0, "30": 45880.0},
            "schmehl_ratio": {"10": 0.7486, "12": 0.80, "14": 0.83, "16": 0.85, "18": 0.8555, "20": 0.83}}
    assert papers_differences(good, readme) == []
    assert papers_differences({}, readme) == []
    for changed in ({"v2_at_5": [False, 323.9]}, {"podgaets": [500_000, 29.41]}, {"meijaard_v1": {"1": [True, 82.1],
                    "2": [True, 160.0]}}, {"tether_power_W": {"40": 45719.0, "30": 45745.0}},
                    {"schmehl_ratio": {**good["schmehl_ratio"], "8": 0.68}}):
        bad = papers_differences({**good, **changed}, readme)
        assert len(bad) == 1, (changed, bad)
    no_at_5 = {**good, "meijaard_claims": [*claims[:2], [claims[2][0], "no"]]}  # 2026-12-01's CPU: 5 m/s not at the top
    assert len(papers_differences(no_at_5, readme)) == 1
    qualified = readme.replace("at the top,", "at the top (at 1 m/s; not in 2026-12-01's chaotic 5 m/s run),")
    assert papers_differences(no_at_5, qualified) == [] and len(papers_differences(good, qualified)) == 1
    table = " stable in plane (153 kW at 2 m/s) ... periodic at 1-5 m/s (102 kW at 2 m/s, 324 kW at 5 m/s)"
    with_v2 = {**good, "v2_at_2": [True, 102.2]}
    assert papers_differences(with_v2, readme + table) == []
    assert len(papers_differences(with_v2, readme)) == 2  # the env table's rows missing
    assert len(papers_differences({**with_v2, "v2_at_2": [True, 98.0]}, readme + table)) == 1
