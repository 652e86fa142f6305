"""The mutation campaign over the shipped configs (issue 34): every number, text, flag and list of a scene, wing,
cable or agent file changed one at a time into a wrong type, a negative, NaN, a huge value, removed, or joined by
an unknown field, then loaded the way the package loads it. Each outcome is a clear error (a ``ConfigError`` whose
message names the file, the field and the value), an accepted change with a documented meaning
(:data:`ACCEPTED`), or a defect: a raw error (any other exception) or a silent load.

``python -m tests.config_mutations`` prints the tally and every defect; ``tests/test_config_mutations.py`` holds it.
"""

from __future__ import annotations

import math
import shutil
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from fnmatch import fnmatch
from pathlib import Path
from typing import Any

import yaml

from laddermill_gym.model.configio import CONFIG_DIR, ConfigError, load_yaml_text

#: The files mutated (relative to configs/) and the scene a wing or cable file is loaded through.
SCENES = ("scenes/tethered_wing.yaml", "scenes/ladder_chain.yaml", "scenes/laddermill.yaml",
          "scenes/pumping_kite.yaml", "scenes/podgaets_5km.yaml")
PARTS = {"wings/meijaard_wing.yaml": "scenes/tethered_wing.yaml",
         "cables/dyneema_25mm.yaml": "scenes/tethered_wing.yaml"}
RL_AGENTS = ("agents/ppo_tethered_wing.yaml", "agents/sac_tethered_wing.yaml", "agents/ppo_laddermill.yaml",
             "agents/ppo_rotorcraft.yaml", "agents/ppo_pumping_kite.yaml")
LQR_AGENTS = ("agents/lqr_tethered_wing.yaml", "agents/lqr_ladder_chain.yaml", "agents/lqr_laddermill.yaml")

#: Changes that load on purpose, with their documented meaning: (field, kind) -> meaning; a field written with a
#: leading "*." matches that last part of any file's field.
ACCEPTED: dict[tuple[str, str], str] = {
    ("*.description", "missing"): "optional text, default ''",
    ("*.direction_inf_rad", "negative"): "wind turning the other way with height (bounds [-pi, pi])",
    ("*.direction_inf_rad", "missing"): "default 0: no turning",
    ("*.direction_height", "missing"): "default 500 m",
    ("*.density_model", "missing"): "default barometric (Meijaard eq. 3)",
    ("*.scale_height", "missing"): "default 8400 m",
    ("*.v1", "negative"): "wind falling with height above the boundary layer (bounds [-0.1, 0.1] 1/s)",
    ("*.Jxz", "negative"): "a product of inertia has either sign",
    ("*.ground_height", "negative"): "ground below the origin (bounds +-100 km)",
    ("*.ground_height", "missing"): "default 0 m",
    ("*.ground_contact", "missing"): "default stop",
    ("*.end", "missing"): "default null: a free upper end",
    ("*.alpha_deg", "negative"): "a negative target angle of attack (bounds +-90 deg)",
    ("*.alpha_deg", "missing"): "default 8 deg (point mass: the pitch default)",
    ("*.elevation_deg", "missing"): "default 45 deg",
    ("*.elevator_up_deg", "missing"): "default 0 deg",
    ("*.elevator_down_deg", "missing"): "default 0 deg",
    ("*.elevator_up_deg", "negative"): "a negative elevator within the wing's limits",
    ("*.elevator_down_deg", "negative"): "a negative elevator within the wing's limits",
    ("*.roll_deg", "negative"): "an attitude angle within +-180 deg",
    ("*.yaw_deg", "negative"): "an attitude angle within +-180 deg",
    ("*.pitch_deg", "negative"): "an attitude angle within +-180 deg",
    ("*.roll_deg", "missing"): "default 0 deg",
    ("*.yaw_deg", "missing"): "default 0 deg",
    ("*.pitch_deg", "missing"): "default: the rigid scene's alpha_deg, else 0",
    ("*.rtol", "missing"): "default 1e-8",
    ("*.atol", "missing"): "default 1e-10",
    ("*.max_speed", "missing"): "point mass: default 1000 m/s",
    ("*.seed", "missing"): "default 0",
    ("*.normalize_observations", "missing"): "default true",
    ("*.env_kwargs", "missing"): "default: the registered arguments",
    ("*.disturbances", "missing"): "default: none",
    ("*.hyperparameters", "missing"): "default: Stable-Baselines3's",
    ("*.policy_kwargs", "missing"): "default: Stable-Baselines3's",
    ("*.structure", "missing"): "default decentralised",
    ("*.first_fraction", "missing"): "default 0.1",
    ("*.last_fraction", "missing"): "default 1.1",
    ("*.efficiency", "missing"): "default 1",
    ("*.element_length", "missing"): "rigid scenes: unused by the rigid model",
    ("*.wing", "missing"): "default rigid",
    ("station", "missing"): "a scene without a station: the cable does not move (as ladder_chain)",
    ("*.mode", "missing"): "default prescribed",
    ("dimension", "missing"): "point mass: default 3 (the point-mass fidelity is 3D)",
    ("env_kwargs.*", "missing"): "default: the registered argument (envs.ENV_IDS) or its settings field",
    ("disturbances[[]*", "missing"): "default: the disturbance's own range (atmosphere/disturbances.py)",
    ("hyperparameters.*", "missing"): "default: Stable-Baselines3's",
    ("policy_kwargs.*", "missing"): "default: Stable-Baselines3's",
    ("net_arch", "short"): "a network of one hidden layer",
    ("*.net_arch.vf", "short"): "a critic of one hidden layer",
    ("init_from", "missing"): "default: the actor starts from random weights",
    ("critic_warmup", "missing"): "default: no critic-only phase (the actor learns from the first update)",
    ("validation", "missing"): "default: the kept model is the best on the registered evaluation scenario",
    ("validation.sets.*", "missing"): "a validation set fewer (the others still select the kept model)",
    ("validation.sets.*.disturbances[[]*", "missing"): "default: the disturbance's own range "
                                                        "(atmosphere/disturbances.py)",
    ("log_std_init", "negative"): "a smaller initial action noise (bounds [-20, 2])",
    ("seed", "huge"): "any seed in numpy's range [0, 2^32)",
    ("total_timesteps", "huge"): "an upper bound: time_limit_minutes ends training first",
    ("time_limit_minutes", "huge"): "no time limit: total_timesteps ends training first",
    ("checkpoint_every", "huge"): "no checkpoint before the final model",
    ("eval.every", "huge"): "evaluated at the start and at the end only",
    ("*.failure_penalty", "huge"): "a reward weight: any finite number >= 0 (envs/task_settings.py)",
    ("*.reference_power", "huge"): "the power the reward is divided by: any power > 0 W",
}


