"""Sizes that build arrays are checked against the memory they would take before anything is allocated (issue 34
item 1): ``chain.n_wings: 1000000000`` once allocated without limit (20 GB) until the out-of-memory killer ended the
process. The estimates of ``model/memory.py`` are held to the arrays a simulator actually allocates."""

from __future__ import annotations

import tracemalloc

import numpy as np
import pytest

from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model import memory
from laddermill_gym.model.configio import ConfigError


def test_a_billion_wings_are_refused_naming_the_field_and_the_memory():
    tracemalloc.start()
    try:
        with pytest.raises(ConfigError, match=r"ladder_chain.yaml \(with overrides\): field 'chain.n_wings' = "
                                              r"1000000000: 1000000000 wings and 1000000001 elements .* would take "
                                              r"about [\d.e+]+ PB of memory, more than the limit"):
            load_scene("ladder_chain", overrides={"chain": {"n_wings": 10**9}})
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 20e6  # refused before the arrays: nothing near the model's size was allocated
    with pytest.raises(ConfigError, match=r"tethered_wing.yaml: n_wings = 1000000000 \(override\): .* of memory"):
        load_scene("tethered_wing", n_wings=10**9)


def test_elements_and_point_mass_nodes_are_refused_by_memory():
    with pytest.raises(ConfigError, match=r"elements_per_piece = 100000 \(override\): 1 wing and 100000 elements "
                                          r"\(99999 cable nodes\) would take about"):
        load_scene("tethered_wing", elements_per_piece=100000)
    with pytest.raises(ConfigError, match=r"podgaets_5km.yaml \(with overrides\): field 'fidelity.element_length' = "
                                          r"1e-06: a string of 5050000000 nodes would take about 1.21 TB"):
        load_scene("podgaets_5km", overrides={"fidelity": {"element_length": 1e-6}})


def test_the_limit_is_half_the_memory_or_the_variable(monkeypatch):
    monkeypatch.delenv(memory.LIMIT_VARIABLE, raising=False)
    limit, source = memory.memory_limit()
    assert limit == memory.physical_memory() // 2 and "half of this machine's memory" in source
    monkeypatch.setenv(memory.LIMIT_VARIABLE, "0.001")  # 1 MB: the paper's chain needs more
    with pytest.raises(ConfigError, match=r"field 'chain.n_wings' = 101: 101 wings .* more than the limit 1 MB "
                                          r"\(LADDERMILL_MEMORY_LIMIT_GB = 0.001\)"):
        load_scene("ladder_chain")
    monkeypatch.setenv(memory.LIMIT_VARIABLE, "lots")
    with pytest.raises(ValueError, match="LADDERMILL_MEMORY_LIMIT_GB = 'lots': must be a number of GB > 0"):
        memory.memory_limit()


def test_batched_copies_are_refused_before_allocation():
    from laddermill_gym.sim.batch import BatchSimulator

    sc = load_scene("tethered_wing", elements_per_piece=1)
    with pytest.raises(ValueError, match=r"n_copies = 1000000000: 1000000000 copies of [\d.]+ kB would take about "
                                         r"[\d.]+ TB of memory"):
        BatchSimulator(sc.assembly, 10**9, sc.settings)


def test_point_mass_copies_are_refused_before_allocation():
    """PointMassChain-v0's native vector env with a billion copies: refused naming num_envs and the memory (before:
    a list of a billion packed models was built until memory ran out)."""
    import gymnasium as gym

    with pytest.raises(ValueError, match=r"num_envs = 1000000000: 1000000000 copies of a \d+-node string would take "
                                         r"about [\d.]+ [TP]B of memory"):
        gym.make_vec("laddermill_gym/PointMassChain-v0", num_envs=10**9, vectorization_mode="vector_entry_point")


@pytest.mark.parametrize("scene, options, bodies", [
    ("ladder_chain", dict(n_wings=400, dt=1e-3), 400),                 # wings on single elements
    ("tethered_wing", dict(elements_per_piece=800, dt=1e-6), 800),     # one wing, 799 nodes
])
def test_the_estimate_bounds_the_arrays_a_simulator_allocates(scene, options, bodies):
    """Oracle: tracemalloc's count of the arrays allocated by building the scene and its simulator (numpy reports
    every allocation to it) is below the estimate per body, and above a third of it (the estimate is not vacuous)."""
    from laddermill_gym.sim.simulator import Simulator

    tracemalloc.start()
    try:
        sc = load_scene(scene, **options)
        Simulator(sc.assembly, np.zeros(sc.assembly.state_size), sc.settings)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert sc.assembly.n_wings + sc.assembly.n_nodes == bodies
    assert memory.RIGID_BYTES_PER_BODY * bodies / 3 < peak < memory.RIGID_BYTES_PER_BODY * bodies


def test_the_point_mass_estimate_bounds_its_arrays():
    """Oracle: ``held_bytes`` of the packed string, its workspace and state, with room for a start state, the
    tensions and a copy: the estimate per node is at least twice what the simulation holds."""
    from laddermill_gym.model.pointmass import held_bytes, make_work, pack

    sc = load_scene("podgaets_5km", element_length=0.1)
    s = sc.string
    held = held_bytes(pack(s), make_work(s), np.zeros(s.state_size), sc.controls)["total"]
    assert 2 * held < memory.pointmass_bytes(s.n_nodes) < 10 * held
