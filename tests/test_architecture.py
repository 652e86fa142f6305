"""The house rules of ARCHITECTURE.md ("Layers", "Rules"), checked on the source (issue 11 point 1 and 2): layers
import downward only, no import cycles, no module imports another's private name, files under 400 lines, functions
under 80 unless a kernel says why, no literal state offset outside the data contract, and every folder's
``__init__.py`` says what it may import. The oracle is the layer table below, written from ARCHITECTURE.md."""

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
    "model": 1,
    "reference": 2, "sim": 2,
    "ladder": 3, "rotorcraft": 3, "quasisteady": 3,
    "envs": 4,
    "control": 5,
    "plotting": 6, "animation": 6, "studies": 6, "derivations": 6,
    "harness": 7,
    "cli": 8, "__main__": 8,
    "": 4,  # the package's own __init__: the public API (model, sim, ladder) and the env registration (envs)
}


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
    both_ways = sorted({tuple(sorted((a, b))) for a in edges for b in edges[a] if a in edges.get(b, ())})
    assert not both_ways, f"sub-packages importing each other: {both_ways}"


def test_no_module_level_import_cycle():
    graph = defaultdict(set)
    modules = {_module(p): p for p in _sources("laddermill_gym")}
    for name, path in modules.items():
        for node in ast.parse(path.read_text()).body:  # module level only: a function's import runs later
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("laddermill_gym"):
                for a in node.names:
                    full = f"{node.module}.{a.name}"
                    graph[name].add(full if full in modules else node.module)
    state: dict[str, int] = {}

    def visit(m, stack):
        state[m] = 1
        for n in graph.get(m, ()):
            if n == m or n not in modules:
                continue
            if state.get(n) == 1:
                raise AssertionError(f"import cycle: {' -> '.join(stack[stack.index(n):] + [n])}")
            if n not in state:
                visit(n, stack + [n])
        state[m] = 2

    for m in modules:
        if m not in state:
            visit(m, [m])


def test_no_module_imports_a_private_name_of_another():
    found = [f"{path.relative_to(ROOT)}:{line} from {module} import {n}"
             for path in _sources("laddermill_gym", "agents", "tests")
             for line, module, names in _imports(path)
             for n in names if n.startswith("_") and not n.startswith("__")]
    found += [f"{path.relative_to(ROOT)}:{node.lineno} from {node.module} import {a.name}"
              for path in _sources("tests") for node in ast.walk(ast.parse(path.read_text()))
              if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("tests")
              for a in node.names if a.name.startswith("_")]
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
    pattern = re.compile(r"(?<![\w.+-])13\s*\*\s*[A-Za-z_(]|[\w)\]]\s*\*\s*13(?![\w.])")
    found = [f"{p.relative_to(ROOT)}:{i}: {line.strip()}" for p in _sources("laddermill_gym", "agents")
             if p.name != "contract.py"
             for i, line in enumerate(p.read_text().splitlines(), 1)
             if pattern.search(line.split("#")[0]) and not line.lstrip().startswith(('"', "'", "``"))]
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
    pattern = re.compile(r"(?<![\w.+-])13\s*\*\s*[A-Za-z_(]|[\w)\]]\s*\*\s*13(?![\w.])")
    assert pattern.search("    o = 13 * k") and pattern.search("x = n * 13") and not pattern.search("1e-13 * s")
