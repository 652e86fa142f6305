"""The gust suite gusts-v2 (configs/benchmarks/gusts-v2.yaml) and what it needs from the envs.

Oracles: the frozen gusts-v1.yaml (v2 repeats every v1 scenario unchanged); the scene files' wind profile in closed
form (Meijaard et al. 1999 eq. 1 above the boundary layer, v = v0 + v1 (h - h0)) at the reference heights the
IEC entries name; the wing and cable node positions read from the env state at every control step against the
bounds of the gust grid the kernels read (the packed header ``gp``): every point of the loop and the kite stays
on the grid over the episode; a disturbed episode against the undisturbed one of the same seed (the disturbance
reaches the system); the trim action against the control effort of the open-loop controller (zero).
"""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs import ENV_IDS
from laddermill_gym.envs.laddermill.gust_extent import point_positions
from laddermill_gym.envs.laddermill.task import MillTask
from laddermill_gym.kernels import contract as C
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.studies.gusts import gust_bench as gb
from laddermill_gym.studies.gusts.gust_suite import load_suite

LM, PK = "laddermill_gym/LadderMill-v0", "laddermill_gym/PumpingKite-v0"
V2 = load_suite("gusts-v2")
#: the spatial (grid) scenarios v2 adds for the mill
MILL_GRID = ("EWS_IA", "NTM_IB", "dryden_light", "dryden_moderate")


def _wind(scene: str, h: float) -> float:
    """Meijaard et al. 1999 eq. (1) above the boundary layer: v0 + v1 (h - h0) [m/s] (the scene file's numbers)."""
    w = load_scene(scene).assembly.wind
    assert h > w.h0
    return w.v0 + w.v1 * (h - w.h0)


def test_v2_loads_with_every_registered_env():
    # gusts-v2 was fixed before PumpingKite-v1 and LadderMill-v1 existed; a suite is never changed, a later version
    # adds envs
    assert V2.version == 2 and set(V2.envs) == set(ENV_IDS) - {"laddermill_gym/PumpingKite-v1",
                                                               "laddermill_gym/LadderMill-v1",
                                                               "laddermill_gym/LadderMill-v2",
                                                               "laddermill_gym/LadderMill-v3",
                                                               "laddermill_gym/LadderChain-v1",
                                                               "laddermill_gym/TetheredWing-v1",
                                                               "laddermill_gym/Rotorcraft-v1"}
    for _, scenarios in V2.envs.values():
        assert all(sc.duration > sc.start for sc in scenarios)
    names = {s.name for s in V2.envs[LM][1]}
    assert set(MILL_GRID) <= names
    assert {"direction_step", "speed_step_20pct", "one_cos_20s", "EOG_IA", "EDC_IA", "NTM_IB"} <= {
        s.name for s in V2.envs[PK][1]}


def test_v2_repeats_every_v1_scenario_unchanged():
    v1 = load_suite("gusts-v1")
    for env_id, (kw, scenarios) in v1.envs.items():
        kw2, scenarios2 = V2.envs[env_id]
        assert kw2 == kw
        assert scenarios2[: len(scenarios)] == scenarios


def test_iec_entries_use_the_scene_wind_at_the_reference_height():
    env = gym.make(PK)
    h_trim = float(-env.unwrapped.task.x_trim[2])  # the kite's CG height at the reel-out trim [m]
    env.close()
    for s in V2.envs[PK][1]:
        for d in s.disturbances:
            if "hub_height" in d:
                assert d["hub_height"] == pytest.approx(h_trim, abs=0.05)
                assert d["wind_speed"] == pytest.approx(_wind("pumping_kite", d["hub_height"]), abs=0.005)
    for s in V2.envs[LM][1]:
        for d in s.disturbances:
            if d["type"] in ("EWS", "Turbulence"):
                assert d["wind_speed"] == pytest.approx(_wind("laddermill", 1748.0), abs=0.005)


def _grid_bounds(task, b: int = 0):
    """(xi low, xi high, h low, h high, U) of copy b's packed gust grid (what the kernels read)."""
    gp = task.batch.air.gp[b]
    xi0, h0 = gp[C.GP_XI0], gp[C.GP_H0]
    return (xi0, xi0 + (gp[C.GP_NXI] - 1) * gp[C.GP_DXI], h0, h0 + (gp[C.GP_NH] - 1) * gp[C.GP_DH],
            gp[C.GP_ADVECTION])


