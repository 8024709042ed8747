"""The Gymnasium helper on CartPole: seeded episodes, the same returns for the same network, evolution."""
from __future__ import annotations

import pytest

import neat_duel as nd

gymnasium = pytest.importorskip("gymnasium")
from neat_duel import gym  # noqa: E402


def test_cartpole_is_seeded_and_evolves() -> None:
    params = nd.Params(pop_size=30, n_inputs=4, n_outputs=2, allow_recurrent=False)
    pop = nd.Population(params, seed=1)
    g = pop.genome(0)
    env = gymnasium.make("CartPole-v1")
    a = gym.evaluate(g, env, episodes=3, seed=7)
    assert a == gym.evaluate(g.network(), "CartPole-v1", episodes=3, seed=7) and a >= 1.0
    assert gym.evaluate(g, env, episodes=1, seed=7, max_steps=3) <= 3.0
    recs = pop.run(gym.fitness(env, episodes=2, seed=0), 8)
    assert recs[-1]["best_fitness"] >= recs[0]["best_fitness"] and recs[-1]["best_fitness"] > 30
    # the same run again: the same records (the environment's episodes are seeded)
    again = nd.Population(params, seed=1).run(gym.fitness("CartPole-v1", episodes=2, seed=0), 8)
    assert again == recs


def test_spaces_and_errors() -> None:
    env = gymnasium.make("MountainCarContinuous-v0")
    see, act = gym.default_observe(env), gym.default_act(env)
    x = see(env.observation_space.high)
    assert all(abs(v - 1.0) < 1e-9 for v in x)
    assert float(act([0.5])[0]) == pytest.approx(0.0)
    net = nd.Population(nd.Params(pop_size=4, n_inputs=2, n_outputs=1), seed=1).genome(0).network()
    r = gym.evaluate(net, env, max_steps=20, seed=1)
    assert r == gym.evaluate(net, env, max_steps=20, seed=1)
    with pytest.raises(ValueError, match="episodes"):
        gym.evaluate(net, env, episodes=0)
    f = gym.fitness(env, max_steps=50, seed=1)
    with pytest.raises(ValueError, match="may not be negative"):
        f(nd.Population(nd.Params(pop_size=4, n_inputs=2, n_outputs=1), seed=1).genome(0))
