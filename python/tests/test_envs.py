"""neat_duel.envs: PettingZoo's and Gymnasium's checks, the C world game for game against duel_evolve play's traces,
the rounding of actions, the seeding of layouts, sides and opponents, the vectorised stepper."""
from __future__ import annotations

import csv
import math
import pathlib
import subprocess
import sys
import warnings
from typing import Any, Callable

import numpy as np
import pytest

pytest.importorskip("pettingzoo")

import gymnasium  # noqa: E402
from gymnasium.utils.env_checker import check_env  # noqa: E402
from pettingzoo.test import api_test, parallel_api_test, parallel_seed_test  # noqa: E402
from pettingzoo.utils import parallel_to_aec  # noqa: E402

import neat_duel as nd  # noqa: E402
from neat_duel import envs  # noqa: E402
from neat_duel.envs import AGENTS, DuelBatch, DuelEnv, DuelVecEnv, DuelVsEnv  # noqa: E402
from conftest import ROOT, program  # noqa: E402

CHAMPION = ROOT / "tests" / "tools" / "fixtures" / "experiment-tiny" / "runs" / "complexify-2" / "champions" / \
    "gen-00002.blob"
CHAMPION_39 = ROOT / "tests" / "tools" / "fixtures" / "experiment-tiny" / "runs" / "complexify-1" / "champions" / \
    "gen-00001.blob"
# a world other than v1 in every rule a game can feel (duel_rules_check accepts it)
CUSTOM_WORLD = """[world]
rules = v1
radius = 12
start_energy = 1000
food_energy = 150
eat_dist = 20
share_dist = 2
food_range = 400
robot_range = 500
energy_scale = 100
wall_range = 150
"""


def strict(fn: Callable[[], Any]) -> None:
    """fn with every warning an error (PettingZoo's and Gymnasium's checks warn where they could fail), except
    PettingZoo's advice to name agents player_0, ...: the duel's are west and east."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.filterwarnings("ignore", message="We recommend agents to be named")
        fn()


# ---- the APIs' own checks ----

@pytest.mark.parametrize("kw", [{}, {"layouts": "comparison", "render_mode": "ansi"}, {"shaping": 1.0},
                                {"layouts": [3, -1, 140]}])
def test_parallel_api(kw: dict[str, Any]) -> None:
    strict(lambda: parallel_api_test(DuelEnv(**kw), num_cycles=1000))


def test_parallel_seed() -> None:
    strict(lambda: parallel_seed_test(lambda: DuelEnv(layouts="comparison"), num_cycles=1000))


def test_aec_api() -> None:
    """PettingZoo's own conversion to its turn-based API works on it."""
    strict(lambda: api_test(parallel_to_aec(DuelEnv(layouts="comparison")), num_cycles=1000))


@pytest.mark.parametrize("kw", [{}, {"side": "east", "opponent": "hunter", "layouts": "comparison"},
                                {"side": "random", "opponent": ["forager", "builtin:spinner", str(CHAMPION)],
                                 "render_mode": "ansi", "shaping": 0.5}])
def test_gymnasium_check_env(kw: dict[str, Any]) -> None:
    strict(lambda: check_env(gymnasium.make(envs.GYM_ID, **kw).unwrapped))


def test_check_env_without_make() -> None:
    env = DuelVsEnv(nd.Network.load(CHAMPION), side="random")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.filterwarnings("ignore", message=".*not having a spec")
        check_env(env)


def test_seeded_episodes_are_the_same() -> None:
    """Two environments reset with one seed play the same whole game for the same actions (PettingZoo's seed test
    stops after a step); other seeds give other layouts."""
    def episode(seed: int) -> list[Any]:
        env = DuelEnv(layouts="comparison", shaping=0.5)
        rng = np.random.default_rng(99)
        obs, infos = env.reset(seed=seed)
        out: list[Any] = [obs, infos]
        while env.agents:
            out.append(env.step({a: rng.random(3, dtype=np.float32) for a in env.agents}))
        return out

    a, b = episode(7), episode(7)
    assert len(a) == len(b) > 2
    for x, y in zip(a, b):
        assert gymnasium.utils.env_checker.data_equivalence(x, y)
    layouts = {DuelEnv(layouts="comparison").reset(seed=s)[1]["west"]["layout"] for s in range(20)}
    assert len(layouts) > 10


