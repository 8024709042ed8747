"""ppo_selfplay.py - deep-RL self-play on the robot duel: PPO (Stable-Baselines3, CPU) against a pool of its past selves.

The deep-RL counterpart of a coevolution with a Hall of Fame (docs/envs.md, "A deep-RL baseline"): one PPO learner
plays the duel (neat_duel.envs.DuelVsEnv, the C world) against opponents drawn per game from a pool of its own past
policies, a snapshot added every --snapshot-games games; the budget is counted in games, as a coevolution's is.

Its policy is a network the project's runtime runs exactly as trained: 12 sensor inputs and the bias, one hidden
layer, 3 outputs, every unit the runtime's sigmoid 1/(1+exp(-4.9 x)) (the actor's hidden layer uses it, and the
action the environment receives is that sigmoid of the actor's mean), weights kept inside the runtime's Q3.12 range
(|w| < 8). So each snapshot is written as a genome file (neat_duel.Genome.from_genes, step "propagate": the two
layers within one step) that `duel_evolve play`, `ladder`-style comparisons and a firmware run, and the pool's
opponents are those very networks. At the end the final policy is placed on the built-in ladder (288-game
comparisons against each built-in strategy) and, with --against RUN, against each of a run's dominance levels.

    pip install -r examples/rl/requirements.txt      # in a virtual environment, beside the neat_duel package
    python examples/rl/ppo_selfplay.py --out runs/ppo --games 20000 --against runs/quick

It continues where it stopped (the same command): the model, the pool and the counters are saved every
--snapshot-games games in OUT. Results: OUT/result.json and the lines printed at the end.
"""
from __future__ import annotations

import argparse
import json
import os
import time
from typing import Any

import numpy as np
import torch
from stable_baselines3 import PPO
from stable_baselines3.common.callbacks import BaseCallback
from stable_baselines3.common.vec_env import VecEnv, VecMonitor

import neat_duel as nd
from neat_duel import envs

SLOPE = 4.9  # the runtime's sigmoid: 1 / (1 + exp(-4.9 x)) (runtime/src/nrt_sigmoid.c)
W_MAX = 7.99  # the runtime's weights are Q3.12: |w| < 8
# configs/quick.ini plays 200 generations of 6,144 host games: each population's 128 hosts, 24 games each (its
# generations.csv's games column, one row per population, 3,072 a row); comparisons and the dominance tournament not
# counted
QUICK_GAMES = 1_228_800


class NeatSigmoid(torch.nn.Module):
    """The runtime's node function, as a torch activation."""

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return torch.sigmoid(SLOPE * x)


class SelfPlayVecEnv(VecEnv):
    """K duels stepped together in C (neat_duel.envs.DuelVecEnv) as one Stable-Baselines3 VecEnv: in each game the
    learner plays one side (drawn per game) against an opponent drawn per game from the pool, a runtime network
    stepped on its own observation (neat_duel.envs.network_action), as DuelVsEnv does for one game. The learner's
    action is the actor's pre-activation: the robot's motor outputs are its runtime sigmoid (what the exported
    network's output nodes compute), so a policy's mean action is exactly the network's output."""

    render_mode = None  # nothing to draw (Stable-Baselines3 asks)

    def __init__(self, num_games: int, layouts: str, seed: int) -> None:
        import gymnasium

        act = gymnasium.spaces.Box(-4.0, 4.0, shape=(envs.N_ACTIONS,), dtype=np.float32)
        obs = gymnasium.spaces.Box(-1.0, 1.0, shape=(envs.N_OBSERVATIONS,), dtype=np.float32)
        super().__init__(num_games, obs, act)
        self.games = envs.DuelVecEnv(num_games, layouts=layouts)
        self.rng = np.random.default_rng(seed)
        self.seed_value = seed
        self.pool: list[nd.Network] = []
        self.side = np.zeros(num_games, dtype=np.int64)
        self.who = np.zeros(num_games, dtype=np.int64)
        self.obs = np.zeros((num_games, 2, envs.N_OBSERVATIONS), dtype=np.float32)
        self.both = np.zeros((num_games, 2, envs.N_ACTIONS), dtype=np.float32)
        self.actions = np.zeros((num_games, envs.N_ACTIONS), dtype=np.float32)

    def set_opponents(self, pool: list[nd.Network]) -> None:
        """The pool games draw their opponents from, from each game's next start on."""
        self.pool = list(pool)

    def _draw(self, idx: np.ndarray) -> None:
        self.side[idx] = self.rng.integers(2, size=len(idx))
        self.who[idx] = self.rng.integers(len(self.pool), size=len(idx))

    def reset(self) -> np.ndarray:
        self.obs, _ = self.games.reset(seed=self.seed_value)
        self._draw(np.arange(self.num_envs))
        return self.obs[np.arange(self.num_envs), self.side]

    def step_async(self, actions: np.ndarray) -> None:
        self.actions = np.asarray(actions, dtype=np.float64).reshape(self.num_envs, envs.N_ACTIONS)

    def step_wait(self) -> Any:
        k = np.arange(self.num_envs)
        z = np.clip(self.actions, -4.0, 4.0)
        self.both[k, self.side] = 1.0 / (1.0 + np.exp(-SLOPE * z))
        # each opponent on its own observation (feed-forward: no state to keep), as envs.network_action steps it,
        # with the inputs of all games converted at once
        other = 1 - self.side
        x = envs.network_inputs(self.obs[k, other])
        for g in range(self.num_envs):
            self.both[g, other[g]] = self.pool[self.who[g]].step_q15(x[g]).astype(np.float32) / np.float32(32768.0)
        obs, rew, term, trunc, info = self.games.step(self.both)
        done = term | trunc
        mine = rew[k, self.side]
        infos: list[dict[str, Any]] = [{} for _ in k]
        for g in np.flatnonzero(done):
            infos[g]["terminal_observation"] = info["final_obs"][g, self.side[g]].copy()
            infos[g]["TimeLimit.truncated"] = bool(trunc[g] and not term[g])
        if done.any():
            self._draw(np.flatnonzero(done))
        self.obs = obs
        return obs[k, self.side].copy(), mine.astype(np.float32), done, infos

    def close(self) -> None:
        self.games.close()

    def get_attr(self, attr_name: str, indices: Any = None) -> list[Any]:
        return [getattr(self, attr_name)] * len(self._get_indices(indices))

    def set_attr(self, attr_name: str, value: Any, indices: Any = None) -> None:
        setattr(self, attr_name, value)

    def env_method(self, method_name: str, *args: Any, indices: Any = None, **kw: Any) -> list[Any]:
        return [getattr(self, method_name)(*args, **kw)]

    def env_is_wrapped(self, wrapper_class: Any, indices: Any = None) -> list[bool]:
        return [False] * len(self._get_indices(indices))


