"""The on-disk cache of the mill's operating points (issue 32 point 1): LadderMill-v0/v1/v2 find their start by
running the in-plane mill for 1,000-1,400 simulated seconds (30-100 s of CPU), which every new process repeated.
Like numba's kernel cache, the result is kept on disk and read back by later processes.

The folder, the entry format and its checks are ``model/disk_cache.py``'s (``$LADDERMILL_CACHE_DIR``, else
``~/.cache/laddermill_gym``; ``off`` switches the cache off); the entries are in its ``operating_points/`` folder,
one ``.npz`` file each (a few hundred kB).

Keyed by everything the result depends on (:func:`entry_key`): the in-plane scene as loaded (every field of the
:class:`~laddermill_gym.ladder.rigid_scene.Scene` but its file's path: wings, cable, station, wind, initial settings,
integrator), the settling settings, the package version, the source of the code that computes it (:data:`SOURCE_DIRS`,
:data:`SOURCE_FILES`), the numba, numpy, scipy and Python versions, the CPU numba compiles for and the kernels numpy and
OpenBLAS choose (``disk_cache.platform_text``: their last bits differ between machines). A changed input is a new key,
so a stale entry is never looked at.

Stored: the exact float64 arrays and scalars, so a start read back is the same bits as a recomputed one.
"""

from __future__ import annotations

import hashlib
from functools import lru_cache
from pathlib import Path

from laddermill_gym.model.disk_cache import (  # noqa: F401  (the cache's public names, as before, from here)
    CACHE_VARIABLE,
    OFF,
    cache_dir,
    entry_path,
    feed,
    platform_text,
    read_entry,
    write_entry,
)

__all__ = ["CACHE_VARIABLE", "OFF", "SOURCE_DIRS", "SOURCE_FILES", "FORMAT", "cache_dir", "source_digest",
           "entry_key", "entry_path", "read_entry", "write_entry"]

#: the package's folders whose source the operating point's computation runs (the scene readers, packing,
#: simulator, kernels and the wind); every module it imports lies in these or :data:`SOURCE_FILES`
#: (tests/test_op_cache.py checks it in a fresh process)
SOURCE_DIRS = ("kernels", "sim", "ladder", "model", "atmosphere")
#: single files of the computation outside :data:`SOURCE_DIRS`
SOURCE_FILES = ("__init__.py", "envs/laddermill/operating_point.py", "envs/laddermill/op_cache.py")
#: the layout of an entry; a new layout is a new key
FORMAT = 1

#: the package's folder (source paths are relative to it)
PACKAGE = Path(__file__).resolve().parents[2]


@lru_cache(maxsize=4)
def source_digest(dirs: tuple = SOURCE_DIRS, files: tuple = SOURCE_FILES) -> str:
    """SHA-256 of the source files of a computation (path relative to the package, then content), in order: the
    package's folders ``dirs`` and single files ``files`` (default: the operating point's)."""
    h = hashlib.sha256()
    files = [PACKAGE / f for f in files]
    for d in dirs:
        files += sorted((PACKAGE / d).rglob("*.py"))
    for f in files:
        h.update(f.relative_to(PACKAGE).as_posix().encode() + b"\0")
        h.update(f.read_bytes() + b"\0")
    return h.hexdigest()


def entry_key(kind: str, *inputs, skip: tuple = ("file",), sources: tuple = (SOURCE_DIRS, SOURCE_FILES)) -> str:
    """The hex SHA-256 key of an entry of ``kind`` computed from ``inputs`` (dataclasses, arrays, numbers; fields
    named in ``skip`` left out of a dataclass at the top level), with :data:`FORMAT`, ``disk_cache.platform_text``
    and :func:`source_digest` of ``sources`` ((folders, files) of the computation; default the operating point's).
    TypeError when an input cannot be fingerprinted."""
    h = hashlib.sha256(f"{kind}; format {FORMAT}; {platform_text()}; source {source_digest(*sources)};".encode())
    for obj in inputs:
        feed(h, obj, skip)
    return h.hexdigest()


