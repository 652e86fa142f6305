"""kernels/cache_guard: numba's on-disk entries compiled from other sources are not served.

The oracle is numba itself in fresh processes: a cached kernel whose callee lives in another file returns the old
callee's value after that file changes (numba keys an entry by the defining file's source only), and returns the
new value once the guard has run; plus hand-known import closures."""

import os
import subprocess
import sys
import textwrap

import pytest

from laddermill_gym.kernels import cache_guard

CALLER = """
from numba import njit
from pkgx.callee import value

@njit(cache=True)
def outer():
    return value() + 0.5
"""
CALLEE = """
from numba import njit

@njit(cache=True)
def value():
    return {}
"""
RUN = """
import sys
from pathlib import Path
sys.path.insert(0, {root!r})
if {guarded}:
    from laddermill_gym.kernels.cache_guard import guard
    guard(Path({root!r}) / "pkgx")
from pkgx.caller import outer
print(outer())
"""


def _package(tmp_path, callee_value):
    pkg = tmp_path / "pkgx"
    pkg.mkdir(exist_ok=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "caller.py").write_text(CALLER)
    (pkg / "callee.py").write_text(CALLEE.format(callee_value))
    (pkg / "unrelated.py").write_text("X = 1\n")
    return pkg


def _run(tmp_path, guarded, **env_vars):
    # no .pyc: Python's bytecode cache is keyed by the source's mtime in whole seconds and its size, so a callee
    # rewritten within the second of the first run (same size) would be read from the stale .pyc (CI saw it once)
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "NUMBA_CACHE_DIR": "", "PYTHONDONTWRITEBYTECODE": "1",
           **env_vars}
    code = textwrap.dedent(RUN.format(root=str(tmp_path), guarded=guarded))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True)
    return float(out.stdout.strip().splitlines()[-1])


def test_closure_follows_package_imports_from_cached_kernels(tmp_path):
    pkg = _package(tmp_path, 1.0)
    assert cache_guard.kernel_sources(pkg) == [pkg / "callee.py", pkg / "caller.py"]


def test_a_changed_callee_is_recompiled_only_with_the_guard(tmp_path):
    pkg = _package(tmp_path, 1.0)
    assert _run(tmp_path, guarded=False) == 1.5
    (pkg / "callee.py").write_text(CALLEE.format(2.0))
    assert _run(tmp_path, guarded=False) == 1.5  # numba alone: the stale entry (the bug the guard exists for)
    assert _run(tmp_path, guarded=True) == 2.5
    assert _run(tmp_path, guarded=True) == 2.5  # the stamp now matches: entries kept and loaded
    stamps = list(pkg.glob("__pycache__/" + cache_guard.STAMP_NAME))
    digest = cache_guard.stamp_digest(cache_guard.kernel_sources(pkg), pkg)
    assert [s.read_text().strip() for s in stamps] == [digest]
    assert list(pkg.glob("__pycache__/*.nbi"))  # compiled entries kept beside the matching stamp


def test_unchanged_sources_keep_their_entries(tmp_path):
    pkg = _package(tmp_path, 3.0)
    assert _run(tmp_path, guarded=True) == 3.5
    entries = sorted(p.name for p in pkg.glob("__pycache__/*.nb*"))
    assert entries
    assert cache_guard.guard(pkg) == []
    assert sorted(p.name for p in pkg.glob("__pycache__/*.nb*")) == entries


def test_entries_compiled_at_another_optimisation_level_are_removed(tmp_path):
    """numba's index keys an entry on its source, signature and CPU, not on ``NUMBA_OPT``: a process at another
    level would load the other level's machine code (another bits' source, a review of 2026-12-07). Both runs cache
    under their own ``NUMBA_CACHE_DIR``: the package's own guard runs at import too, and at another level it would
    empty the shared cache of every other test."""
    pkg = _package(tmp_path, 1.0)
    cache = tmp_path / "numba"
    assert _run(tmp_path, guarded=True, NUMBA_CACHE_DIR=str(cache)) == 1.5
    entries = [p for p in cache.rglob("*.nbc") if "pkgx" in str(p.parent)]
    before = {p: p.stat().st_mtime_ns for p in entries}
    assert _run(tmp_path, guarded=True, NUMBA_CACHE_DIR=str(cache), NUMBA_OPT="0") == 1.5
    assert before and all(not p.exists() or p.stat().st_mtime_ns != t for p, t in before.items())  # removed
    stamp = entries[0].parent / cache_guard.STAMP_NAME
    assert stamp.read_text().strip() != cache_guard.stamp_digest(cache_guard.kernel_sources(pkg), pkg)  # level 3 here


