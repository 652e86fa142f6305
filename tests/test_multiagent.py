"""The per-wing multi-agent interface (issue 31 point 1): PettingZoo's own API and seed tests on each id, and an
independent oracle: the single-agent env of the same id, seed and (concatenated) actions, whose observation the
agents' local observations must slice bit for bit (own block, neighbours by index arithmetic written here, the
station entries by name) and whose step's terms the agents' rewards must rebuild. The SB3 adapter against the
ParallelEnv (copy b seeded seed + b), and a few hundred PPO steps on it."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from laddermill_gym.envs.laddermill.observation import STATION_OBS_INDEX
from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.kernels.contract import PKO_OFFSET, PKO_SIZE
from tests.env_cases import CASES, LC, LC1, LM, PMC, case_kwargs, make_single

pettingzoo_test = pytest.importorskip("pettingzoo.test", reason="the multiagent extra (PettingZoo) is not installed")
from laddermill_gym.multiagent import parallel_env  # noqa: E402  (needs PettingZoo)

IDS = [LM, LC, LC1, PMC]
#: per id: entries per wing block, action entries per agent, shared entries
SIZES = {LM: (15, 3, 3), LC: (15, 3, 1), LC1: (15, 3, 1), PMC: (PKO_SIZE, 2, 1)}


def make(env_id: str, k: int = 1, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the small mill's fallback start
        return parallel_env(env_id, k=k, **case_kwargs(env_id, **kw))


@pytest.mark.parametrize("env_id", IDS)
def test_pettingzoo_parallel_api_and_seed_tests(env_id):
    pettingzoo_test.parallel_api_test(make(env_id), num_cycles=30)
    pettingzoo_test.parallel_seed_test(lambda: make(env_id), num_cycles=10)


@pytest.mark.parametrize("env_id", IDS)
@pytest.mark.parametrize("k", [0, 2])
def test_agents_and_spaces(env_id, k):
    env, single = make(env_id, k), make_single(env_id)
    m, m_a, g = SIZES[env_id]
    n = single.task.n_wings
    kind = {LM: "slot", LC: "wing", LC1: "wing", PMC: "kite"}[env_id]
    assert env.possible_agents == [f"{kind}_{i}" for i in range(n)]
    assert single.action_space.shape == (n * m_a,)  # the single env's per-wing action, split over the agents
    for a in env.possible_agents:
        assert env.observation_space(a).shape == (m * (1 + 2 * k) + 2 * k + 1 + g,)
        assert env.action_space(a).shape == (m_a,) and env.action_space(a).dtype == np.float32
        assert env.observation_space(a) is env.observation_space(a)
    assert env.state_space.shape == single.observation_space.shape


def expected_local(obs: np.ndarray, n: int, m: int, k: int, shared: np.ndarray) -> np.ndarray:
    """The oracle's local observations (n, d) of a single-agent observation ``obs``: written out entry by entry."""
    rows = []
    for i in range(n):
        row = list(obs[i * m:(i + 1) * m])
        offsets = [d for d in range(-k, k + 1) if d != 0]
        for d in offsets:
            j = i + d
            row += list(obs[j * m:(j + 1) * m]) if 0 <= j < n else [0.0] * m
        row += [1.0 if 0 <= i + d < n else 0.0 for d in offsets]
        row += [i / (n - 1) if n > 1 else 0.0]
        rows.append(row + list(shared))
    return np.array(rows, dtype=np.float32)


def shared_entries(env_id: str, obs: np.ndarray, info: dict | None, p_ref: float):
    """Mill: phase, speed, power ratio by name from the station block; chains: the step's power_W / P_ref."""
    if env_id == LM:
        station = obs[-len(STATION_OBS_INDEX):]
        return [station[STATION_OBS_INDEX[f]] for f in ("cable_phase", "cable_speed", "power_ratio")]
    return None if info is None else [info["power_W"] / p_ref]


def local_terms(env_id: str, single, obs: np.ndarray, a: np.ndarray) -> dict[str, np.ndarray]:
    """The oracle's local reward terms (n,) from the single env's observation and the agents' actions (n, m_a)."""
    t, rc = single.task, single.task.reward_config
    m = SIZES[env_id][0]
    o = obs[: t.n_wings * m].reshape(t.n_wings, m).astype(float)
    dy = o[:, PKO_OFFSET + 1] if env_id == PMC else o[:, OBS_INDEX["dy"]]
    out = {"reward_lateral": -rc.lateral_weight * (1.0 - np.exp(-(dy / t.lateral_scale) ** 2))}
    out["reward_rates"] = (np.zeros(t.n_wings) if env_id == PMC else -rc.rate_weight * (1.0 - np.exp(
        -(o[:, OBS_INDEX["p"]] ** 2 + o[:, OBS_INDEX["r"]] ** 2) / rc.rate_scale ** 2)))
    nominal = np.zeros(a.size) if env_id not in (LC, LC1) else t.actions.nominal_action
    out["reward_effort"] = -rc.effort_weight * (1.0 - np.exp(-np.mean(
        (np.clip(a, -1, 1) - nominal.reshape(a.shape)) ** 2, axis=1)))
    return out


