"""Controller specs on the command line (``laddermill evaluate``, ``gust-bench``, ``demo``) and a trained policy's
control settings (``studies/controller_specs.py``).

Oracles: a shipped policy on another task than its own (``ppo_mill``, trained on LadderMill-v1) is refused by the
command as one line naming the option, the spec and the policy's file, with exit status 2, before any episode runs
(the episode runners replaced by ones that fail if called) and before any output is written; gust-bench's jobs carry
the same env arguments as :func:`policy_env_kwargs` (a shared-policy run folder, an rl-zoo3 run's ``env_kwargs``);
an rl-zoo3 run is accepted on the same task at another physics step (``envs.same_task``: TetheredWing-v0 and v1)
and refused on another task; ``laddermill demo`` flies a run folder trained with groups and bands on an env with
the run's action layout (its config's ``env_kwargs``).
"""

from __future__ import annotations

import pytest
import yaml

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.cli import main as cli_main
from laddermill_gym.control.shipped_policies import shipped_policy_path
from laddermill_gym.studies.controller_specs import policy_env_kwargs
from laddermill_gym.studies.gusts import gust_bench as gb
from laddermill_gym.studies.gusts.gust_suite import load_suite

TW = "laddermill_gym/TetheredWing-v0"
TW1 = "laddermill_gym/TetheredWing-v1"
CHAIN = "laddermill_gym/LadderChain-v0"


def _no_episode(*args, **kwargs):
    raise AssertionError("an episode ran before every controller was checked")


