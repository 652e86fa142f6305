"""What the LQR designs refuse or record, from two reviews (control/lqr.py, lqr_config.py, mill_lqr.py, factory.py,
craft_lqr.py, harness/lqr_report.py).

Oracles: scipy's own ZOH (``expm`` of the augmented matrix) and discrete Riccati solution (``solve_discrete_are``) on
the full lateral model linearised in the test, for the single wing's gain on a tether of several elements; the
config's own scene file, written here with a wind of its own, for the scene's resolution; the design on a fresh task
(never reset), for the mill's orbit recorded after a reset; the period's transition matrix composed here with scipy's
``expm`` from the orbit's lateral models, for the factory's refusal of a mill design; the wing config's own
errors, for the craft config's bounds and messages; and the gain worked with scipy from the eq. (6) blocks that
``laddermill lqr`` prints for the craft, with the check model's stiffness (half-length first element: doubled).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
import scipy.linalg as sla
import yaml

from laddermill_gym.control.craft_lqr import DEFAULT_CRAFT_LQR, load_craft_lqr_config
from laddermill_gym.control.factory import UnstableDesignWarning, make_controller
from laddermill_gym.control.linearize import lateral_subsystem, linearize
from laddermill_gym.control.lqr import (
    DEFAULT_CONFIG,
    LQRController,
    bryson_weights,
    design_ladder_chain,
    design_tethered_wing,
    load_lqr_config,
)
from laddermill_gym.control.mill_lqr import design_mill_lqr, mill_lateral_model, orbit_states, transfer_jacobian
from laddermill_gym.envs.laddermill.task import MillTask
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.configio import CONFIG_DIR, ConfigError
from tests.conftest import SMALL_MILL, small_mill_task

TW = "laddermill_gym/TetheredWing-v0"
SMALL = SMALL_MILL  # not periodic: every design on it is unstable over the period
N = SMALL["scene_options"]["n_wings"]
MILL_CONFIG = CONFIG_DIR / "agents" / "lqr_laddermill.yaml"


def _zoh(A, B, dt):
    n, m = B.shape
    M = np.zeros((n + m, n + m))
    M[:n, :n], M[:n, n:] = A, B
    E = sla.expm(M * dt)
    return E[:n, :n], E[:n, n:]


def _dlqr(A, B, Q, R, dt):
    Ad, Bd = _zoh(A, B, dt)
    P = sla.solve_discrete_are(Ad, Bd, Q, R)
    return np.linalg.solve(R + Bd.T @ P @ Bd, Bd.T @ P @ Ad)


def _full_radius(sc, cfg) -> float:
    """Largest |z| of the wing's own-block gain (scipy) closing the full lateral model (the nodes unobserved)."""
    x, u = sc.initial_state()
    A, B, _, _ = lateral_subsystem(linearize(sc.simulator(x, u), x, u))
    Q, R = bryson_weights(cfg.max_state, cfg.max_input)
    K = np.zeros((2, A.shape[0]))
    K[:, :6] = _dlqr(A[:6, :6], B[:6], Q, R, cfg.control_period)
    Ad, Bd = _zoh(A, B, cfg.control_period)
    return float(np.max(np.abs(np.linalg.eigvals(Ad - Bd @ K))))


def _config(tmp_path, name="lqr.yaml", **changes):
    data = yaml.safe_load(DEFAULT_CONFIG.read_text())
    data.update(changes)
    p = tmp_path / name
    p.write_text(yaml.safe_dump(data))
    return p


# ------------------------------------------------------------------ the single wing's tether nodes (review D, L1)
def test_a_tether_of_several_elements_is_refused_by_the_loader_and_the_factory(tmp_path):
    p = _config(tmp_path, elements_per_piece=4)
    with pytest.raises(ConfigError, match=r"lqr\.yaml: field 'elements_per_piece' = 4: a single-wing design .* use "
                                          r"elements_per_piece = 1"):
        load_lqr_config(p)
    with pytest.raises(ValueError, match=r"cable nodes are not observed.* unstable \(max \|z\| = 1\.01.*"
                                         r"elements_per_piece = 1"):
        make_controller("lqr", TW, {"scene_options": {"elements_per_piece": 4}})


