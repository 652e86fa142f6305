"""The tutorials (``tutorials/*.py``) run by the documentation build, each becoming a page.

Each script runs as written except for the short settings below (a literal replaced on its line, so the build
stays within minutes): in a fresh temporary folder, with this interpreter, ``MPLBACKEND=Agg``. Its page shows the
script's docstring, its code as written (the full settings), what it printed with the short settings and the PNG
files it wrote. A script that exits non-zero, or a short setting whose text is no longer in its script, raises
``mkdocs.exceptions.PluginError`` and fails the build.

``LADDERMILL_DOCS_TUTORIALS=0`` skips running them (the pages then say that they were not run); ``make docs``
and the docs-build test never set it.
"""

from __future__ import annotations

import ast
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TUTORIALS = ROOT / "tutorials"

#: script name -> title, in the order of the site's navigation
ORDER = {
    "quickstart.py": "Quick start: an env, PPO for a minute, the LQR",
    "simulate_and_plot.py": "Simulate a scene and plot it",
    "linearise_with_control.py": "Linearise a scene with python-control",
    "gust_benchmark.py": "Run a gust benchmark and read its scorecard",
    "pointmass_string.py": "The point-mass string",
    "ray_sweep.py": "Scale a sweep out with Ray",
}
#: script name -> [(text on a line of the script, its replacement in the docs build)]
SHORT = {
    "quickstart.py": [("sb3_vec_env(ID, 8, seed=0)", "sb3_vec_env(ID, 1, seed=0)"), ("learn(60_000)", "learn(2_048)"),
                      ("vector_env(ID, 4, {})", "vector_env(ID, 2, {\"episode_time\": 10.0})")],
    "simulate_and_plot.py": [("T_END = 60.0", "T_END = 20.0")],
    "linearise_with_control.py": [],
    "gust_benchmark.py": [("SCENARIOS = None", "SCENARIOS = [\"direction_step\", \"EOG_IA\"]")],
    "pointmass_string.py": [("T_END = 60.0", "T_END = 20.0")],
    "ray_sweep.py": [("WINDS = [6.0, 8.0, 10.0, 12.0, 14.0]", "WINDS = [8.0, 12.0]")],
}
TIMEOUT_S = 600


def _fail(message: str):
    from mkdocs.exceptions import PluginError

    raise PluginError(message)


def shortened(name: str, source: str) -> str:
    """``source`` with the short settings of :data:`SHORT` applied (each must occur exactly once)."""
    for old, new in SHORT.get(name, []):
        if source.count(old) != 1:
            _fail(f"tutorials/{name}: the short setting {old!r} occurs {source.count(old)} times (expected once); "
                  "update docsite/tutorials.py SHORT")
        source = source.replace(old, new)
    return source


def run_tutorial(name: str) -> tuple[str, dict[str, bytes], float]:
    """Run ``tutorials/name`` with its short settings; (stdout and stderr, {png name: bytes}, seconds)."""
    source = (TUTORIALS / name).read_text()
    with tempfile.TemporaryDirectory(prefix="laddermill_tutorial_") as tmp:
        script = Path(tmp) / name
        script.write_text(shortened(name, source))
        env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=str(ROOT))
        t0 = time.perf_counter()
        try:
            proc = subprocess.run([sys.executable, str(script)], cwd=tmp, env=env, capture_output=True, text=True,
                                  timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            _fail(f"tutorials/{name} ran past {TIMEOUT_S} s")
        seconds = time.perf_counter() - t0
        output = proc.stdout + proc.stderr
        if proc.returncode != 0:
            _fail(f"tutorials/{name} failed (exit {proc.returncode}):\n{output[-4000:]}")
        figures = {p.name: p.read_bytes() for p in sorted(Path(tmp).glob("*.png"))}
    return output, figures, seconds


def _docstring(source: str) -> str:
    return ast.get_docstring(ast.parse(source)) or ""


def tutorial_page(name: str, title: str, run: bool) -> list[tuple[str, str | bytes]]:
    """(src_uri, content) of the page of ``tutorials/name`` and of the figures it wrote."""
    source = (TUTORIALS / name).read_text()
    stem = Path(name).stem
    lines = [f"# {title}", "", _docstring(source), "",
             f"The script, `tutorials/{name}`, as it is in the repository:", "",
             "```python", source.rstrip(), "```", ""]
    files: list[tuple[str, str | bytes]] = []
    if run:
        output, figures, seconds = run_tutorial(name)
        settings = "; ".join(f"`{old}` as `{new}`" for old, new in SHORT.get(name, [])) or "none"
        lines += ["## What it printed when this site was built", "",
                  f"Short settings of the docs build: {settings} ({seconds:.0f} s on the build machine).", "",
                  "```text", output.rstrip(), "```", ""]
        for png, data in figures.items():
            uri = f"tutorials/{stem}_{png}"
            files.append((uri, data))
            lines += [f"![{png}]({stem}_{png})", ""]
    else:
        lines += ["*Not run in this build (`LADDERMILL_DOCS_TUTORIALS=0`).*", ""]
    return [(f"tutorials/{stem}.md", "\n".join(lines))] + files


def tutorial_pages():
    """Every tutorial's page and figures, and the tutorials' index; the scripts are run unless
    ``LADDERMILL_DOCS_TUTORIALS=0``."""
    present = sorted(p.name for p in TUTORIALS.glob("*.py"))
    unlisted = sorted(set(present) - set(ORDER))
    if unlisted:
        _fail(f"tutorials {unlisted} are not listed in docsite/tutorials.py ORDER")
    run = os.environ.get("LADDERMILL_DOCS_TUTORIALS", "1") != "0"
    index = ["# Tutorials", "",
             "Scripts in `tutorials/` that run as written (`python tutorials/NAME.py` in the repository); the "
             "documentation build runs each with shorter settings, so a tutorial that breaks fails the build.", ""]
    pages: list[tuple[str, str | bytes]] = []
    for name, title in ORDER.items():
        pages += tutorial_page(name, title, run)
        index.append(f"* [{title}]({Path(name).stem}.md)")
    return [("tutorials/index.md", "\n".join(index) + "\n")] + pages
