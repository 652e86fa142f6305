"""The scorecard-against-step study (``studies/gusts/step_convergence.py``): its step labels and the comparison of
lost episodes, on hand-made rows (the oracle: the rows' own survived flags and end times)."""

from __future__ import annotations

import pytest

from laddermill_gym.studies.gusts.step_convergence import (
    lost_episodes,
    lost_scenarios,
    main,
    parse_step,
    survived_count,
)


def test_step_labels_are_method_and_step():
    assert parse_step("rk4:0.025") == {"physics_step": "rk4", "physics_dt": 0.025, "jacobian_every": 1}
    assert parse_step("ros34pw2:0.05")["physics_step"] == "ros34pw2"
    assert parse_step("ros2:0.05:4") == {"physics_step": "ros2", "physics_dt": 0.05, "jacobian_every": 4}
    with pytest.raises(ValueError, match=r"only a W-method keeps its Jacobian"):
        parse_step("rk4:0.01:2")
    for bad in ("rk4", "rk4:", "rk4:-1", "rk4:zero", "rk4:nan", "ros2:0.05:0", "ros2:0.05:x"):
        with pytest.raises(ValueError, match=r"METHOD:DT"):
            parse_step(bad)
    with pytest.raises(ValueError, match=r"physics_step = 'euler'"):
        parse_step("euler:0.01")


def test_lost_episodes_and_counts_from_rows():
    rows = [dict(controller="lqr", scenario="a", seed=0, survived=True, t_end_s=60.0),
            dict(controller="lqr", scenario="a", seed=1, survived=False, t_end_s=31.25),
            dict(controller="lqr", scenario="b", seed=0, survived=True, t_end_s=60.0),
            dict(controller="pi", scenario="a", seed=0, survived=True, t_end_s=60.0),
            dict(controller="pi", scenario="b", seed=0, survived=False, t_end_s=12.5)]
    lost = lost_episodes(rows)
    assert lost == {("lqr", "a", 1): 31.25, ("pi", "b", 0): 12.5}
    assert lost_scenarios(lost) == {("lqr", "a"), ("pi", "b")}
    assert survived_count(rows, "lqr") == (1, 2) and survived_count(rows, "pi") == (1, 2)


def test_command_line_refuses_a_bad_step_before_running(capsys):
    with pytest.raises(SystemExit):
        main(["--steps", "rk4:0.0125", "rk4"])
    assert "physics step 'rk4': write METHOD:DT" in capsys.readouterr().err


def test_craft_step_options_labels_parse_and_bad_copies_are_refused(capsys):
    from laddermill_gym.envs import ENV_IDS
    from laddermill_gym.studies.benchmarks import craft_step_options as cso

    for env_id, (ref, steps) in cso.STEPS.items():
        assert env_id in ENV_IDS
        assert [parse_step(s)["physics_dt"] for s in (ref, *steps)][0] < 0.01  # the reference is the finest step
    with pytest.raises(SystemExit):
        cso.main(["--copies", "0"])
    assert "--copies = 0: must be a positive integer" in capsys.readouterr().err


def test_an_env_without_a_physics_step_is_refused_in_one_line(capsys):
    """gusts-v4 holds PointMassChain-v0, whose task takes no physics_step: it ended in a TypeError traceback
    (review of 2026-12-08)."""
    from laddermill_gym.studies.gusts import step_convergence

    with pytest.raises(SystemExit) as err:
        step_convergence.main(["--env", "laddermill_gym/PointMassChain-v0", "--suite", "gusts-v4", "--controllers",
                               "open_loop", "--steps", "rk4:0.001", "rk4:0.002"])
    assert err.value.code == 2 and "takes no physics_step" in capsys.readouterr().err