@dataclass(frozen=True)
class Mutation:
    """One change: ``file`` (relative to configs/), the dotted ``field``, the ``kind`` of change, the ``keys`` into
    the YAML data and the ``value`` written (None for "missing")."""

    file: str
    field: str
    kind: str
    keys: tuple
    value: Any

    @property
    def label(self) -> str:
        return f"{self.file}:{self.field}:{self.kind}"


def _dotted(keys: tuple) -> str:
    out = ""
    for k in keys:
        out += f"[{k}]" if isinstance(k, int) else (f".{k}" if out else str(k))
    return out


def _number_changes(v) -> list[tuple[str, Any]]:
    huge = int(v * 10**6) if isinstance(v, int) and v else (v * 1e6 if v else 1e6)
    return [("text", "abc"), ("negative", -abs(v) - (1 if isinstance(v, int) else 1.0)), ("nan", math.nan),
            ("huge", huge)]


#: Free-text fields: any text is a valid value (no "unknown name" change).
FREE_TEXT = ("name", "description")


def _leaf_changes(v, key) -> list[tuple[str, Any]]:
    if isinstance(v, bool):
        return [("text", "maybe")]
    if isinstance(v, (int, float)):
        return _number_changes(v)
    if isinstance(v, str):
        return [("number", 42)] + ([] if key in FREE_TEXT else [("unknown_name", v + "_nosuch")])
    if isinstance(v, list) and v and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in v):
        return [("text", ["abc", *v[1:]]), ("nan", [math.nan, *v[1:]]), ("huge", [v[0] * 1e6 + 1e6, *v[1:]]),
                ("short", v[:-1])]
    return []


def mutations_of(file: str) -> Iterator[Mutation]:
    """Every change of ``file``: each leaf's changes, each mapping's leaves removed and an unknown field added."""
    data = load_yaml_text((CONFIG_DIR / file).read_text(), file)

    def walk(node, keys):
        if isinstance(node, dict):
            yield Mutation(file, _dotted((*keys, "typo_field")), "unknown", (*keys, "typo_field"), 1.0)
            for k, v in node.items():
                if v is not None and k != "type":
                    yield Mutation(file, _dotted((*keys, k)), "missing", (*keys, k), None)
                yield from walk(v, (*keys, k))
            return
        if isinstance(node, list) and node and all(isinstance(x, dict) for x in node):
            for i, item in enumerate(node):
                yield from walk(item, (*keys, i))
            return
        for kind, value in _leaf_changes(node, keys[-1] if keys else None):
            yield Mutation(file, _dotted(keys), kind, keys, value)

    yield from walk(data, ())


