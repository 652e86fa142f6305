"""Keep numba's on-disk cache from serving machine code compiled from other sources.

numba keys a cached function by the source of the file that defines it (its SHA-256) and by its signature, not by
the files its callees and global constants come from. When ``kernels/rigid/rosenbrock.py`` changes and
``kernels/rigid/observe.py`` does not (a ``git pull``, or a new release installed over an old one: pip removes the
package's files, not numba's ``*.nbi`` / ``*.nbc`` beside them), the step kernel compiled into observe.py's cache
entries still holds the old Rosenbrock code, and results differ from a fresh process's in the last bits or more.
The brief asks for bit-identical results whatever the state of numba's cache, so :func:`guard` runs once at
``import laddermill_gym``, before any kernel is called:

1. :func:`kernel_sources` finds the package's files a compiled kernel can depend on: those that define cached
   kernels (``cache=True``) and, transitively, the package modules they import (callees, slot constants and
   parameters frozen into the machine code);
2. :func:`sources_digest` hashes their paths and contents (SHA-256), with numba's settings that its own index
   does not key on (:func:`codegen_settings`: the optimisation level);
3. in the folder numba caches each of those files in (under ``NUMBA_CACHE_DIR``, else beside the source, else
   numba's user-wide folder: numba's order), a stamp file holds the digest the entries there were compiled under;
   where it differs, the folder's ``*.nbi`` / ``*.nbc`` files are removed first and the stamp is written after
   (atomically), so a process never sees a new stamp beside old entries;
4. every index numba writes or reads for a file of the package carries that digest as this process computed it
   (:func:`install_locators`: numba's cache locators, whose source stamp, the file's mtime and size, gets the digest
   beside it). A process that imported the package before its sources were edited still compiles the old code; its
   entries now carry the old digest, so a process of the new sources finds them stale instead of loading them (and
   the other way round), though both share the folder and its stamp.

The digests are taken when the guard runs, at ``import laddermill_gym``; a module of the package first imported after
an edit runs the edited code under the digest taken before it (the package's kernel modules are imported with it).
:func:`sources_as_imported` tells whether the package's files still hold the bytes they held then: the on-disk caches
of starts and operating points (``model/disk_cache.py``) neither read nor write while they do not.

A removed entry only costs its recompilation. A folder that cannot be written is left alone (numba does not cache
there either). Switch off with ``LADDERMILL_CACHE_GUARD=off`` (then numba's own rules apply).
"""

from __future__ import annotations

import hashlib
import os
import re
import tempfile
from pathlib import Path

__all__ = ["STAMP_NAME", "SWITCH", "guard", "kernel_sources", "sources_digest", "stamp_digest",
           "codegen_settings", "cache_folders", "package_digest", "sources_as_imported", "install_locators"]

#: the stamp file written into each cache folder
STAMP_NAME = "laddermill_gym_sources.sha256"
#: environment variable that switches the guard off (value ``off``)
SWITCH = "LADDERMILL_CACHE_GUARD"
_IMPORT = r"^\s*(?:from\s+{0}((?:\.\w+)*)\s+import\s+(\([^)]*\)|[^\n]*)|import\s+{0}((?:\.\w+)+))"
_PACKAGE = Path(__file__).resolve().parent.parent
#: package root -> the stamp digest of its kernel sources when the guard ran in this process (numba's index stamps)
_STAMPS: dict[Path, str] = {}
#: package root -> :func:`package_digest` when the guard ran in this process
_IMPORTED: dict[Path, str] = {}


def _module_index(root: Path, paths) -> dict[str, Path]:
    """Dotted module name (relative to ``root``) -> file, of the package's ``paths``: a module ``a/b.py`` is
    ``a.b``, a package ``a/b/__init__.py`` is ``a.b`` too unless ``a/b.py`` exists (that one is found first). A
    lookup here replaces a filesystem test per imported name (about 2,000 of them; 20 ms of every start)."""
    index: dict[str, Path] = {}
    for path in paths:
        parts = path.relative_to(root).parts
        package = parts[-1] == "__init__.py"
        dotted = ".".join(parts[:-1] if package else (*parts[:-1], parts[-1][:-3]))
        if dotted and (not package or dotted not in index):
            index[dotted] = path
    return index


