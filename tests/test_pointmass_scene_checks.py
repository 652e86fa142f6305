"""Scenes at the point-mass fidelity read what they are given or refuse it (a review of 2026-12-07): the starts from
the rigid model read the file with the same overrides (oracle: the rigid scene loaded with them by the rigid path);
element_length and dt overrides finite and > 0 at load; the rigid fidelity's switches refused or honoured
(cable_aero: false, oracle: the external force of a cable node is its weight alone); ground_contact 'flag' refused;
the env's default resolution only where the file has none; the scene file's comment on the base tension against the
quasi-static start."""

import math
import re

import numpy as np
import pytest

from laddermill_gym.kernels.contract import TM_DT, TM_T0
from laddermill_gym.kernels.pointmass.forces import external_force, node_mass
from laddermill_gym.kernels.wind import modulation
from laddermill_gym.ladder.pointmass_mill import overrides_key
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.ladder.scene_files import scene_path
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.model.pointmass import pack
from laddermill_gym.sim.pointmass import PointMassSimulator

CHAIN = {"fidelity": "pointmass", "element_length": 70.0}


@pytest.mark.parametrize("overrides", [{"wind": {"v0": 12.0}}, {"chain": {"piece_length": 60.0}}])
def test_the_rigid_start_reads_the_same_overrides(overrides):
    """The point-mass chain starts at the rigid model's static equilibrium of the same file: with overrides, the one
    ``load_scene`` gives at the rigid fidelity with them (its wings' CG positions, to the interpolation's
    roundoff). Before, the bare file's: the v0 = 8 start for v0 = 12, and 70 m pieces stretched onto 60 m elements
    (3.5-4.3 MN)."""
    el = overrides.get("chain", {}).get("piece_length", 70.0)
    pm = load_scene("ladder_chain", fidelity="pointmass", element_length=el, overrides=overrides)
    x, _ = pm.initial_state()
    rigid = load_scene("ladder_chain", overrides=overrides)
    sim = rigid.simulator(*rigid.initial_state())
    np.testing.assert_allclose(x.reshape(-1, 6)[pm.string.kite_nodes, :3], sim.wing_positions(), rtol=0, atol=1e-9)


def test_the_rigid_periodic_start_is_keyed_on_the_overrides():
    a = load_scene("laddermill", **CHAIN)
    b = load_scene("laddermill", **CHAIN, overrides={"wind": {"v0": 9.0}})
    assert overrides_key(a) == "null" and overrides_key(b) == '{"wind": {"v0": 9.0}}'


@pytest.mark.parametrize("key, value", [("element_length", 0.0), ("element_length", math.nan),
                                        ("element_length", math.inf), ("element_length", -70.0),
                                        ("element_length", True), ("element_length", "70"), ("dt", 0.0),
                                        ("dt", -0.01), ("dt", math.nan), ("dt", math.inf)])
def test_bad_resolution_or_step_overrides_are_refused_at_load(key, value):
    """Before: element_length 0 ZeroDivisionError, NaN ValueError, dt inf accepted (a non-finite state at the first
    step), dt NaN or negative refused only by the simulator, without the file."""
    options = {**CHAIN, key: value}
    with pytest.raises(ConfigError, match=re.escape(f"ladder_chain.yaml: {key} = {value!r} (override): must be a "
                                                    "finite number > 0")):
        load_scene("ladder_chain", **options)


@pytest.mark.parametrize("key, value, why", [("sag", False, "no sag correction"), ("sag", True, "no sag correction"),
                                             ("dimension", 2, "3D only"), ("elements_per_piece", 2, "element_length")])
def test_the_rigid_fidelitys_switches_are_refused(key, value, why):
    with pytest.raises(ConfigError, match=rf"ladder_chain.yaml: {key} = {value!r} \(override\): not at the "
                                          rf"point-mass fidelity: .*{why}"):
        load_scene("ladder_chain", **CHAIN, **{key: value})
    assert load_scene("ladder_chain", **CHAIN, dimension=3).string.n_nodes == 101


