"""The disturbance lists and optional phases of a training config (:mod:`laddermill_gym.control.rl_config`), read
strictly.

* ``init_from``: the linear actor of a PPO policy started at a model-based controller
  (:mod:`laddermill_gym.control.warm_start`);
* ``critic_warmup``: the first ``steps`` env steps train the critic only (the actor's weights and its action noise
  frozen), at their own ``learning_rate``: PPO's first policy updates then use advantages of a critic that has
  learned the started policy's values, rather than of random weights;
* ``validation``: every ``every`` env steps the deterministic policy flies ``episodes`` episodes of each named set
  of DRAWN disturbances (seeds ``seed``, ``seed`` + 1, ..., or from a set's own ``seed``; two sets of one
  turbulence model on the same seeds fly the same fields, scaled, which the harness warns of; a benchmark's own
  scripted scenarios and seeds are never a validation set), and the policy that survives the most of them is kept
  as the run's ``best_model.zip``
  (:mod:`laddermill_gym.harness.validation`); its optional ``selection`` ranks them by episodes survived (the
  default, ``rule: survived``) or, ``rule: paired``, by episodes survived minus ``penalty`` x the episodes a
  ``reference`` controller (the LQR) survives and the policy loses, its outcomes flown once per run.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from laddermill_gym.atmosphere.disturbance_spec import disturbance_from_dict
from laddermill_gym.model.configio import ConfigError, Section

__all__ = ["check_disturbances", "DISTURBANCE_BOUNDS", "GRID_EXTENT", "RESIDUAL_ALGORITHM", "CriticWarmup",
           "ValidationSet", "Validation", "Selection", "read_init_from", "read_critic_warmup", "read_validation"]


@dataclass(frozen=True)
class CriticWarmup:
    """The critic-only phase: ``steps`` env steps (all copies) at ``learning_rate``."""

    steps: int
    learning_rate: float


@dataclass(frozen=True)
class ValidationSet:
    """``episodes`` episodes of the drawn ``disturbances`` (mappings as a config's ``disturbances``); ``seed``: the
    set's first episode seed (None: the validation's ``seed``)."""

    name: str
    episodes: int
    disturbances: list[dict[str, Any]]
    seed: int | None = None


@dataclass(frozen=True)
class Selection:
    """How validated policies are ranked: ``rule`` ``survived`` (episodes survived, then the smaller RMS lateral
    excursion) or ``paired`` (episodes survived minus ``penalty`` [-] x the episodes the ``reference`` controller,
    a factory spec ``lqr`` or ``lqr:<config>``, survives and the policy loses; then the smaller RMS)."""

    rule: str = "survived"
    penalty: float = 0.0
    reference: str = "lqr"


@dataclass(frozen=True)
class Validation:
    """Checkpoint selection on drawn disturbances: every ``every`` env steps, the sets' episodes of
    ``episode_time`` [s], copy i of a set seeded ``seed + i``, ranked by ``selection``."""

    every: int
    seed: int
    episode_time: float
    sets: tuple[ValidationSet, ...]
    selection: Selection = Selection()


#: Disturbance parameters a config may set beyond the disturbances' own checks: (bound, why).
DISTURBANCE_BOUNDS: dict[str, tuple[float, str]] = {
    "speed_std": (1.0, "a standard deviation of the speed factor of the whole mean wind"),
    "direction_std": (math.pi, "rad: half a turn"),
    "correlation_time": (86400.0, "s: a day"),
    "w20": (100.0, "m/s: the turbulence's wind at 20 ft (MIL-HDBK-1797 severe: 45 kt = 23 m/s)"),
    "wind_speed": (150.0, "m/s: the fastest wind (ladder/bounds.py)"),
    "fade_in": (86400.0, "s: a day"),
    "hub_height": (1.0e5, "m: the extent of a turbulence grid (GRID_EXTENT)"),
    "dh": (1000.0, "m: a turbulence grid's row spacing"),
    "dxi": (1000.0, "m: a turbulence grid's column spacing"),
}
#: Extent [m] of a turbulence grid's ``heights`` and ``along_wind`` pairs: 100 km, beyond every system here (the
#: mill's chain reaches 3.6 km); a larger grid would not fit in memory
GRID_EXTENT = 1.0e5


def check_disturbances(s: Section) -> list:
    """The ``disturbances`` list, each entry read by ``atmosphere.disturbance_spec`` (errors naming the entry, the
    field and the value), its flags true or false and the numbers of :data:`DISTURBANCE_BOUNDS` within them."""
    import dataclasses

    disturbances = s.raw("disturbances", []) or []
    if not isinstance(disturbances, list):
        raise s.error("disturbances", disturbances, "must be a list of mappings with a 'type'")
    for i, d in enumerate(disturbances):
        if not isinstance(d, dict):
            raise s.error(f"disturbances[{i}]", d, "must be a mapping with a 'type'")
        entry = Section(d, s.file, f"disturbances[{i}]")
        for key, value in d.items():
            if isinstance(value, list):
                entry.vector(key)  # a range [low, high]: numbers
        try:
            dist = disturbance_from_dict(d, f"disturbances[{i}]")
        except ValueError as err:
            raise ConfigError(f"{s.file}: {err}") from None
        for f in dataclasses.fields(dist):
            if f.name in d and isinstance(f.default, bool):
                entry.flag(f.name)
            elif f.name in d and f.name in DISTURBANCE_BOUNDS:
                high, why = DISTURBANCE_BOUNDS[f.name]
                entry.number(f.name, nonneg=True, high=high, why=why)
            elif f.name in d and f.name in ("heights", "along_wind") and max(map(abs, d[f.name])) > GRID_EXTENT:
                raise entry.error(f.name, d[f.name], f"must lie within +-{GRID_EXTENT:g} m (a grid of that extent)")
    return list(disturbances)


#: The residual policies (the controller plus a learned residual) and the algorithm each is written for:
#: control/residual_policy.py (PPO), control/residual_sac.py (SAC)
RESIDUAL_ALGORITHM = {"ResidualPolicy": "PPO", "ResidualSACPolicy": "SAC"}


def read_init_from(s: Section, algo: str, policy_kwargs: dict, normalized: bool,
                   policy: str = "MlpPolicy") -> str | None:
    """``init_from``: absent, or ``lqr`` / ``lqr:<config>`` (the rotorcraft: also ``lqr_guard:<config>`` in hold mode,
    control/craft_tip_guard.py) for a PPO with a linear actor (``net_arch.pi: []``)
    and normalised observations (control/warm_start.py), or for a PPO with ``policy: ResidualPolicy`` and raw
    observations (``normalize_observations: false``: the policy normalises; control/residual_policy.py), or for a
    SAC with ``policy: ResidualSACPolicy`` and raw observations (control/residual_sac.py)."""
    spec = s.raw("init_from", None)
    if spec is None:
        if policy in RESIDUAL_ALGORITHM:
            raise s.error("policy", policy, "needs init_from (the controller the residual is added to)")
        return None
    guard = isinstance(spec, str) and spec.startswith("lqr_guard:")
    if not (isinstance(spec, str) and (spec == "lqr" or spec.startswith("lqr:") or guard)):
        raise s.error("init_from", spec, "must be 'lqr', 'lqr:<config>' or (the rotorcraft) 'lqr_guard:<config>' with "
                      "mode: hold (the controller the actor starts at)")
    if guard and policy in RESIDUAL_ALGORITHM:
        raise s.error("init_from", spec, f"policy: {policy} adds its residual to an LQR's gains; a guard has none "
                      "(start a linear actor at it: policy MlpPolicy, net_arch.pi: [])")
    if guard:
        from laddermill_gym.control.craft_tip_guard import load_tip_guard_config

        if load_tip_guard_config(spec.split(":", 1)[1]).mode != "hold":
            raise s.error("init_from", spec, "is the blade-tip guard in limit mode, whose min() is not affine in the "
                          "observation (a linear actor would start at the LQR); start at a guard with mode: hold")
    if policy in RESIDUAL_ALGORITHM:
        if algo != RESIDUAL_ALGORITHM[policy] or normalized:
            raise s.error("init_from", spec, f"with policy: {policy} needs algorithm: {RESIDUAL_ALGORITHM[policy]} "
                          f"(got {algo}) and normalize_observations: false (got {normalized}): the policy "
                          f"normalises itself")
        return spec
    arch = policy_kwargs.get("net_arch")
    if algo != "PPO" or not normalized or not (isinstance(arch, dict) and arch.get("pi") == []):
        raise s.error("init_from", spec, f"needs algorithm: PPO (got {algo}), normalize_observations: true (got "
                      f"{normalized}) and a linear actor, policy_kwargs.net_arch.pi: [] (got {arch!r})")
    return spec


def read_critic_warmup(s: Section, init_from: str | None, total: int | None = None) -> CriticWarmup | None:
    """``critic_warmup`` (absent: none): ``steps`` [env steps] and ``learning_rate`` [-]; only with ``init_from``
    (a critic learns the values of a policy worth keeping, not of random weights), and ``steps`` below ``total``
    (``total_timesteps``, when given: the actor trains after the warm-up)."""
    if not s.has("critic_warmup"):
        return None
    cw = s.section("critic_warmup")
    if init_from is None:
        raise s.error("critic_warmup", cw.data, "needs init_from (the actor it freezes is the started controller)")
    out = CriticWarmup(cw.number("steps", integer=True, positive=True, high=10**9, why="env steps"),
                       cw.number("learning_rate", positive=True, high=1.0, why="the optimiser's step"))
    if total is not None and out.steps >= total:
        raise cw.error("steps", out.steps, f"must be below total_timesteps = {total} (the actor trains only after "
                       "the warm-up: it would never train)")
    cw.done()
    return out


def read_validation(s: Section) -> Validation | None:
    """``validation`` (absent: none): ``every`` [env steps], ``seed``, ``episode_time`` [s] and ``sets``, a
    mapping of names to ``episodes``, ``disturbances`` (checked as the training's) and an optional ``seed`` of the
    set's own (its episodes seeded ``seed``, ``seed`` + 1, ...; absent: the validation's)."""
    if not s.has("validation"):
        return None
    v = s.section("validation")
    every = v.number("every", integer=True, positive=True, high=10**9, why="env steps")
    seed = v.number("seed", integer=True, nonneg=True, high=2 ** 32 - 1, why="numpy's seed range")
    episode_time = v.number("episode_time", positive=True, high=3600.0, why="s: an hour per validation episode")
    raw = v.raw("sets")
    if not isinstance(raw, dict) or not raw:
        raise v.error("sets", raw, "must be a mapping of set names to {episodes, disturbances}")
    sets = []
    for name in raw:
        sec = Section(raw[name], s.file, f"validation.sets.{name}")
        episodes = sec.number("episodes", integer=True, positive=True, high=1000, why="each validation runs them")
        own = sec.number("seed", integer=True, nonneg=True, high=2 ** 32 - 1, why="numpy's seed range") \
            if sec.has("seed") else None
        dist = check_disturbances(sec)
        if not dist:
            raise sec.error("disturbances", dist, "must list at least one disturbance (drawn per episode)")
        sec.done()
        sets.append(ValidationSet(str(name), episodes, dist, own))
    selection = read_selection(v)
    v.done()
    return Validation(every, seed, episode_time, tuple(sets), selection)


def read_selection(v: Section) -> Selection:
    """``validation.selection`` (absent: ``rule: survived``, the original ranking): ``rule`` ``survived`` or
    ``paired``; with ``paired`` a ``penalty`` [-] (> 0, at most 1000: one episode the reference holds and the policy
    loses costs that many survived ones) and a ``reference`` (``lqr`` or ``lqr:<config>``; default ``lqr``)."""
    if not v.has("selection"):
        return Selection()
    sec = v.section("selection")
    rule = sec.text("rule", choices=("survived", "paired"))
    if rule == "survived":
        for key in ("penalty", "reference"):
            if sec.has(key):
                raise sec.error(key, sec.raw(key), "applies only to rule: paired")
        sec.done()
        return Selection()
    penalty = sec.number("penalty", positive=True, high=1000.0, why="survived episodes per lost reference episode")
    reference = sec.raw("reference", "lqr")
    if not (isinstance(reference, str) and (reference == "lqr" or reference.startswith("lqr:"))):
        raise sec.error("reference", reference, "must be 'lqr' or 'lqr:<config>' (the controller paired with)")
    sec.done()
    return Selection("paired", float(penalty), reference)
