"""Page group of docs/learned_mill.md: ``python -m laddermill_gym.harness.gain_locality`` (the centralised LQR's
gain by slot distance), run in a fresh process and parsed from what it prints."""

from __future__ import annotations

import re

from docsite.paper_figures import run_command


def gain_locality() -> dict:
    """``python -m laddermill_gym.harness.gain_locality`` (about 5 minutes under load): per slot distance 0-10 the
    mean and largest dimensionless block norm and the share of the gain (``rows``, as printed), the means' range over
    6-10 (``far``: "lo-hi") and their
    printed shares' sum (``far_share``), the share beyond 10, the band's spectral radii ("k0".."k4" as printed;
    ``tail``: the one value bands 6, 8 and all print, or "differ") and the own-slot norms every 5th slot (``own``, as
    printed)."""
    argv = ["laddermill_gym.harness.gain_locality"]
    out = run_command(argv, 1800)
    rows = [dict(zip(("mean", "largest", "share"), m.groups(), strict=True))
            for m in re.finditer(r"^ +\d+ \| +([\d.]+) \| +([\d.]+) \| ([\d.]+)$", out, re.M)]
    bands = dict(re.findall(r"^band \|i - j\| <= (\d+): spectral radius of the design model's closed loop ([\d.]+)$",
                            out, re.M))
    beyond = re.search(r"^beyond 10: share ([\d.]+)$", out, re.M)
    own = re.search(r"^own-slot block norm, slots 0, 5, \.\.: (.*)$", out, re.M)
    if len(rows) != 11 or len(bands) != 8 or beyond is None or own is None:
        raise RuntimeError(f"python -m {argv[0]} printed {len(rows)} distance rows and {len(bands)} bands (11 and 8 "
                           f"expected), beyond 10: {beyond}, own-slot norms: {own}:\n{out[-3000:]}")
    far = [r["mean"] for r in rows[6:]]
    tail = {v for k, v in bands.items() if int(k) >= 6}
    return {"rows": rows, "far": f"{min(far, key=float)}-{max(far, key=float)}", "beyond": beyond.group(1),
            "far_share": f"{sum(float(r['share']) for r in rows[6:]):.3f}",
            "bands": {f"k{k}": v for k, v in bands.items()}, "tail": tail.pop() if len(tail) == 1 else "differ",
            "own": own.group(1)}
