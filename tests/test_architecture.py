"""The house rules of ARCHITECTURE.md ("Layers", "Rules"), checked on the source (issue 11 point 1 and 2): layers
import downward only, no import circle (lazy imports inside functions included, issue 28), no module imports
another's private name, files under 400 lines, functions under 80 unless a kernel says why, no literal state offset
outside the data contract, and every folder's ``__init__.py`` says what it may import. The oracle is the layer
table below, written from ARCHITECTURE.md."""

from __future__ import annotations

import ast
import re
from collections import defaultdict
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "laddermill_gym"

#: ARCHITECTURE.md's layers, bottom (0) to top: a module may import its own sub-package and any of a rank no higher
#: than its own. Equal ranks may import each other only one way (no cycle, checked separately).
RANK = {
    "contract": -1, "configs": 0, "kernels": 0, "atmosphere": 0,  # configs: the shipped data (a namespace package)
    "figure_files": 0,  # figures for files on their own Agg canvas; imports matplotlib only
    "warning_site": 0,  # where a warning about a user's input points; imports nothing of the package
    "model": 1,
    "reference": 2, "sim": 2,
    "ladder": 3, "rotorcraft": 3, "quasisteady": 3,
    "envs": 4,
    "control": 5, "multiagent": 5,  # multiagent: the per-wing PettingZoo env and SB3 adapter over envs' tasks
    "plotting": 6, "animation": 6, "studies": 6, "derivations": 6,
    "harness": 7,
    "cli": 8, "__main__": 8,
    "": 4,  # the package's own __init__: the public API (model, sim, ladder) and the env registration (envs)
}
#: Parts whose ``__init__.py`` names exactly what they may import (beside themselves): held to that list.
ONLY = {
    "atmosphere": {"contract"},
    "kernels": {"contract"},  # the bottom layer: the wind sampling kernels live in kernels/wind.py
    "model": {"contract", "kernels", "atmosphere", "configs"},
    "reference": {"contract", "model"},
    "sim": {"contract", "kernels", "atmosphere", "model"},
    "quasisteady": {"contract", "model", "atmosphere", "configs", "figure_files"},
    "derivations": {"model"},
}
#: studies/ by topic (issue 28): the other topics each topic may import (beside the shared modules at the top of
#: studies/ and the layers below), as its ``__init__.py`` says; the shared modules import no topic.
STUDIES = {
    "benchmarks": {"gusts"}, "mill": {"benchmarks"}, "gusts": set(), "lateral": set(), "numerics": set(),
    "pointmass": set(), "pumping": set(), "rotorcraft": {"gusts"},
}
#: A literal 3D rigid-body offset: ``13 * k`` or ``k * 13`` (not a number like 1e-13 * s).
THIRTEEN = re.compile(r"(?<![\w.+-])13\s*\*\s*[A-Za-z_(]|[\w)\]]\s*\*\s*13(?![\w.])")


def _sources(*folders):
    for folder in folders:
        for path in sorted((ROOT / folder).rglob("*.py")):
            if "__pycache__" not in path.parts and "data" not in path.relative_to(ROOT).parts[1:2]:
                yield path


def _part(module: str) -> str:
    """The top-level sub-package (or module) of ``laddermill_gym.X.Y``: 'X'; '' for the package itself; 'contract'
    for the data contract, the bottom of every layer."""
    if module.startswith("laddermill_gym.kernels.contract"):
        return "contract"
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


def _module(path: Path) -> str:
    rel = path.relative_to(ROOT).with_suffix("")
    parts = rel.parts[:-1] if rel.name == "__init__" else rel.parts
    return ".".join(parts)


def _is_module(name: str) -> bool:
    """True if ``name`` (dotted, from ``laddermill_gym``) is a module or package of the source tree."""
    base = ROOT.joinpath(*name.split("."))
    return base.with_suffix(".py").is_file() or (base / "__init__.py").is_file()