LONG_LIVED = """
import sys
from pathlib import Path
sys.path.insert(0, {root!r})
from laddermill_gym.kernels.cache_guard import guard
guard(Path({root!r}) / "pkgx")
from pkgx.caller import outer
print("imported", flush=True)
sys.stdin.readline()  # the test edits the callee and runs a process of the new sources meanwhile
print(outer())
"""


def test_a_process_older_than_an_edit_does_not_serve_its_old_code(tmp_path):
    """A process that imported the package before its callee was edited compiles the old code after a process of the
    new sources has stamped the folder: numba alone (the index stamp is the caller file's mtime and size) would then
    serve its old machine code to every later process. The index now carries the sources' digest of the process
    that wrote it, so the later process recompiles (a review of 2026-12-07)."""
    pkg = _package(tmp_path, 1.0)
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "NUMBA_CACHE_DIR": "", "PYTHONDONTWRITEBYTECODE": "1"}
    old = subprocess.Popen([sys.executable, "-c", textwrap.dedent(LONG_LIVED.format(root=str(tmp_path)))],
                           stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    try:
        assert old.stdout.readline().strip() == "imported"  # the old sources are loaded, nothing compiled yet
        (pkg / "callee.py").write_text(CALLEE.format(2.0))
        assert _run(tmp_path, guarded=True) == 2.5  # a process of the new sources stamps the folder and caches
        out, err = old.communicate("go\n", timeout=120)
    finally:
        if old.poll() is None:
            old.kill()
    assert float(out.strip().splitlines()[-1]) == 1.5, err  # the old process runs (and caches) its old code
    assert _run(tmp_path, guarded=True) == 2.5  # numba alone served 1.5 here
    assert _run(tmp_path, guarded=True) == 2.5


def test_the_locators_stamp_only_the_guarded_packages_files(tmp_path):
    """numba's own locators keep every file outside a guarded package (a user's kernels are cached as numba does)."""
    from numba.core import caching

    if os.environ.get(cache_guard.SWITCH, "").strip().lower() == "off":  # the guard stamps nothing in this process
        pytest.skip(f"{cache_guard.SWITCH}=off: this process runs numba's own locators (the guard's subprocess tests "
                    "above switch it on themselves)")

    cache_guard.install_locators()
    classes = caching.CacheImpl._locator_classes
    ours = [c for c in classes if c.__name__.startswith("ImportStamped")]
    assert [c.__name__ for c in ours] == ["ImportStampedUserProvidedCacheLocator", "ImportStampedInTreeCacheLocator",
                                          "ImportStampedUserWideCacheLocator"]
    cache_guard.install_locators()
    assert [c for c in caching.CacheImpl._locator_classes if c.__name__.startswith("ImportStamped")] == ours
    outside = tmp_path / "user_kernels.py"
    outside.write_text("def f():\n    return 1\n")
    assert all(c.from_function(None, str(outside)) is None for c in ours)
    from laddermill_gym.kernels import small

    fn = small.quat_rotation.py_func
    loc = next(c.from_function(fn, small.__file__) for c in ours if c.from_function(fn, small.__file__) is not None)
    stamp = loc.get_source_stamp()
    assert stamp[1] == cache_guard.stamp_digest(cache_guard.kernel_sources())
    assert stamp[0] == caching.InTreeCacheLocator(fn, small.__file__).get_source_stamp()


def test_disk_cache_entries_are_neither_read_nor_written_by_code_older_than_the_files(tmp_path, monkeypatch):
    """model/disk_cache: a process whose package files changed since it imported them does not use the cache."""
    import warnings

    import numpy as np

    from laddermill_gym.model import disk_cache

    monkeypatch.setenv(disk_cache.CACHE_VARIABLE, str(tmp_path / "cache"))
    path = disk_cache.entry_path("probe", "x", "k" * 64)
    assert disk_cache.write_entry(path, "k" * 64, {"a": np.arange(3.0)})
    assert disk_cache.read_entry(path, "k" * 64)["a"].tolist() == [0.0, 1.0, 2.0]
    monkeypatch.setattr(cache_guard, "package_digest", lambda root=None: "another")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert disk_cache.read_entry(path, "k" * 64) is None
        assert disk_cache.write_entry(path, "k" * 64, {"a": np.arange(4.0)}) is False
    assert len(np.load(path)["a"]) == 3  # untouched
    assert sum("changed since this process imported it" in str(w.message) for w in caught) <= 1
