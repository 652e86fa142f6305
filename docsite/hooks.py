"""MkDocs hooks of the documentation site (mkdocs.yml ``hooks:``), run by ``make docs``.

* One page per registered env id (``envs/<id>.md``), written from the env class's Gymnasium-style docstring and the
  registry (``laddermill_gym.envs.ENV_IDS``, ``ENTRY_POINTS``, the task's signature): :mod:`docsite.env_pages`;
  they are kept in the repository (``python -m docsite.generate`` writes them) and the build fails when one differs
  from what the code gives now.
* The tutorials (``tutorials/*.py``) are run, each in a fresh folder with the short settings of
  :data:`docsite.tutorials.SHORT`, and each becomes a page with its code, what it printed and its figures; a
  tutorial that fails fails the build (:mod:`docsite.tutorials`). ``LADDERMILL_DOCS_TUTORIALS=0`` skips running
  them (their pages then say so) for a quick look at the text; the checked build never sets it.
* The command reference (``commands/``) from the parsers' ``--help``: :mod:`docsite.commands`, kept and checked
  the same way.
* Sphinx roles left in docstrings (``:class:`~a.b.C```) are shown as code.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from docsite.generate import stale  # noqa: E402
from docsite.tutorials import tutorial_pages  # noqa: E402

_ROLE = re.compile(r":(?:class|func|meth|mod|data|attr|obj|exc):<code>~?([\w.]+?)</code>")


def _short(match: re.Match) -> str:
    return f"<code>{match.group(1)}</code>"


def on_files(files, config):
    """Fail when a kept generated page is stale; add the tutorial pages and their figures to the site's files."""
    from mkdocs.exceptions import PluginError
    from mkdocs.structure.files import File

    bad = stale()
    if bad:
        raise PluginError(f"generated pages differ from the code: {', '.join(bad)}; run python -m docsite.generate")
    for src_uri, content in tutorial_pages():
        files.append(File.generated(config, src_uri, content=content))
    return files


def on_page_content(html, page, config, files):
    """``:class:`~x.y.Z``` as rendered from a docstring (the role name, then code) becomes plain code."""
    return _ROLE.sub(_short, html)