def _imports(path: Path):
    """(line, imported module, names) of every ``import`` / ``from ... import`` of laddermill_gym in the file, at any
    depth (a lazy import inside a function is still an import)."""
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("laddermill_gym"):
            yield node.lineno, node.module, [a.name for a in node.names]
        elif isinstance(node, ast.Import):
            for a in node.names:
                if a.name.startswith("laddermill_gym"):
                    yield node.lineno, a.name, []


def test_every_part_of_the_package_has_a_layer():
    parts = {_part(_module(p)) for p in _sources("laddermill_gym")}
    assert parts <= set(RANK), f"add these to RANK and to ARCHITECTURE.md's table: {sorted(parts - set(RANK))}"


def test_layers_import_downward_only_and_parts_import_each_other_one_way():
    upward, edges = [], defaultdict(set)
    for path in _sources("laddermill_gym"):
        mine = _part(_module(path))
        for line, module, names in _imports(path):
            targets = {_part(f"{module}.{n}") if _is_module(f"{module}.{n}") else _part(module) for n in names or [""]}
            for other in targets - {mine}:
                edges[mine].add(other)
                if RANK[other] > RANK[mine]:
                    upward.append(f"{path.relative_to(ROOT)}:{line} ({mine}, layer {RANK[mine]}) imports {module} "
                                  f"(layer {RANK[other]})")
    assert not upward, "\n".join(upward)
    beyond = {part: sorted(edges[part] - allowed) for part, allowed in ONLY.items() if edges[part] - allowed}
    assert not beyond, f"imports beyond what the folder's __init__ says: {beyond}"
    both_ways = sorted({tuple(sorted((a, b))) for a in edges for b in edges[a] if a in edges.get(b, ())})
    assert not both_ways, f"sub-packages importing each other: {both_ways}"


def _import_time(body):
    """The statements that run when a module is imported: its top level, including the bodies of ``if``, ``try``,
    ``with`` and class statements, but not of functions."""
    for node in body:
        yield node
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
            continue
        for field in ("body", "orelse", "finalbody", "handlers"):
            yield from _import_time(getattr(node, field, []) or [])


def _package_modules() -> dict[str, Path]:
    return {_module(p): p for p in _sources("laddermill_gym")}


