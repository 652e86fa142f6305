"""The command reference page (``commands.md``): ``laddermill --help`` and every command's ``--help``, captured
from the parsers themselves when the site is built, so the page is the command line as it is."""

from __future__ import annotations

import contextlib
import io
import os


def _help(argv: list[str]) -> str:
    """What ``laddermill ARGV`` prints, at a fixed width of 110 columns (argparse reads ``COLUMNS``)."""
    from laddermill_gym.cli import main

    saved = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = "110"
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        try:
            main(argv)
        except SystemExit:
            pass
        finally:
            if saved is None:
                del os.environ["COLUMNS"]
            else:
                os.environ["COLUMNS"] = saved
    return out.getvalue().rstrip()


def _descriptions(top: str) -> dict[str, str]:
    """command -> its one-line help, read from the top-level ``--help`` (argparse's layout: the name indented by
    4, its text after it or on the next lines, continuation lines indented further)."""
    out: dict[str, str] = {}
    current = None
    for line in top.split("positional arguments:", 1)[1].split("options:", 1)[0].splitlines():
        if line.startswith("    ") and not line.startswith("     ") and not line.strip().startswith("{"):
            name, _, text = line.strip().partition(" ")
            current = name
            out[name] = text.strip()
        elif current and line.strip():
            out[current] = (out[current] + " " + line.strip()).strip()
    return out


def commands_pages() -> dict[str, str]:
    """Markdown pages: ``commands/index.md`` (the overview table and ``laddermill --help``) and
    ``commands/<name>.md`` (each command's ``--help``)."""
    from laddermill_gym.cli import FORWARDED

    top = _help(["--help"])
    names = [n for n in top.split("{", 1)[1].split("}", 1)[0].split(",")]
    lines = ["# Command reference", "",
             "`laddermill COMMAND ...` (or `python -m laddermill_gym COMMAND ...`). These pages are the parsers' own "
             "`--help`, captured when this site was built; worked examples with their measured outputs are in "
             "[the command line](../command_line.md).", "",
             "| command | what it does | module |", "|---|---|---|"]
    described = _descriptions(top)
    for n in names:
        module = FORWARDED.get(n, ("laddermill_gym.cli", ""))[0]
        lines.append(f"| [`{n}`]({n}.md) | {described.get(n, '')} | `{module}` |")
    lines += ["", "## laddermill --help", "", "```text", top, "```", ""]
    pages = {"commands/index.md": "\n".join(lines)}
    for n in names:
        pages[f"commands/{n}.md"] = "\n".join([f"# laddermill {n}", "", described.get(n, ""), "", "```text",
                                               _help([n, "--help"]), "```", ""])
    return pages
