"""Networks on Gymnasium environments: seeded episodes, observations scaled into the runtime's range, actions.

gymnasium is an optional dependency (``pip install .[gym]``); nothing here imports it until it is used::

    import neat_duel as nd
    from neat_duel import gym

    params = nd.Params(pop_size=50, n_inputs=4, n_outputs=2)
    pop = nd.Population(params, seed=1)
    pop.run(gym.fitness("CartPole-v1", episodes=3, seed=0), generations=20)
"""
from __future__ import annotations

from typing import Any, Callable, Sequence

import numpy as np

from ._core import Genome, Network

Observe = Callable[[Any], Sequence[float]]
Act = Callable[[Sequence[float]], Any]


def _make(env: Any) -> Any:
    if isinstance(env, str):
        import gymnasium

        return gymnasium.make(env)
    return env


def default_observe(env: Any) -> Observe:
    """Observations into [-1, 1): a Box's finite bounds mapped linearly, unbounded values passed as they are
    (the runtime saturates them); a Discrete observation one-hot."""
    space = env.observation_space
    name = type(space).__name__
    if name == "Discrete":
        n = int(space.n)

        def one_hot(obs: Any) -> Sequence[float]:
            v = [0.0] * n
            v[int(obs) - int(space.start)] = 1.0
            return v

        return one_hot
    low = np.asarray(space.low, dtype=np.float64).ravel()
    high = np.asarray(space.high, dtype=np.float64).ravel()
    finite = np.isfinite(low) & np.isfinite(high) & (high > low)
    lo, span = np.where(finite, low, 0.0), np.where(finite, high - low, 1.0)

    def scale(obs: Any) -> Sequence[float]:
        x = np.asarray(obs, dtype=np.float64).ravel()
        return list(np.where(finite, 2.0 * (x - lo) / span - 1.0, x))

    return scale


def default_act(env: Any) -> Act:
    """Outputs into an action: the largest output's index for a Discrete space (one output an action), each
    output in [0, 1) mapped onto a Box's bounds."""
    space = env.action_space
    name = type(space).__name__
    if name == "Discrete":
        start = int(space.start)
        return lambda out: start + int(np.argmax(out))
    if name == "Box":
        low = np.asarray(space.low, dtype=np.float64)
        high = np.asarray(space.high, dtype=np.float64)
        return lambda out: (low + np.asarray(out).reshape(low.shape) * (high - low)).astype(space.dtype)
    raise TypeError(f"action space {space}: give act= for it (Discrete and Box have defaults)")


def evaluate(
    net: Network | Genome,
    env: Any,
    *,
    episodes: int = 1,
    seed: int = 0,
    max_steps: int | None = None,
    observe: Observe | None = None,
    act: Act | None = None,
) -> float:
    """The mean return of net (or a genome's network) over episodes of env (an Env, or an id for gymnasium.make).

    Episode k starts from env.reset(seed=seed + k), the network reset: the same network gives the same returns.
    One network step per environment step; an episode ends when the environment terminates or truncates it, or
    after max_steps.
    """
    if episodes < 1:
        raise ValueError("episodes: at least 1")
    e = _make(env)
    if isinstance(net, Genome):
        net = net.network()
    see = observe or default_observe(e)
    do = act or default_act(e)
    total = 0.0
    for k in range(episodes):
        obs, _ = e.reset(seed=seed + k)
        net.reset()
        steps = 0
        while True:
            obs, reward, terminated, truncated, _ = e.step(do(net.step(see(obs))))
            total += float(reward)
            steps += 1
            if terminated or truncated or (max_steps is not None and steps >= max_steps):
                break
    return total / episodes


def fitness(
    env: Any,
    *,
    episodes: int = 1,
    seed: int = 0,
    max_steps: int | None = None,
    observe: Observe | None = None,
    act: Act | None = None,
    offset: float = 0.0,
) -> Callable[[Genome], float]:
    """A fitness function for Population.run: evaluate's mean return plus offset (a fitness may not be negative:
    give an offset for environments whose returns can be)."""
    e = _make(env)
    see = observe or default_observe(e)  # once, not again for every genome
    do = act or default_act(e)

    def f(genome: Genome) -> float:
        r = evaluate(genome, e, episodes=episodes, seed=seed, max_steps=max_steps, observe=see, act=do) + offset
        if r < 0:
            raise ValueError(f"a return of {r - offset} with offset {offset}: a fitness may not be negative")
        return r

    return f


__all__ = ["evaluate", "fitness", "default_observe", "default_act"]
