"""studies/gusts/switch_controllers.py: a hand-over at 0 s is the second controller alone, one after the end is
the first alone (each against run_episodes of that controller by itself)."""

import pytest

from laddermill_gym.control.factory import make_controller
from laddermill_gym.studies.gusts.gust_bench import run_episodes
from laddermill_gym.studies.gusts.switch_controllers import handover_outcomes, scenario

ENV = "laddermill_gym/TetheredWing-v0"


def test_handover_ends_are_the_single_controllers():
    sc = scenario(ENV, "EDC_IA")  # open loop fails it, the LQR survives (gusts-v1 scorecard)
    alone = {c: run_episodes(make_controller(c, ENV, {}), ENV, {}, [0], sc["duration"], sc["disturbances"])
             for c in ("open_loop", "lqr")}
    rows = handover_outcomes(ENV, "EDC_IA", 0, ["open_loop", "lqr"], [0.0, 1000.0])
    assert rows[0][1:] == (int(alone["lqr"]["failure"][0]), pytest.approx(alone["lqr"]["t_end"][0]))
    assert rows[1][1:] == (int(alone["open_loop"]["failure"][0]), pytest.approx(alone["open_loop"]["t_end"][0]))
    assert rows[0][1] == 0 and rows[1][1] != 0


def test_unknown_scenario_is_named():
    with pytest.raises(ValueError, match="no scenario 'nope'"):
        scenario(ENV, "nope")