def test_the_wing_gain_is_checked_on_the_full_lateral_model():
    """Four elements: the gain on the wing's own block (stable there) leaves the full lateral model unstable (the
    review's 1.0133), so the design refuses it; two elements: it holds the full model, and the design records it."""
    cfg = load_lqr_config()
    four = load_scene("tethered_wing", elements_per_piece=4)
    rho4 = _full_radius(four, cfg)
    assert rho4 > 1.0
    with pytest.raises(ValueError, match=r"12 states, not 6: the tether's cable nodes are not observed") as err:
        design_tethered_wing(cfg, four)
    assert float(str(err.value).split("max |z| = ")[1].split(")")[0]) == pytest.approx(rho4, rel=1e-5)
    two = load_scene("tethered_wing", elements_per_piece=2)
    d = design_tethered_wing(cfg, two)
    assert np.max(np.abs(d.lqr.closed_loop)) < 1.0 and d.full_closed_loop.size == 8
    assert np.max(np.abs(d.full_closed_loop)) == pytest.approx(_full_radius(two, cfg), rel=1e-8)
    assert np.max(np.abs(d.full_closed_loop)) < 1.0
    assert design_tethered_wing(cfg).full_closed_loop is None  # one element: the wing's own model is the whole


# ------------------------------------------------------------------ the config's scene (L3)
def test_the_scene_is_the_one_beside_the_config_wherever_the_design_runs(tmp_path, monkeypatch, capsys):
    from laddermill_gym.harness.lqr_report import main

    here, there = tmp_path / "cfg", tmp_path / "elsewhere"
    here.mkdir()
    there.mkdir()
    scene = yaml.safe_load((CONFIG_DIR / "scenes" / "tethered_wing.yaml").read_text())
    scene["wing_type"], scene["cable"] = "package:wings/meijaard_wing.yaml", "package:cables/dyneema_25mm.yaml"
    for folder, v0 in ((here, 9.0), (there, 12.0)):
        scene["name"], scene["wind"]["v0"] = f"wing_{folder.name}", v0
        (folder / "myscene.yaml").write_text(yaml.safe_dump(scene))
    cfg_path = _config(here, "lqr_my.yaml", scene="myscene.yaml")
    monkeypatch.chdir(there)  # a file of the same name here: the one the loader did not check
    cfg = load_lqr_config(cfg_path)
    assert cfg.scene == str((here / "myscene.yaml").resolve())
    d = design_tethered_wing(cfg_path)
    assert d.scene.assembly.wind.v0 == 9.0 and d.scene.name == "wing_cfg"
    oracle = design_tethered_wing(cfg, load_scene(here / "myscene.yaml", elements_per_piece=1))
    assert d.lqr.K.tobytes() == oracle.lqr.K.tobytes()
    assert LQRController.from_config(cfg_path).gains.tobytes() == oracle.lqr.K[None].tobytes()
    assert main(["--config", str(cfg_path)]) == 0
    assert "scene wing_cfg:" in capsys.readouterr().out
    assert load_lqr_config(DEFAULT_CONFIG).scene == "tethered_wing"  # a shipped scene's bare name stays a name


# ------------------------------------------------------------------ fields a design does not use (L5)
def test_fields_a_fixed_scenes_design_ignores_are_refused(tmp_path):
    with pytest.raises(ConfigError, match=r"dm\.yaml: field 'design_model' = 'period_mean': scene tethered_wing is "
                                          "not a moving-cable mill"):
        load_lqr_config(_config(tmp_path, "dm.yaml", design_model="period_mean"))
    with pytest.raises(ConfigError, match=r"st\.yaml: field 'structure' = 'centralised': scene tethered_wing has one "
                                          "wing"):
        load_lqr_config(_config(tmp_path, "st.yaml", structure="centralised"))
    cfg = load_lqr_config()
    with pytest.raises(ValueError, match=r"lqr_tethered_wing\.yaml: design_model = 'period_mean' is the moving-cable"):
        design_tethered_wing(dataclasses.replace(cfg, design_model="period_mean"))
    with pytest.raises(ValueError, match=r"lqr_tethered_wing\.yaml: structure = 'centralised': a single wing"):
        design_tethered_wing(dataclasses.replace(cfg, structure="centralised"))
    with pytest.raises(ValueError, match=r"design_model = 'period_mean' is the moving-cable mill's"):
        design_ladder_chain(dataclasses.replace(load_lqr_config("lqr_ladder_chain"), design_model="period_mean"))


def test_from_config_refuses_a_mill_scene():
    """The mill's LQR is designed on an env's orbit (it observes a station too: LadderMill-v1's observation has 4
    entries more than 101 slots' 15)."""
    with pytest.raises(ValueError, match=r"lqr_laddermill_v1\.yaml: scene laddermill_v1 is a moving-cable mill"):
        LQRController.from_config("lqr_laddermill_v1")