# ---- observations, actions, rewards ----

def test_observation_is_the_sensors() -> None:
    env = DuelEnv()
    obs, infos = env.reset(seed=0)
    for side in AGENTS:
        o = obs[side]
        assert o.dtype == np.float32 and o.shape == (12,) and env.observation_space(side).contains(o)
        assert np.array_equal(o * 32768, np.round(o * 32768))  # Q1.15 values, exactly
    # the start is mirror-symmetric: both robots read the same; the food ahead of neither (facing the walls)
    assert np.array_equal(obs["west"], obs["east"])
    assert obs["west"][10] == 0.0  # energy difference 0
    assert obs["west"][11] == np.float32(1 - 100 / 200)  # the wall 100 ahead, range 200: 1 - 100/200


def test_action_rounding() -> None:
    """An action a becomes floor(a * 32768 + 0.5) saturated, as a network's output: q / 32768 is q again, and
    the game for every action in q's rounding interval is the game for q / 32768."""
    qs = [0, 1, 2, 3, 12345, 20000, 32766, 32767]
    cases: list[tuple[float, int]] = []
    for q in qs:
        for d in (-0.5, -0.25, 0.0, 0.25, 0.375, 0.5):
            if 0 <= q + d <= 32767.5:
                cases.append(((q + d) / 32768, min(32767, math.floor(q + d + 0.5))))
    cases += [(1.0, 32767), (2.0, 32767), (-0.25, 0), (float("nan"), 0), (float("inf"), 32767)]
    k = len(cases)
    for lane in range(3):  # turn left, turn right, forward each
        got, want = DuelBatch(k), DuelBatch(k)
        a = np.zeros((k, 2, 3), dtype=np.float32)
        b = np.zeros((k, 2, 3), dtype=np.float32)
        for i, (x, q) in enumerate(cases):
            a[i, :, lane] = np.float32(x)
            b[i, :, lane] = np.float32(q / 32768)
            assert np.float32(q / 32768) * 32768 == q
        ra, rb = got.step(a), want.step(b)
        for x, y in zip(ra, rb):
            assert np.array_equal(x, y)
        for i, (x, q) in enumerate(cases):
            assert got.state(i) == want.state(i), (lane, x, q)
        # and neighbouring q differ, so the comparison above can fail
        if lane == 2:
            states = [want.state(i)["west"]["x"] for i, (_, q) in enumerate(cases) if q in (12345, 12346)]
            assert len(set(states)) == 2


def test_rewards_and_shaping() -> None:
    """+1/-1 on a collision only (a hunter ahead on energy catches an idle robot), shaped rewards the change of
    the energy difference / energy_scale when asked, zero-sum."""
    for shaping in (0.0, 2.0):
        env = DuelVsEnv("idle", side="west", shaping=shaping)
        obs, info = env.reset(seed=0)
        start = info["energy"]
        total, steps, rewards = 0.0, 0, []
        terminated = truncated = False
        while not (terminated or truncated):
            # the learner forages first (eats to get ahead), then hunts
            act = envs.builtin_action("forager-hunter", obs)
            obs, r, terminated, truncated, info = env.step(act)
            rewards.append(r)
            total += r
            steps += 1
        assert terminated and not truncated and info["outcome"] == "west"
        assert rewards[-1] != 0
        if shaping == 0.0:
            assert rewards[:-1] == [0.0] * (steps - 1) and rewards[-1] == 1.0
        else:
            # the idle robot keeps its 1200: the sum of the shaped terms is the learner's own energy change
            want = 1.0 + shaping * (info["energy"] - start) / 200
            assert total == pytest.approx(want, rel=1e-5)
            assert any(r > 0 for r in rewards[:-1]) and any(r < 0 for r in rewards[:-1])


@pytest.mark.parametrize("shaping", [0.0, 1.0])
def test_zero_sum_rewards_and_end(shaping: float) -> None:
    env = DuelEnv(shaping=shaping)
    env.reset(seed=1)
    rng = np.random.default_rng(5)
    while env.agents:
        _, rew, term, trunc, infos = env.step({a: rng.random(3, dtype=np.float32) for a in env.agents})
        assert rew["west"] == -rew["east"]
        assert not any(math.copysign(1.0, r) < 0 for r in rew.values() if r == 0)  # 0.0, never -0.0
        assert term["west"] == term["east"] and trunc["west"] == trunc["east"]
    assert trunc["west"] and infos["west"]["t"] == envs.MAX_STEPS and infos["west"]["outcome"] == "timeout"
    with pytest.raises(RuntimeError):
        env.step({"west": np.zeros(3), "east": np.zeros(3)})
    env.reset()
    with pytest.raises(KeyError):
        env.step({"west": np.zeros(3)})


