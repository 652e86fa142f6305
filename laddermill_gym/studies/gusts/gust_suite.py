"""Versioned gust benchmark suites (``configs/benchmarks/<name>.yaml``): the strict reader.

A suite file has ``version`` (an integer) and ``envs``: per registered environment id, ``env_kwargs`` (a mapping
of the environment's arguments, not ``episode_time`` or ``disturbances``, which the scenarios set) and
``scenarios``: a list of ``{name, start [s], duration [s], seeds [list of int], disturbances [list of
mappings]}``. Unknown fields, bad values and bad disturbance entries raise ConfigError naming the file, the
field and the value.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from laddermill_gym.atmosphere.disturbance_spec import parse_disturbances
from laddermill_gym.model.configio import ConfigError, Section, find_config, read_yaml

__all__ = ["Scenario", "Suite", "load_suite"]


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
    """A suite: its name (file stem), ``version``, file and, per environment id, (env_kwargs, scenarios)."""

    name: str
    version: int
    path: Path
    envs: dict


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
    return Suite(Path(path).stem, int(version), Path(path), envs)
