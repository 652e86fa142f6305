"""Ctrl-C during a long run keeps what was computed (issue 34 item 9): ``laddermill simulate`` stops after the current
chunk of steps, writes the record (.npz, figures), says so and exits 130; a second Ctrl-C aborts at once. The
Ctrl-C is a real SIGINT sent to this process from a timer thread while the run is in a compiled call."""

from __future__ import annotations

import os
import signal
import threading

import numpy as np
import pytest

from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.sim.recording import CHUNK_STEPS, check_step_count, record


def _sigint_after(seconds: float) -> threading.Thread:
    """A thread that sends this process one SIGINT after ``seconds``; the caller joins it."""
    t = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    t.start()
    return t


@pytest.fixture(scope="module")
def scene():
    return load_scene("tethered_wing", elements_per_piece=1)


def test_ctrl_c_stops_after_a_chunk_with_a_consistent_state(scene):
    """Samples of 20,000 steps run in chunks of 1000: the stop lands between samples, on a whole chunk. Oracle: an
    independent simulator stepped the same number of steps from the same start reaches the recorded last state."""
    sim = scene.simulator()
    x0, t0, dt = sim.state.copy(), sim.t, sim.settings.dt
    previous = signal.getsignal(signal.SIGINT)
    timer = _sigint_after(1.0)
    rec = record(sim, 1e6, 100.0, progress=False, interruptible=True)
    timer.join()
    assert signal.getsignal(signal.SIGINT) is previous  # the handler is restored
    assert rec.interrupted and rec.error is None
    steps = round((rec.t[-1] - t0) / dt)
    assert steps % CHUNK_STEPS == 0 and 0 < rec.t[-1] < 1e6
    ref = scene.simulator(x0, sim.initial_controls)
    ref.step(n_steps=steps)
    np.testing.assert_allclose(rec.views["wing_position_m"][-1], ref.views()["wing_position_m"], rtol=1e-9,
                               atol=1e-9)


def test_the_first_ctrl_c_is_a_request_and_the_second_aborts(capsys):
    from laddermill_gym.sim.interrupt import stop_requests

    with pytest.raises(KeyboardInterrupt), stop_requests("stopping soon") as request:
        os.kill(os.getpid(), signal.SIGINT)  # Python runs the handler at the next bytecode of this thread
        assert request.requested and request.count == 1
        os.kill(os.getpid(), signal.SIGINT)
        for _ in range(1000):  # not reached: the second SIGINT raises
            pass
    assert capsys.readouterr().err == "stopping soon\n"


def test_simulate_writes_what_it_recorded_and_exits_130(tmp_path, capsys, monkeypatch):
    """The SIGINT is sent 0.5 s after the recorded run has started (however long the set-up took)."""
    from contextlib import contextmanager

    from laddermill_gym.cli import main as cli_main
    from laddermill_gym.sim import recording

    real = recording.stop_requests

    @contextmanager
    def armed(message=None):
        with real(message) as request:
            timer = _sigint_after(0.5)
            try:
                yield request
            finally:
                timer.join()

    monkeypatch.setattr(recording, "stop_requests", armed)
    out = tmp_path / "run"
    code = cli_main(["simulate", "tethered_wing", "--time", "100000", "--sample-dt", "1", "--out", str(out),
                     "--quiet", "--no-step-check"])
    captured = capsys.readouterr()
    assert code == 130, captured.err
    assert "Ctrl-C: stopping after the current chunk of steps" in captured.err
    assert "interrupted (Ctrl-C) at t = " in captured.err and "wrote what was recorded" in captured.err
    data = np.load(out / "tethered_wing.npz")
    assert 1 < data["t_s"].size < 100001 and data["t_s"][-1] == pytest.approx(data["t_s"].size - 1)
    assert (out / "tethered_wing_shape.png").is_file()


def test_ctrl_c_before_the_run_is_one_line_and_130(capsys):
    """A Ctrl-C outside the recorded run (the set-up, a forwarded command) ends the command with one line."""
    from laddermill_gym.cli import run_guarded

    def interrupted():
        raise KeyboardInterrupt

    assert run_guarded("stress", interrupted) == 130
    assert capsys.readouterr().err == "laddermill stress: interrupted (Ctrl-C)\n"


def test_step_counts_are_warned_and_refused():
    """dt 1e-12 once set up 10^12 steps with no output: above 1e9 steps refused, above 1e7 warned."""
    assert check_step_count(0.005, 60.0) is None
    assert "2e+07 steps" in check_step_count(1e-6, 20.0)
    with pytest.raises(ValueError, match=r"integrator.dt = 1e-12 s: 1 s of simulation would take 1e\+12 steps"):
        check_step_count(1e-12, 1.0)


def test_training_ends_at_the_next_step_after_ctrl_c(tmp_path):
    """``laddermill train``: the SB3 callback returns False (SB3 ends ``learn``) once Ctrl-C was pressed, after which
    the model and the evaluations so far are saved (``harness/train.train``)."""
    pytest.importorskip("stable_baselines3")
    from tqdm import tqdm

    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.harness.train import make_callback
    from laddermill_gym.sim.interrupt import StopRequest

    stop = StopRequest()
    with tqdm(total=10, disable=True) as bar:
        cb = make_callback(load_rl_config("ppo_tethered_wing"), tmp_path, None, bar, stop)
        cb.num_timesteps, cb.next_eval = 5, 10**9  # no evaluation, no checkpoint in this step
        cb.next_val = 10**9  # nor a validation (the config validates from its first step: control/rl_phases.py)
        assert cb._on_step() is True
        stop.count = 1
        assert cb._on_step() is False


def test_stress_quick_and_episodes_precedence():
    """``--quick`` lowers the default episodes; an explicit ``--episodes`` holds with it (no silent override)."""
    import argparse

    from laddermill_gym.studies.numerics import stress

    def episodes(*argv):
        p = argparse.ArgumentParser()
        stress.add_parser(p.add_subparsers())
        return stress.check_options(p.parse_args(["stress", "tethered_wing", *argv]))

    assert episodes() == stress.EPISODES and episodes("--quick") == stress.QUICK_EPISODES
    assert episodes("--quick", "--episodes", "7") == 7 and episodes("--episodes", "7") == 7