# ------------------------------------------------------------------ the craft config's bounds (L6)
@pytest.mark.parametrize("field, value, wing_field", [
    ("control_period", 5000.0, "control_period"),
    ("max_state.phi_deg", 1e9, "max_state.phi_deg"),
    ("max_state.y", 2e4, "max_state.y"),
    ("max_input_deg.differential", 95.0, "max_input_deg.rudder"),
])
def test_the_craft_lqr_config_has_the_wing_configs_bounds(tmp_path, field, value, wing_field):
    def write(src, key, name):
        data = yaml.safe_load(src.read_text())
        head, _, leaf = key.rpartition(".")
        (data[head] if head else data)[leaf] = value
        p = tmp_path / name
        p.write_text(yaml.safe_dump(data))
        return p

    with pytest.raises(ConfigError) as craft_err:
        load_craft_lqr_config(write(DEFAULT_CRAFT_LQR, field, "craft.yaml"))
    with pytest.raises(ConfigError) as wing_err:
        load_lqr_config(write(DEFAULT_CONFIG, wing_field, "wing.yaml"))
    assert f"field '{field}'" in str(craft_err.value)
    why = str(wing_err.value).split(": ", 2)[2]  # "must be ... (why)", after the file and the field
    assert str(craft_err.value).endswith(why) and "at most" in why


def test_the_craft_lqr_config_names_a_missing_craft_and_a_wind_beyond_any_measured(tmp_path):
    data = yaml.safe_load(DEFAULT_CRAFT_LQR.read_text())
    for key, value, match in (("craft", "no_such_craft", r"field 'craft' = 'no_such_craft': no such craft file"),
                              ("wind_speed", 200.0, r"field 'wind_speed' = 200\.0: must be at most 150")):
        p = tmp_path / f"{key}.yaml"
        p.write_text(yaml.safe_dump(dict(data, **{key: value})))
        with pytest.raises(ConfigError, match=match):
            load_craft_lqr_config(p)


# ------------------------------------------------------------------ the mill (L2, L4)
@pytest.fixture(scope="module")
def small_mill():
    return small_mill_task()


def test_the_mill_orbit_is_recorded_in_a_steady_wind_after_a_reset(small_mill):
    """A reset draws the paper's direction step into copy 0's air: the design records the orbit in a steady wind all
    the same (the gains of a fresh task's design, bit for bit), and the orbit recorded in the drawn air is refused."""
    cfg = load_lqr_config(MILL_CONFIG)
    fresh = design_mill_lqr(cfg, small_mill, n_phases=2)
    task = MillTask(1, **SMALL, operating_point=small_mill.op)
    task.reset(np.ones(1, dtype=bool), [np.random.default_rng(0)])
    assert task.simulator(0).model.md.max() > 0.0  # the step is in the copy's air
    assert design_mill_lqr(cfg, task, n_phases=2).gains.tobytes() == fresh.gains.tobytes()
    sim = task.simulator(0)
    sim.reset(state=np.array(task.op.state), t=0.0, controls=np.array(task.u_op))
    with pytest.raises(ValueError, match=r"the mill's orbit left the x-z plane at t = .* slot \d+'s y"):
        orbit_states(sim, 2)


def test_the_factory_warns_of_a_mill_design_unstable_over_the_period(small_mill):
    """The small mill's design grows over the period: the period's transition matrix, composed here with scipy's
    ZOH from the orbit's lateral models and the simulator's transfer, has spectral radius > 1, and the factory
    warns of it naming that radius."""
    cfg = load_lqr_config(MILL_CONFIG)
    with pytest.warns(UnstableDesignWarning, match=r"does not hold the orbit: .* spectral radius") as seen:
        make_controller("lqr", "laddermill_gym/LadderMill-v0", {k: v for k, v in SMALL.items() if k != "scene"})
    said = float(str(seen[0].message).split("spectral radius ")[1].split(" ")[0])
    d = design_mill_lqr(cfg, small_mill)
    sim = small_mill.simulator(0)
    sim.reset(state=np.array(small_mill.op.state), t=0.0, controls=np.array(small_mill.u_op))
    states, before = orbit_states(sim, 8)
    n_steps = round(sim.assembly.station.piece_length / small_mill.op.cable_speed / cfg.control_period)
    phi = np.eye(6 * N)
    for j, x in enumerate(states):
        Ad, Bd = _zoh(*mill_lateral_model(sim, x, np.array(small_mill.u_op)), cfg.control_period)
        phi = np.linalg.matrix_power(Ad - Bd @ d.gains, round((j + 1) * n_steps / 8) - round(j * n_steps / 8)) @ phi
    rho = float(np.max(np.abs(np.linalg.eigvals(transfer_jacobian(sim, before) @ phi))))
    assert rho > 1.0 and said > 1.0
    assert np.log(said) == pytest.approx(np.log(rho), rel=1e-3)


