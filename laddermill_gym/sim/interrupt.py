"""Ctrl-C as a request to stop at the next chance, for long runs that keep what they computed.

Python raises ``KeyboardInterrupt`` at the next bytecode after the signal, which for a compiled numba call is when it
returns: anywhere in the Python around it, between updating a state and its time. Inside :func:`stop_requests` a
first Ctrl-C only sets ``requested``; the run checks it between its compiled calls (``sim/recording.record``: after
each chunk of steps), stops there with a consistent state and saves what it has. A second Ctrl-C raises
``KeyboardInterrupt`` at once. Outside the main thread (where Python delivers signals) it does nothing.
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager


class StopRequest:
    """Whether Ctrl-C was pressed (``requested``) and how often (``count``)."""

    def __init__(self):
        self.count = 0

    @property
    def requested(self) -> bool:
        return self.count > 0


@contextmanager
def stop_requests(message: str | None = None) -> Iterator[StopRequest]:
    """A :class:`StopRequest` set by the first Ctrl-C (SIGINT) inside the block; the second raises
    KeyboardInterrupt. ``message`` is printed (to stderr) at the first. The previous handler is restored after."""
    request = StopRequest()
    if threading.current_thread() is not threading.main_thread():
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