# ---- layouts, seeds, sides, opponents ----

def test_layout_draws() -> None:
    """reset(seed=S) draws layouts[default_rng(S).integers(len(layouts))], and resets without a seed go on with
    the same generator."""
    for layouts, pool in (("comparison", list(range(144))), ([5, -1, 77], [5, -1, 77]), ("training", [-1])):
        env = DuelEnv(layouts=layouts)  # type: ignore[arg-type]
        for seed in range(10):
            rng = np.random.default_rng(seed)
            assert env.reset(seed=seed)[1]["east"]["layout"] == pool[rng.integers(len(pool))]
            for _ in range(3):
                assert env.reset()[1]["west"]["layout"] == pool[rng.integers(len(pool))]
    env = DuelEnv(layouts="comparison")
    _, infos = env.reset(seed=3, options={"layout": 42})
    assert infos["west"]["layout"] == 42 and infos["west"]["food_mask"] == 2047
    rng = np.random.default_rng(3)
    rng.integers(144)
    assert env.reset()[1]["west"]["layout"] == rng.integers(144)  # the draw was made all the same
    for bad in ("Comparison", [], [144], [-2]):
        with pytest.raises(ValueError):
            DuelEnv(layouts=bad)  # type: ignore[arg-type]


def test_vs_env_draws_layout_side_opponent() -> None:
    opponents: list[Any] = ["forager", "hunter", nd.Network.load(CHAMPION), CHAMPION]
    env = DuelVsEnv(opponents, side="random", layouts="comparison")
    seen = set()
    for seed in range(24):
        rng = np.random.default_rng(seed)
        layout, side, who = rng.integers(144), rng.integers(2), rng.integers(4)
        _, info = env.reset(seed=seed)
        assert (info["layout"], info["side"]) == (layout, AGENTS[side])
        assert info["opponent"] == env.opponents[who].name
        seen.add((info["side"], who))
    assert len(seen) == 8
    assert DuelVsEnv(side="east").reset(seed=0)[1]["side"] == "east"
    # a pool that changes: the next reset draws from the new one
    env.set_opponents(["spinner"])
    assert env.reset(seed=0)[1]["opponent"] == "builtin:spinner"
    env.set_opponents([nd.Network.load(CHAMPION)] * 2 + ["idle"])
    rng = np.random.default_rng(5)
    rng.integers(144), rng.integers(2)
    assert env.reset(seed=5)[1]["opponent"] == env.opponents[rng.integers(3)].name
    with pytest.raises(ValueError):
        DuelVsEnv("forrager")
    with pytest.raises(ValueError):
        DuelVsEnv(side="north")
    with pytest.raises(ValueError):
        DuelVsEnv([])


def test_config_world() -> None:
    """The world's rules come from a configuration (a DuelConfig or its path), v1 by default."""
    v1 = DuelEnv()
    assert v1.batch.world_id == 0xB43972DEF416B019
    path = ROOT / "configs" / "quick.ini"
    assert DuelEnv(config=path).batch.world_id == nd.DuelConfig.from_ini(path).world_id
    cfg = nd.DuelConfig()
    cfg.set("world.start_energy=900")
    env = DuelEnv(config=cfg)
    assert env.batch.world_id == cfg.world_id != v1.batch.world_id
    assert env.reset(seed=0)[1]["west"]["energy"] == 900.0


def test_render() -> None:
    env = DuelEnv(render_mode="ansi")
    env.reset(seed=0)
    text = env.render()
    assert text is not None and "W" in text and "E" in text and text.count("*") == 9
    with pytest.warns(UserWarning):
        assert DuelEnv().render() is None


# ---- the built-in strategies, the network helpers ----