@pytest.mark.parametrize("env_id", IDS)
def test_agents_slice_the_single_env_bit_for_bit(env_id):
    k, seed = 2, 7
    env, single = make(env_id, k), make_single(env_id)
    m, m_a, _ = SIZES[env_id]
    n = single.task.n_wings
    obs, _ = env.reset(seed=seed)
    ref, info0 = single.reset(seed=seed)
    local = np.array([obs[a] for a in env.possible_agents])
    expected = expected_local(ref, n, m, k, shared_entries(env_id, ref, None, 1.0) or local[0, -1:])
    np.testing.assert_array_equal(local, expected)
    np.testing.assert_array_equal(env.state(), ref)
    rng, amplitude, steps = np.random.default_rng(1), CASES[env_id][1], CASES[env_id][2]
    p_ref = info0["reference_power_W"]
    for _ in range(steps):
        a = rng.uniform(-1.2, 1.2, (n, m_a)) * amplitude * 3  # some entries clipped
        obs, rew, term, trunc, infos = env.step({ag: a[i].astype(np.float32) for i, ag in enumerate(env.agents)})
        ref, r_single, t_single, tr_single, info = single.step(a.astype(np.float32).reshape(-1))
        local = np.array([obs[ag] for ag in env.possible_agents])
        np.testing.assert_array_equal(local, expected_local(ref, n, m, k, shared_entries(env_id, ref, info, p_ref)))
        assert set(term.values()) == {t_single} and set(trunc.values()) == {tr_single}
        terms = local_terms(env_id, single, ref, a.astype(np.float32).astype(float))
        for i, ag in enumerate(env.possible_agents):
            assert infos[ag]["reward_shared"] == info["reward_power"] + info["reward_failure"]
            assert infos[ag]["power_W"] == info["power_W"] and infos[ag]["failure"] == info["failure"]
            for name, value in terms.items():
                np.testing.assert_allclose(infos[ag][name], value[i], rtol=1e-6, atol=1e-12, err_msg=name)
            assert rew[ag] == pytest.approx(sum(infos[ag][f"reward_{x}"] for x in
                                                ("shared", "lateral", "rates", "effort")), rel=1e-12)
        if t_single or tr_single:
            assert env.agents == []
            break


@pytest.mark.parametrize(("kw", "needle"), [
    (dict(env_id="laddermill_gym/TetheredWing-v0"), "TetheredWing-v0"), (dict(env_id="nope"), "nope"),
    (dict(env_id=LC, k=-1), "k = -1"), (dict(env_id=LC, k=1.5), "k = 1.5"), (dict(env_id=LC, k=True), "k = True"),
    (dict(env_id=LC, bogus=1), "bogus"), (dict(env_id=LC, groups="all"), "groups = 'all'"),
    (dict(env_id=LM, generator_torque=True), "generator_torque"),
])
def test_bad_construction_arguments_are_named(kw, needle):
    env_id = kw.pop("env_id")
    extra = case_kwargs(env_id) if env_id in CASES else {}
    with pytest.raises(ValueError, match=needle.replace(".", r"\.")):
        parallel_env(env_id, **{**extra, **kw})


def test_bad_actions_are_named_and_move_nothing():
    env = make(LC)
    with pytest.raises(RuntimeError, match="reset"):
        env.step({a: np.zeros(3) for a in env.possible_agents})
    env.reset(seed=0)
    good = {a: np.zeros(3, np.float32) for a in env.agents}
    cases = [({k: v for k, v in good.items() if k != "wing_2"}, "missing \\['wing_2'\\]"),
             (dict(good, wing_9=np.zeros(3)), "unknown \\['wing_9'\\]"),
             (dict(good, wing_1=np.zeros(4)), "agent wing_1.*shape \\(4,\\)"),
             (dict(good, wing_0=np.array([0.0, np.nan, 0.0])), "agent wing_0.*non-finite"),
             (dict(good, wing_3="0 0 0"), "agent wing_3"), (np.zeros((5, 3)), "must be a dict")]
    t0 = env.task.batch.t.copy()
    for actions, needle in cases:
        with pytest.raises(ValueError, match=needle):
            env.step(actions)
    np.testing.assert_array_equal(env.task.batch.t, t0)  # nothing stepped
    env.step(good)
    assert env.task.batch.t[0] > t0[0]


