"""MkDocs hooks of the documentation site (mkdocs.yml ``hooks:``), run by ``make docs``.

* One page per registered env id (``envs/<id>.md``), written from the env class's Gymnasium-style docstring and the
  registry (``laddermill_gym.envs.ENV_IDS``, ``ENTRY_POINTS``, the task's signature) at every build, so a page is
  the code as it is: :mod:`docsite.env_pages`.
* The tutorials (``tutorials/*.py``) are run, each in a fresh folder with the short settings of
  :data:`docsite.tutorials.SHORT`, and each becomes a page with its code, what it printed and its figures; a
  tutorial that fails fails the build (:mod:`docsite.tutorials`). ``LADDERMILL_DOCS_TUTORIALS=0`` skips running
  them (their pages then say so) for a quick look at the text; the checked build never sets it.
* The command reference (``commands/``) from the parsers' ``--help``, the same way: :mod:`docsite.commands`.
* Sphinx roles left in docstrings (``:class:`~a.b.C```) are shown as code.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from docsite.commands import commands_pages  # noqa: E402
from docsite.env_pages import env_pages  # noqa: E402
from docsite.tutorials import tutorial_pages  # noqa: E402

_ROLE = re.compile(r":(?:class|func|meth|mod|data|attr|obj|exc):<code>~?([\w.]+?)</code>")


def _short(match: re.Match) -> str:
    return f"<code>{match.group(1)}</code>"


def on_files(files, config):
    """Add the generated pages (env pages, command reference, tutorial pages and their figures) to the site."""
    from mkdocs.structure.files import File

    pages = list(env_pages()) + list(commands_pages().items()) + list(tutorial_pages())
    for src_uri, content in pages:
        files.append(File.generated(config, src_uri, content=content))
    return files


def on_page_content(html, page, config, files):
    """``:class:`~x.y.Z``` as rendered from a docstring (the role name, then code) becomes plain code."""
    return _ROLE.sub(_short, html)