def _imported_files(index: dict[str, Path], match: re.Match) -> list[Path]:
    """The package files one import statement reads: the module named after ``from`` and every imported name that
    is a submodule of it (``from pkg.kernels import contract``), or the module of ``import pkg.x.y``."""
    if match.group(3) is not None:
        dotted = [match.group(3).lstrip(".")]
    else:
        base = match.group(1).lstrip(".")
        names = re.findall(r"\w+", match.group(2).split("#")[0])
        dotted = [base] + [f"{base}.{name}" if base else name for name in names]
    return [index[d] for d in dotted if d in index]


def _read_sources(root: Path) -> dict[Path, bytes]:
    """The package's ``.py`` files at ``root`` and their bytes, sorted by path (read once per guard)."""
    return {p: p.read_bytes() for p in sorted(root.rglob("*.py"))}


def kernel_sources(root: Path = _PACKAGE, data: dict[Path, bytes] | None = None) -> list[Path]:
    """The package's files (sorted) that define cached kernels, closed under the package imports they make
    (``data``: the files' bytes as :func:`_read_sources` gives them, else read here)."""
    data = _read_sources(root) if data is None else data
    texts = {p: b.decode("utf-8", errors="replace") for p, b in data.items()}
    index = _module_index(root, texts)
    imports = re.compile(_IMPORT.format(re.escape(root.name)), re.M)
    todo = [p for p, text in texts.items() if "cache=True" in text]
    found: set[Path] = set()
    while todo:
        path = todo.pop()
        if path in found:
            continue
        found.add(path)
        for match in imports.finditer(texts.get(path, "")):
            todo.extend(_imported_files(index, match))
    return sorted(found)


def sources_digest(paths: list[Path], root: Path = _PACKAGE, data: dict[Path, bytes] | None = None) -> str:
    """SHA-256 (hex) of the files' paths relative to ``root`` and their bytes (from ``data`` where it holds them),
    in the given order."""
    digest = hashlib.sha256()
    for path in paths:
        digest.update(path.relative_to(root).as_posix().encode() + b"\0")
        data_ = data[path] if data is not None and path in data else path.read_bytes()
        digest.update(len(data_).to_bytes(8, "little") + data_)
    return digest.hexdigest()


def stamp_digest(paths: list[Path], root: Path = _PACKAGE, data: dict[Path, bytes] | None = None) -> str:
    """The stamp a cache folder's entries were compiled under: SHA-256 (hex) of :func:`sources_digest` and
    :func:`codegen_settings`."""
    return hashlib.sha256(f"{sources_digest(paths, root, data)} {codegen_settings()}".encode()).hexdigest()


def codegen_settings() -> str:
    """numba's code-generation settings that numba's own cache index does not key on (its optimisation level,
    ``NUMBA_OPT``; the target CPU it keys itself): entries compiled under others are removed like stale sources."""
    from numba.core import config

    return f"opt {int(config.OPT)}"