@pytest.mark.parametrize("how", ["keyword", "file"])
def test_cable_aero_off_leaves_a_cable_node_its_weight_alone(how):
    """cable_aero false (the keyword or the file's fidelity.cable_aero) takes the drag off the string: the external
    force on a cable node moving through the wind is m g (before: the drag stayed, cn0 1.1)."""
    kw = {"cable_aero": False} if how == "keyword" else {"overrides": {"fidelity": {"cable_aero": False}}}
    sc = load_scene("ladder_chain", fidelity="pointmass", element_length=7.0, **kw)
    on = load_scene("ladder_chain", fidelity="pointmass", element_length=7.0)
    assert (sc.string.cable.cn0, sc.string.cable.ct0) == (0.0, 0.0) and on.string.cable.cn0 == 1.1
    x, _ = on.initial_state()
    x.reshape(-1, 6)[:, 3:] = [3.0, -2.0, 1.0]
    j = 3  # a cable node (kites every 10 nodes from node 9)
    forces = []
    for scene in (sc, on):
        M = pack(scene.string)
        s, d, _, _ = modulation(0.0, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
        forces.append(np.array(external_force(0.0, x, j, scene.controls, M, s, d)))
        weight = node_mass(j, M) * scene.string.gravity
    np.testing.assert_allclose(forces[0], [0.0, 0.0, weight], rtol=1e-15, atol=0)
    assert np.abs(forces[1] - forces[0]).max() > 1.0  # with the drag on


def test_ground_contact_flag_is_refused():
    with pytest.raises(ConfigError, match=r"field 'integrator.ground_contact' = 'flag': the point-mass fidelity has "
                                          r"'stop' .* and 'off'"):
        load_scene("ladder_chain", **CHAIN, overrides={"integrator": {"ground_contact": "flag"}})
    off = load_scene("ladder_chain", **CHAIN, overrides={"integrator": {"ground_contact": "off"}})
    assert off.string.ground_height == -math.inf


def test_the_env_keeps_the_files_element_length():
    """PointMassEnv's default element_length (1 m) applies only where the file names none: podgaets_5km's 1 cm
    stands (before: 1 m, 100 times coarser than the file), an override in the file's section too."""
    from laddermill_gym.envs.pointmass.env import PointMassEnv

    env = PointMassEnv(scene="podgaets_5km", scene_options={"n_wings": 2}, episode_time=1.0)
    assert env.task.string.element_length == 0.01 and env.task.string.n_nodes == 10_000
    env = PointMassEnv(scene="podgaets_5km", scene_options={"n_wings": 2, "overrides": {
        "fidelity": {"element_length": 5.0}}}, episode_time=1.0)
    assert env.task.string.element_length == 5.0
    env = PointMassEnv(scene="tethered_wing", episode_time=1.0)  # a rigid file: no element_length
    assert env.task.string.element_length == 1.0


def test_the_scene_files_base_tension_comment_matches_the_quasi_static_start():
    """configs/scenes/podgaets_5km.yaml says the base tension's share of the breaking load (before: "about 45 %",
    at 37 %); oracle: the first element's tension of the quasi-static start (at 1 m elements: the same pieces)."""
    from laddermill_gym.ladder.pointmass_scene import quasi_static_state

    text = scene_path("podgaets_5km").read_text()
    said = float(re.search(r"base tension about (\d+) % of\s+#? *the cable's breaking load", text).group(1))
    sc = load_scene("podgaets_5km", element_length=1.0)
    x = quasi_static_state(sc.string, sc.controls)
    first = PointMassSimulator(sc.string, x, sc.controls, sc.dt).tensions()[0]
    assert abs(said - 100.0 * first / sc.string.cable.breaking_load) < 1.0, (said, first)