def policy_genome(model: PPO) -> nd.Genome:
    """The actor as genes: inputs 1..12 and the bias (node 0) -> H hidden -> 3 outputs, step "propagate"."""
    pol = model.policy
    hidden = pol.mlp_extractor.policy_net[0]  # Linear(12, H), then NeatSigmoid
    out = pol.action_net  # Linear(H, 3)
    w1, b1 = hidden.weight.detach().cpu().numpy(), hidden.bias.detach().cpu().numpy()
    w2, b2 = out.weight.detach().cpu().numpy(), out.bias.detach().cpu().numpy()
    n_in, n_out, n_h = envs.N_OBSERVATIONS, envs.N_ACTIONS, w1.shape[0]
    conns: list[tuple[int, int, float]] = []
    for k in range(n_h):
        node = 1 + n_in + n_out + k
        conns.append((0, node, float(b1[k])))
        conns += [(1 + i, node, float(w1[k, i])) for i in range(n_in)]
    for o in range(n_out):
        conns.append((0, 1 + n_in + o, float(b2[o])))
        conns += [(1 + n_in + n_out + k, 1 + n_in + o, float(w2[o, k])) for k in range(n_h)]
    return nd.Genome.from_genes(n_in, n_out, n_h, conns, step="propagate")


def clamp_actor(model: PPO) -> None:
    """Keeps the actor's weights in the runtime's range (they rarely leave it; when they do, the network would not
    be the policy)."""
    with torch.no_grad():
        for layer in (model.policy.mlp_extractor.policy_net[0], model.policy.action_net):
            layer.weight.clamp_(-W_MAX, W_MAX)
            layer.bias.clamp_(-W_MAX, W_MAX)


class SelfPlay(BaseCallback):
    """Counts games; every `every` games adds the current policy to the pool (a genome file), hands the pool to
    every environment, and saves the model, so that the run continues after a stop."""

    def __init__(self, out: str, every: int, budget: int, state: dict[str, Any]) -> None:
        super().__init__()
        self.out, self.every, self.budget, self.state = out, every, budget, state

    def _on_step(self) -> bool:
        dones = self.locals["dones"]
        self.state["games"] += int(np.sum(dones))
        if self.state["games"] >= self.state["next_snapshot"]:
            snapshot(self.model, self.out, self.state)
            self.training_env.env_method("set_opponents", pool_networks(self.out, self.state))
            print(f"games {self.state['games']:,} of {self.budget:,}: pool {len(self.state['pool'])}, "
                  f"{self.num_timesteps:,} learner steps, {self.state['seconds']:.0f} s, "
                  f"CPU {self.state['cpu_seconds']:.0f} s", flush=True)
        return self.state["games"] < self.budget


def snap_name(games: int) -> str:
    """The pool's file of the policy after `games` games."""
    return f"snap-{games:09d}.genome"


_clock = [time.time(), time.process_time()]  # wall and CPU time (user+sys, all threads) at the last snapshot