def _writable(folder: Path) -> bool:
    """Whether ``folder`` exists or can be made, and a file can be written in it (numba's own test)."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
        tempfile.TemporaryFile(dir=folder).close()
    except OSError:
        return False
    return True


def cache_folders(paths: list[Path]) -> list[Path]:
    """The folder numba caches each file's functions in, in numba's order of choice: under ``NUMBA_CACHE_DIR`` when
    it is set, else ``__pycache__`` beside the file when it can be written, else numba's user-wide cache folder
    (numba's naming of the per-folder subpath). The folders are made (numba would make them at the first save)."""
    from numba.core import caching, config
    from numba.misc.appdirs import AppDirs

    folders = set()
    for source_dir in sorted({path.parent for path in paths}):
        sub = caching.UserProvidedCacheLocator.get_suitable_cache_subpath(str(source_dir / "__init__.py"))
        if config.CACHE_DIR:
            candidates = [Path(config.CACHE_DIR) / sub]
        else:
            user_wide = Path(AppDirs(appname="numba", appauthor=False).user_cache_dir) / sub
            candidates = [source_dir / "__pycache__", user_wide]
        chosen = next((c for c in candidates if _writable(c)), None)
        if chosen is not None:
            folders.add(chosen)
    return sorted(folders)


def _refresh(folder: Path, digest: str) -> bool:
    """Remove the folder's numba entries when its stamp is not ``digest`` and write the stamp; whether removed."""
    stamp = folder / STAMP_NAME
    try:
        if stamp.read_text().strip() == digest:
            return False
    except OSError:
        pass
    removed = False
    for entry in list(folder.glob("*.nbi")) + list(folder.glob("*.nbc")):
        try:
            entry.unlink()
            removed = True
        except FileNotFoundError:  # another process removed it first
            pass
    fd, tmp = tempfile.mkstemp(dir=folder, prefix=".stamp")
    with os.fdopen(fd, "w") as f:
        f.write(digest + "\n")
    os.replace(tmp, stamp)
    return removed


def guard(root: Path = _PACKAGE) -> list[Path]:
    """Apply the rule above once to the package at ``root``; the folders whose entries were removed (empty when
    switched off)."""
    root = root.resolve()
    data = _read_sources(root)
    _IMPORTED[root] = sources_digest(list(data), root, data)  # package_digest, from the same read
    if os.environ.get(SWITCH, "").strip().lower() == "off":
        return []
    sources = kernel_sources(root, data)
    digest = stamp_digest(sources, root, data)
    _STAMPS[root] = digest
    install_locators()
    removed = []
    for folder in cache_folders(sources):
        try:
            if _refresh(folder, digest):
                removed.append(folder)
        except OSError:  # a folder that vanished or cannot be written: numba cannot cache there either
            continue
    return removed


def package_digest(root: Path = _PACKAGE) -> str:
    """SHA-256 (hex) of every ``.py`` file of the package at ``root`` (sorted; path and bytes, as
    :func:`sources_digest`)."""
    return sources_digest(sorted(root.rglob("*.py")), root)


def sources_as_imported(root: Path = _PACKAGE) -> bool:
    """Whether the package's ``.py`` files hold the bytes they held when the guard ran in this process (at ``import
    laddermill_gym``; True for a root the guard never ran on). About 8 ms: for the writes and reads of computed
    entries, not per step."""
    before = _IMPORTED.get(root.resolve())
    return before is None or package_digest(root) == before


def _root_of(py_file: str) -> Path | None:
    """The guarded package root ``py_file`` lies in, if any."""
    path = Path(py_file).resolve()
    return next((root for root in _STAMPS if path.is_relative_to(root)), None)


class _ImportStamp:
    """numba cache-locator mixin for the guarded packages' files: the index's source stamp is numba's own (the
    file's mtime and size) with the kernel sources' digest as the guard computed it in this process, so entries
    compiled from other sources of the package (another process's, before or after an edit) read as stale. Files
    outside the guarded packages are left to numba's own locators (``from_function`` returns None)."""

    _root: Path | None = None

    @classmethod
    def from_function(cls, py_func, py_file):
        root = _root_of(py_file)
        if root is None:
            return None
        self = super().from_function(py_func, py_file)
        if self is not None:
            self._root = root
        return self

    def get_source_stamp(self):
        return super().get_source_stamp(), _STAMPS[self._root]


def install_locators() -> None:
    """Put :class:`_ImportStamp` versions of numba's three file-backed locators (``NUMBA_CACHE_DIR``, beside the
    source, user-wide: numba's order) before numba's own, once per process. numba reads its locator list when a
    cached function is defined, so this runs before the package's kernels are imported. A list given by
    ``NUMBA_CACHE_LOCATOR_CLASSES`` replaces numba's and this one: numba's own rules then apply."""
    from numba.core import caching

    classes = caching.CacheImpl._locator_classes
    if any(issubclass(c, _ImportStamp) for c in classes):
        return
    bases = (caching.UserProvidedCacheLocator, caching.InTreeCacheLocator, caching.UserWideCacheLocator)
    classes[:0] = [type(f"ImportStamped{b.__name__}", (_ImportStamp, b), {}) for b in bases]