# ---------------------------------------------------------- the chain's decentralised design (review 2026-12-07)
def test_the_factory_warns_of_a_decentralised_chain_design_the_coupled_chain_does_not_hold():
    """The default chain LQR (lqr_ladder_chain.yaml, decentralised) is stable on each wing's own lateral block but
    not on the whole chain's coupled lateral model: gains designed here with scipy on the full model's diagonal
    6 x 6 blocks, closing the full model (ZOH with scipy's expm), give max |z| > 1, the figure the factory's warning
    states; the centralised config builds without a warning."""
    import warnings

    with pytest.warns(UnstableDesignWarning, match=r"decentralised design on .*LadderChain-v0's chain does not hold "
                                                   r"the full coupled lateral model") as seen:
        make_controller("lqr", "laddermill_gym/LadderChain-v0")
    said = float(str(seen[0].message).split("max |z| ")[1].split(" ")[0])
    cfg = load_lqr_config(CONFIG_DIR / "agents" / "lqr_ladder_chain.yaml")
    sc = load_scene(cfg.scene)
    x, u = sc.initial_state()
    A, B, _, _ = lateral_subsystem(linearize(sc.simulator(x, u), x, u))
    Q, R = bryson_weights(cfg.max_state, cfg.max_input)
    K = sla.block_diag(*[_dlqr(A[6 * k:6 * k + 6, 6 * k:6 * k + 6], B[6 * k:6 * k + 6, 2 * k:2 * k + 2], Q, R,
                               cfg.control_period) for k in range(sc.assembly.n_wings)])
    Ad, Bd = _zoh(A, B, cfg.control_period)
    rho = float(np.max(np.abs(np.linalg.eigvals(Ad - Bd @ K))))
    assert rho > 1.0 and said == pytest.approx(rho, abs=2e-4)
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnstableDesignWarning)
        make_controller("lqr:" + str(CONFIG_DIR / "agents" / "lqr_ladder_chain_central.yaml"),
                        "laddermill_gym/LadderChain-v0")


# ------------------------------------------------------------------ the craft's design, printed (review C, R3)
def test_laddermill_lqr_prints_the_default_crafts_eq6_design(capsys):
    """``laddermill lqr --config lqr_rotorcraft``: eq. (6)'s blocks of the default craft (two elements per tether),
    whose gain, worked here with scipy from the printed blocks and the config's Bryson weights, is the printed one;
    against the straight single-element check model the diagonal stiffness doubles (the attachment's element is half
    as long) and the thrust tilt's entry stays."""
    from laddermill_gym.harness.lqr_report import main
    from laddermill_gym.rotorcraft.craft import load_craft
    from laddermill_gym.rotorcraft.roll_lateral import derive_roll_lateral
    from laddermill_gym.studies.rotorcraft.craft_stability import straight_tether_variant

    assert main(["--config", "lqr_rotorcraft"]) == 0
    out = capsys.readouterr().out
    assert "2 elements per tether" in out
    blocks = {k: np.array(yaml.safe_load(out.split(f"   {k} = ")[1].split("\n")[0].split(" per rad")[0]))
              for k in ("M", "D", "K", "(alpha, beta)")}
    gain = np.array(yaml.safe_load(out.split("columns (y, phi, vy, p)): ")[1].split("\n")[0]))
    Mi = np.linalg.inv(blocks["M"])
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Mi @ blocks["K"], -Mi @ blocks["D"]]])
    B = np.concatenate([np.zeros(2), Mi @ blocks["(alpha, beta)"]])[:, None]
    cfg = yaml.safe_load(DEFAULT_CRAFT_LQR.read_text())
    ms = cfg["max_state"]
    Q = np.diag(1.0 / np.array([ms["y"], np.radians(ms["phi_deg"]), ms["vy"], np.radians(ms["p_deg_s"])]) ** 2)
    R = np.array([[1.0 / np.radians(cfg["max_input_deg"]["differential"]) ** 2]])
    # x = (y, phi, y', phi'), and p = phi' at the level trim: the gain's columns (y, phi, vy, p)
    np.testing.assert_allclose(_dlqr(A, B, Q, R, cfg["control_period"])[0], gain, atol=3e-4)
    check = derive_roll_lateral(straight_tether_variant(load_craft()).simulator())
    np.testing.assert_allclose(np.diag(blocks["K"]) / np.diag(check.K), 2.0, rtol=0.02)
    assert blocks["K"][0, 1] == pytest.approx(check.K[0, 1], rel=1e-3)


