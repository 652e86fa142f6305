"""A small on-disk cache of exact float64 results (issue 32 point 1): what a start computes the same way in every
process (the mill's operating point, a wing's or craft's trim, a wing table's spline coefficients) is stored once
and read back by later processes, the same bits.

Where: ``$LADDERMILL_CACHE_DIR`` when set (:data:`CACHE_VARIABLE`), else ``$XDG_CACHE_HOME/laddermill_gym``, else
``~/.cache/laddermill_gym``; one ``.npz`` file per entry in a folder per kind, which may be deleted at any time.
``LADDERMILL_CACHE_DIR=off`` (:data:`OFF`) switches the cache off.

An entry's key is a SHA-256 its user computes from everything the result depends on (:func:`feed` fingerprints
dataclasses, arrays and numbers canonically; :func:`platform_text` names the versions, the CPU and the kernels numpy and
OpenBLAS choose). Stored: the exact arrays and scalars (``np.savez``, no pickle), written atomically (a temporary file
in the same folder, flushed to disk, then renamed). An entry is trusted only when it reads back whole, holds its own key
(the full key, not only the file name's prefix) and its payload's SHA-256 matches; anything else is recomputed and
overwritten. A folder that cannot be written gives one warning and the computation goes on uncached. A process
whose package files changed since it imported the package (``kernels.cache_guard.sources_as_imported``: an edit or an
install during a session) runs code the keys no longer describe: it neither reads nor writes entries (one warning).
"""

from __future__ import annotations

import hashlib
import os
import sys
import tempfile
import warnings
from dataclasses import fields, is_dataclass
from enum import Enum
from functools import lru_cache
from pathlib import Path

import numpy as np

from laddermill_gym.kernels.cache_guard import sources_as_imported
from laddermill_gym.model.machine import KERNEL_VARIABLES, numpy_simd_level

__all__ = ["CACHE_VARIABLE", "OFF", "cache_dir", "feed", "platform_text", "payload_digest", "entry_path",
           "read_entry", "write_entry"]

#: the environment variable naming the cache folder (or ``off``)
CACHE_VARIABLE = "LADDERMILL_CACHE_DIR"
#: the value of :data:`CACHE_VARIABLE` that switches the cache off
OFF = "off"
_WARNED: set = set()
_STALE = "the package's files changed since this process imported it"


def _code_as_imported() -> bool:
    """Whether this process's code is still the package's on disk (module doc); one warning the first time not."""
    if sources_as_imported():
        return True
    if _STALE not in _WARNED:
        _WARNED.add(_STALE)
        warnings.warn(f"{_STALE}: its results are neither read from nor written to the on-disk cache "
                      f"({cache_dir()}); start a new process to use it", RuntimeWarning, stacklevel=4)
    return False


def cache_dir() -> Path | None:
    """The cache folder (module doc), or None when :data:`CACHE_VARIABLE` is ``off``."""
    env = os.environ.get(CACHE_VARIABLE)
    if env:
        return None if env.strip().lower() == OFF else Path(env).expanduser()
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "laddermill_gym"


def feed(h, obj, skip: tuple = ()) -> None:
    """Feed ``obj`` into the hash ``h`` canonically: type tags, dataclass fields by name (those named in ``skip``
    left out at this level), sequences in order, mappings sorted by key, floats by their exact hex, arrays by
    dtype, shape and bytes. TypeError for anything else (then the entry is not cached)."""
    if obj is None or isinstance(obj, (bool, int, str, Path, Enum)):
        h.update(f"{type(obj).__name__}:{obj!r};".encode())
    elif isinstance(obj, (float, np.floating)):
        h.update(f"f:{float(obj).hex()};".encode())
    elif isinstance(obj, np.integer):
        h.update(f"i:{int(obj)};".encode())
    elif isinstance(obj, np.ndarray):
        if obj.dtype == object:
            raise TypeError("an object array")
        a = np.ascontiguousarray(obj)
        h.update(f"a:{a.dtype.str}:{a.shape};".encode() + a.tobytes())
    elif is_dataclass(obj) and not isinstance(obj, type):
        h.update(f"d:{type(obj).__module__}.{type(obj).__qualname__}(".encode())
        for f in fields(obj):
            if f.name not in skip:
                h.update(f"{f.name}=".encode())
                feed(h, getattr(obj, f.name))
        h.update(b");")
    elif isinstance(obj, (tuple, list)):
        h.update(f"s{len(obj)}(".encode())
        for v in obj:
            feed(h, v)
        h.update(b");")
    elif isinstance(obj, dict):
        h.update(f"m{len(obj)}(".encode())
        for k in sorted(obj, key=repr):
            feed(h, k)
            feed(h, obj[k])
        h.update(b");")
    else:
        raise TypeError(f"cannot fingerprint a {type(obj).__module__}.{type(obj).__qualname__}")