def test_builtin_action() -> None:
    obs = DuelEnv().reset(seed=0)[0]["west"]
    assert envs.builtin_action("spinner", obs).tolist() == [32767 / 32768, 0.0, 0.0]
    assert envs.builtin_action("builtin:idle", obs).tolist() == [0.0, 0.0, 0.0]
    many = np.stack([obs] * 5)
    assert envs.builtin_action("forager", many).shape == (5, 3)
    with pytest.raises(nd.ArgumentError):
        envs.builtin_action("forrager", obs)
    with pytest.raises(ValueError):
        envs.builtin_action("forager", obs[:11])



def test_network_inputs_many_are_each_rows() -> None:
    rng = np.random.default_rng(5)
    obs = rng.integers(-32768, 32768, size=(40, 12)).astype(np.float32) / np.float32(32768)
    obs[0, :4] = [1.0, -1.0, 2.0, np.nan]  # saturated both ways, and NaN (as 0)
    many = envs.network_inputs(obs)
    assert many.shape == (40, 13) and many.dtype == np.int16
    for i in range(40):
        assert np.array_equal(many[i], envs.network_inputs(obs[i]))
    assert many[0, :5].tolist() == [32767, 32767, -32768, 32767, 0]
    assert envs.network_inputs(obs[3]).shape == (13,)


# ---- the trace: the environment's game is duel_evolve play's, bit for bit ----

def _fmt(v: float) -> str:
    return f"{v:.6f}"


def _event(infos: dict[str, dict[str, Any]]) -> str:
    """The trace's event column from a step's infos: eat:SIDE:i for each item eaten, then how the game ended."""
    ev = [f"eat:{s}:{i}" for s in AGENTS for i in range(11) if infos[s]["ate"] >> i & 1]
    o = infos["west"]["outcome"]
    if o in ("west", "east", "draw"):
        ev.append(f"collision:{o}")
    elif o == "timeout":
        ev.append("timeout")
    return ";".join(ev)


def _side_columns(info: dict[str, Any], obs: np.ndarray, action: np.ndarray) -> list[str]:
    assert info["x"] == info["raw"]["x"] / 65536.0 and info["energy"] == info["raw"]["energy"] / 65536.0
    return ([_fmt(info["x"]), _fmt(info["y"]), _fmt(info["heading"]), _fmt(info["energy"]), _fmt(32767 / 32768)] +
            [_fmt(float(v)) for v in obs] + [_fmt(float(v)) for v in action])


class _Player:
    """One side's controller as duel_play runs it: a network stepped by Network.step_q15 on the bias and the
    observation in Q1.15, or a built-in strategy through duel_builtin_act."""

    def __init__(self, spec: str) -> None:
        self.builtin = spec[8:] if spec.startswith("builtin:") else None
        self.net = None if self.builtin else nd.Network.load(spec)
        self.twin = None if self.builtin else nd.Network.load(spec)  # the same, stepped by envs.network_action
        self.step_name = "builtin" if self.builtin else self.net.step_mode  # type: ignore[union-attr]

    def act(self, obs: np.ndarray) -> np.ndarray:
        if self.builtin is not None:
            return envs.builtin_action(self.builtin, obs)
        assert self.net is not None
        scaled = obs.astype(np.float64) * 32768
        assert np.array_equal(scaled, np.round(scaled))
        x = np.concatenate(([32767], scaled)).astype(np.int16)
        assert np.array_equal(x, envs.network_inputs(obs))
        q = self.net.step_q15(x)
        a = (q.astype(np.float32) / np.float32(32768)).astype(np.float32)
        assert self.twin is not None and np.array_equal(envs.network_action(self.twin, obs), a)
        return a


def _play(tmp: pathlib.Path, a: str, b: str, food: int | None, side: str, world: str | None) -> list[str]:
    duel = program("DUEL_EVOLVE")
    trace = tmp / "trace.csv"
    cmd = [str(duel), "play", a, b, "--side", side, "--trace", str(trace), "--force"]
    cmd += ["--food", str(food)] if food is not None else []
    cmd += ["--world", world if world is not None else "v1"]
    subprocess.run(cmd, check=True, capture_output=True)
    return trace.read_text().splitlines()