def all_mutations() -> list[Mutation]:
    return [m for f in (*SCENES, *PARTS, *RL_AGENTS, *LQR_AGENTS) for m in mutations_of(f)]


def _apply(data, m: Mutation):
    node = data
    for k in m.keys[:-1]:
        node = node[k]
    if m.kind == "missing":
        del node[m.keys[-1]]
    else:
        node[m.keys[-1]] = m.value
    return data


def _shown(value) -> list[str]:
    """The ways a message may show ``value``."""
    if isinstance(value, list):
        return [s for s in _shown(value[0]) if s]  # a list is shown whole: its changed first entry is in it
    if isinstance(value, float):
        return [repr(value), str(value), f"{value:g}", f"{value:.4g}", f"{value:.6g}"]
    return [repr(value), str(value)]


def accepted(m: Mutation) -> str | None:
    """The documented meaning of a change that loads on purpose, else None."""
    last = m.field.rsplit(".", 1)[-1]
    for (pattern, kind), meaning in ACCEPTED.items():
        if kind == m.kind and (fnmatch(m.field, pattern) or fnmatch(last, pattern.removeprefix("*."))):
            return meaning
    return None


def judge(m: Mutation, err: BaseException | None) -> str:
    """'clear', 'accepted', 'silent' (loaded, no documented meaning), 'raw' (not a ConfigError) or 'vague' (a
    ConfigError not naming the file, the field or the value)."""
    if err is None:
        return "accepted" if accepted(m) else "silent"
    if not isinstance(err, ConfigError):
        return "raw"
    msg = str(err)
    file_ok = Path(m.file).name in msg
    field = m.field.split("[")[0]
    parent = field.rsplit(".", 1)[0] if m.kind == "missing" and "." in field else field  # a section lacking it
    field_ok = any(f in msg for f in (field, field.rsplit(".", 1)[-1], f"'{parent}'"))
    value_ok = m.kind in ("missing",) or any(s in msg for s in _shown(m.value))
    return "clear" if file_ok and field_ok and value_ok else "vague"


class Campaign:
    """A writable copy of the configs in ``root`` on which mutations are applied one at a time and loaded."""

    def __init__(self, root: Path):
        self.root = root
        for kind in ("scenes", "wings", "cables", "agents"):
            shutil.copytree(CONFIG_DIR / kind, root / kind, dirs_exist_ok=True)
        self.original = {f: (root / f).read_text() for f in (*SCENES, *PARTS, *RL_AGENTS, *LQR_AGENTS)}

    def loader(self, file: str) -> Callable[[], Any]:
        if file.startswith("scenes/") or file in PARTS:
            from laddermill_gym.ladder.scene import load_scene

            return lambda: load_scene(self.root / PARTS.get(file, file))
        if file in LQR_AGENTS:
            from laddermill_gym.control.lqr_config import load_lqr_config

            return lambda: load_lqr_config(self.root / file)
        from laddermill_gym.control.rl_config import load_rl_config

        return lambda: load_rl_config(self.root / file)

    def run(self, m: Mutation) -> tuple[str, BaseException | None]:
        """(verdict, the error) of one mutation; the file is restored afterwards."""
        path = self.root / m.file
        data = _apply(load_yaml_text(self.original[m.file], m.file), m)
        path.write_text(yaml.safe_dump(data, sort_keys=False))
        err = None
        try:
            self.loader(m.file)()
        except Exception as e:  # noqa: BLE001 (every outcome is judged)
            err = e
        finally:
            path.write_text(self.original[m.file])
        return judge(m, err), err


def main() -> None:
    import tempfile
    from collections import Counter

    muts = all_mutations()
    with tempfile.TemporaryDirectory() as tmp:
        c = Campaign(Path(tmp))
        tally, bad = Counter(), []
        for m in muts:
            verdict, err = c.run(m)
            tally[verdict] += 1
            if verdict not in ("clear", "accepted"):
                bad.append(f"{verdict:8s} {m.label} = {m.value!r}: {type(err).__name__ if err else ''} {err or ''}")
    errors = len(muts) - tally["accepted"]
    print(f"{len(muts)} mutations: {dict(tally)}; clear {tally['clear']} of {errors} errors "
          f"({100 * tally['clear'] / max(errors, 1):.1f} %)")
    print("\n".join(bad))


if __name__ == "__main__":
    main()
