"""The robot duel as reinforcement-learning environments, stepped by the C world (docs/envs.md).

- ``DuelEnv``: a PettingZoo ``ParallelEnv`` with the agents ``west`` and ``east``;
- ``DuelVecEnv``: K games at once on numpy arrays, for speed (the C batch ``DuelBatch`` under it);
- ``DuelVsEnv``: a single-agent Gymnasium ``Env`` against a built-in strategy or a champion network.

Every rule is duelsim's own: the games are held and stepped in C (``neat_duel._core.DuelBatch``:
``duel_world_init_rules``, ``duel_sense``, ``duel_world_step``), never re-implemented here. A robot observes its 12
sensor values (a network's inputs 1..12, Q1.15 / 32768) and acts with its 3 motor outputs (turn left, turn right,
forward) in [0, 1]. This module imports pettingzoo and gymnasium (``pip install neat-duel[envs]``); ``import
neat_duel`` does not::

    from neat_duel.envs import DuelEnv

    env = DuelEnv(layouts="comparison")
    obs, infos = env.reset(seed=1)
    while env.agents:
        obs, rewards, terminations, truncations, infos = env.step(
            {agent: env.action_space(agent).sample() for agent in env.agents})
"""
from __future__ import annotations

import math
import os
from typing import Any, Optional, Sequence, Tuple, Union

import gymnasium
import numpy as np
import numpy.typing as npt
from gymnasium import spaces
from pettingzoo import ParallelEnv  # type: ignore[import-untyped]

from ._core import DuelBatch, DuelConfig, Network, duel_builtin_act, duel_builtins

__all__ = [
    "AGENTS",
    "GYM_ID",
    "MAX_STEPS",
    "N_ACTIONS",
    "N_OBSERVATIONS",
    "DuelBatch",
    "DuelEnv",
    "DuelVecEnv",
    "DuelVsEnv",
    "builtin_action",
    "network_action",
    "network_inputs",
    "resolve_layouts",
]

AGENTS: Tuple[str, str] = ("west", "east")
"""The two agents, in the order of every array's side axis: 0 west, 1 east."""
N_OBSERVATIONS = 12
"""A robot's observation: its sensor values, a network's inputs 1..12 (the bias, input 0, left out)."""
N_ACTIONS = 3
"""A robot's action: turn left, turn right, forward, each in [0, 1]."""
MAX_STEPS = 750
"""A game's step limit (docs/duel-world.md): a game without a collision by then is truncated."""
COMPARISON_LAYOUTS = 144
"""The comparison food layouts, 0..143; -1 is the training layout."""

Layouts = Union[str, Sequence[int]]
"""``"training"`` (the 9 training items), ``"comparison"`` (the 144 comparison layouts) or a list of layouts (-1 the
training one, 0..143 comparison ones)."""
ConfigLike = Union[DuelConfig, str, os.PathLike[str], None]
"""A run configuration whose ``[world]`` rules the games follow: a ``DuelConfig``, the path of an INI file, or None
for world v1."""
Observation = npt.NDArray[np.float32]
Action = npt.NDArray[np.float32]
Opponent = Union[str, Network, os.PathLike[str]]
"""A built-in strategy's name (``"forager"``, ``"builtin:forager"``), a ``Network``, or a champion blob's path."""

_OUTCOMES = ("running", "west", "east", "draw", "timeout")


def resolve_layouts(layouts: Layouts) -> npt.NDArray[np.int64]:
    """The food layouts an environment draws from, as an int64 array: ``"training"`` is [-1], ``"comparison"``
    0..143, a list is itself (each -1..143; at least one)."""
    if isinstance(layouts, str):
        if layouts == "training":
            return np.array([-1], dtype=np.int64)
        if layouts == "comparison":
            return np.arange(COMPARISON_LAYOUTS, dtype=np.int64)
        raise ValueError(f"layouts: 'training', 'comparison' or a list of layouts (-1..143), not {layouts!r}")
    values = [int(k) for k in layouts]
    if not values:
        raise ValueError("layouts: an empty list")
    for k in values:
        if not -1 <= k < COMPARISON_LAYOUTS:
            raise ValueError(f"layouts: {k} is not a layout (-1 the training one, 0..143 the comparison ones)")
    return np.array(values, dtype=np.int64)


