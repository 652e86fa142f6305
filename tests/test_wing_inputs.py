"""The wing file's inputs (a review of 2026-12-07): a table whose alpha-rate lift makes the mass matrix indefinite, and
list fields holding YAML booleans or quoted numbers.

Oracles: the closed form of the alpha-rate term's added mass, rho S c / 4 CLad along the lift direction (the mass
block then has a negative eigenvalue below CLad = -4 m / (rho S c)); the error text naming the field and value.
"""

import shutil
from pathlib import Path

import numpy as np
import pytest

from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.configio import ConfigError

WINGS = Path(__file__).resolve().parents[1] / "configs" / "wings"


def _wing_copy(tmp_path, table_scale: float | None = None, replace: dict | None = None) -> Path:
    """configs/wings/meijaard_wing.yaml and its table in tmp_path, the table's CLad column times ``table_scale`` and
    the YAML's lines starting with a key of ``replace`` replaced by its value."""
    src = (WINGS / "meijaard_wing.yaml").read_text().splitlines()
    for key, line in (replace or {}).items():
        src = [line if s.startswith(key + ":") else s for s in src]
    (tmp_path / "wing.yaml").write_text("\n".join(src) + "\n")
    table = tmp_path / "meijaard_wing_aero.csv"
    shutil.copy(WINGS / "meijaard_wing_aero.csv", table)
    if table_scale is not None:
        lines = table.read_text().splitlines()
        head = next(i for i, s in enumerate(lines) if not s.startswith("#"))
        col = lines[head].split(",").index("CLad")
        for i in range(head + 1, len(lines)):
            cells = lines[i].split(",")
            cells[col] = repr(float(float(cells[col]) * table_scale))
            lines[i] = ",".join(cells)
        table.write_text("\n".join(lines) + "\n")
    return tmp_path / "wing.yaml"


def test_a_table_whose_alpha_rate_lift_makes_the_mass_matrix_indefinite_is_refused(tmp_path):
    wing = load_scene("tethered_wing").assembly.wing(0)
    rho0 = load_scene("tethered_wing").assembly.wind.rho0
    least = -4.0 * wing.mass / (rho0 * wing.area * wing.chord)  # closed form: mass + rho S c / 4 CLad = 0
    clad_min = wing.aero.column("CLad").min()
    assert clad_min > least  # the shipped table passes (its smallest CLad is -0.63 near -18 deg)
    scale = 1.05 * least / clad_min  # the same table with its smallest CLad 5 % past the bound
    with pytest.raises(ConfigError, match=r"CLad = -1\.2\d* at alpha = .* not positive definite"):
        load_scene("tethered_wing", overrides={"wing_type": str(_wing_copy(tmp_path, scale))})
    scale = 0.95 * least / clad_min
    assert np.isfinite(load_scene("tethered_wing", overrides={"wing_type": str(_wing_copy(tmp_path, scale))})
                       .assembly.wing(0).mass)


@pytest.mark.parametrize("line, shown", [("attachment: [0.2605, 0.0, true]", "True"),
                                         ('aero_reference: [0.75, 0.0, "0"]', "'0'")])
def test_a_list_field_with_a_boolean_or_a_quoted_number_is_refused(tmp_path, line, shown):
    key = line.split(":")[0]
    with pytest.raises(ConfigError, match=rf"{key}.*{shown}.*must be a list of numbers"):
        load_scene("tethered_wing", overrides={"wing_type": str(_wing_copy(tmp_path, replace={key: line}))})
