"""In-process memoisation that notices an edited input file.

The envs keep what is costly to rebuild (a scene's trim, the mill's operating point, a craft's trim, the point-mass
starts) per process, keyed on the arguments: a scene's name or path and its overrides. A name or a path does not say
what the file holds, so a file edited during a session (a sweep that rewrites one YAML, a notebook) was ignored for
the rest of it. :func:`input_cache` keys on the arguments and the working directory (a relative path, or a config
name found there, names another file after a ``chdir``) and, besides, records every file the call read (the loaders
report them: :func:`note_read`, called by ``configio.read_yaml`` and ``aero_table.load_aero_table``) with the
SHA-256 of its bytes; a hit whose files have changed since is computed again. Checking costs one hash of a few
small files (tens of kB) per hit. A cached call inside another reports its files to the outer one, hit or not, so
nested caches see the same edits.
"""

from __future__ import annotations

import functools
import hashlib
import os
import threading
from collections import OrderedDict
from contextlib import contextmanager
from pathlib import Path

__all__ = ["note_read", "recorded_reads", "input_cache"]

_LOCAL = threading.local()


def note_read(path) -> None:
    """Report that a loader read the file ``path``: every recording open on this thread (:func:`recorded_reads`)
    gets its resolved path."""
    for files in getattr(_LOCAL, "open", ()):
        files.add(str(Path(path).resolve()))


@contextmanager
def recorded_reads():
    """A set that collects the files read (:func:`note_read`) on this thread while the block runs."""
    stack = _LOCAL.__dict__.setdefault("open", [])
    files: set[str] = set()
    stack.append(files)
    try:
        yield files
    finally:
        del stack[next(i for i, f in enumerate(stack) if f is files)]  # by identity: empty sets are equal


def _digest(path: str) -> str | None:
    try:
        return hashlib.sha256(Path(path).read_bytes()).hexdigest()
    except OSError:
        return None


def _cwd() -> str:
    """The working directory (relative paths and config names resolve against it first), "" where it is gone."""
    try:
        return os.getcwd()
    except OSError:
        return ""


def input_cache(maxsize: int):
    """Decorator: memoise a function of hashable arguments on them and the working directory (the ``maxsize`` most
    recently used results, as ``functools.lru_cache``), a result kept only while every file its call read holds the
    same bytes. The wrapper has ``cache_clear()``; exceptions are not cached."""

    def decorate(fn):
        entries: OrderedDict = OrderedDict()
        lock = threading.RLock()

        @functools.wraps(fn)
        def cached(*args, **kwargs):
            key = (args, tuple(sorted(kwargs.items())), _cwd())  # a relative path names another file elsewhere
            with lock:
                hit = entries.get(key)
            if hit is not None and all(_digest(f) == d for f, d in hit[1].items()):
                with lock:
                    if key in entries:
                        entries.move_to_end(key)
                for f in hit[1]:  # an outer cached call depends on them as well
                    note_read(f)
                return hit[0]
            with recorded_reads() as files:  # an outer call's recording gets them too
                value = fn(*args, **kwargs)
            with lock:
                entries[key] = (value, {f: _digest(f) for f in files})
                entries.move_to_end(key)
                while len(entries) > maxsize:
                    entries.popitem(last=False)
            return value

        cached.cache_clear = entries.clear
        return cached

    return decorate
