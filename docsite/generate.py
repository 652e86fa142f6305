"""Write the generated pages that are kept in the repository (so that they read on GitHub too): one page per env id
(``laddermill_gym/docs/envs/``) and the command reference (``laddermill_gym/docs/commands/``).

``python -m docsite.generate`` writes them; ``python -m docsite.generate --check`` (and every docs build, through
``docsite/hooks.py``) fails naming the pages that differ from what the code gives now.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "laddermill_gym" / "docs"


def generated() -> dict[Path, str]:
    """path -> content of every kept generated page."""
    from docsite.commands import commands_pages
    from docsite.env_pages import env_pages

    pages = {DOCS / uri: text for uri, text in env_pages()}
    pages.update({DOCS / uri: text for uri, text in commands_pages().items()})
    return pages


def stale() -> list[str]:
    """The kept generated pages whose file differs from what the code gives now (missing ones included)."""
    return [str(p.relative_to(ROOT)) for p, text in generated().items()
            if not p.is_file() or p.read_text() != text]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m docsite.generate", description=__doc__.split("\n\n")[0])
    p.add_argument("--check", action="store_true", help="only check; exit 1 naming the stale pages")
    args = p.parse_args(argv)
    if args.check:
        bad = stale()
        for name in bad:
            print(f"stale: {name}")
        return 1 if bad else 0
    for path, text in generated().items():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        print(f"wrote {path.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