@lru_cache(maxsize=1)
def platform_text() -> str:
    """numba, numpy, scipy and Python versions, the host CPU, the target numba compiles for (``NUMBA_CPU_NAME`` and
    ``NUMBA_CPU_FEATURES``, the host's when unset: ``generic`` has no fused multiply-add) and its optimisation level
    (``NUMBA_OPT``), numpy's SIMD level and the variables that choose numpy's and OpenBLAS's kernels
    (:data:`KERNEL_VARIABLES`): everything on one machine that moves a start's last bits."""
    from importlib.metadata import PackageNotFoundError, version

    import llvmlite.binding as llvm
    import numba
    import numba.core.config as cfg

    try:  # the installed distribution's (the source's __version__ is in the hashed __init__.py too)
        ours = version("laddermill_gym")
    except PackageNotFoundError:
        ours = "not installed"
    kernels = ", ".join(f"{k}={os.environ.get(k, '')}" for k in KERNEL_VARIABLES)
    return (f"laddermill_gym {ours}; numba {numba.__version__}; numpy {np.__version__}; scipy {version('scipy')}; "
            f"python {sys.version_info[:3]}; cpu {llvm.get_host_cpu_name()} {llvm.get_host_cpu_features().flatten()}; "
            f"numba target {cfg.CPU_NAME or 'host'} {cfg.CPU_FEATURES or 'host'}, opt {cfg.OPT}; "
            f"numpy simd {numpy_simd_level()}; {kernels}")


def payload_digest(arrays: dict) -> str:
    h = hashlib.sha256()
    for name in sorted(arrays):
        feed(h, name)
        feed(h, np.asarray(arrays[name]))
    return h.hexdigest()


def entry_path(kind: str, label: str, key: str) -> Path | None:
    """The file of an entry: ``<cache>/<kind>s/<label>-<key[:24]>.npz`` (``label`` made file-safe); None when the
    cache is off."""
    root = cache_dir()
    if root is None:
        return None
    safe = "".join(c if c.isalnum() or c in "-_." else "_" for c in label)[-60:] or "entry"
    return root / f"{kind}s" / f"{safe}-{key[:24]}.npz"


def read_entry(path: Path | None, key: str) -> dict | None:
    """The arrays of the entry at ``path`` (name -> numpy array, scalars as 0-d arrays) if it is whole and holds
    ``key`` and a matching payload digest; None otherwise (missing, unreadable, corrupt or another key's)."""
    if path is None or not path.is_file() or not _code_as_imported():
        return None
    try:
        # numpy leaves the file open when it is not a zip archive; the file opened here is closed either way
        with open(path, "rb") as fh, np.load(fh, allow_pickle=False) as z:
            data = {k: z[k] for k in z.files}
    except Exception:  # a truncated or garbled file: numpy and zipfile raise many kinds; recompute it
        return None
    stored_key, digest = data.pop("__key__", None), data.pop("__digest__", None)
    if stored_key is None or digest is None or str(stored_key) != key or str(digest) != payload_digest(data):
        return None
    return data


def write_entry(path: Path | None, key: str, arrays: dict) -> bool:
    """Write ``arrays`` (name -> array or scalar) with ``key`` and their digest atomically to ``path``; True when
    written. A folder that cannot be written gives one RuntimeWarning naming it and False."""
    if path is None or not _code_as_imported():
        return False
    data = {k: np.asarray(v) for k, v in arrays.items()}
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.stem + ".", suffix=".tmp")
        with os.fdopen(fd, "wb") as fh:
            np.savez(fh, __key__=np.asarray(key), __digest__=np.asarray(payload_digest(data)), **data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
        return True
    except OSError as err:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)
        if str(path.parent) not in _WARNED:
            _WARNED.add(str(path.parent))
            warnings.warn(f"{CACHE_VARIABLE}: cannot write the cache entry {path} ({err}); computing without "
                          f"the on-disk cache (set {CACHE_VARIABLE} to a writable folder, or to '{OFF}')",
                          RuntimeWarning, stacklevel=3)
        return False

