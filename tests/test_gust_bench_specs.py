"""Controller specs as gust-bench resolves them (studies/controller_specs.py, studies/gusts/gust_bench.py) and the
studies that read the shipped configs (studies/gusts/switch_controllers.py, studies/numerics/closed_loop.py).

Oracles: the shipped policy's own folder (``control.shipped_policies.shipped_policy_path``, as ``make_controller``
reads a name) against a folder of the same name in the working directory that carries another control period;
``model.configio.config_path`` for a config after a prefix; the suite as ``gust_suite.load_suite`` reads it; the
package's data folder ``CONFIG_DIR`` pointed elsewhere (an installed wheel has no ``configs/`` beside the package).
"""

from __future__ import annotations

import yaml

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.control.shipped_policies import shipped_policy_path
from laddermill_gym.model import configio
from laddermill_gym.model.configio import CONFIG_DIR
from laddermill_gym.studies.controller_specs import controller_label, policy_env_kwargs
from laddermill_gym.studies.gusts import gust_bench as gb

TW = "laddermill_gym/TetheredWing-v0"


def test_a_shipped_policys_name_is_the_shipped_policy_whatever_the_working_directory_holds(tmp_path, monkeypatch):
    shadow = tmp_path / "ppo_tethered_wing"
    shadow.mkdir()
    data = yaml.safe_load((shipped_policy_path("ppo_tethered_wing") / "config.yaml").read_text())
    data["env_kwargs"]["control_dt"] = 0.1  # a run of that name here, trained on another control period
    (shadow / "config.yaml").write_text(yaml.safe_dump(data))
    monkeypatch.chdir(tmp_path)
    shipped = policy_env_kwargs(str(shipped_policy_path("ppo_tethered_wing")), TW)
    assert policy_env_kwargs("ppo_tethered_wing", TW) == shipped == {}
    assert policy_env_kwargs(str(shadow), TW) == {"control_dt": 0.1}  # the folder itself, named by its path
    assert gb.absolute_spec("ppo_tethered_wing") == "ppo_tethered_wing"  # a name: workers read the shipped one too
    assert controller_label("ppo_tethered_wing") == "ppo_tethered_wing"
    kws = [kw["env_kwargs"] for fn, kw in gb.warmup_tasks(gb.load_suite("gusts-v1"), [TW], ["ppo_tethered_wing"])
           if fn is gb.warmup_episode]
    assert kws and all(kw == {} for kw in kws)


def test_a_config_after_a_prefix_is_made_absolute_as_the_factory_finds_it(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    agents = CONFIG_DIR / "agents"
    assert gb.absolute_spec("lqr:lqr_tethered_wing") == f"lqr:{(agents / 'lqr_tethered_wing.yaml').resolve()}"
    assert gb.absolute_spec("lqr_guard:lqr_tip_hold_rotorcraft") == \
        f"lqr_guard:{(agents / 'lqr_tip_hold_rotorcraft.yaml').resolve()}"
    (tmp_path / "mine.yaml").write_text("x: 1\n")
    assert gb.absolute_spec("lqr:mine.yaml") == f"lqr:{(tmp_path / 'mine.yaml').resolve()}"
    assert gb.absolute_spec("lqr:nosuch.yaml") == "lqr:nosuch.yaml"  # left for the factory's own error
    assert controller_label("lqr_guard:/a/b/lqr_tip_hold_rotorcraft.yaml") == "lqr_guard:lqr_tip_hold_rotorcraft"


def test_switch_controllers_reads_the_suite_through_the_package_data(tmp_path, monkeypatch):
    """The hand-over study's scenario is the suite's as load_suite reads it, found through CONFIG_DIR: with the
    package's data elsewhere (a wheel's), the repository's configs/ is not read."""
    from laddermill_gym.studies.gusts.gust_suite import load_suite
    from laddermill_gym.studies.gusts.switch_controllers import scenario

    sc = scenario(TW, "EDC_IA")
    expected = next(s for s in load_suite("gusts-v1").envs[TW][1] if s.name == "EDC_IA")
    assert (sc["duration"], tuple(sc["disturbances"]), sc["env_kwargs"]) == (expected.duration,
                                                                             expected.disturbances, {})
    wheel = tmp_path / "site" / "laddermill_gym" / "configs"
    (wheel / "benchmarks").mkdir(parents=True)
    edited = (CONFIG_DIR / "benchmarks" / "gusts-v1.yaml").read_text().replace("name: EDC_IA", "name: EDC_IA_X")
    (wheel / "benchmarks" / "elsewhere.yaml").write_text(edited)
    monkeypatch.setattr(configio, "CONFIG_DIR", wheel)
    monkeypatch.chdir(tmp_path)
    assert scenario(TW, "EDC_IA_X", "elsewhere")["duration"] == expected.duration


def test_handover_builds_both_controllers_as_gust_bench_does(monkeypatch):
    """Both controllers built before any episode through controller_specs.build_controllers with the suite's env
    arguments; a pair that needs two envs is refused."""
    import pytest

    from laddermill_gym.studies import controller_specs
    from laddermill_gym.studies.gusts import switch_controllers as sw

    calls = []

    def build(specs, env_id, env_kwargs=None, **kw):
        calls.append((list(specs), env_id, env_kwargs))
        return {"a": (object(), {"control_dt": 0.05}), "b": (object(), {"control_dt": 0.1})}

    monkeypatch.setattr(controller_specs, "build_controllers", build)
    monkeypatch.setattr(gb, "run_episodes", lambda *a, **k: pytest.fail("an episode ran"))
    with pytest.raises(ValueError, match="different env arguments"):
        sw.handover_outcomes(TW, "EDC_IA", 0, ["a", "b"], [1.0])
    assert calls == [(["a", "b"], TW, {})]


def test_the_closed_loop_study_finds_its_configs_in_the_package_data(tmp_path, monkeypatch):
    """The module read afresh with the package's data folder elsewhere (a wheel's): its LQR configs are there."""
    import importlib.util
    import sys

    wheel = tmp_path / "site" / "laddermill_gym" / "configs"
    monkeypatch.setattr(configio, "CONFIG_DIR", wheel)
    name = "laddermill_gym.studies.numerics.closed_loop"
    spec = importlib.util.find_spec(name)
    fresh = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, name, fresh)  # the package's own module is put back after the test
    spec.loader.exec_module(fresh)
    assert {p.parent for p in fresh.LQR_CONFIGS.values()} == {wheel / "agents"}


def test_the_warm_up_episodes_do_not_warn_of_a_disturbance_past_their_end():
    import warnings

    from laddermill_gym.envs.task_base import LateDisturbanceWarning

    suite = gb.load_suite("gusts-v1")
    tasks = [(fn, kw) for fn, kw in gb.warmup_tasks(suite, ["laddermill_gym/Rotorcraft-v0"], ["open_loop"])
             if fn is gb.warmup_episode and kw["disturbances"]]
    assert tasks and tasks[0][1]["duration"] < 5.0  # the grid scenario's gusts start later than the warm-up ends
    fn, kw = tasks[0]
    late = []
    for run in (fn, gb.episodes_task):  # the warm-up, then the same short episode as a task of its own
        with warnings.catch_warnings(record=True) as seen:
            warnings.simplefilter("always")
            run(**kw)
        late.append([w for w in seen if issubclass(w.category, LateDisturbanceWarning)])
    assert late[0] == [] and late[1] and "episode_time" in str(late[1][0].message)
