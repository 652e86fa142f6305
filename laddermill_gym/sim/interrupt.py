"""Ctrl-C as a request to stop at the next chance, for long runs that keep what they computed.

Python raises ``KeyboardInterrupt`` at the next bytecode after the signal, which for a compiled numba call is when it
returns: anywhere in the Python around it, between updating a state and its time. Inside :func:`stop_requests` a
first Ctrl-C only sets ``requested``; the run checks it between its compiled calls (``sim/recording.record``: after
each chunk of steps), stops there with a consistent state and saves what it has. A second Ctrl-C raises
``KeyboardInterrupt`` at once. Outside the main thread (where Python delivers signals) the signal does not reach it.

A worker process of a batch (``studies/parallel``) hears its caller instead of the terminal: the terminal's Ctrl-C
reaches every process of its process group, local workers included, and the caller alone decides what it means
(:func:`ignore_terminal_interrupts`; from the worker's first instruction on: :func:`children_ignore_interrupts`). The
caller's stop reaches the worker's open blocks, in whichever thread they run, through :func:`request_stop`.
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["StopRequest", "stop_requests", "request_stop", "ignore_terminal_interrupts", "children_ignore_interrupts"]

# The requests of the stop_requests blocks open now (any thread); whether request_stop was called (a block opened
# after it starts requested); whether SIGINT is this process's to handle (False in a batch's worker).
_OPEN: list = []
_LOCK = threading.Lock()
_PROCESS = {"stopped": False, "terminal": True}


class StopRequest:
    """Whether Ctrl-C was pressed (``requested``) and how often (``count``)."""

    def __init__(self):
        self.count = 0

    @property
    def requested(self) -> bool:
        return self.count > 0


def request_stop() -> int:
    """Ask this process's open :func:`stop_requests` blocks to stop, as a first Ctrl-C does there, and every block
    opened later to start stopped (a batch's worker whose caller was interrupted: its next task ends at its first
    check). Returns the number of open blocks asked."""
    with _LOCK:
        _PROCESS["stopped"] = True
        for request in _OPEN:
            request.count = max(request.count, 1)
        return len(_OPEN)


def ignore_terminal_interrupts() -> None:
    """Make this process deaf to SIGINT (a batch's worker: the terminal's Ctrl-C is its caller's to handle, and the
    caller passes a stop on through :func:`request_stop`); :func:`stop_requests` then installs no handler. Called in
    the main thread; elsewhere only the handlers of later blocks are skipped."""
    _PROCESS["terminal"] = False
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)


@contextmanager
def children_ignore_interrupts() -> Iterator[None]:
    """SIGINT ignored in this process while the block starts child processes: a child inherits the ignoring and keeps
    it from its first instruction on (Python installs its KeyboardInterrupt handler only where SIGINT is not ignored),
    so a Ctrl-C while it imports cannot kill it. A Ctrl-C pressed inside the block itself (milliseconds per child
    started) is lost. Only in the main thread; elsewhere it does nothing."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


@contextmanager
def stop_requests(message: str | None = None) -> Iterator[StopRequest]:
    """A :class:`StopRequest` set by the first Ctrl-C (SIGINT) inside the block, or by :func:`request_stop`; the second
    Ctrl-C raises KeyboardInterrupt. ``message`` is printed (to stderr) at the first Ctrl-C. The previous handler is
    restored after."""
    request = StopRequest()
    with _LOCK:
        request.count = int(_PROCESS["stopped"])
        _OPEN.append(request)
    try:
        if not _PROCESS["terminal"] or threading.current_thread() is not threading.main_thread():
            yield request
            return

        def handler(signum, frame):
            request.count += 1
            if request.count > 1:
                raise KeyboardInterrupt
            if message:
                import sys

                print(message, file=sys.stderr, flush=True)

        previous = signal.signal(signal.SIGINT, handler)
        try:
            yield request
        finally:
            signal.signal(signal.SIGINT, previous)
    finally:
        with _LOCK:
            _OPEN.remove(request)