def _scenarios(tmp: pathlib.Path) -> list[tuple[str, str, int | None, str, str | None]]:
    bench = program("DUEL_BENCH")
    subprocess.run([str(bench), "--write-blobs", str(tmp)], check=True, capture_output=True)
    world = tmp / "world.ini"
    world.write_text(CUSTOM_WORLD)
    c, fh = str(CHAMPION), "builtin:forager-hunter"
    return [
        (c, fh, 5, "west", None),                                        # a collision, food eaten
        (c, fh, 5, "east", None),
        (c, str(tmp / "net39b.blob"), 77, "east", None),                 # two networks to the step limit
        (str(tmp / "net202a.blob"), str(tmp / "net202b.blob"), None, "west", None),  # training food, 202 conns
        (str(CHAMPION_39), "builtin:hunter", 143, "west", None),
        (c, fh, 5, "east", str(world)),                                  # every chosen rule other than v1's
        (c, fh, None, "west", str(world)),
    ]


def test_trace_equals_duel_evolve_play(tmp_path: pathlib.Path) -> None:
    """Each game through DuelEnv, its controllers acting on the observations, is duel_evolve play's game: every
    row of play --trace rebuilt from the environment's observations, actions and infos, string for string."""
    events: set[str] = set()
    for a, b, food, side, world in _scenarios(tmp_path):
        lines = _play(tmp_path, a, b, food, side, world)
        header, rows = lines[0], lines[1:]
        assert header.startswith("t,west_x,west_y,west_heading,west_energy,west_in0,")
        west, east = (_Player(a), _Player(b)) if side == "west" else (_Player(b), _Player(a))
        env = DuelEnv(layouts=[food if food is not None else -1], config=world)
        obs, infos = env.reset(seed=0)
        got: list[str] = []
        rew: dict[str, float] = {}
        term: dict[str, bool] = {}
        trunc: dict[str, bool] = {}
        while env.agents:
            acts = {"west": west.act(obs["west"]), "east": east.act(obs["east"])}
            row = [str(infos["west"]["t"])]
            for s in AGENTS:
                row += _side_columns(infos[s], obs[s], acts[s])
            food_mask = infos["west"]["food_mask"]
            obs, rew, term, trunc, infos = env.step(acts)
            row += [str(food_mask), _event(infos), f"{env.batch.world_id:016x}", west.step_name, east.step_name]
            got.append(",".join(row))
        what = f"play {a} {b} --food {food} --side {side} --world {world}"
        assert len(got) == len(rows), what
        for t, (g, w) in enumerate(zip(got, rows)):
            assert g == w, f"{what}: step {t}\n env: {g}\n play: {w}"
        last = rows[-1].split(",")[-4]
        events.update(e.split(":")[0] + (":" + e.split(":")[1] if e.startswith("collision") else "")
                      for e in last.split(";"))
        events.update("eat" for r in rows if ",eat:" in r)
        outcome = infos["west"]["outcome"]
        want = {"west": (1.0, -1.0), "east": (-1.0, 1.0)}.get(outcome, (0.0, 0.0))
        assert (rew["west"], rew["east"]) == want
        assert term["west"] == (outcome in ("west", "east", "draw")) and trunc["west"] == (outcome == "timeout")
    # the games met every kind of end they can meet here, and food was eaten
    assert {"eat", "timeout", "collision:west", "collision:east"} <= events, events


def test_vs_env_trace(tmp_path: pathlib.Path) -> None:
    """DuelVsEnv is the same game from either side: a network learner against a built-in, and a built-in learner
    against a network opponent, each column of its side as play --trace prints it."""
    c = str(CHAMPION)
    for learner, opponent, side in ((c, "builtin:forager-hunter", "west"), ("builtin:forager-hunter", c, "east"),
                                    ("builtin:hunter", str(CHAMPION_39), "west")):
        lines = _play(tmp_path, learner, opponent, 5, side, None)
        rows = [r.split(",") for r in lines[1:]]
        col = lines[0].split(",").index(f"{side}_x")
        me = _Player(learner)
        opp: Any = nd.Network.load(opponent) if not opponent.startswith("builtin:") else opponent
        env = DuelVsEnv(opp, side=side, layouts=[5])
        obs, info = env.reset(seed=0)
        n = 0
        done = False
        while not done:
            act = me.act(obs)
            got = [str(info["t"])] + _side_columns(info, obs, act)
            want = [rows[n][0]] + rows[n][col:col + 4 + 13 + 3]
            assert got == want, f"{learner} vs {opponent}, {side}, step {n}"
            obs, r, term, trunc, info = env.step(act)
            done = term or trunc
            n += 1
        assert n == len(rows)


# ---- the vectorised form ----

