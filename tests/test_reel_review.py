"""The reeling tether's and the winch's edges found by a review of 2026-12-07 (kernels/reel.py,
envs/pumping/winch_scene.py, envs/pumping/reel_start.py, model/winch.py).

Before: the env's reel-in sentence on a reeling tether used the single winch's rule (it named a rest length of
-198.1 m and a start length of 60 m where the kernel stopped on a drum element of 1.9 m under 2 m); the catenary start
failed on a short steep tether whose elastic catenary exists; an initial winch speed outside the speed limits loaded
and failed only at the simulator's build, without the file. Oracles: the kernel's own LIMIT status on the same state,
an independent root of the catenary's end equations (scipy's ``root`` on the closed form of ``catenary_point``, from
its own guess), and the config file's field.
"""

import math

import numpy as np
import pytest
from scipy.optimize import root

from laddermill_gym.envs.pumping.reel_start import catenary_point, solve_catenary
from laddermill_gym.envs.pumping.winch_scene import load_pumping, winch_limit_text
from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.reel import relabel
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.model.packing import pack_model


def test_the_reel_in_sentence_is_the_reeling_kinds_own_end_stop():
    ps = load_pumping("pumping_kite_reeling")
    asm, st, xo = ps.assembly, ps.assembly.station, ps.assembly.body_state_size
    x, _ = ps.initial_state()
    assert winch_limit_text(st, 0.0, x, xo) is None  # the start: far from any end stop
    ln = st.reel.element_length
    for drum, merges, stops in ((1.9, st.nodes_in_air - 1, True), (2.1, st.nodes_in_air - 1, False),
                                (1.9, st.nodes_in_air - 2, False)):  # two nodes in the air: it merges instead
        y = x.copy()
        y[xo + C.SX_TRANSFERS] = -merges
        y[xo + C.SX_MOVED] = drum - st.piece_length - merges * ln  # l_d = l_p + s - m l_n
        text = winch_limit_text(st, 100.0, y, xo)
        kernel = relabel(pack_model(asm).kind, y.copy(), pack_model(asm))
        assert (kernel == C.LIMIT) == stops == (text is not None), (drum, merges, kernel, text)
        if stops:
            assert f"rest length {drum:g} m" in text and f"element length {ln:.4g} m (2 m)" in text


def test_the_catenary_start_solves_a_short_steep_tether():
    span, rise, length, w, ea = 11.310997208341238, 99.35920111022158, 100.0, 0.3 * 9.80665, 2.16e7

    def miss(q):
        x, z = catenary_point(length, q[0], q[1], w, ea)
        return [x - span, z - rise]

    t = 4.0 * w * length  # an independent guess: four times the weight along the chord
    c = span / math.hypot(span, rise)
    ref = root(miss, [t * c, t * math.sqrt(1.0 - c * c) - w * length], method="hybr", options={"xtol": 1e-14})
    assert ref.success and np.abs(miss(ref.x)).max() < 1e-9
    h, v = solve_catenary(span, rise, length, w, ea)  # refused before ("no catenary of 100.0 m spans ...")
    assert h == pytest.approx(ref.x[0], rel=1e-8) and v == pytest.approx(ref.x[1], rel=1e-8)


def test_an_initial_winch_speed_outside_its_limits_is_refused_naming_the_file(tmp_path):
    from pathlib import Path

    import laddermill_gym

    root_dir = Path(laddermill_gym.__file__).resolve().parents[1]
    text = (root_dir / "configs/pumping/pumping_kite.yaml").read_text()
    assert "initial_speed_m_s: 0.0" in text
    scene = (root_dir / "configs/scenes/pumping_kite.yaml").resolve()
    cfg = tmp_path / "fast.yaml"
    cfg.write_text(text.replace("scene: pumping_kite ", f"scene: {scene} ")
                   .replace("initial_speed_m_s: 0.0", "initial_speed_m_s: 20.0"))
    with pytest.raises(ConfigError, match=rf"{cfg}: field 'winch.initial_speed_m_s' = 20.0: must lie within "
                                          r"speed_limits \[-16.7, 10.0\] m/s"):
        load_pumping(cfg)