def _one_line_error(err: str, command: str, spec: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err
    assert lines[0].startswith(f"laddermill {command}: error: --controllers {spec!r}: "), lines[0]
    assert str(shipped_policy_path(spec)) in lines[0]  # names the policy's file
    return lines[0]


def test_evaluate_refuses_a_mismatched_policy_before_any_episode(tmp_path, monkeypatch, capsys):
    from laddermill_gym.harness import evaluate as ev

    monkeypatch.setattr(ev, "run_episodes", _no_episode)
    out = tmp_path / "eval"
    code = cli_main(["evaluate", "--env", TW, "--controllers", "lqr", "ppo_mill", "--episodes", "1",
                     "--episode-time", "1", "--out", str(out)])
    assert code == 2
    line = _one_line_error(capsys.readouterr().err, "evaluate", "ppo_mill")
    assert "LadderMill-v1" in line and TW in line
    assert not out.exists()


def test_gust_bench_refuses_a_mismatched_policy_before_any_episode(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(gb, "run_episodes", _no_episode)
    out = tmp_path / "bench"
    code = cli_main(["gust-bench", "--suite", "gusts-v1", "--env", TW, "--controllers", "open_loop", "ppo_mill",
                     "--out", str(out)])
    assert code == 2
    _one_line_error(capsys.readouterr().err, "gust-bench", "ppo_mill")
    assert not out.exists()


def test_demo_refuses_a_mismatched_policy_before_any_mill_is_built(tmp_path, monkeypatch, capsys):
    import gymnasium

    from laddermill_gym.studies.mill import control_demo as demo

    monkeypatch.setattr(gymnasium, "make_vec", _no_episode)
    with pytest.raises(SystemExit) as err:
        demo.main(["--env", "laddermill_gym/LadderMill-v1", "--controllers", "ppo_tethered_wing", "--no-gif",
                   "--time", "1", "--out", str(tmp_path / "demo")])
    assert err.value.code == 2
    _one_line_error(capsys.readouterr().err.replace(" (see laddermill demo --help)", ""), "demo",
                    "ppo_tethered_wing")
    assert not (tmp_path / "demo").exists()


def _job_kwargs(spec: str, env_id: str) -> list[dict]:
    """The env arguments of gust-bench's tasks for ``spec`` on ``env_id`` (its warm-up tasks, one per kernel
    variant; the benchmark's tasks take the same jobs)."""
    tasks = gb.warmup_tasks(load_suite("gusts-v1"), [env_id], [spec])
    kws = [kw["env_kwargs"] for fn, kw in tasks if fn is gb.warmup_episode]
    assert kws
    return kws


def test_gust_bench_jobs_carry_a_shared_policy_run_folders_settings():
    spec = str(shipped_policy_path("ppo_chain"))  # a shared per-wing run folder (config.yaml is no SB3 run's)
    suite_kwargs = load_suite("gusts-v1").envs[CHAIN][0]
    for kw in _job_kwargs(spec, CHAIN):
        assert kw == dict(suite_kwargs, **policy_env_kwargs(spec, CHAIN))


@pytest.fixture
def zoo_run(tmp_path):
    """A minimal rl-zoo3 run folder on TetheredWing-v0 trained with control_dt 0.1 s (args.yml, config.yml, an
    empty model file: the settings are read, the model is not loaded)."""
    pytest.importorskip("stable_baselines3")  # read_zoo_run checks the algorithm's class
    name = "laddermill_gym-TetheredWing-v0"
    run = tmp_path / "logs" / "ppo" / f"{name}_1"
    (run / name).mkdir(parents=True)
    (run / name / "args.yml").write_text(yaml.safe_dump({"algo": "ppo", "env": TW,
                                                         "env_kwargs": {"control_dt": 0.1, "episode_time": 5.0}}))
    (run / name / "config.yml").write_text(yaml.safe_dump({"normalize": False}))
    (run / f"{name}.zip").write_bytes(b"")
    return run


def test_zoo_run_settings_on_the_same_task_and_in_gust_bench_jobs(zoo_run):
    from laddermill_gym.harness import evaluate as ev

    assert policy_env_kwargs(str(zoo_run), TW) == {"control_dt": 0.1}
    assert ev.policy_env_kwargs(str(zoo_run), TW1) == {"control_dt": 0.1}  # the same task on another physics step
    with pytest.raises(ValueError, match=r"an rl-zoo3 run on 'laddermill_gym/TetheredWing-v0', evaluated on "
                                         r"'laddermill_gym/Rotorcraft-v0'"):
        policy_env_kwargs(str(zoo_run), "laddermill_gym/Rotorcraft-v0")
    assert all(kw["control_dt"] == 0.1 for kw in _job_kwargs(str(zoo_run), TW))


@pytest.mark.filterwarnings("ignore:LadderMill operating point")  # the 11-wing mill's settle, cut short
def test_demo_flies_a_run_trained_with_groups_on_the_runs_action_layout(tmp_path, capsys):
    """A run folder of configs/agents/ppo_laddermill.yaml (bands x 2 surfaces, on an 11-wing mill here) with an
    untrained PPO model of its spaces: the demo builds its env with the run's groups (the registered layout's action
    size would be refused)."""
    pytest.importorskip("stable_baselines3")
    import gymnasium as gym
    import numpy as np
    from stable_baselines3 import PPO

    from laddermill_gym.envs.laddermill.actions import action_count
    from laddermill_gym.envs.laddermill.observation import N_OBS_PER_SLOT, N_STATION_OBS
    from laddermill_gym.model.configio import CONFIG_DIR
    from laddermill_gym.studies.mill import control_demo as demo

    data = yaml.safe_load((CONFIG_DIR / "agents" / "ppo_laddermill.yaml").read_text())
    data["env_kwargs"].update(scene_options={"n_wings": 11}, settle={"max_time": 100.0})
    run = tmp_path / "run"
    run.mkdir()
    (run / "config.yaml").write_text(yaml.safe_dump(data))
    kw = data["env_kwargs"]
    n_act = action_count(11, kw["groups"], kw["n_bands"], kw["surfaces"])

    class Spaces(gym.Env):
        observation_space = gym.spaces.Box(-np.inf, np.inf, (N_OBS_PER_SLOT * 11 + N_STATION_OBS,), np.float32)
        action_space = gym.spaces.Box(-1.0, 1.0, (n_act,), np.float32)

    PPO("MlpPolicy", Spaces(), policy_kwargs={"net_arch": [8]}, device="cpu").save(run / "model.zip")
    out = tmp_path / "demo"
    assert demo.main(["--env", "laddermill_gym/LadderMill-v0", "--controllers", str(run), "--time", "0.1",
                      "--no-gif", "--no-progress", "--out", str(out)]) == 0
    assert (out / "demo.csv").is_file()
    assert "run" in capsys.readouterr().out


def test_a_run_s_physics_step_stays_with_its_own_id(tmp_path, monkeypatch):
    """A v0 training config that pins ``physics_dt: 0.05`` made TetheredWing-v1 (two RK4 steps of 25 ms) step RK4 at
    50 ms under paired_survival --env and the commands' controller specs, neither id's step (review of 2026-12-08).
    Flown on its own id the run keeps it; on another id of the task it is left out. Oracles: the settings by hand
    and the env paired_survival builds."""
    import gymnasium as gym
    import numpy as np

    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.harness import paired_survival as ps

    raw = yaml.safe_load(open("configs/agents/ppo_tethered_wing_severe.yaml").read())
    raw["env_kwargs"]["physics_dt"] = 0.05
    run = tmp_path / "run"
    run.mkdir()
    (run / "config.yaml").write_text(yaml.safe_dump(raw))
    assert load_rl_config(run / "config.yaml").carried_env_kwargs()["physics_dt"] == 0.05
    assert policy_env_kwargs(str(run), TW)["physics_dt"] == 0.05
    assert "physics_dt" not in policy_env_kwargs(str(run), TW1)
    steps = []

    def episodes(controller, env_id, kw, seeds, episode_time, disturbances):
        env = gym.make(env_id, **kw).unwrapped
        steps.append((env_id, env.task.batch.settings.method, env.task.batch.settings.dt))
        env.close()
        return {"failure": np.zeros(len(seeds), dtype=int)}

    monkeypatch.setattr(gb, "run_episodes", episodes)
    ps.paired_survival(run / "config.yaml", "ntm_ib", 1, 5000, ["lqr", "open_loop"], TW1)
    assert steps == [(TW1, "rk4", 0.025)] * 2  # v1's registered step
