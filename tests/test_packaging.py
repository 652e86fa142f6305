"""Packaging: the package list in pyproject.toml, a wheel that runs outside the repository, user scenes.

The wheel is built from a copy of the source files in a temporary folder, not from the repository itself:
setuptools packs whatever lies in the repository's ``build/lib`` (stale modules of earlier builds included)
and would write ``build/`` and ``*.egg-info`` into the working tree.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import textwrap
import tomllib
import zipfile
from pathlib import Path

import gymnasium as gym
import pytest
import yaml
from gymnasium.envs.registration import load_env_creator

import laddermill_gym
from laddermill_gym.model.configio import ConfigError

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "laddermill_gym"
CONFIGS = ROOT / "configs"


def _pyproject() -> dict:
    with open(ROOT / "pyproject.toml", "rb") as fh:
        return tomllib.load(fh)


def _source_packages() -> set[str]:
    """Dotted names of the folders under laddermill_gym/ that hold an __init__.py."""
    return {".".join(init.parent.relative_to(ROOT).parts) for init in PACKAGE.rglob("__init__.py")
            if "__pycache__" not in init.parts}


# ------------------------------------------------------------------------------------------- a. package list
def test_pyproject_lists_every_package():
    setuptools_cfg = _pyproject()["tool"]["setuptools"]
    listed = setuptools_cfg["packages"]
    assert len(listed) == len(set(listed)), f"pyproject.toml lists a package twice: {sorted(listed)}"
    want = _source_packages() | {"laddermill_gym.configs"}
    missing, extra = sorted(want - set(listed)), sorted(set(listed) - want)
    assert not missing and not extra, (f"pyproject.toml [tool.setuptools] packages: missing {missing} "
                                       f"(folders with an __init__.py), extra {extra} (no such package folder)")
    assert setuptools_cfg["package-dir"] == {"laddermill_gym.configs": "configs"}


# ------------------------------------------------------------------------------------------- b. the wheel
#: Run inside the wheel's install, from a folder outside the repository; prints one JSON line.
_WHEEL_SCRIPT = textwrap.dedent("""
    import json
    import sys

    import gymnasium as gym
    import numpy as np
    from gymnasium.envs.registration import load_env_creator

    import laddermill_gym
    from laddermill_gym.envs import ENV_IDS
    from laddermill_gym.ladder.scene import available_scenes
    from laddermill_gym.model.configio import CONFIG_DIR
    from laddermill_gym.rotorcraft.config import load_craft_config

    out = {"package": laddermill_gym.__file__, "config_dir": str(CONFIG_DIR), "scenes": available_scenes()}
    scene = laddermill_gym.load_scene("tethered_wing")
    sim = scene.simulator()
    x = sim.step(n_steps=5).copy()
    out["scene_file"] = str(scene.file)
    out["sim"] = {"t": sim.t, "finite": bool(np.all(np.isfinite(x))), "moved": bool(np.any(x != sim.initial_state))}
    out["envs"] = {}
    # the laddermill's default start costs ~20 s (its periodic motion); an 11-wing mill settled for 50 s will do here
    small = {f"laddermill_gym/LadderMill-v{v}": {"scene_options": {"n_wings": 11}, "settle": {"max_time": 50.0}}
             for v in (0, 1, 2, 3)}
    # every id's entry point imports from the wheel; the ids named on the command line ("all": every id) are made,
    # reset and stepped (each family compiles its kernels anew in the empty cache: about 30 s each)
    out["entry_points"] = {env_id: load_env_creator(gym.spec(env_id).entry_point).__module__ for env_id in ENV_IDS}
    for env_id in ENV_IDS if sys.argv[1:] == ["all"] else sys.argv[1:]:
        env = gym.make(env_id, **small.get(env_id, {}))
        obs, _ = env.reset(seed=0)
        env.action_space.seed(0)
        obs2, reward, terminated, truncated, _ = env.step(env.action_space.sample())
        out["envs"][env_id] = {"finite": bool(np.all(np.isfinite(obs)) and np.all(np.isfinite(obs2))),
                               "reward": float(reward), "module": type(env.unwrapped).__module__}
        env.close()
    craft = load_craft_config("roberts_flying_model")
    out["craft"] = {"name": craft.name, "file": str(craft.file), "mass": craft.mass}
    # the command line: help and a short simulation, from this folder
    import contextlib
    import io
    import os

    from laddermill_gym.cli import main as cli_main

    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        try:
            cli_main(["--help"])
        except SystemExit as e:
            out["cli_help"] = {"exit": e.code, "lists_simulate": "simulate" in buf.getvalue()}
        code = cli_main(["simulate", "tethered_wing", "--time", "0.5", "--out", "sim_out", "--quiet"])
    out["cli_simulate"] = {"exit": code, "npz": os.path.isfile(os.path.join("sim_out", "tethered_wing.npz"))}
    # a short Stable-Baselines3 run on the batched env (when the rl extra is installed)
    try:
        from stable_baselines3 import PPO
    except ImportError:
        out["sb3"] = None
    else:
        import torch

        from laddermill_gym.envs.sb3 import sb3_vec_env

        torch.set_num_threads(1)
        venv = sb3_vec_env("laddermill_gym/TetheredWing-v0", 2, seed=0, episode_time=5.0)
        model = PPO("MlpPolicy", venv, n_steps=250, batch_size=100, n_epochs=1, seed=0, device="cpu")
        model.learn(1000)
        out["sb3"] = {"steps": int(model.num_timesteps)}
    print("RESULT " + json.dumps(out))
