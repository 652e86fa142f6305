"""Disturbances as plain data: every disturbance is a mapping ``{"type": <class name>, <parameter>: value, ...}``
(a YAML mapping, a JSON object, a Python dict), so an environment's ``disturbances=`` argument survives
``EnvSpec.to_json`` and rl-zoo3's saved ``config.yml``.

* :func:`disturbance_from_spec` builds one disturbance (unknown type or field, a bad value: ValueError naming
  the entry, the field and the value);
* :func:`parse_disturbances` takes what an environment accepts: None (its default), a disturbance or
  mapping, a list of them, or YAML text of a mapping or a list;
* :func:`disturbance_to_spec` writes a disturbance back as a mapping of plain values (tuples as lists), the
  inverse of :func:`disturbance_from_spec`.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import yaml

from laddermill_gym.atmosphere.disturbances import (
    DirectionStep,
    Disturbance,
    OneMinusCosineGust,
    RandomPerturbation,
    Schedule,
)
from laddermill_gym.atmosphere.iec_gusts import ECD, EDC, EOG, EWS, Ramp, SpeedStep
from laddermill_gym.atmosphere.turbulence import Turbulence

__all__ = ["DISTURBANCE_TYPES", "disturbance_from_dict", "disturbance_from_spec", "disturbance_to_spec",
           "parse_disturbances"]

#: Every disturbance type a mapping may name.
DISTURBANCE_TYPES: dict[str, type[Disturbance]] = {cls.__name__: cls for cls in (
    DirectionStep, OneMinusCosineGust, RandomPerturbation, Schedule, EOG, EDC, ECD, EWS, SpeedStep, Ramp,
    Turbulence)}


def _plain(value):
    """A YAML / JSON value: tuples and arrays as lists, numpy scalars as Python numbers."""
    if isinstance(value, (tuple, list, np.ndarray)):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    return value


def _typed(value):
    """Lists (YAML / JSON) as tuples, the form the frozen disturbances hold."""
    if isinstance(value, list):
        return tuple(_typed(v) for v in value)
    return value


def disturbance_from_spec(spec: dict, where: str = "disturbances") -> Disturbance:
    """A disturbance from a mapping ``{type: <class name>, <parameter>: value, ...}``; a two-element list is a
    (low, high) range drawn per episode where the type allows it. Raises ValueError naming ``where``, the
    field and the value."""
    if not isinstance(spec, dict) or "type" not in spec:
        raise ValueError(f"{where} = {spec!r}: must be a mapping with a 'type' (one of {sorted(DISTURBANCE_TYPES)})")
    kind = spec["type"]
    if kind not in DISTURBANCE_TYPES:
        raise ValueError(f"{where}.type = {kind!r}: must be one of {sorted(DISTURBANCE_TYPES)}")
    cls = DISTURBANCE_TYPES[kind]
    known = {f.name for f in dataclasses.fields(cls)}
    params = {}
    for key, value in spec.items():
        if key == "type":
            continue
        if key not in known:
            raise ValueError(f"{where}.{key} = {value!r}: unknown parameter of {kind} (known: {sorted(known)})")
        params[key] = _typed(value)
    try:
        dist = cls(**params)
        dist.sample(np.arange(3.0), np.random.default_rng(0))  # validate values and ranges now
    except (TypeError, ValueError) as err:
        raise ValueError(f"{where} ({kind}): {err}") from None
    return dist


#: The name the agent configs (``control/rl_config.py``) read their ``disturbances:`` entries with.
disturbance_from_dict = disturbance_from_spec


def disturbance_to_spec(dist: Disturbance) -> dict:
    """The mapping of a disturbance (every field, plain values): ``disturbance_from_spec`` of it is equal to
    ``dist``."""
    if not (isinstance(dist, Disturbance) and dataclasses.is_dataclass(dist)
            and DISTURBANCE_TYPES.get(type(dist).__name__) is type(dist)):
        raise ValueError(f"{dist!r}: not one of the disturbance types {sorted(DISTURBANCE_TYPES)}")
    out = {"type": type(dist).__name__}
    for f in dataclasses.fields(dist):
        out[f.name] = _plain(getattr(dist, f.name))
    return out


def parse_disturbances(value, default=None, where: str = "disturbances") -> tuple[Disturbance, ...]:
    """The disturbances an environment's ``disturbances=`` argument names: None gives ``default`` (a sequence
    of disturbances); otherwise a :class:`Disturbance`, a mapping, a list / tuple of either, or YAML text of
    a mapping or a list. Raises ValueError naming the entry (``disturbances[i]``), the field and the value."""
    if value is None:
        return tuple(default or ())
    if isinstance(value, str):
        try:
            value = yaml.safe_load(value)
        except yaml.YAMLError as err:
            raise ValueError(f"{where}: not valid YAML ({err})") from None
    if isinstance(value, (Disturbance, dict)):
        value = [value]
    if not isinstance(value, (list, tuple)):
        raise ValueError(f"{where} = {value!r}: must be a disturbance, a mapping or a list of them")
    out = []
    for i, d in enumerate(value):
        if isinstance(d, dict):
            d = disturbance_from_spec(d, f"{where}[{i}]")
        if not isinstance(d, Disturbance):
            raise ValueError(f"{where}[{i}] = {d!r}: not a Disturbance or its mapping")
        out.append(d)
    return tuple(out)


def spec_equal(a: Disturbance, b: Disturbance) -> bool:
    """Whether two disturbances have the same type and field values (NaN-free floats compared exactly)."""
    if type(a) is not type(b):
        return False
    for f in dataclasses.fields(a):
        x, y = _plain(getattr(a, f.name)), _plain(getattr(b, f.name))
        if isinstance(x, float) and isinstance(y, float) and math.isnan(x) and math.isnan(y):
            continue
        if x != y:
            return False
    return True
