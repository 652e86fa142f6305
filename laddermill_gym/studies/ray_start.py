"""Joining or starting the Ray cluster of a :class:`~laddermill_gym.studies.parallel.Pool` (``--ray``), and the
actors' start: an address that does not answer is refused in seconds, and an actor gets tasks only once it has
started.

Ray's ``ray.init(address=HOST:PORT)`` retries an address that does not answer without end (a review of 2026-12-07
saw it retry for four minutes), so :func:`probe` first opens a plain TCP connection to the address's host and port.
An actor that waits for a CPU (other jobs hold the cluster's) cannot run a task given to it, so the pool asks each
actor's ``ready`` first and hands tasks only to the actors that answered (:class:`Starting`).
"""

from __future__ import annotations

import os
import socket
import time
import warnings

__all__ = ["PROBE_TIMEOUT_S", "SLOW_START_S", "probe", "Starting"]

#: how long a cluster address may take to accept a TCP connection [s]
PROBE_TIMEOUT_S = 5.0
#: after this long [s] with tasks waiting and no actor started, the pool warns that the cluster's CPUs are taken
SLOW_START_S = 60.0


def probe(address: str) -> None:
    """Refuse (UsageError naming ``--ray`` and the value) a cluster address whose host and port do not accept a TCP
    connection within :data:`PROBE_TIMEOUT_S`: ``HOST:PORT``, ``ray://HOST:PORT``, or for ``auto`` the address in
    ``RAY_ADDRESS`` when one is set. ``local``, a bare ``auto`` (Ray itself says at once that no cluster runs) and an
    address without a port are left to Ray."""
    from laddermill_gym.studies.commands import UsageError

    target = os.environ.get("RAY_ADDRESS", "") if address == "auto" else address
    text = target.removeprefix("ray://")
    host, sep, port = text.rpartition(":")
    if target in ("", "local", "auto") or not sep or not port.isdigit():
        return
    try:
        with socket.create_connection((host.strip("[]") or "127.0.0.1", int(port)), timeout=PROBE_TIMEOUT_S):
            pass
    except OSError as err:
        where = f" (RAY_ADDRESS={target})" if address == "auto" else ""
        raise UsageError(f"--ray {address}{where}: no Ray cluster answers at {host}:{port} ({err})") from None


class Starting:
    """The actors of a pool that have not yet answered ``ready`` (``refs``: ready call -> actor), those that have
    (``ready``) and the errors of those that could not start. :meth:`admit` moves the answered ones; once one actor
    has started, each that could not is warned of with its cause (RuntimeWarning)."""

    def __init__(self, ray, actors: list):
        self.ray, self.total = ray, len(actors)
        self.refs = {a.ready.remote(): a for a in actors}
        self.ready: list = []
        self.errors: list = []
        self.named = 0  # errors warned of
        self.since = time.monotonic()
        self.warned = False

    def admit(self, free: list) -> None:
        """Move every actor whose ``ready`` has answered into ``ready`` and ``free``, or its error into ``errors``;
        RuntimeError when no actor is left that could start (its message: the first start's error)."""
        if self.refs:
            answered, _ = self.ray.wait(list(self.refs), num_returns=len(self.refs), timeout=0)
            for ref in answered:
                actor = self.refs.pop(ref)
                try:
                    self.ray.get(ref)
                except Exception as err:  # its start's error, raised again by ``ready``
                    self.errors.append(err)
                    continue
                self.ready.append(actor)
                free.append(actor)
        if self.ready:  # the batch goes on without those that could not start: say why their CPUs stay unused
            for i in range(self.named, len(self.errors)):
                warnings.warn(f"a Ray worker could not start and gets no tasks ({i + 1} of {self.total} so far): "
                              f"{_cause_line(self.errors[i])}", RuntimeWarning, stacklevel=3)
            self.named = len(self.errors)
        if not self.ready and not self.refs:
            raise RuntimeError(f"no Ray worker could start ({len(self.errors)} tried): "
                               f"{_cause_line(self.errors[0])}") from self.errors[0]

    def warn_if_slow(self) -> None:
        """Warn once when tasks have waited :data:`SLOW_START_S` with no actor started: the cluster's CPUs are held by
        other jobs (the tasks start when they are freed)."""
        if self.ready or self.warned or time.monotonic() - self.since < SLOW_START_S:
            return
        self.warned = True
        free = self.ray.available_resources().get("CPU", 0)
        failed = f"; {len(self.errors)} could not start ({_cause_line(self.errors[0])})" if self.errors else ""
        warnings.warn(f"none of the {self.total} Ray workers has started after {SLOW_START_S:.0f} s{failed}: the "
                      f"cluster has {free:g} CPUs free of {self.ray.cluster_resources().get('CPU', 0):g} (other jobs "
                      "hold the rest); the tasks start when a worker does", RuntimeWarning, stacklevel=3)


def _cause_line(err: BaseException) -> str:
    """The first line of a worker's start error (Ray's error wraps the worker's own as its ``cause``)."""
    cause = getattr(err, "cause", None)
    first = str(cause if isinstance(cause, BaseException) else err).strip().splitlines()
    return first[0] if first else type(err).__name__
