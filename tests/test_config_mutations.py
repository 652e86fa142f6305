"""The mutation campaign of issue 34 (``tests/config_mutations.py``): the shipped scene, wing, cable and agent
configs changed one field at a time (wrong type, negative, NaN, huge, removed, an unknown field) and loaded. Every
change is a clear error (a ConfigError naming the file, the field and the value) or loads with a documented meaning
(``ACCEPTED``); none raw, none silent, at least 97 % of the errors clear.

The default run takes every 11th change of the campaign (about 160, a few seconds); ``-m slow`` runs all of them
(about 1800). ``python -m tests.config_mutations`` prints the whole tally and every defect."""

from __future__ import annotations

from collections import Counter

import pytest

from tests.config_mutations import (
    LQR_AGENTS,
    PARTS,
    RL_AGENTS,
    SCENES,
    Campaign,
    Mutation,
    accepted,
    all_mutations,
    judge,
)

ALL = all_mutations()


def _run(campaign: Campaign, muts: list[Mutation]) -> tuple[Counter, list[str]]:
    tally, defects = Counter(), []
    for m in muts:
        verdict, err = campaign.run(m)
        tally[verdict] += 1
        if verdict not in ("clear", "accepted"):
            defects.append(f"{verdict} {m.label} = {m.value!r}: {type(err).__name__ if err else 'loaded'} {err or ''}")
    return tally, defects


def _check(tally: Counter, defects: list[str], n: int) -> None:
    errors = n - tally["accepted"]
    share = tally["clear"] / errors
    print(f"{n} mutations: {tally['clear']} clear errors of {errors} ({100 * share:.1f} %), {tally['accepted']} "
          f"accepted with a documented meaning")
    assert tally["raw"] == 0 and tally["silent"] == 0, "\n".join(defects)
    assert share >= 0.97, "\n".join(defects)


@pytest.fixture(scope="module")
def campaign(tmp_path_factory):
    return Campaign(tmp_path_factory.mktemp("configs"))


def test_the_campaign_is_large_and_covers_every_kind_of_change():
    files = {m.file for m in ALL}
    kinds = Counter(m.kind for m in ALL)
    assert len(ALL) >= 1200 and len(ALL[::11]) >= 120
    assert {"text", "negative", "nan", "huge", "missing", "unknown"} <= set(kinds)
    assert set(SCENES) | set(PARTS) | set(RL_AGENTS) | set(LQR_AGENTS) == files


def test_every_11th_mutation_is_a_clear_error_or_documented(campaign):
    pytest.importorskip("stable_baselines3")
    sample = ALL[::11]
    tally, defects = _run(campaign, sample)
    _check(tally, defects, len(sample))


@pytest.mark.slow
def test_every_mutation_is_a_clear_error_or_documented(campaign):
    pytest.importorskip("stable_baselines3")
    tally, defects = _run(campaign, ALL)
    _check(tally, defects, len(ALL))


def test_the_judge_tells_clear_from_vague_raw_and_silent():
    """The campaign's verdicts on made-up outcomes: the oracle of the two tests above."""
    from laddermill_gym.model.configio import ConfigError

    m = Mutation("scenes/x.yaml", "wind.v0", "huge", ("wind", "v0"), 8e6)
    assert judge(m, ConfigError("/a/scenes/x.yaml: field 'wind.v0' = 8000000.0: must be at most 150")) == "clear"
    assert judge(m, ConfigError("/a/scenes/x.yaml: field 'wind.v0': too large")) == "vague"  # no value
    assert judge(m, ConfigError("/a/scenes/y.yaml: field 'wind.v0' = 8e+06: too large")) == "vague"  # another file
    assert judge(m, ValueError("x.yaml: wind.v0 = 8e+06")) == "raw"
    assert judge(m, None) == "silent"
    gone = Mutation("scenes/x.yaml", "wind.direction_height", "missing", ("wind", "direction_height"), None)
    assert judge(gone, None) == "accepted" and accepted(gone)  # the documented default


def test_yaml_1_2_floats_load_as_numbers(campaign):
    """Issue 34 item 4: 1e6, 1.0e6, 1e300 and 2.5E-3 are numbers (PyYAML's YAML 1.1 reads them as text)."""
    from laddermill_gym.ladder.scene import load_scene
    from laddermill_gym.model.configio import ConfigError, load_yaml_text

    assert load_yaml_text("a: [1e6, 1.0e6, 1e300, 2.5E-3, -4e+2, 7, .5]", "t")["a"] == [
        1e6, 1e6, 1e300, 2.5e-3, -400.0, 7, 0.5]
    assert isinstance(load_yaml_text("n: 7", "t")["n"], int) and load_yaml_text("s: '1e6'", "t")["s"] == "1e6"
    path, cable = campaign.root / "scenes" / "tethered_wing.yaml", campaign.root / "cables" / "dyneema_25mm.yaml"
    text, cable_text = path.read_text(), cable.read_text()
    assert "  v0: 8.0 " in text and "EA: 2.16e+7 " in cable_text
    try:
        path.write_text(text.replace("  v0: 8.0 ", "  v0: 8e0 "))
        cable.write_text(cable_text.replace("EA: 2.16e+7 ", "EA: 2.5e7 "))
        sc = load_scene(path)
        assert sc.assembly.wind.v0 == 8.0 and sc.cable.EA == 2.5e7
        path.write_text(text.replace("  v0: 8.0 ", "  v0: 1e300 "))
        with pytest.raises(ConfigError, match=r"field 'wind.v0' = 1e\+300: must be at most 1e\+12"):
            load_scene(path)
    finally:
        path.write_text(text)
        cable.write_text(cable_text)
