"""Long groups (:data:`docsite.long_figures.LONG`) for the craft and wind pages (rotor, rotor design, pumping,
power curve, wind, reeling tether, benchmarks, controllers, quasi-steady): mostly tests that print the values they
assert (``pytest -s``), each quick enough to run on its own, so that a quoted number has a command that prints it."""

from __future__ import annotations

from docsite.long_group import Long

CRAFT_TESTS = {
    # rotor.md: the closed forms' C_Q against the blade-element integration (the test prints each case's difference)
    "rotor_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_rotor.py -k "closed_forms_against or '
                        'near_axial"', "3 s", "rotor.md"),
    # reeling_tether.md: the hanging tether of 5 and 10 elements against the elastic catenary
    "reel_tether_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_reel_tether.py -k hanging_tether',
                              "2 s", "reeling_tether.md"),
    # power_curve.md: the depower rule's trims against their closed-form targets
    "depower_rule_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_power_curve_mill.py -k '
                               'depower_rule_trims', "2 s", "power_curve.md"),
}