def test_reset_options_and_bad_seeds_are_refused_by_name():
    """Options the envs ignore (the disturbances are construction arguments) are named: in a warning by the
    ParallelEnv (PettingZoo's API test resets with {"options": 1}), refused by the SB3 adapter; seeds that are not
    integers >= 0 are refused (before, both dropped or truncated them without a word)."""
    import warnings

    env = make(LC)
    with pytest.warns(UserWarning, match="options = \\{'disturbances': \\[\\]\\}.*takes no reset options"):
        env.reset(seed=0, options={"disturbances": []})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        env.reset(seed=0, options={})  # an empty mapping is no option
    venv = shared_policy_vec_env(LC, 2, k=1, seed=5, **case_kwargs(LC))
    with pytest.raises(ValueError, match="options = \\{'episode_time': 1.0\\}"):
        venv.set_options({"episode_time": 1.0})
    venv.set_options(None)
    for seed in (1.5, "3", True, -1):
        with pytest.raises(ValueError, match=f"seed = {seed!r}: must be an integer >= 0"):
            venv.seed(seed)
    assert venv.seed(np.int64(7))[:venv.n_agents] == [7] * venv.n_agents


def shared_policy_vec_env(*args, **kw):
    """The SB3 adapter, skipping the test without the rl extra (SB3)."""
    pytest.importorskip("stable_baselines3", reason="the rl extra (SB3) is not installed")
    from laddermill_gym.multiagent import shared_policy_vec_env as make_venv

    return make_venv(*args, **kw)


def test_sb3_adapter_copies_are_the_parallel_env_seeded_seed_plus_b():
    kw = case_kwargs(LC)
    venv = shared_policy_vec_env(LC, 2, k=1, seed=5, **kw)
    n = venv.n_agents
    assert venv.num_envs == 2 * n and venv.observation_space.shape == make(LC).observation_space("wing_0").shape
    obs = venv.reset()
    rng = np.random.default_rng(0)
    for b in range(2):
        env = make(LC)
        ref, _ = env.reset(seed=5 + b)
        np.testing.assert_array_equal(obs[b * n:(b + 1) * n], np.array([ref[a] for a in env.possible_agents]))
    actions = rng.uniform(-0.3, 0.3, (2 * n, 3)).astype(np.float32)
    obs, rew, dones, infos = venv.step(actions)
    env = make(LC)
    env.reset(seed=6)
    ref, r, *_ = env.step({a: actions[n + i] for i, a in enumerate(env.possible_agents)})
    np.testing.assert_array_equal(obs[n:], np.array([ref[a] for a in env.possible_agents]))
    np.testing.assert_array_equal(rew[n:], np.array([r[a] for a in env.possible_agents], dtype=np.float32))
    assert not dones.any() and infos[n]["reward_shared"] == infos[2 * n - 1]["reward_shared"]
    with pytest.raises(ValueError, match="shape"):
        venv.step(np.zeros((n, 3)))
    with pytest.raises(ValueError, match="n_copies = 0"):
        shared_policy_vec_env(LC, 0, **kw)


def test_one_shared_policy_trains_a_few_hundred_ppo_steps():
    venv = shared_policy_vec_env(LC, 2, k=1, seed=0, **case_kwargs(LC, episode_time=1.0))
    from stable_baselines3 import PPO

    model = PPO("MlpPolicy", venv, n_steps=32, batch_size=80, n_epochs=2, seed=0, device="cpu",
                    policy_kwargs={"net_arch": [32, 32]})
    model.learn(total_timesteps=2 * 32 * venv.num_envs)
    assert model.num_timesteps == 2 * 32 * venv.num_envs  # 640 agent-steps over 2 rollouts
    action, _ = model.predict(venv.reset(), deterministic=True)
    assert action.shape == (venv.num_envs, 3) and np.all(np.abs(action) <= 1.0)