def _config(config: ConfigLike) -> Optional[DuelConfig]:
    if config is None or isinstance(config, DuelConfig):
        return config
    return DuelConfig.from_ini(config)


def network_inputs(obs: npt.ArrayLike) -> npt.NDArray[np.int16]:
    """A robot's 13 network inputs in Q1.15 from its observation: the bias (32767), then each value as
    ``neat_duel.q15`` converts it (floor(v * 32768 + 0.5), saturated to [-32768, 32767]; exact for an
    observation, which is q / 32768). What ``duel_play`` feeds a network, for ``Network.step_q15``.
    obs (12,) gives (13,); many observations (n, 12) give (n, 13) at once, row i that of obs[i]."""
    x = np.asarray(obs, dtype=np.float64)
    if x.shape != (N_OBSERVATIONS,) and (x.ndim != 2 or x.shape[1] != N_OBSERVATIONS):
        x = x.reshape(N_OBSERVATIONS)  # one observation of another shape with 12 values, as before
    q = np.clip(np.floor(np.nan_to_num(x) * 32768.0 + 0.5), -32768, 32767)
    out = np.empty(x.shape[:-1] + (N_OBSERVATIONS + 1,), dtype=np.int16)
    out[..., 0] = 32767
    out[..., 1:] = q
    return out


def network_action(net: Network, obs: npt.ArrayLike) -> Action:
    """One step of a network on a robot's observation, as a duel steps it (``Network.step_q15`` on
    ``network_inputs(obs)``): its outputs q as the action q / 32768, which the environment turns back into q."""
    return net.step_q15(network_inputs(obs)).astype(np.float32) / np.float32(32768.0)


def builtin_action(name: str, obs: npt.ArrayLike) -> Action:
    """A built-in strategy's action (C's ``duel_builtin_act``) for an observation (12,) or many (n, 12): (3,) or
    (n, 3) float32, each output q / 32768. name: one of ``neat_duel.duel_builtins()``, ``builtin:`` allowed."""
    x = np.asarray(obs, dtype=np.float32)
    if x.shape[-1:] != (N_OBSERVATIONS,):
        raise ValueError(f"obs: the last axis holds the {N_OBSERVATIONS} sensor values, not shape {x.shape}")
    out = duel_builtin_act(name, np.ascontiguousarray(x.reshape(-1, N_OBSERVATIONS)))
    return out.reshape(x.shape[:-1] + (N_ACTIONS,))


def _heading(bam: int) -> float:
    """A binary angle in radians in (-pi, pi], computed as the trace prints it (tools/common/duel_trace.c)."""
    if bam == 0x80000000:
        return math.pi
    return float(bam - (1 << 32) if bam >= 1 << 31 else bam) * (math.pi / 2147483648.0)


def _agent_info(state: dict[str, Any], side: str) -> dict[str, Any]:
    """One agent's info: the game's and its robot's state, in board units and in the world's own numbers."""
    r = state[side]
    return {
        "t": state["t"],
        "layout": state["layout"],
        "food_mask": state["food_mask"],
        "outcome": state["outcome"],
        "x": r["x"] / 65536.0,
        "y": r["y"] / 65536.0,
        "heading": _heading(r["heading"]),
        "energy": r["energy"] / 65536.0,
        "eaten": r["eaten"],
        "ate": r["ate"],
        "raw": {"x": r["x"], "y": r["y"], "heading": r["heading"], "energy": r["energy"]},
    }


def _render_ansi(batch: DuelBatch, k: int, width: int = 40, height: int = 20) -> str:
    """Game k as text: the board (north up; W and E the robots, lower case when the game is over, * the food), then a
    line per robot."""
    s = batch.state(k)
    grid = [["." for _ in range(width)] for _ in range(height)]

    def cell(x: int, y: int) -> Tuple[int, int]:
        col = min(width - 1, int(x / 65536.0 / 600.0 * width))
        row = min(height - 1, int((600.0 - y / 65536.0) / 600.0 * height))
        return row, col

    for i, (fx, fy) in enumerate(batch.food(k)):
        if s["food_mask"] >> i & 1:
            row, col = cell(fx, fy)
            grid[row][col] = "*"
    over = s["outcome"] != "running"
    for side, mark in (("west", "W"), ("east", "E")):
        row, col = cell(s[side]["x"], s[side]["y"])
        grid[row][col] = mark.lower() if over else mark
    layout = "training" if s["layout"] < 0 else f"comparison {s['layout']}"
    lines = [f"t {s['t']}/{MAX_STEPS}, layout {layout}, {s['outcome']}"]
    lines += ["".join(r) for r in grid]
    for side in AGENTS:
        r = s[side]
        lines.append(f"{side}: x {r['x'] / 65536.0:.2f} y {r['y'] / 65536.0:.2f} "
                     f"heading {math.degrees(_heading(r['heading'])):.1f} deg energy {r['energy'] / 65536.0:.2f} "
                     f"eaten {r['eaten']}")
    return "\n".join(lines) + "\n"