# ------------------------------------------------------ the craft's gain on the whole craft (review 2026-12-07)
def test_the_craft_gain_is_checked_on_the_whole_crafts_linear_model():
    """Eq. (6) leaves out the tethers' nodes: the design also closes its gain on the simulator's whole linear model
    (30 states on the default craft's two-element tethers). Oracle: the gain placed on the named minimal states
    (wing0_y, wing0_phi, wing0_vy, wing0_p: eq. (6)'s y, phi, y', p at a level trim), ZOH with scipy's expm; the
    loop is stable but less damped than eq. (6)'s own; with a gain of the wrong sign both say it grows."""
    from laddermill_gym.control.craft_lqr import design_craft_lqr, full_craft_check
    from laddermill_gym.kernels.contract import CU_DIFFERENTIAL

    d = design_craft_lqr()
    lin = linearize(d.sim, d.x_trim, d.u_trim)
    n = lin.A.shape[0]
    K = np.zeros((lin.B.shape[1], n))
    K[CU_DIFFERENTIAL, [lin.state_names.index(f"wing0_{s}") for s in ("y", "phi", "vy", "p")]] = d.gain
    Ad, Bd = _zoh(lin.A, lin.B, d.config.control_period)
    rho = float(np.max(np.abs(np.linalg.eigvals(Ad - Bd @ K))))
    assert n == 30 and d.full_closed_loop.size == n
    assert float(np.max(np.abs(d.full_closed_loop))) == pytest.approx(rho, abs=1e-6)
    assert np.max(np.abs(d.lqr.closed_loop)) < rho < 1.0
    assert d.trim_residual == pytest.approx(lin.residual) and d.trim_residual < 1e-6
    K[CU_DIFFERENTIAL] *= -1.0  # a gain of the wrong sign: the same oracle and the check agree it grows
    rho_wrong = float(np.max(np.abs(np.linalg.eigvals(Ad - Bd @ K))))
    wrong = full_craft_check(d.sim, -d.gain, d.config.control_period)[0]
    assert rho_wrong > 1.0 and float(np.max(np.abs(wrong))) == pytest.approx(rho_wrong, abs=1e-6)


def test_the_factory_warns_of_a_craft_gain_the_whole_craft_does_not_hold(tmp_path):
    """A roll weight six times tighter than the shipped config's (phi 0.5 deg against 3 deg) gives a gain that holds
    eq. (6) but not the whole craft's linear model: the factory builds it and warns, naming the radius, which the
    scipy oracle of the test above gives too; the shipped config builds without a warning."""
    import warnings

    from laddermill_gym.control.craft_lqr import design_craft_lqr
    from laddermill_gym.kernels.contract import CU_DIFFERENTIAL

    text = DEFAULT_CRAFT_LQR.read_text()
    assert "  phi_deg: 3.0 " in text
    mine = tmp_path / "lqr_tight_roll.yaml"
    mine.write_text(text.replace("  phi_deg: 3.0 ", "  phi_deg: 0.5 ", 1))
    with pytest.warns(UnstableDesignWarning, match=r"does not hold the whole craft's linear model \(30 states") as seen:
        make_controller(f"lqr:{mine}", "laddermill_gym/Rotorcraft-v0")
    said = float(str(seen[0].message).split("max |z| ")[1].split(" ")[0])
    d = design_craft_lqr(mine)
    lin = linearize(d.sim, d.x_trim, d.u_trim)
    K = np.zeros((lin.B.shape[1], lin.A.shape[0]))
    K[CU_DIFFERENTIAL, [lin.state_names.index(f"wing0_{s}") for s in ("y", "phi", "vy", "p")]] = d.gain
    Ad, Bd = _zoh(lin.A, lin.B, d.config.control_period)
    assert said == pytest.approx(float(np.max(np.abs(np.linalg.eigvals(Ad - Bd @ K)))), abs=1e-5) and said > 1.0
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnstableDesignWarning)
        make_controller("lqr", "laddermill_gym/Rotorcraft-v0")