""")


def _run(cmd: list[str], what: str, **kw) -> subprocess.CompletedProcess:
    proc = subprocess.run(cmd, capture_output=True, text=True, **kw)
    assert proc.returncode == 0, (f"{what} failed (exit {proc.returncode}): {' '.join(map(str, cmd))}\n"
                                  f"--- stdout ---\n{proc.stdout[-4000:]}\n--- stderr ---\n{proc.stderr[-8000:]}")
    return proc


@pytest.fixture(scope="module")
def wheel_site(tmp_path_factory) -> tuple[Path, Path]:
    """(wheel, site folder it is installed in) built offline from a copy of the source files."""
    tmp = tmp_path_factory.mktemp("wheel")
    src = tmp / "src"
    src.mkdir()
    junk = shutil.ignore_patterns("__pycache__", "*.py[cod]", "*.nbi", "*.nbc", "figures")
    for name in ("pyproject.toml", "README.md"):
        shutil.copy2(ROOT / name, src / name)
    shutil.copytree(PACKAGE, src / "laddermill_gym", ignore=junk)
    shutil.copytree(CONFIGS, src / "configs", ignore=junk)
    env = {**os.environ, "PIP_DISABLE_PIP_VERSION_CHECK": "1", "PIP_NO_INPUT": "1"}
    _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "--no-index", ".",
          "-w", str(tmp / "dist")], "building the wheel", cwd=src, env=env, timeout=300)
    wheels = list((tmp / "dist").glob("laddermill_gym-*.whl"))
    assert len(wheels) == 1, f"expected one wheel in {tmp / 'dist'}, got {wheels}"
    site = tmp / "site"
    _run([sys.executable, "-m", "pip", "install", "--no-deps", "--no-index", "--target", str(site), str(wheels[0])],
         "installing the wheel", cwd=tmp, env=env, timeout=300)
    return wheels[0], site


def test_wheel_holds_the_sources_and_configs(wheel_site):
    wheel, _ = wheel_site
    with zipfile.ZipFile(wheel) as zf:
        names = {n for n in zf.namelist() if not n.startswith("laddermill_gym-")}
    modules = {n for n in names if n.endswith(".py")}
    want_modules = {p.relative_to(ROOT).as_posix() for p in PACKAGE.rglob("*.py") if "__pycache__" not in p.parts}
    assert modules == want_modules, (f"wheel modules: missing {sorted(want_modules - modules)}, "
                                     f"extra {sorted(modules - want_modules)}")
    configs = {n for n in names if n.startswith("laddermill_gym/configs/")}
    want_configs = {"laddermill_gym/configs/" + p.relative_to(CONFIGS).as_posix()
                    for pattern in ("*/*.yaml", "*/*.csv", "*/*.csv.gz", "*/*.txt", "*/*.md")
                    for p in CONFIGS.glob(pattern)}
    assert configs == want_configs, (f"wheel configs: missing {sorted(want_configs - configs)}, "
                                     f"extra {sorted(configs - want_configs)}")
    assert "laddermill_gym/py.typed" in names
    policies = {p.relative_to(ROOT).as_posix() for p in (PACKAGE / "policies").rglob("*") if p.is_file()}
    assert policies <= names, f"wheel policies: missing {sorted(policies - names)}"  # model, actor, stats, README


@pytest.mark.parametrize("made", [pytest.param(["laddermill_gym/TetheredWing-v0"], id="one-env"),
                                  pytest.param(["all"], id="every-env", marks=pytest.mark.slow)])
def test_wheel_runs_outside_the_repository(wheel_site, tmp_path, made):
    """The wheel's install, from a folder outside the repository, with an empty numba cache: a simulation, every
    env id's entry point, the envs ``made`` (one family by default; ``-m slow``: every id), the command line and
    a short SB3 run."""
    _, site = wheel_site
    work = tmp_path / "elsewhere"
    work.mkdir()
    (work / "check_wheel.py").write_text(_WHEEL_SCRIPT, encoding="utf-8")
    env = {**os.environ, "PYTHONPATH": str(site), "NUMBA_CACHE_DIR": str(tmp_path / "numba_cache"),
           "MPLBACKEND": "Agg", "PYTHONDONTWRITEBYTECODE": "1"}
    proc = _run([sys.executable, "check_wheel.py", *made], "the wheel's smoke run", cwd=work, env=env, timeout=600)
    lines = [ln for ln in proc.stdout.splitlines() if ln.startswith("RESULT ")]
    assert lines, f"no RESULT line\n--- stdout ---\n{proc.stdout[-4000:]}\n--- stderr ---\n{proc.stderr[-8000:]}"
    out = json.loads(lines[-1][len("RESULT "):])
    site_r = site.resolve()

    def in_site(p: str) -> bool:
        return Path(p).resolve().is_relative_to(site_r)

    assert in_site(out["package"]), f"laddermill_gym imported from {out['package']}, not the wheel's {site}"
    assert in_site(out["config_dir"]), f"configs found at {out['config_dir']}, not in the wheel's {site}"
    assert in_site(out["scene_file"]) and in_site(out["craft"]["file"])
    assert out["scenes"] == sorted(p.stem for p in (ROOT / "configs" / "scenes").glob("*.yaml"))
    assert out["sim"]["finite"] and out["sim"]["moved"] and out["sim"]["t"] > 0
    assert out["entry_points"] == {env_id: load_env_creator(gym.spec(env_id).entry_point).__module__
                                   for env_id in laddermill_gym.envs.ENV_IDS}  # the same modules as in the tree
    assert set(out["envs"]) == (set(laddermill_gym.envs.ENV_IDS) if made == ["all"] else set(made))
    for env_id, r in out["envs"].items():
        assert r["finite"], f"{env_id}: observation not finite"
        assert r["module"].startswith("laddermill_gym."), r
    assert out["craft"]["name"] == "roberts_flying_model"
    assert out["cli_help"] == {"exit": 0, "lists_simulate": True}
    assert out["cli_simulate"] == {"exit": 0, "npz": True}
    try:
        import stable_baselines3  # noqa: F401
    except ImportError:
        assert out["sb3"] is None
    else:
        assert out["sb3"]["steps"] >= 1000


# ------------------------------------------------------------------------------------------- c. user scenes
def _user_scene(folder: Path, wing_type: str, cable: str) -> Path:
    text = (CONFIGS / "scenes" / "tethered_wing.yaml").read_text(encoding="utf-8")
    text, n_wing = re.subn(r"(?m)^wing_type:.*$", f"wing_type: {wing_type}", text)
    text, n_cable = re.subn(r"(?m)^cable:.*$", f"cable: {cable}", text)
    assert n_wing == 1 and n_cable == 1, "configs/scenes/tethered_wing.yaml: no single wing_type:/cable: line"
    path = folder / "my_scene.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def test_user_scene_outside_the_repository(tmp_path, monkeypatch):
    user = tmp_path / "user"
    user.mkdir()
    # not the scene's own cable (dyneema_25mm), so the values show which file was read
    shutil.copy2(CONFIGS / "cables" / "kevlar_2p5mm.yaml", user / "my_cable.yaml")
    path = _user_scene(user, "package:wings/meijaard_wing.yaml", "my_cable.yaml")
    other = tmp_path / "cwd"
    other.mkdir()
    monkeypatch.chdir(other)  # the cable path is relative to the scene file, not to the working directory

    scene = laddermill_gym.load_scene(path)

    wing = yaml.safe_load((CONFIGS / "wings" / "meijaard_wing.yaml").read_text(encoding="utf-8"))
    cable = yaml.safe_load((CONFIGS / "cables" / "kevlar_2p5mm.yaml").read_text(encoding="utf-8"))
    assert scene.file == path
    (wing_type,) = scene.assembly.wing_types
    assert wing_type.mass == wing["mass"]
    assert wing_type.name == wing["name"]
    assert set(cable) == {"diameter", "mass_per_length", "EA", "DA", "breaking_load", "cn0", "ct0"}
    for key, value in cable.items():
        assert getattr(scene.cable, key) == value, key
    assert scene.assembly.cable_cn0 == cable["cn0"] and scene.assembly.cable_ct0 == cable["ct0"]


@pytest.mark.parametrize(("field", "wing_type", "cable", "missing"), [
    ("wing_type", "no_such_folder/no_wing.yaml", "my_cable.yaml", "no_wing.yaml"),
    ("wing_type", "package:wings/no_wing.yaml", "my_cable.yaml", "no_wing.yaml"),
    ("wing_type", "no_wing", "my_cable.yaml", "no_wing.yaml"),
    ("cable", "package:wings/meijaard_wing.yaml", "no_cable.yaml", "no_cable.yaml"),
])
def test_missing_part_names_scene_file_and_field(tmp_path, field, wing_type, cable, missing):
    shutil.copy2(CONFIGS / "cables" / "kevlar_2p5mm.yaml", tmp_path / "my_cable.yaml")
    path = _user_scene(tmp_path, wing_type, cable)
    with pytest.raises(ConfigError) as err:
        laddermill_gym.load_scene(path)
    msg = str(err.value)
    assert str(path) in msg and f"field '{field}'" in msg and missing in msg and "no such file" in msg, msg
