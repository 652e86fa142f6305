"""One documentation page per registered environment id, in Gymnasium's layout, from the code itself.

The text is the env class's docstring (Description, Action Space, Observation Space, Rewards, Starting State,
Episode End, Arguments, Version History: the sections every env family writes, ARCHITECTURE.md "Adding an env
family"); around it this module adds what the registry knows: how to make it, its entry points, the defaults
registered with the id and every argument of its task with the task's own default. Nothing is typed in twice, so a
page cannot drift from the code. The pages are built when the site is built (``docsite/hooks.py``).
"""

from __future__ import annotations

import importlib
import inspect
import re

#: sections a page must carry (Gymnasium's); a docstring without one fails the build
REQUIRED = ("## Description", "## Action Space", "## Observation Space", "## Rewards", "## Starting State",
            "## Episode End", "## Arguments", "## Version History")
_ROLE = re.compile(r":(?:class|func|meth|mod|data|attr|obj|exc):`~?([\w.]+?)`")


def _roles_to_code(text: str) -> str:
    """``:class:`~a.b.C``` -> ```a.b.C``` (Sphinx roles in the docstrings are plain code on the site)."""
    return _ROLE.sub(lambda m: f"`{m.group(1)}`", text)


_SEPARATOR = re.compile(r"^\|[-:| ]+\|$")


def _escape_table_pipes(text: str) -> str:
    """In a pipe table's rows, a ``|`` without a space on both sides is text, not a cell border (as in
    ``asin(v_a / |V_a|)``): escape it so the row keeps its columns."""
    out = []
    for line in text.splitlines():
        if len(line) > 1 and line.startswith("|") and line.endswith("|") and not _SEPARATOR.match(line):
            inner = line[1:-1]
            chars = [("\\|" if c == "|" and not (0 < i < len(inner) - 1 and inner[i - 1] == " " == inner[i + 1])
                      else c) for i, c in enumerate(inner)]
            line = "|" + "".join(chars) + "|"
        out.append(line)
    return "\n".join(out)


def _cell(value) -> str:
    return "`" + repr(value).replace("|", "\\|") + "`"


def page_name(env_id: str) -> str:
    """``laddermill_gym/TetheredWing-v0`` -> ``TetheredWing-v0``."""
    return env_id.split("/", 1)[1]


def _class(entry_point: str):
    module, name = entry_point.split(":")
    return getattr(importlib.import_module(module), name)


def env_page(env_id: str) -> str:
    """The Markdown page of ``env_id``; ValueError when the env's docstring lacks one of :data:`REQUIRED`."""
    from laddermill_gym.envs import ENTRY_POINTS, ENV_IDS, task_class

    single, vector, task = ENTRY_POINTS[env_id]
    doc = inspect.cleandoc(_class(single).__doc__ or "")
    missing = [s for s in REQUIRED if s not in doc]
    if missing:
        raise ValueError(f"{single}: its docstring lacks {missing}, which the env page {env_id} needs")
    summary, _, body = doc.partition("\n\n")  # the first paragraph, however many lines it takes
    summary = " ".join(summary.split())
    registered = ENV_IDS[env_id]
    params = [p for p in inspect.signature(task_class(env_id)).parameters.values()
              if p.name not in ("n_copies", "parallel")]
    lines = [f"# {page_name(env_id)}", "", summary.strip(), "",
             "| | |", "|---|---|",
             f"| Make | `gymnasium.make(\"{env_id}\")` (after `import laddermill_gym`) |",
             f"| Batched | `gymnasium.make_vec(\"{env_id}\", n, vectorization_mode=\"vector_entry_point\")` |",
             f"| Stable-Baselines3 | `laddermill_gym.envs.sb3.sb3_vec_env(\"{env_id}\", n)` |",
             f"| Single env | `{single.replace(':', '.')}` |",
             f"| Vector env | `{vector.replace(':', '.')}` |",
             f"| Task (B copies) | `{task.replace(':', '.')}` |", "",
             _escape_table_pipes(_roles_to_code(body.strip())), "",
             "## Registered defaults", "",
             "The keyword arguments registered with the id (`laddermill_gym.envs.ENV_IDS`); "
             "`gymnasium.make(id, **kwargs)` overrides any of them.", "",
             "| argument | registered value |", "|---|---|"]
    lines += [f"| `{k}` | {_cell(v)} |" for k, v in registered.items()]
    lines += ["", "## Every argument", "",
              f"All arguments the environment takes (`laddermill_gym.envs.env_arguments(\"{env_id}\")`), with the "
              "task's default where the id registers none.", "",
              "| argument | default |", "|---|---|"]
    for p in params:
        value = registered.get(p.name, p.default)
        shown = "(required)" if value is inspect.Parameter.empty else _cell(value)
        mark = " (registered)" if p.name in registered else ""
        lines.append(f"| `{p.name}` | {shown}{mark} |")
    return "\n".join(lines) + "\n"


def index_page() -> str:
    """``envs/index.md``: the ids with their summaries and links."""
    from laddermill_gym.envs import ENTRY_POINTS, ENV_IDS

    lines = ["# Environments", "",
             "Every id is registered on `import laddermill_gym`; each has a single env, a native vector env "
             "(one compiled kernel over all copies) and a task of B copies behind both. These pages are written "
             "from the env classes' docstrings and the registry when the site is built.", "",
             "| id | what it simulates |", "|---|---|"]
    for env_id in ENV_IDS:
        doc = inspect.cleandoc(_class(ENTRY_POINTS[env_id][0]).__doc__ or "")
        lines.append(f"| [`{env_id}`]({page_name(env_id)}.md) | {' '.join(doc.partition(chr(10) * 2)[0].split())} |")
    return "\n".join(lines) + "\n"


def env_pages():
    """(src_uri, Markdown) of the index and of every registered id."""
    from laddermill_gym.envs import ENV_IDS

    yield "envs/index.md", index_page()
    for env_id in ENV_IDS:
        yield f"envs/{page_name(env_id)}.md", env_page(env_id)