def snapshot(model: PPO, out: str, state: dict[str, Any]) -> None:
    """Adds the current policy to the pool and saves everything a continuation needs, with the time spent so far
    (summed over the sessions of a run that was stopped and continued)."""
    now = [time.time(), time.process_time()]
    state["seconds"] = state.get("seconds", 0.0) + now[0] - _clock[0]
    state["cpu_seconds"] = state.get("cpu_seconds", 0.0) + now[1] - _clock[1]
    _clock[:] = now
    clamp_actor(model)
    name = snap_name(state["games"])
    policy_genome(model).save(os.path.join(out, "pool", name))
    state["pool"].append(name)
    state["next_snapshot"] = state["games"] + state["every"]
    model.save(os.path.join(out, "model.tmp.zip"))  # then renamed: a stop while saving keeps the last model whole
    os.replace(os.path.join(out, "model.tmp.zip"), os.path.join(out, "model.zip"))
    tmp = os.path.join(out, "state.json.tmp")
    with open(tmp, "w") as f:
        json.dump(state, f)
    os.replace(tmp, os.path.join(out, "state.json"))


def pool_networks(out: str, state: dict[str, Any]) -> list[nd.Network]:
    return [nd.Genome.load(os.path.join(out, "pool", n)).network() for n in state["pool"]]


def place(genome_file: str, against: str | None) -> dict[str, Any]:
    """The final policy on the built-in ladder and against a run's dominants: 288-game comparisons (wins, losses)."""
    net = nd.Genome.load(genome_file).network()
    result: dict[str, Any] = {"builtins": {}, "dominants": []}
    for b in nd.duel_builtins():
        c = nd.duel_compare(net, b)
        result["builtins"][b] = c
    if against:
        rd = nd.runs.RunDir(against)
        for d in rd.dominants():
            c = nd.duel_compare(net, rd.champion_network(d["generation"]))
            result["dominants"].append({"level": d["level"], "generation": d["generation"], **c})
    return result


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True, help="the run's directory (continued when it holds a run)")
    ap.add_argument("--games", type=int, default=QUICK_GAMES, help="the budget in games (default: a quick coevolution's)")
    ap.add_argument("--snapshot-games", type=int, default=None, help="games between snapshots (default: budget / 50)")
    ap.add_argument("--envs", type=int, default=64, help="games played side by side (stepped together in C)")
    ap.add_argument("--hidden", type=int, default=16, help="the policy's hidden units")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--layouts", default="comparison", help="training or comparison food layouts")
    ap.add_argument("--against", default=None, help="a run directory whose dominants the final policy meets")
    a = ap.parse_args(argv)
    torch.set_num_threads(1)  # small networks: threads cost more than they give; the envs run side by side
    os.makedirs(os.path.join(a.out, "pool"), exist_ok=True)
    state_path = os.path.join(a.out, "state.json")
    resumed = os.path.exists(state_path)
    if resumed:
        with open(state_path) as f:
            state = json.load(f)
        if state["budget"] != a.games or state["seed"] != a.seed:
            raise SystemExit(f"{a.out} holds a run of {state['budget']} games, seed {state['seed']}: not this one")
    else:
        every = a.snapshot_games or max(1, a.games // 50)
        state = {"games": 0, "budget": a.games, "seed": a.seed, "every": every, "next_snapshot": 0, "pool": []}

    venv = VecMonitor(SelfPlayVecEnv(a.envs, a.layouts, a.seed + state["games"]))
    if resumed:
        model = PPO.load(os.path.join(a.out, "model.zip"), env=venv, device="cpu")
    else:
        kw = dict(net_arch=dict(pi=[a.hidden], vf=[64, 64]), activation_fn=NeatSigmoid)
        model = PPO("MlpPolicy", venv, policy_kwargs=kw, n_steps=256, batch_size=1024, seed=a.seed, device="cpu",
                    verbose=0)
        snapshot(model, a.out, state)  # the pool starts with the untrained policy, as a coevolution's first hosts
    venv.env_method("set_opponents", pool_networks(a.out, state))
    if state["games"] < state["budget"]:
        model.learn(total_timesteps=10**12, callback=SelfPlay(a.out, state["every"], a.games, state),
                    reset_num_timesteps=not resumed)
        if state["pool"][-1] != snap_name(state["games"]):  # the callback's last snapshot may be this very policy
            snapshot(model, a.out, state)
    final = os.path.join(a.out, "ppo-final.genome")
    policy_genome(model).save(final)
    res = {"games": state["games"], "learner_steps": int(model.num_timesteps), "pool": len(state["pool"]),
           "seconds": round(state["seconds"]), "cpu_seconds": round(state["cpu_seconds"]), **place(final, a.against)}
    tmp = os.path.join(a.out, "result.json.tmp")
    with open(tmp, "w") as f:
        json.dump(res, f, indent=1)
    os.replace(tmp, os.path.join(a.out, "result.json"))
    print(f"{res['games']:,} games, {res['learner_steps']:,} learner steps; the final policy: {final}")
    for b, c in res["builtins"].items():
        print(f"  vs {b:15s} {c['wins']:3d} wins {c['losses']:3d} losses of 288")
    for d in res["dominants"]:
        print(f"  vs level {d['level']:2d} (generation {d['generation']}) {d['wins']:3d} wins {d['losses']:3d} losses")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
