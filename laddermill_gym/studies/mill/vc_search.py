"""The search for the best cable speed V_c at one wind V0 (``laddermill power-curve``'s default, issue 30 point 3):
a stated adaptive rule that replaces a hand refinement of a fixed grid.

The rule, per wind (the cases of one wind run in sequence, each decision on the cases before it):

1. the grid GRID = 2, 3, 5 m/s (the paper's 2 and 5 m/s and one between);
2. up: while the case at the highest V_c tried is an operating point (:func:`operating`: periodic, within the tension
   limit, positive power), the next of RAISE = 6, 7, 8, 9, 10 m/s; the first that is not one ends the climb;
3. between: where 3 m/s is the best and 5 m/s not an operating point, 4 m/s;
4. down: where no case is an operating point, or the best is the lowest V_c tried (2 m/s), LOW = 1 then 0.5 m/s.

The best is then :func:`best` over every case tried (the largest power among the operating points). The evaluator is
a callable V_c -> row (a fresh case, or a row looked up in earlier runs: :class:`Lookup`, ``--replay``), so the same
walk runs both ways.
"""

from __future__ import annotations

from collections.abc import Callable

GRID = (2.0, 3.0, 5.0)  # [m/s] the first cases: the paper's 2 and 5 m/s (Meijaard et al. 1999, Figs. 6-7) and 3
RAISE = (6.0, 7.0, 8.0, 9.0, 10.0)  # [m/s] the climb while the fastest case is an operating point
BETWEEN = (3.0, 5.0, 4.0)  # [m/s] (best, failed above it, tried between): 4 m/s where 3 is best and 5 fails
LOW = (1.0, 0.5)  # [m/s] tried where nothing operates or the best is the lowest V_c tried


def operating(row: dict) -> bool:
    """An operating point: periodic, the last period's tensions within the limit, and power taken (> 0 kW)."""
    return bool(row["periodic"] and row["within_limit"] and row["power_kW"] > 0.0)


def best(rows: list[dict]) -> dict | None:
    """The operating point with the largest power, None when there is none."""
    ok = [r for r in rows if operating(r)]
    return max(ok, key=lambda r: r["power_kW"]) if ok else None


def search(evaluate: Callable[[float], dict]) -> list[dict]:
    """The rule of the module docstring at one wind: the rows of the cases tried, in the order tried."""
    rows = [evaluate(v) for v in GRID]
    for v in RAISE:
        if not operating(max(rows, key=lambda r: r["v_c_m_s"])):
            break
        rows.append(evaluate(v))
    by_v = {r["v_c_m_s"]: r for r in rows}
    top, failed, between = BETWEEN
    b = best(rows)
    if b is not None and b["v_c_m_s"] == top and failed in by_v and not operating(by_v[failed]):
        rows.append(evaluate(between))
    b = best(rows)
    if b is None or b["v_c_m_s"] == min(by_v):
        rows += [evaluate(v) for v in LOW]
    return rows


class MissingCase(LookupError):
    """A case the walk needs that the earlier runs do not hold."""


class Lookup:
    """The evaluator of ``--replay``: (V0, V_c) -> the earlier runs' row of that case (``rows``, keyed by
    (V0, V_c) [m/s]); raises :class:`MissingCase` naming V0 and V_c and the files (``sources``) when there is none."""

    def __init__(self, rows: dict[tuple[float, float], dict], sources: str):
        self.rows, self.sources = rows, sources

    def __call__(self, v0: float, v_c: float, **_settings) -> dict:
        if (v0, v_c) not in self.rows:
            held = sorted(v for w, v in self.rows if w == v0)
            raise MissingCase(f"V0 {v0:g} m/s, V_c {v_c:g} m/s: the search needs this case and {self.sources} hold "
                              f"none with the run's settings (at this wind they hold V_c {held or 'none'})")
        return self.rows[(v0, v_c)]


def search_case(v0: float, case: Callable[..., dict], **kwargs) -> list[dict]:
    """:func:`search` at wind ``v0`` [m/s] with ``case(v0=v0, v_c=V_c, **kwargs)`` as the evaluator (a picklable
    task for the worker pool: the cases of one wind in sequence)."""
    return search(lambda v_c: case(v0=v0, v_c=v_c, **kwargs))


__all__ = ["BETWEEN", "GRID", "LOW", "RAISE", "Lookup", "MissingCase", "best", "operating", "search", "search_case"]
