"""torch's thread count for training (``laddermill train --torch-threads``, ``$LADDERMILL_TORCH_THREADS``): the
option wins over the variable, the variable over the default of one thread; bad values are refused by name."""

from __future__ import annotations

import pytest

from laddermill_gym.harness.train import TORCH_THREADS_VAR, torch_threads


def test_default_is_one_thread(monkeypatch):
    monkeypatch.delenv(TORCH_THREADS_VAR, raising=False)
    assert torch_threads() == 1


def test_option_then_variable(monkeypatch):
    monkeypatch.setenv(TORCH_THREADS_VAR, "4")
    assert torch_threads() == 4
    assert torch_threads(2) == 2


@pytest.mark.parametrize("value", ["0", "-1", "two", "1.5"])
def test_bad_variable_is_named(monkeypatch, value):
    monkeypatch.setenv(TORCH_THREADS_VAR, value)
    with pytest.raises(ValueError, match=f"{TORCH_THREADS_VAR} = '{value}'"):
        torch_threads()


def test_bad_option_is_named():
    with pytest.raises(ValueError, match="--torch-threads = 0"):
        torch_threads(0)


def test_train_command_refuses_a_bad_count(monkeypatch, capsys):
    from laddermill_gym.harness.train import main
    from laddermill_gym.model.configio import CONFIG_DIR

    monkeypatch.setenv(TORCH_THREADS_VAR, "none")
    with pytest.raises(SystemExit):
        main([str(CONFIG_DIR / "agents" / "ppo_tethered_wing.yaml")])
    assert f"{TORCH_THREADS_VAR} = 'none'" in capsys.readouterr().err
