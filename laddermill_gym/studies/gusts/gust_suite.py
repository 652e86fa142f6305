"""Versioned gust benchmark suites (``configs/benchmarks/<name>.yaml``): the strict reader.

A suite file has ``version`` (an integer) and ``envs``: per registered environment id, ``env_kwargs`` (a mapping
of the environment's arguments, not ``episode_time`` or ``disturbances``, which the scenarios set) and
``scenarios``: a list of ``{name, start [s], duration [s], seeds [list of int], disturbances [list of
mappings]}``. Unknown fields, bad values (the env arguments' values too, checked as a training config's are, without
building the env) and bad disturbance entries raise ConfigError naming the file, the field and the value.

A shipped suite is frozen: its file's SHA-256 is pinned here (:data:`SHIPPED_SHA256`), and a suite of a shipped
name whose file does not match is refused, naming the file and both hashes (a changed suite is a new version). The
suites up to gusts-v5 leave ``low_frequencies`` to the code's default, ``rescale`` (their files do not say so:
writing it in would change the scenarios as loaded); ``tests/test_gust_bench_harness.py`` holds that default to them.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path

from laddermill_gym.atmosphere.disturbance_spec import parse_disturbances
from laddermill_gym.model.configio import ConfigError, Section, find_config, read_yaml

__all__ = ["Scenario", "Suite", "load_suite", "SHIPPED_SHA256", "file_sha256"]

#: SHA-256 of each shipped suite file (``configs/benchmarks/<name>.yaml``), pinned when the suite was frozen
SHIPPED_SHA256 = {
    "gusts-v1": "2886b162ce38570babb27327e3fc5fd76bbcc1496c11e7d56038934e4a304250",
    "gusts-v2": "1beaaf75ee03a293e09f262da94997b9b835283757d3d77592d6f4275476aecb",
    "gusts-v3": "50e50b2d866ce5f6bdef6a27c4c372debbc9b79f1f34249221751e3a38fdf5d4",
    "gusts-v4": "3690ca8ea2b122ffe8c478f139273f65211b38bc92baf183d4490f294f8c9aca",
    "gusts-v5": "2a0ccdc1c74f2853d3458453021e9fd7f90a6ae4e86ac98e5de7ad54a5f067d6",
    "gusts-v6": "ac8e149a237c0778a7f50555f19768d051812e25a30d85e3f58b44a1fdca0eef",
}


@dataclass(frozen=True)
class Scenario:
    """One named episode set: ``disturbances`` (plain mappings), ``start`` and ``duration`` [s], ``seeds``."""

    name: str
    start: float
    duration: float
    seeds: tuple[int, ...]
    disturbances: tuple[dict, ...]


@dataclass(frozen=True)
class Suite:
    """A suite: its name (file stem), ``version``, file and, per environment id, (env_kwargs, scenarios); ``sha256``
    the file's SHA-256 (hex) as read."""

    name: str
    version: int
    path: Path
    envs: dict
    sha256: str = ""


def file_sha256(path: str | Path) -> str:
    """The SHA-256 (hex) of the bytes of the file at ``path``."""
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def _check_frozen(path: Path) -> str:
    """The SHA-256 of the suite file ``path``; ConfigError naming the file and both hashes when its name is a shipped
    suite's (:data:`SHIPPED_SHA256`) and its content is not that suite's."""
    digest = file_sha256(path)
    pinned = SHIPPED_SHA256.get(Path(path).stem)
    if pinned is not None and digest != pinned:
        raise ConfigError(f"{path}: SHA-256 {digest}, not the frozen suite {Path(path).stem}'s {pinned}: a shipped "
                          "suite is never changed (a change is a new version, configs/benchmarks/<name>-vN.yaml; a "
                          "suite of your own needs a name of its own)")
    return digest