def _import_graph(modules: dict[str, Path], statements=ast.walk):
    """{module: {imported module: first line}} over the package's modules, from the import statements that
    ``statements(tree)`` yields (``ast.walk``: every import, lazy ones inside functions too; ``_import_time``: those
    that run when the module is imported); ``modules``: {dotted name: file}. ``from A import B`` is an edge to
    ``A.B`` when that is a module, else to ``A``; the packages above an imported module are not edges (their
    ``__init__`` runs, but cannot import the importer back without a cycle of its own)."""
    graph: dict[str, dict[str, int]] = defaultdict(dict)
    for name, path in modules.items():
        for node in statements(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("laddermill_gym"):
                targets = [f"{node.module}.{a.name}" if f"{node.module}.{a.name}" in modules else node.module
                           for a in node.names]
            elif isinstance(node, ast.Import):
                targets = [a.name for a in node.names if a.name.startswith("laddermill_gym")]
            else:
                continue
            for target in targets:
                if target in modules and target != name:
                    graph[name].setdefault(target, node.lineno)
    return graph


def _circles(graph) -> list[str]:
    """Every import circle of ``graph`` (its strongly connected components of two or more modules, Tarjan's
    algorithm), each written as its modules and the import lines that close it, sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found = []

    def visit(m):
        index[m] = low[m] = len(index)
        stack.append(m)
        for n in graph.get(m, ()):
            if n not in index:
                visit(n)
                low[m] = min(low[m], low[n])
            elif n in stack:
                low[m] = min(low[m], index[n])
        if low[m] == index[m]:
            component = []
            while not component or component[-1] != m:
                component.append(stack.pop())
            if len(component) > 1:
                found.append(sorted(component))

    for m in sorted(graph):
        if m not in index:
            visit(m)
    short = {m: m.split(".", 1)[-1] for c in found for m in c}
    return sorted(" <-> ".join(short[m] for m in c) + ": " + ", ".join(
        f"{short[a]}:{graph[a][b]} imports {short[b]}" for a in c for b in sorted(graph[a]) if b in c)
        for c in found)


def test_no_module_level_import_cycle():
    circles = _circles(_import_graph(_package_modules(), lambda tree: _import_time(tree.body)))
    assert not circles, "import cycles when the modules load:\n" + "\n".join(circles)


def test_no_import_circle_even_through_lazy_imports():
    """An import inside a function still ties the two modules together: every import, at any depth, goes one way
    (issue 28 point 4), inside a folder as between folders."""
    circles = _circles(_import_graph(_package_modules()))
    assert not circles, "import circles (lazy imports included):\n" + "\n".join(circles)


def test_no_module_imports_a_private_name_of_another():
    found = [f"{path.relative_to(ROOT)}:{line} from {module} import {n}"
             for path in _sources("laddermill_gym", "agents", "tests")
             for line, module, names in _imports(path)
             for n in names if n.startswith("_") and not n.startswith("__")]
    found += [f"{path.relative_to(ROOT)}:{node.lineno} from {node.module} import {a.name}"
              for path in _sources("tests") for node in ast.walk(ast.parse(path.read_text()))
              if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("tests")
              for a in node.names if a.name.startswith("_")]
    found += [f"{path.relative_to(ROOT)}:{line} {name}" for path in _sources("laddermill_gym", "agents", "tests")
              for line, name in _private_attributes(path)]
    assert not found, "\n".join(found)


def _private_attributes(path: Path):
    """(line, 'alias._name') wherever a module of the package, bound to a name by an import, is asked for a private
    attribute."""
    tree = ast.parse(path.read_text())
    aliases = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            aliases |= {a.asname for a in node.names if a.name.startswith("laddermill_gym") and a.asname}
        elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith("laddermill_gym"):
            aliases |= {a.asname or a.name for a in node.names if _is_module(f"{node.module}.{a.name}")}
    for node in ast.walk(tree):
        if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in aliases
                and node.attr.startswith("_") and not node.attr.startswith("__")):
            yield node.lineno, f"{node.value.id}.{node.attr}"


def test_the_topics_of_studies_import_only_the_topics_their_init_names():
    topics = {p.parent.name for p in (PACKAGE / "studies").glob("*/__init__.py")}
    assert topics == set(STUDIES), f"studies/ topics {sorted(topics)}, STUDIES lists {sorted(STUDIES)}"
    found = []
    for path in _sources("laddermill_gym/studies"):
        rel = path.relative_to(PACKAGE / "studies").parts
        mine = rel[0] if len(rel) > 1 else None  # None: a shared module at the top of studies/
        for line, module, names in _imports(path):
            for n in names or [""]:
                parts = (f"{module}.{n}" if n else module).split(".")
                other = parts[2] if parts[:2] == ["laddermill_gym", "studies"] and len(parts) > 2 else None
                if other in STUDIES and other != mine and other not in STUDIES.get(mine, set()):
                    found.append(f"{path.relative_to(ROOT)}:{line} ({mine or 'shared'}) imports studies.{other}")
    assert not found, "\n".join(found)


def test_files_under_400_lines():
    long = [f"{p.relative_to(ROOT)}: {n}" for p in _sources("laddermill_gym", "agents", "tests")
            if (n := len(p.read_text().splitlines())) > 400]
    assert not long, long


def test_functions_under_80_lines_or_a_kernel_that_says_why():
    found = []
    for path in _sources("laddermill_gym", "agents", "tests"):
        lines = path.read_text().splitlines()
        for node in ast.walk(ast.parse("\n".join(lines))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.end_lineno - node.lineno >= 80:
                top = min([node.lineno] + [d.lineno for d in node.decorator_list])
                above = "\n".join(lines[max(0, top - 9): top - 1])
                kernel = any("njit" in ast.unparse(d) for d in node.decorator_list)
                if not (kernel and re.search(r"#.*80 lines", above)):
                    found.append(f"{path.relative_to(ROOT)}:{node.lineno} {node.name}: "
                                 f"{node.end_lineno - node.lineno + 1} lines")
    assert not found, found


def test_no_literal_rigid_body_offset_outside_the_contract():
    """A state offset of the 3D rigid body (13 entries) is written ``B3_SIZE * k``, never ``13 * k``."""
    found = [f"{p.relative_to(ROOT)}:{i}: {line.strip()}" for p in _sources("laddermill_gym", "agents")
             if p.name != "contract.py"
             for i, line in enumerate(p.read_text().splitlines(), 1)
             if THIRTEEN.search(line.split("#")[0]) and not line.lstrip().startswith(('"', "'", "``"))]
    assert not found, "\n".join(found)


@pytest.mark.parametrize("init", sorted(p.relative_to(ROOT).as_posix() for p in PACKAGE.rglob("__init__.py")
                                       if "__pycache__" not in p.parts and "configs" not in p.parts), ids=str)
def test_each_folder_says_what_lives_there_and_what_it_may_import(init):
    if init == "laddermill_gym/__init__.py":  # the package itself: its docstring is the user's first example
        return
    doc = ast.get_docstring(ast.parse((ROOT / init).read_text())) or ""
    first = doc.split("\n\n")[0]
    assert first and re.search(r"\bimport", first, re.IGNORECASE), f"{init}: say what it may import, first paragraph"


def test_the_checks_catch_what_they_look_for(tmp_path):
    """The patterns on known text: an upward lazy import, a private import, a literal offset."""
    src = tmp_path / "m.py"
    src.write_text("def f():\n    from laddermill_gym.envs.task import _hidden, WingTask\n    o = 13 * k\n")
    found = list(_imports(src))
    assert found == [(2, "laddermill_gym.envs.task", ["_hidden", "WingTask"])]
    assert _part(found[0][1]) == "envs" and RANK["envs"] > RANK["sim"]
    assert THIRTEEN.search("    o = 13 * k") and THIRTEEN.search("x = n * 13") and not THIRTEEN.search("1e-13 * s")
    src.write_text("import laddermill_gym.studies.gust_bench as gb\ntry:\n    from laddermill_gym.sim import batch\n"
                   "except ImportError:\n    pass\nprint(gb._hidden, batch._x, gb.__doc__)\n")
    assert [name for _, name in _private_attributes(src)] == ["gb._hidden", "batch._x"]
    assert sum(isinstance(n, ast.ImportFrom) for n in _import_time(ast.parse(src.read_text()).body)) == 1
    # a circle closed by a lazy import: found over every import, not over the import-time ones
    pkg = tmp_path / "laddermill_gym"
    pkg.mkdir()
    (pkg / "a.py").write_text("from laddermill_gym.b import g\n")
    (pkg / "b.py").write_text("def g():\n    from laddermill_gym import a\n    return a\n")
    (pkg / "c.py").write_text("import laddermill_gym.a\n")
    modules = {f"laddermill_gym.{m}": pkg / f"{m}.py" for m in "abc"}
    assert _circles(_import_graph(modules)) == ["a <-> b: a:1 imports b, b:2 imports a"]
    assert _circles(_import_graph(modules, lambda tree: _import_time(tree.body))) == []
    assert _circles({"x": {"y": 1}, "y": {"z": 2}, "z": {"x": 3, "w": 4}, "w": {}}) == [
        "x <-> y <-> z: x:1 imports y, y:2 imports z, z:3 imports x"]