def test_a_non_finite_state_costs_each_agent_the_full_penalty_as_the_single_env():
    """The task's reward maps a non-finite lateral or rate argument to the full penalty (``shaped_reward``); the
    per-agent terms did not (every agent's reward was NaN; the review of 2026-12-07)."""
    env = parallel_env(LM, k=1, **case_kwargs(LM))
    single = make_single(LM)
    env.reset(seed=0)
    single.reset(seed=0)
    env.task.batch.states[0, :] = np.nan
    single.task.batch.states[0, :] = np.nan
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        _, rewards, terminated, _, infos = env.step({a: np.zeros(3, np.float32) for a in env.agents})
        _, r_single, t_single, _, i_single = single.step(np.zeros(single.action_space.shape, np.float32))
    assert t_single and all(terminated.values())
    assert np.isfinite(r_single) and all(np.isfinite(r) for r in rewards.values())
    rc = single.unwrapped.task.reward_config
    for a in env.possible_agents:
        assert infos[a]["reward_lateral"] == pytest.approx(-rc.lateral_weight)  # S(nan) = 1, as i_single's
        assert infos[a]["reward_rates"] == pytest.approx(-rc.rate_weight)
    assert i_single["reward_lateral"] == pytest.approx(-rc.lateral_weight)


def test_sb3_adapter_infos_and_observations_are_the_parallel_envs_entry_for_entry():
    """The SB3 adapter's infos and observations, step by step through an episode's end and the reset after it (2
    copies of 5 wings, k = 2, some action entries clipped), against a reference loop over the ParallelEnvs seeded
    seed + b: every info entry's value and Python type (``n_clipped`` included), the observations and the terminal
    observation against ``expected_local`` (written out entry by entry above)."""
    k, B, seed = 2, 2, 5
    kw = case_kwargs(LC, episode_time=0.2)  # 4 control periods of 0.05 s
    venv = shared_policy_vec_env(LC, B, k=k, seed=seed, **kw)
    refs = [make(LC, k, episode_time=0.2) for _ in range(B)]
    n, m = venv.n_agents, SIZES[LC][0]
    venv.reset()
    p_ref = [env.reset(seed=seed + b)[1]["wing_0"]["reference_power_W"] for b, env in enumerate(refs)]
    keys = ("power_W", "failure", "t", "n_clipped", "reward_shared", "reward_lateral", "reward_rates", "reward_effort")
    rng, ended = np.random.default_rng(3), 0
    for _ in range(6):
        actions = rng.uniform(-1.5, 1.5, (B * n, 3)).astype(np.float32)
        obs, rew, dones, infos = venv.step(actions)
        assert len(infos) == B * n
        for b, env in enumerate(refs):
            _, r, term, trunc, pinfo = env.step({a: actions[b * n + i] for i, a in enumerate(env.possible_agents)})
            last = expected_local(env.task.obs[0], n, m, k, [pinfo["wing_0"]["power_W"] / p_ref[b]])
            done = env.agents == []
            if done:
                ended += 1
                after, _ = env.reset()  # the copy's next episode, drawn from the same generator
                after = np.array([after[a] for a in env.possible_agents])
                start = expected_local(env.task.obs[0], n, m, k, after[0, -1:])
            for i, a in enumerate(env.possible_agents):
                j = b * n + i
                want = {key: pinfo[a][key] for key in keys}
                want["TimeLimit.truncated"] = trunc[a] and not term[a]
                got = dict(infos[j])
                if done:
                    np.testing.assert_array_equal(got.pop("terminal_observation"), last[i])
                    np.testing.assert_array_equal(obs[j], start[i])
                else:
                    np.testing.assert_array_equal(obs[j], last[i])
                assert got == want and {f: type(v) for f, v in got.items()} == {f: type(v) for f, v in want.items()}
                assert rew[j] == np.float32(r[a]) and dones[j] == done
        assert any(info["n_clipped"] > 0 for info in infos)
    assert ended == B  # both copies ended (at 0.2 s) and were reset within the six steps


def test_local_observations_clip_each_entry_as_the_bounds_say():
    """Non-finite and out-of-bound entries of the single-agent observation (the clip is applied to the wing blocks
    before they are gathered into every agent's view): each local entry is its bound (NaN: the upper one)."""
    venv = shared_policy_vec_env(LC, 1, k=2, seed=0, **case_kwargs(LC))
    venv.reset()
    view, n, m = venv.view, venv.n_agents, SIZES[LC][0]
    obs = np.repeat(venv.task.obs, 3, axis=0)
    obs[0, [0, m + 3, 4 * m + 1]] = np.nan, np.inf, -np.inf
    obs[1, : n * m] *= 1e9  # far outside the bounds
    shared = np.array([[0.3], [np.nan], [-5e3]])
    got = view.local_observations(obs, shared)
    lo, hi = view.obs_low.astype(np.float32), view.obs_high.astype(np.float32)
    for b in range(3):
        raw = expected_local(obs[b], n, m, 2, shared[b])
        np.testing.assert_array_equal(got[b], np.where(np.isnan(raw), hi, np.clip(raw, lo, hi)))
    assert np.isfinite(got).all()