def _run(env_id: str, scenario, duration: float, seed: int = 0, controller: str | None = None,
         check_cover: bool = False):
    """Step ``scenario`` (disturbances as the suite) for ``duration`` [s] with the zero action (the trim / operating
    point) or ``controller``; returns (observations (T, n_obs), times (T,), failure code). With ``check_cover``:
    assert every wing and cable node stays on the gust grid at every step."""
    from laddermill_gym.control.factory import make_controller

    env = gym.make_vec(env_id, num_envs=1, vectorization_mode="vector_entry_point", episode_time=duration,
                       disturbances=[dict(d) for d in scenario.disturbances] if scenario else [])
    task = env.task
    ctrl = make_controller(controller, env_id) if controller else None
    obs, _ = env.reset(seed=[seed])
    out, times, code = [obs[0]], [0.0], 0
    if check_cover:
        lo, hi, h_lo, h_hi, u = _grid_bounds(task)
    while True:
        a = ctrl.predict(obs, deterministic=True)[0] if ctrl else np.zeros((1, task.n_actions), np.float32)
        obs, _, term, trunc, info = env.step(a)
        out.append(obs[0])
        times.append(float(info["t"][0]))
        if check_cover:
            p = point_positions(task.batch.assembly, task.batch.states)[0]
            xi = -p[:, 0] - u * times[-1]  # p . e - U t, e = (-1, 0, 0): the grids' heading is 0
            assert np.all((xi >= lo) & (xi <= hi)), f"t = {times[-1]} s: xi {xi.min()}..{xi.max()} off [{lo}, {hi}]"
            assert np.all((-p[:, 2] >= h_lo) & (-p[:, 2] <= h_hi)), f"t = {times[-1]} s: heights off the grid"
        if term[0] or trunc[0]:
            code = int(info["failure"][0])
            break
    env.close()
    return np.array(out), np.array(times), code


def _scenario_cases():
    cases = []
    for env_id in (PK, LM):
        for s in V2.envs[env_id][1]:
            marks = [pytest.mark.slow] if env_id == LM else []  # the mill's operating point: about 25 s per process
            cases.append(pytest.param(env_id, s, marks=marks, id=f"{env_id.split('/')[1]}-{s.name}"))
    return cases


@pytest.mark.parametrize("env_id, scenario", _scenario_cases())
def test_every_pumping_and_mill_scenario_runs_with_its_disturbance_active(env_id, scenario):
    """A shortened episode (to 3 s past the scenario's start: the mill's EWS front reaches the hauled station 1.9 s
    after it) runs, and the disturbance reaches the system: the observations leave those of the undisturbed
    episode of the same seed."""
    duration = scenario.start + 3.0
    disturbed, times, _ = _run(env_id, scenario, duration, seed=scenario.seeds[0])
    calm, _, _ = _run(env_id, None, duration, seed=scenario.seeds[0])
    assert times.size > 5 and np.all(np.isfinite(disturbed))
    k = min(len(disturbed), len(calm))
    assert np.max(np.abs(disturbed[:k] - calm[:k])) > 1e-9


@pytest.mark.slow
def test_mill_turbulence_grid_covers_every_point_over_the_episode():
    """NTM_IB of LadderMill-v0 at its full 60 s with the mill's LQR: every wing CG and cable node stays inside the
    packed grid (xi = p . e - U t and h) at every control step, and the suite's grids raise no cover warning."""
    s = next(x for x in V2.envs[LM][1] if x.name == "NTM_IB")
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        _, times, _ = _run(LM, s, s.duration, seed=s.seeds[0], controller="lqr", check_cover=True)
    assert times[-1] > 1.0
    # the loop at its operating point over the whole 60 s (the episode above ends early in a failure): every slot's
    # orbit, the cable nodes and the stations stay on the grid at every time up to the scenario's end
    env = gym.make_vec(LM, num_envs=1, vectorization_mode="vector_entry_point", episode_time=s.duration,
                       disturbances=[dict(d) for d in s.disturbances])
    env.reset(seed=[0])
    lo, hi, h_lo, h_hi, u = _grid_bounds(env.task)
    ext = env.task.loop_extent()
    print(f"LadderMill-v0's loop at its operating point: heights {ext.heights[0]:.1f} to {ext.heights[1]:.1f} m, "
          f"p . e {ext.along_wind[0]:.1f} to {ext.along_wind[1]:.1f} m; the grid {h_lo:.0f} to {h_hi:.0f} m high, "
          f"{lo:.0f} to {hi:.0f} m along the wind")
    assert lo <= ext.along_wind[0] - u * s.duration and ext.along_wind[1] <= hi
    assert h_lo <= ext.heights[0] and ext.heights[1] <= h_hi
    env.close()