def _check_env_values(path: Path, env_id: str, kwargs: dict) -> None:
    """ConfigError naming ``envs.<env_id>.env_kwargs.<key>`` and its value for an env argument the env would refuse:
    its type and range, settings mappings, named files and choices as a training config's
    (``control.rl_env_kwargs.check_env_kwargs``, without building the env) and the physics step
    (``envs.physics_step.check_physics_step``). The episode against the control period is the scenarios' check."""
    from laddermill_gym.control.rl_env_kwargs import check_env_kwargs
    from laddermill_gym.envs.physics_step import check_physics_step

    field = f"envs.{env_id}.env_kwargs"
    probe = dict(kwargs)
    if "control_dt" in probe:  # one period (after control_dt's own check): the durations are checked below
        probe["episode_time"] = probe["control_dt"]
    try:
        check_env_kwargs(Section({}, path), env_id, probe)
    except ConfigError as err:
        raise ConfigError(str(err).replace("field 'env_kwargs.", f"field '{field}.")) from None
    try:
        check_physics_step(kwargs.get("physics_step"))
    except ValueError as err:
        why = str(err).split(": ", 1)[-1]  # "physics_step = VALUE: WHY"
        raise ConfigError(f"{path}: field '{field}.physics_step' = {kwargs['physics_step']!r}: {why}") from None


def _scenario(sec: Section) -> Scenario:
    name = sec.text("name")
    start = sec.number("start", nonneg=True)
    duration = sec.number("duration", positive=True)
    if start >= duration:
        raise sec.error("start", start, f"must be before the end of the episode (duration {duration} s)")
    seeds = sec.raw("seeds")
    if not (isinstance(seeds, list) and seeds and all(isinstance(s, int) and not isinstance(s, bool) and s >= 0
                                                      for s in seeds)) or len(set(seeds)) != len(seeds):
        raise sec.error("seeds", seeds, "must be a non-empty list of distinct integers >= 0")
    dist = sec.raw("disturbances")
    if not isinstance(dist, list):
        raise sec.error("disturbances", dist, "must be a list of disturbance mappings")
    try:
        parse_disturbances(dist, where=f"{sec.path}.disturbances")
    except ValueError as err:
        raise ConfigError(f"{sec.file}: {err}") from None
    sec.done()
    return Scenario(name, start, duration, tuple(seeds), tuple(dict(d) for d in dist))


def load_suite(name_or_path: str | Path) -> Suite:
    """The suite ``configs/benchmarks/<name>.yaml`` (or a YAML path), checked: known environment ids, the
    environments' arguments, unique scenario names, valid disturbances."""
    from laddermill_gym.envs import ENV_IDS, env_arguments, episode_argument_error

    path = find_config("benchmarks", name_or_path, "suite")
    digest = _check_frozen(path)
    top = read_yaml(path)
    version = top.number("version", integer=True, positive=True)
    envs_sec = top.section("envs")
    top.done()
    envs = {}
    for env_id in list(envs_sec.data):
        sec = envs_sec.section(env_id)
        if env_id not in ENV_IDS:
            raise ConfigError(f"{path}: field 'envs.{env_id}': not a registered environment ({sorted(ENV_IDS)})")
        kw = sec.section("env_kwargs", {})
        known = set(env_arguments(env_id)) - {"episode_time", "disturbances"}
        for key in kw.data:
            if key not in known:
                raise kw.error(key, kw.data[key], f"{env_id} takes no such argument here (known: {sorted(known)})")
        _check_env_values(path, env_id, kw.data)
        scen_list = sec.raw("scenarios")
        if not isinstance(scen_list, list) or not scen_list:
            raise sec.error("scenarios", scen_list, "must be a non-empty list")
        sec.done()
        scenarios = tuple(_scenario(Section(s, path, f"envs.{env_id}.scenarios[{i}]"))
                          for i, s in enumerate(scen_list))
        for i, sc in enumerate(scenarios):  # an episode is a whole number of control periods (the env refuses it)
            why = episode_argument_error(env_id, dict(kw.data, episode_time=sc.duration))
            if why:
                raise ConfigError(f"{path}: field 'envs.{env_id}.scenarios[{i}].duration' = {sc.duration!r} s: {why}")
        names = [s.name for s in scenarios]
        if len(set(names)) != len(names):
            raise sec.error("scenarios", names, "scenario names must be unique")
        envs[env_id] = (dict(kw.data), scenarios)
    envs_sec.used.update(envs_sec.data)
    return Suite(Path(path).stem, int(version), Path(path), envs, digest)