def _obs_space() -> spaces.Box[np.float32]:
    return spaces.Box(low=-1.0, high=1.0, shape=(N_OBSERVATIONS,), dtype=np.float32)


def _act_space() -> spaces.Box[np.float32]:
    return spaces.Box(low=0.0, high=1.0, shape=(N_ACTIONS,), dtype=np.float32)


class DuelEnv(ParallelEnv):  # type: ignore[misc]  # pettingzoo has no type information
    """The robot duel as a PettingZoo ``ParallelEnv``: agents ``west`` and ``east`` step at once.

    - observation: a ``Box(-1, 1, (12,), float32)``, the robot's inputs 1..12 (Q1.15 / 32768);
    - action: a ``Box(0, 1, (3,), float32)``, (turn left, turn right, forward), each a -> floor(a * 32768 + 0.5)
      saturated, as a network's output (an output q is the action q / 32768, which maps back to q);
    - reward: +1 to the winner and -1 to the loser of a collision, 0 on a draw, a timeout and every other step;
      plus ``shaping`` times the change of (own energy - other's energy) / energy_scale each step (0, off, by
      default);
    - terminations after a collision, truncations at step 750;
    - ``reset(seed=S)`` draws the food layout ``layouts[rng.integers(len(layouts))]`` with
      ``rng = numpy.random.default_rng(S)``; a reset without a seed draws the next from the same generator;
      ``options={"layout": K}`` plays layout K instead (the draw is made all the same, so the generator's
      sequence does not depend on it).

    Each agent's info holds the game's state as the world keeps it (docs/envs.md): t, layout, food_mask, outcome,
    the robot's x, y, heading (radians), energy, eaten, ate (bit i: it ate item i in the step), and ``raw`` (x, y,
    energy in Q16.16, heading a binary angle).
    """

    metadata: dict[str, Any] = {"name": "neat_duel_v0", "render_modes": ["ansi"], "is_parallelizable": True}

    def __init__(
        self,
        layouts: Layouts = "training",
        config: ConfigLike = None,
        shaping: float = 0.0,
        render_mode: Optional[str] = None,
    ) -> None:
        """layouts: the food layouts reset draws from; config: the ``[world]`` rules (default v1); shaping: the
        shaped reward's weight (0: off); render_mode: None or ``"ansi"``."""
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode: None or 'ansi', not {render_mode!r}")
        self.render_mode = render_mode
        self.layouts = resolve_layouts(layouts)
        self.config = _config(config)
        self.batch = DuelBatch(1, config=self.config, shaping=float(shaping))
        self.possible_agents: list[str] = list(AGENTS)
        self.agents: list[str] = []
        self._obs_spaces = {a: _obs_space() for a in AGENTS}
        self._act_spaces = {a: _act_space() for a in AGENTS}
        self._rng = np.random.default_rng()
        self._actions = np.zeros((1, 2, N_ACTIONS), dtype=np.float32)
        self._index = np.zeros(1, dtype=np.int64)

    def observation_space(self, agent: str) -> spaces.Box[np.float32]:
        """The agent's observation space (the same object every call)."""
        return self._obs_spaces[agent]

    def action_space(self, agent: str) -> spaces.Box[np.float32]:
        """The agent's action space (the same object every call)."""
        return self._act_spaces[agent]

    def _infos(self) -> dict[str, dict[str, Any]]:
        state = self.batch.state(0)
        return {a: _agent_info(state, a) for a in AGENTS}

    def reset(
        self, seed: Optional[int] = None, options: Optional[dict[str, Any]] = None
    ) -> Tuple[dict[str, Observation], dict[str, dict[str, Any]]]:
        """A new game: its first observations and infos."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        layout = int(self.layouts[self._rng.integers(len(self.layouts))])
        if options is not None and "layout" in options:
            layout = int(resolve_layouts([options["layout"]])[0])
        obs = self.batch.reset(self._index, np.array([layout], dtype=np.int64))
        self.agents = list(AGENTS)
        return {a: obs[0, i] for i, a in enumerate(AGENTS)}, self._infos()

    def step(
        self, actions: dict[str, npt.ArrayLike]
    ) -> Tuple[
        dict[str, Observation],
        dict[str, float],
        dict[str, bool],
        dict[str, bool],
        dict[str, dict[str, Any]],
    ]:
        """One step of both robots: actions maps each agent to its (3,) action."""
        if not self.agents:
            raise RuntimeError("the game is over (or has not begun): call reset()")
        for i, a in enumerate(AGENTS):
            if a not in actions:
                raise KeyError(f"no action for {a}: a step takes both agents' actions")
            self._actions[0, i] = np.asarray(actions[a], dtype=np.float32).reshape(N_ACTIONS)
        obs, rew, term, trunc = self.batch.step(self._actions)
        terminated, truncated = bool(term[0]), bool(trunc[0])
        if terminated or truncated:
            self.agents = []
        return (
            {a: obs[0, i] for i, a in enumerate(AGENTS)},
            {a: float(rew[0, i]) for i, a in enumerate(AGENTS)},
            {a: terminated for a in AGENTS},
            {a: truncated for a in AGENTS},
            self._infos(),
        )

    def render(self) -> Optional[str]:
        """The board as text (render_mode "ansi"); None without a render mode."""
        if self.render_mode is None:
            gymnasium.logger.warn("render() without a render_mode: DuelEnv(render_mode='ansi')")
            return None
        return _render_ansi(self.batch, 0)

    def close(self) -> None:
        """Nothing to release (the game lives in the DuelBatch)."""

    def state(self) -> npt.NDArray[np.float32]:
        """Both robots' observations, (2, 12), west then east: a global view (for a centralised critic)."""
        obs: Observation = self.batch.observe()[0]
        return obs