def test_pumping_turbulence_grid_covers_the_kite_over_the_episode():
    """NTM_IB of PumpingKite-v0, 200 s with the LQR-assisted cycle (reel-out to 500 m and more): the kite stays on
    the grid at every control step."""
    s = next(x for x in V2.envs[PK][1] if x.name == "NTM_IB")
    _, times, _ = _run(PK, s, s.duration, seed=s.seeds[0], controller="lqr", check_cover=True)
    assert times[-1] > 60.0


def test_mill_warns_when_a_turbulence_grid_misses_the_loop():
    """An 11-wing mill (short settling): a grid up to 20 m misses the loop (stations at 50 m height) and the
    warning names the field; a grid over [0, 2000] m x [-500, 2000] m covers it silently."""
    small = dict(scene_options={"n_wings": 11}, settle={"max_time": 100.0}, episode_time=2.0)
    low = [{"type": "Turbulence", "model": "NTM", "wind_class": "IB", "heights": [0.0, 20.0]}]
    with pytest.warns(RuntimeWarning, match=r"disturbances\[0\]\.heights = \[0, 20\] m does not cover"):
        task = MillTask(disturbances=low, **small)
    ext = task.loop_extent()
    assert ext.heights[0] <= 50.0 and ext.heights[1] > 50.0  # the stations are at 50 m (configs/scenes/laddermill.yaml)
    assert ext.along_wind[0] <= -100.0 <= 0.0 <= ext.along_wind[1]  # the hauled (x = 100 m) and veered (x = 0) stations
    wide = [{"type": "Turbulence", "model": "NTM", "wind_class": "IB", "heights": [0.0, 2000.0],
             "along_wind": [-500.0, 2000.0]}]
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        MillTask(disturbances=wide, **small)


def test_pumping_vector_env_resets_one_copy_while_the_other_steps():
    """NextStep autoreset of one copy of the pumping kite (whose info has no reward_effort) while the other steps:
    the resetting copy's reward terms are zero, the other's are the step's."""
    env = gym.make_vec(PK, num_envs=2, vectorization_mode="vector_entry_point", episode_time=2.0)
    env.reset(seed=[0, 1])
    env._autoreset[0] = True  # as after copy 0's episode ended in the previous step
    _, reward, _, _, info = env.step(np.zeros((2, env.task.n_actions), np.float32))
    assert reward[0] == 0.0 and info["reward_power"][0] == 0.0 and info["t"][0] == 0.0
    assert info["t"][1] == pytest.approx(env.task.control_dt)
    env.close()


def test_gust_bench_on_the_pumping_kite_measures_effort_from_the_trim(tmp_path):
    """The open-loop controller holds a = 0, the pumping kite's trim action: control effort exactly 0; a scenario
    without disturbance is its own reference (energy ratio 1 where energy is made, here none: winch stopped)."""
    path = tmp_path / "pk.yaml"
    path.write_text(f"version: 1\nenvs:\n  {PK}:\n    env_kwargs: {{}}\n    scenarios:\n"
                    "      - {name: gust, start: 0.5, duration: 2.0, seeds: [0, 1],\n"
                    "         disturbances: [{type: SpeedStep, step: 0.2, time: 0.5}]}\n")
    rows = gb.run_suite(load_suite(path), [], ["open_loop"], progress=False)
    assert len(rows) == 2 and all(r["control_effort"] == 0.0 and r["survived"] for r in rows)
    assert all(r["energy_J"] == 0.0 for r in rows)  # the winch stopped: no energy at the drum