def test_vec_env_is_k_single_games() -> None:
    """DuelVecEnv's K games (on 1 or 2 threads) are K DuelEnv games: the same observations, rewards and ends; with
    autoreset each ended game starts again at once on the next layout drawn from the reset's generator."""
    k, seed, steps = 5, 11, 1700
    rng = np.random.default_rng(seed)
    actions = np.random.default_rng(3).random((steps, k, 2, 3), dtype=np.float32)
    vecs = [DuelVecEnv(k, layouts="comparison", threads=t, shaping=0.5) for t in (1, 2)]
    outs = [v.reset(seed=seed) for v in vecs]
    layouts = rng.integers(144, size=k)
    for o in outs:
        assert np.array_equal(o[1]["layout"], layouts)

    def single(layout: int) -> tuple[DuelEnv, np.ndarray]:
        e = DuelEnv(shaping=0.5)
        o = e.reset(options={"layout": layout})[0]
        return e, np.stack([o["west"], o["east"]])

    singles = []
    for i in range(k):
        e, o = single(int(layouts[i]))
        assert np.array_equal(outs[0][0][i], o)
        singles.append(e)
    episodes = 0
    for step in range(steps):
        results = [v.step(actions[step]) for v in vecs]
        for x, y in zip(results[0][:4], results[1][:4]):
            assert np.array_equal(x, y)
        assert np.array_equal(results[0][4]["final_obs"], results[1][4]["final_obs"])
        obs, rew, term, trunc, info = results[0]
        ended = info["_final_obs"]
        assert np.array_equal(ended, term | trunc)
        if ended.any():
            # the next draws of the same generator, one call for the games that ended, in their order
            assert np.array_equal(info["layout"][ended], rng.integers(144, size=int(ended.sum())))
        for i, e in enumerate(singles):
            so, sr, st, su, _ = e.step({"west": actions[step, i, 0], "east": actions[step, i, 1]})
            assert np.array_equal(info["final_obs"][i], np.stack([so["west"], so["east"]]))
            assert (rew[i, 0], rew[i, 1]) == (np.float32(sr["west"]), np.float32(sr["east"]))
            assert (term[i], trunc[i]) == (st["west"], su["west"])
            if ended[i]:
                episodes += 1
                singles[i], first = single(int(info["layout"][i]))
                assert np.array_equal(obs[i], first) and vecs[0].batch.state(i)["t"] == 0
            else:
                assert np.array_equal(obs[i], info["final_obs"][i])
    assert episodes >= 2 * k


def test_batch_misuse() -> None:
    b = DuelBatch(3)
    with pytest.raises(nd.ArgumentError):
        b.step(np.zeros((2, 2, 3), dtype=np.float32))
    with pytest.raises(TypeError):
        b.step(np.zeros((3, 3, 2), dtype=np.float32))
    before = [b.state(i) for i in range(3)]
    with pytest.raises(nd.ArgumentError):
        b.reset(np.array([0, 3]), np.array([1, 1]))
    with pytest.raises(nd.ArgumentError):
        b.reset(np.array([0, 1]), np.array([1, 144]))
    assert [b.state(i) for i in range(3)] == before  # nothing half-done
    with pytest.raises(IndexError):
        b.state(3)
    with pytest.raises(ValueError):
        DuelBatch(0)
    with pytest.raises(TypeError):
        DuelBatch(1, config="configs/quick.ini")  # type: ignore[arg-type]
    # a game over is not stepped again until reset
    b.reset(np.array([0]), np.array([-1]))
    go = np.ones((3, 2, 3), dtype=np.float32)
    for _ in range(750):
        _, _, term, trunc = b.step(go)
    s = b.state(0)
    assert trunc[0] and s["t"] == 750 and s["outcome"] == "timeout"
    obs, rew, term, trunc = b.step(go)
    assert b.state(0) == s and trunc[0] and not term[0] and rew[0].tolist() == [0.0, 0.0]


def test_import_without_pettingzoo() -> None:
    """import neat_duel needs neither pettingzoo nor gymnasium; neat_duel.envs needs them."""
    code = ("import sys; sys.modules['pettingzoo'] = None; sys.modules['gymnasium'] = None\n"
            "import neat_duel\n"
            "assert 'neat_duel.envs' not in sys.modules\n"
            "try:\n    import neat_duel.envs\nexcept ImportError:\n    print('ok')\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert r.stdout == "ok\n"