class DuelVecEnv:
    """K duels at once on numpy arrays: both robots of every game step in one C call (``DuelBatch``).

    ``reset(seed)`` -> (obs (K, 2, 12), info); ``step(actions (K, 2, 3))`` -> (obs, rewards (K, 2),
    terminated (K,), truncated (K,), info), the side axis west then east, float32 and bool arrays. The
    observations, actions, rewards and layouts are ``DuelEnv``'s. With ``autoreset`` (the default) a game that
    ends in a step starts again at once: the obs returned for it is the new game's first, ``info["final_obs"]``
    holds every game's observation before any reset (``info["_final_obs"]``: the games that ended), and the new
    layouts are drawn from the generator ``reset`` seeded (``rng = numpy.random.default_rng(seed)``: reset draws
    ``layouts[rng.integers(len(layouts), size=K)]``, a step in which n games ended
    ``layouts[rng.integers(len(layouts), size=n)]`` for them in the order of the games). ``threads`` steps the games
    on that many threads (each game alone: the same results). Without autoreset an ended game stays as it ended
    (reward 0, its flags repeated) until ``reset`` or ``batch.reset(indices, layouts)`` starts it again.
    """

    def __init__(
        self,
        num_games: int,
        layouts: Layouts = "training",
        config: ConfigLike = None,
        shaping: float = 0.0,
        autoreset: bool = True,
        threads: int = 1,
    ) -> None:
        """num_games games (K) of config's world, on layouts; see the class."""
        self.layouts = resolve_layouts(layouts)
        self.config = _config(config)
        self.batch = DuelBatch(num_games, config=self.config, shaping=float(shaping), threads=threads)
        self.num_games = int(num_games)
        self.autoreset = bool(autoreset)
        self.single_observation_space = _obs_space()
        self.single_action_space = _act_space()
        self.observation_space = spaces.Box(-1.0, 1.0, (self.num_games, 2, N_OBSERVATIONS), np.float32)
        self.action_space = spaces.Box(0.0, 1.0, (self.num_games, 2, N_ACTIONS), np.float32)
        self._rng = np.random.default_rng()
        self._all = np.arange(self.num_games, dtype=np.int64)
        self.layout = np.full(self.num_games, -1, dtype=np.int64)

    def reset(self, seed: Optional[int] = None) -> Tuple[Observation, dict[str, Any]]:
        """Every game from its start, on layouts drawn from default_rng(seed): (obs (K, 2, 12), {"layout": (K,)})."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        self.layout = self.layouts[self._rng.integers(len(self.layouts), size=self.num_games)]
        obs = self.batch.reset(self._all, self.layout)
        return obs, {"layout": self.layout.copy()}

    def step(
        self, actions: npt.ArrayLike
    ) -> Tuple[Observation, npt.NDArray[np.float32], npt.NDArray[np.bool_], npt.NDArray[np.bool_], dict[str, Any]]:
        """One step of every game: actions (K, 2, 3) float32 (another float array is converted)."""
        obs, rew, term, trunc = self.batch.step(np.ascontiguousarray(actions, dtype=np.float32))
        info: dict[str, Any] = {}
        if self.autoreset:
            ended = term | trunc
            info["_final_obs"] = ended
            info["final_obs"] = obs
            if ended.any():
                idx = self._all[ended]
                info["final_obs"] = obs.copy()
                self.layout[idx] = self.layouts[self._rng.integers(len(self.layouts), size=len(idx))]
                obs[idx] = self.batch.reset(idx, self.layout[idx])
        info["layout"] = self.layout
        return obs, rew, term, trunc, info

    def close(self) -> None:
        """Nothing to release."""


class _Opponent:
    """The other robot of a DuelVsEnv: a built-in strategy or a network, acting on its observation."""

    def __init__(self, who: Opponent) -> None:
        self.builtin: Optional[str] = None
        self.net: Optional[Network] = None
        if isinstance(who, Network):
            self.net = who
            self.name = f"network ({who.n_conns} connections)"
        elif isinstance(who, str) and (who.startswith("builtin:") or who in duel_builtins()):
            self.builtin = who[8:] if who.startswith("builtin:") else who
            builtin_action(self.builtin, np.zeros(N_OBSERVATIONS, dtype=np.float32))  # an unknown name fails here
            self.name = "builtin:" + self.builtin
        elif isinstance(who, (str, os.PathLike)):
            if isinstance(who, str) and not os.path.exists(who):
                raise ValueError(f"opponent {who!r}: neither a built-in strategy ({', '.join(duel_builtins())}) "
                                 "nor a file")
            self.net = Network.load(who)
            self.name = os.fspath(who)
        else:
            raise TypeError(f"opponent: a built-in strategy's name, a Network or a blob's path, not "
                            f"{type(who).__name__}")
        if self.net is not None and (self.net.n_inputs != N_OBSERVATIONS or self.net.n_outputs != N_ACTIONS):
            raise ValueError(f"opponent {self.name}: a network of {self.net.n_inputs} inputs and "
                             f"{self.net.n_outputs} outputs; the duel's have {N_OBSERVATIONS} and {N_ACTIONS}")

    def reset(self) -> None:
        if self.net is not None:
            self.net.reset()

    def act(self, obs: Observation) -> Action:
        if self.net is not None:
            return network_action(self.net, obs)
        assert self.builtin is not None
        return builtin_action(self.builtin, obs)


def _opponents(opponent: Union[Opponent, Sequence[Opponent]]) -> list[_Opponent]:
    """One opponent or a list of them, checked."""
    whos: list[Opponent]
    if isinstance(opponent, (str, Network, os.PathLike)):
        whos = [opponent]
    else:
        whos = list(opponent)
    if not whos:
        raise ValueError("opponent: an empty list")
    return [_Opponent(w) for w in whos]


class DuelVsEnv(gymnasium.Env[Observation, Action]):
    """The robot duel for one learning agent (a Gymnasium ``Env``): the other robot is a built-in strategy, a
    champion network, or one of a list drawn per episode.

    Observation, action and reward are the learning robot's, as in ``DuelEnv``. ``side``: the learner's side,
    ``"west"``, ``"east"`` or ``"random"`` (drawn per episode). Each ``reset(seed=S)`` seeds gymnasium's
    ``np_random`` (``numpy.random.default_rng(S)``'s generator) and draws, in this order,
    ``rng.integers(len(layouts))`` (the layout), ``rng.integers(2)`` (the side, used when ``"random"``: 0 west)
    and ``rng.integers(len(opponents))`` (the opponent); a reset without a seed goes on with the same generator.
    ``options={"layout": K}`` plays layout K (the draws are made all the same). A network opponent is reset at
    every episode and stepped as ``duel_play`` steps it. The info is the learner's
    ``DuelEnv`` info, with ``side`` and ``opponent``.
    """

    metadata: dict[str, Any] = {"render_modes": ["ansi"], "render_fps": 30}

    def __init__(
        self,
        opponent: Union[Opponent, Sequence[Opponent]] = "forager",
        side: str = "west",
        layouts: Layouts = "training",
        config: ConfigLike = None,
        shaping: float = 0.0,
        render_mode: Optional[str] = None,
    ) -> None:
        """opponent: one or a list (see the class); side: ``"west"``, ``"east"`` or ``"random"``."""
        if side not in ("west", "east", "random"):
            raise ValueError(f"side: 'west', 'east' or 'random', not {side!r}")
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode: None or 'ansi', not {render_mode!r}")
        self.opponents = _opponents(opponent)
        self.side_rule = side
        self.render_mode = render_mode
        self.layouts = resolve_layouts(layouts)
        self.config = _config(config)
        self.batch = DuelBatch(1, config=self.config, shaping=float(shaping))
        self.observation_space = _obs_space()
        self.action_space = _act_space()
        self.side = 0
        self._opponent = self.opponents[0]
        self._other_obs = np.zeros(N_OBSERVATIONS, dtype=np.float32)
        self._actions = np.zeros((1, 2, N_ACTIONS), dtype=np.float32)
        self._over = True
        self._index = np.zeros(1, dtype=np.int64)

    def set_opponents(self, opponent: Union[Opponent, Sequence[Opponent]]) -> None:
        """Replaces the opponents (one or a list, as the constructor takes them) from the next reset on: a
        self-play pool that grows. The episode in play keeps its opponent."""
        self.opponents = _opponents(opponent)

    def _info(self) -> dict[str, Any]:
        info = _agent_info(self.batch.state(0), AGENTS[self.side])
        info["side"] = AGENTS[self.side]
        info["opponent"] = self._opponent.name
        return info

    def reset(
        self, *, seed: Optional[int] = None, options: Optional[dict[str, Any]] = None
    ) -> Tuple[Observation, dict[str, Any]]:
        """A new episode: the learner's first observation and info."""
        super().reset(seed=seed)
        rng = self.np_random
        layout = int(self.layouts[rng.integers(len(self.layouts))])
        side = int(rng.integers(2))
        who = int(rng.integers(len(self.opponents)))
        if options is not None and "layout" in options:
            layout = int(resolve_layouts([options["layout"]])[0])
        self.side = side if self.side_rule == "random" else AGENTS.index(self.side_rule)
        self._opponent = self.opponents[who]
        self._opponent.reset()
        obs = self.batch.reset(self._index, np.array([layout], dtype=np.int64))
        self._other_obs = obs[0, 1 - self.side]
        self._over = False
        return obs[0, self.side], self._info()

    def step(self, action: Action) -> Tuple[Observation, float, bool, bool, dict[str, Any]]:
        """One step: the learner's action, the opponent's from its own observation."""
        if self._over:
            raise RuntimeError("the episode is over (or has not begun): call reset()")
        self._actions[0, self.side] = np.asarray(action, dtype=np.float32).reshape(N_ACTIONS)
        self._actions[0, 1 - self.side] = self._opponent.act(self._other_obs)
        obs, rew, term, trunc = self.batch.step(self._actions)
        self._other_obs = obs[0, 1 - self.side]
        terminated, truncated = bool(term[0]), bool(trunc[0])
        self._over = terminated or truncated
        return obs[0, self.side], float(rew[0, self.side]), terminated, truncated, self._info()

    def render(self) -> Optional[str]:
        """The board as text (render_mode "ansi"); None without a render mode."""
        if self.render_mode is None:
            gymnasium.logger.warn("render() without a render_mode: DuelVsEnv(render_mode='ansi')")
            return None
        return _render_ansi(self.batch, 0)


GYM_ID = "neat_duel/DuelVs-v0"
"""DuelVsEnv's Gymnasium id: ``gymnasium.make("neat_duel/DuelVs-v0", opponent="hunter")`` (registered when this
module is imported)."""
if GYM_ID not in gymnasium.registry:
    gymnasium.register(id=GYM_ID, entry_point="neat_duel.envs:DuelVsEnv")
