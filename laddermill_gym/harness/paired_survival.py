"""Two controllers on the same drawn episodes: which survives where the other does not (a paired comparison).

A benchmark scenario with three seeds (gusts-v1's NTM_IB) counts a controller as surviving only when all three
episodes do, so where each controller survives about half of the fields of a turbulence model the count is decided
largely by those three fields. This flies both controllers on ``episodes`` fields of one of a training config's
validation sets, drawn with seeds from ``seed`` on (choose seeds no selection used: held out), and reports the
pairs: both survive, only the first, only the second, neither; and the two-sided exact sign test of the discordant
pairs (McNemar's exact test: under "equally robust" each discordant pair goes either way with probability 1/2).

    python -m laddermill_gym.harness.paired_survival --config configs/agents/ppo_tethered_wing_severe.yaml \\
        --set ntm_ib --episodes 200 --seed 5000 --controllers lqr ppo_tethered_wing

``--env laddermill_gym/TetheredWing-v1`` flies the same episodes on another id of the config's task (another physics
step, ``envs.same_task``).
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

__all__ = ["sign_test", "paired_survival", "main"]


def sign_test(only_first: int, only_second: int) -> float:
    """Two-sided exact p-value [-] of the sign test on ``only_first`` against ``only_second`` discordant pairs:
    the probability, each pair a fair coin, of a split at least as uneven (1.0 without discordant pairs)."""
    n, k = only_first + only_second, min(only_first, only_second)
    if only_first < 0 or only_second < 0:
        raise ValueError(f"sign_test: counts must be >= 0, got {only_first}, {only_second}")
    if n == 0:
        return 1.0
    tail = Fraction(sum(math.comb(n, i) for i in range(k + 1)), 2 ** n)  # exact: 2.0 ** n overflows from n = 1024
    return float(min(Fraction(1), 2 * tail))


def paired_survival(config: str, set_name: str, episodes: int, seed: int, controllers: list[str],
                    env_id: str | None = None) -> dict:
    """Survival (bool array per controller, episode i seeded ``seed + i``) of two ``controllers`` (factory specs)
    on ``episodes`` episodes of the validation set ``set_name`` of ``config``, with the pair counts and
    :func:`sign_test`'s p-value; on ``env_id`` (None: the config's env; else an id of the same task,
    ``envs.same_task``, ValueError naming both otherwise)."""
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.control.trained_settings import carried_to
    from laddermill_gym.envs import same_task
    from laddermill_gym.harness.validation import selection_overlaps
    from laddermill_gym.studies.gusts.gust_bench import run_episodes

    if len(controllers) != 2:
        raise ValueError(f"paired_survival: two controllers to compare, got {controllers}")
    cfg = load_rl_config(config)
    sets = {} if cfg.validation is None else {s.name: s for s in cfg.validation.sets}
    if set_name not in sets:
        raise ValueError(f"{config}: validation set {set_name!r} not found (sets: {sorted(sets)})")
    env = cfg.env_id if env_id is None else env_id
    if not same_task(env, cfg.env_id):
        raise ValueError(f"env_id = {env!r}: not the task of {config} ({cfg.env_id}) on another physics step")
    if not (isinstance(episodes, int) and episodes >= 1):
        raise ValueError(f"episodes = {episodes!r}: must be a whole number >= 1")
    if not (isinstance(seed, int) and 0 <= seed and seed + episodes - 1 <= 2 ** 32 - 1):
        raise ValueError(f"seed = {seed!r}: the episodes' seeds {seed} .. {seed + episodes - 1} must lie in 0 .. "
                         f"{2 ** 32 - 1} (numpy's seed range)")
    kw = carried_to(cfg.env_id, env, cfg.carried_env_kwargs())  # another id of the task: its own physics step
    seeds = list(range(seed, seed + episodes))
    selected_on = selection_overlaps(cfg.validation, set_name, seeds)
    if selected_on:
        raise ValueError(f"seed = {seed}: the episodes' seeds {seed} .. {seed + episodes - 1} are those the "
                         f"validation of {config} selects on ({', '.join(selected_on)}): not held out")
    built = {spec: make_controller(spec, env, kw) for spec in controllers}  # both before any episode: a bad spec
    alive = {}                                                               # fails at once
    for spec in controllers:
        rec = run_episodes(built[spec], env, kw, seeds, cfg.validation.episode_time, sets[set_name].disturbances)
        alive[spec] = np.asarray(rec["failure"]) == 0
    a, b = (alive[c] for c in controllers)
    counts = dict(both=int(np.sum(a & b)), only_first=int(np.sum(a & ~b)), only_second=int(np.sum(~a & b)),
                  neither=int(np.sum(~a & ~b)))
    return dict(alive=alive, **counts, p_value=sign_test(counts["only_first"], counts["only_second"]))


def main(argv: list[str] | None = None) -> None:
    from laddermill_gym.studies.commands import Parser, UsageError, check_number

    p = Parser(prog="python -m laddermill_gym.harness.paired_survival", description=__doc__.split("\n\n")[0])
    p.add_argument("--config", required=True, help="training config holding the validation set")
    p.add_argument("--set", required=True, help="validation set name (e.g. ntm_ib)")
    p.add_argument("--episodes", type=int, default=200, help="episodes (fields) [-]")
    p.add_argument("--seed", type=int, default=5000, help="first episode seed (held out from every selection)")
    p.add_argument("--controllers", nargs=2, required=True, help="two controller specs (lqr, ppo_tethered_wing)")
    p.add_argument("--env", default=None, help="an id of the config's task on another physics step (default: the "
                   "config's env)")
    a = p.parse_args(argv)
    try:
        check_number("--episodes", a.episodes, low=1, high=100000, integer=True, strict=False)
        check_number("--seed", a.seed, low=0, high=2 ** 32 - a.episodes, integer=True, strict=False)
        if a.controllers[0] == a.controllers[1]:
            raise UsageError(f"--controllers {a.controllers}: the same controller twice")
        r = paired_survival(a.config, a.set, a.episodes, a.seed, a.controllers, a.env)
    except (ValueError, OSError) as err:  # ConfigError and UsageError are ValueErrors; a missing file an OSError
        p.error(str(err).replace("\n", " "))
    first, second = a.controllers
    for c in a.controllers:
        print(f"{c}: survives {int(r['alive'][c].sum())}/{a.episodes}")
    print(f"both {r['both']}, only {first} {r['only_first']}, only {second} {r['only_second']}, neither "
          f"{r['neither']}; sign test p = {r['p_value']:.3g}")


if __name__ == "__main__":
    main()
