"""Quick start (the README's): make an env and step it, train PPO briefly (60,000 env steps), evaluate it
against the LQR on four seeded 300 s episodes.

Needs the ``rl`` extra (Stable-Baselines3 and torch). The tuned configuration
(``laddermill train configs/agents/ppo_tethered_wing.yaml``) beat the LQR's return after about four minutes of
training (controllers.md). Run it as ``python tutorials/quickstart.py``.
"""
import gymnasium as gym
from stable_baselines3 import PPO

from laddermill_gym.control.factory import make_controller
from laddermill_gym.envs.sb3 import sb3_vec_env
from laddermill_gym.harness.evaluate import run_episodes, vector_env

ID = "laddermill_gym/TetheredWing-v0"
env = gym.make(ID)  # one wing on a 100 m tether, the paper's 0.01 rad wind-direction step at 1 s
obs, info = env.reset(seed=0)
obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
model = PPO("MlpPolicy", sb3_vec_env(ID, 8, seed=0), seed=0).learn(60_000)  # 60,000 env steps
for name, controller in {"PPO": model, "LQR": make_controller("lqr", ID)}.items():
    r = run_episodes(controller, vector_env(ID, 4, {}), record=False)  # seeds 0-3, 300 s episodes
    print(f"{name}: mean return {r.returns.mean():.0f}, flew {r.lengths_s.mean():.1f} s")
