"""Scale a sweep out with Ray: the tethered wing under a gust at five wind speeds, open loop and under the LQR.

Every point of the sweep is one independent task, a pair ``(function, kwargs)`` of plain picklable data:
here :func:`laddermill_gym.studies.gusts.gust_bench.episodes_task` (one episode of a controller on an env with
the given disturbances) with the wind speed set through the scene's overrides. ``run_tasks`` runs the list
serially (``workers=0``), on local processes (``workers=N``) or on Ray (``ray="local"`` starts a one-node Ray
here; ``ray="auto"`` joins a running cluster, e.g. after ``ray start --head`` and ``ray start --address=...`` on
the other nodes); the results come back in the order of the tasks and are the same whichever way they ran,
which the script checks for one point against a serial run. The LQR is designed by each worker at each wind
speed's own operating point (``make_controller("lqr", env_id, env_kwargs)``). Needs the extra ``[ray]``
(``pip install -e ".[ray]"``). Run it as ``python tutorials/ray_sweep.py``.
"""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from laddermill_gym.studies.gusts.gust_bench import episodes_task  # noqa: E402
from laddermill_gym.studies.parallel import run_tasks  # noqa: E402

ENV = "laddermill_gym/TetheredWing-v0"
WINDS = [6.0, 8.0, 10.0, 12.0, 14.0]  # [m/s] the scene's reference wind speed v0
CONTROLLERS = ["open_loop", "lqr"]
GUST = {"type": "OneMinusCosineGust", "amplitude": 0.3, "duration": 4.0, "time": 5.0,
        "direction_amplitude": 0.05}  # +30 % speed and 0.05 rad direction over 4 s (gusts-v1's one_cos_4s)
DURATION = 40.0  # [s] episode length


def task(v0: float, controller: str) -> tuple:
    """One point of the sweep: the task function and its keyword arguments."""
    kwargs = {"scene_options": {"overrides": {"wind": {"v0": v0}}}}
    return episodes_task, dict(env_id=ENV, env_kwargs=kwargs, spec=controller, seeds=(0,), duration=DURATION,
                               disturbances=(GUST,))


if __name__ == "__main__":
    points = [(v0, c) for v0 in WINDS for c in CONTROLLERS]
    results = run_tasks([task(v0, c) for v0, c in points], ray="local", workers=2, desc="sweep", progress=False)

    serial = episodes_task(**task(*points[-1])[1])  # the last point again, in this process
    same = all(np.array_equal(np.asarray(serial[k]), np.asarray(results[-1][k]))
               for k in ("t_end", "failure", "energy_J", "peak_tension_N", "lateral"))
    print(f"last point on Ray == serial, bit for bit: {same}")

    print(f"{'v0 [m/s]':>9}{'controller':>12}{'t_end [s]':>11}{'max |dy| [m]':>14}{'mean P [kW]':>13}  cause")
    lateral = {c: [] for c in CONTROLLERS}
    for (v0, c), r in zip(points, results, strict=True):
        dy = float(np.nanmax(r["lateral"]))
        t_end = float(r["t_end"][0])
        power = float(r["energy_J"][0]) / t_end / 1e3
        lateral[c].append(dy)
        print(f"{v0:>9.1f}{c:>12}{t_end:>11.2f}{dy:>14.2f}{power:>13.2f}  {r['cause'][0] or '-'}")

    fig, ax = plt.subplots(figsize=(6, 3.5))
    for c in CONTROLLERS:
        ax.plot(WINDS, lateral[c], "o-", label=c)
    ax.set(xlabel="reference wind speed v0 [m/s]", ylabel="largest lateral offset [m]", yscale="log",
           title=f"{ENV.split('/')[1]}: 4 s gust, 30 % and 0.05 rad")
    ax.legend()
    fig.tight_layout()
    fig.savefig("ray_sweep.png", dpi=120)
    print("wrote ray_sweep.png")
