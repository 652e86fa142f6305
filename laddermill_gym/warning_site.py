"""Where a warning about a user's input points: the user's own line, past this package's and Gymnasium's frames.

A fixed ``stacklevel`` is right for one call path only: an env's argument check runs at a different depth under
``gymnasium.make``, ``gymnasium.make_vec`` and the env class called directly, so a fixed level pointed into
Gymnasium's registration code on some paths (a review of 2026-12-08). Python 3.12's ``skip_file_prefixes`` does
this; the package supports 3.10 and 3.11 too.
"""

from __future__ import annotations

import os
import sys

__all__ = ["user_stacklevel"]

_PACKAGE = os.path.dirname(os.path.abspath(__file__))


def _skipped() -> tuple[str, ...]:
    prefixes = [_PACKAGE + os.sep]
    gymnasium = sys.modules.get("gymnasium")
    if gymnasium is not None and getattr(gymnasium, "__file__", None):
        prefixes.append(os.path.dirname(os.path.abspath(gymnasium.__file__)) + os.sep)
    return tuple(prefixes)


def user_stacklevel() -> int:
    """The ``stacklevel`` for a ``warnings.warn`` in the function that calls this one: the first frame above it
    whose file lies outside this package and Gymnasium (1 would be that function itself); the outermost frame's
    level where every frame is inside (a script run from the package)."""
    skipped = _skipped()
    frame, level = sys._getframe(1), 1
    while frame.f_back is not None and os.path.abspath(frame.f_code.co_filename).startswith(skipped):
        frame, level = frame.f_back, level + 1
    return level
