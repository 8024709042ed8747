"""The package under misuse (issue 49, section 7): each case crashed, hung, or raised a misleading error before.
The thread cases run under a timeout, so a hang fails the test instead of the suite."""
from __future__ import annotations

import _thread
import pathlib
import threading
import time
from typing import Any, Callable

import numpy as np
import pytest

import neat_duel as nd
from neat_duel import runs

from conftest import ROOT


def duel_params(pop: int = 16) -> nd.Params:
    return nd.Params(pop_size=pop, n_inputs=12, n_outputs=3, pop_stagnation=0)


def small_coev(seed: int = 1, pop: int = 16) -> nd.Coevolution:
    return nd.Coevolution(duel_params(pop), seed=seed, compare_configs=4)


def in_thread(fn: Callable[[], Any], timeout: float = 120.0) -> None:
    """fn in a daemon thread; fails (not hangs) when it does not return within timeout seconds."""
    err: list[BaseException] = []

    def body() -> None:
        try:
            fn()
        except BaseException as e:  # noqa: BLE001 - handed to the test's thread
            err.append(e)

    t = threading.Thread(target=body, daemon=True)
    t.start()
    t.join(timeout)
    assert not t.is_alive(), f"{fn} did not return within {timeout} s"
    if err:
        raise err[0]


def coin(a: nd.Network, b: nd.Network, config: int, a_first: bool, seed: int) -> int:
    return 1 if seed % 2 else -1


def test_game_calling_step_of_its_own_coevolution_is_refused() -> None:
    coev = nd.Coevolution(nd.Params(pop_size=12, n_inputs=2, n_outputs=1, pop_stagnation=0), seed=1,
                          compare_configs=2)
    seen: list[BaseException] = []

    def game(a: nd.Network, b: nd.Network, config: int, a_first: bool, seed: int) -> int:
        try:
            coev.step(coin)
        except nd.StateError as e:
            seen.append(e)
            raise
        return 1

    with pytest.raises(nd.StateError, match="already playing a generation"):
        coev.step(game)
    assert seen
    assert coev.generation == 0
    coev.step(coin)  # usable afterwards
    assert coev.generation == 1


def test_reading_a_coevolution_from_its_game_is_refused() -> None:
    coev = nd.Coevolution(nd.Params(pop_size=12, n_inputs=2, n_outputs=1, pop_stagnation=0), seed=1,
                          compare_configs=2)

    def game(a: nd.Network, b: nd.Network, config: int, a_first: bool, seed: int) -> int:
        coev.population("A")
        return 1

    with pytest.raises(nd.StateError, match="already playing a generation"):
        coev.step(game)


def test_two_coevolutions_sharing_one_duel_in_threads() -> None:
    duel = nd.Duel(threads=1)
    coevs = [small_coev(1), small_coev(2)]

    def both() -> None:
        ts = [threading.Thread(target=c.run, args=(duel, 3)) for c in coevs]
        for t in ts:
            t.start()
        for t in ts:
            t.join()

    in_thread(both)
    assert [c.generation for c in coevs] == [3, 3]
    # the same as each alone
    alone = small_coev(2)
    alone.run(nd.Duel(threads=1), 3)
    assert alone.to_bytes() == coevs[1].to_bytes()


def test_two_threads_stepping_one_coevolution() -> None:
    coev = small_coev(3)
    errors: list[BaseException] = []

    def step() -> None:
        try:
            coev.run(nd.Duel(threads=1), 3)
        except nd.StateError as e:
            errors.append(e)

    def both() -> None:
        ts = [threading.Thread(target=step) for _ in range(2)]
        for t in ts:
            t.start()
        for t in ts:
            t.join()

    in_thread(both)
    assert 3 <= coev.generation <= 6
    # whatever interleaving: a checkpoint that loads, and no corruption
    assert nd.Coevolution.from_bytes(coev.to_bytes()).generation == coev.generation
    # a Python game in two threads: one of them refused, never two in one generation
    coev2 = nd.Coevolution(nd.Params(pop_size=12, n_inputs=2, n_outputs=1, pop_stagnation=0), seed=1,
                           compare_configs=2)
    gate = threading.Event()

    def slow(a: nd.Network, b: nd.Network, config: int, a_first: bool, seed: int) -> int:
        gate.set()
        time.sleep(0.001)
        return 1

    first = threading.Thread(target=coev2.step, args=(slow,))
    first.start()
    gate.wait(30)
    with pytest.raises(nd.StateError, match="already playing a generation"):
        coev2.step(coin)
    first.join()
    assert coev2.generation == 1


def test_ctrl_c_stops_run_between_generations() -> None:
    coev = small_coev(4, pop=24)
    duel = nd.Duel(threads=1)
    coev.step(duel)
    t0 = time.perf_counter()
    coev.step(duel)
    one = time.perf_counter() - t0
    timer = threading.Timer(max(0.2, 3 * one), _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            coev.run(duel, 100000)
    finally:
        timer.cancel()
    assert coev.generation < 100000
    coev.step(duel)  # whole: it goes on


@pytest.mark.parametrize("answer", [np.bool_(True), 1, "yes", [0]])
def test_until_takes_any_truth_value(answer: Any) -> None:
    coev = nd.Coevolution(nd.Params(pop_size=12, n_inputs=2, n_outputs=1, pop_stagnation=0), seed=1,
                          compare_configs=2)
    assert len(coev.run(coin, 5, until=lambda r: answer)) == 1


@pytest.mark.parametrize("answer", [np.bool_(False), None, 0, ""])
def test_until_false_values(answer: Any) -> None:
    coev = nd.Coevolution(nd.Params(pop_size=12, n_inputs=2, n_outputs=1, pop_stagnation=0), seed=1,
                          compare_configs=2)
    assert len(coev.run(coin, 2, until=lambda r: answer)) == 2


def test_play_many_wrong_types_say_what_is_wrong() -> None:
    duel = nd.Duel(threads=1)
    with pytest.raises(TypeError, match="matches"):
        duel.play_many(3)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="match 0"):
        duel.play_many([3])  # type: ignore[list-item]
    with pytest.raises(TypeError, match="match 0: food"):
        duel.play_many([("forager", "hunter", 1.5, True)])  # type: ignore[list-item]
    with pytest.raises(TypeError, match="match 0: food"):
        duel.play_many([("forager", "hunter", [1], True)])  # type: ignore[list-item]
    with pytest.raises(TypeError, match="match 0: a_west"):
        duel.play_many([("forager", "hunter", 1, [True])])  # type: ignore[list-item]
    with pytest.raises(TypeError, match="a match's player"):
        duel.play_many([(7, "hunter", 1, True)])  # type: ignore[list-item]
    # a tuple of matches is a sequence too
    assert duel.play_many((("forager", "idle", 0, True),)) in ([1], [-1], [0])


def test_step_into_refuses_an_output_it_cannot_write() -> None:
    pop = nd.Population(nd.Params(pop_size=8, n_inputs=2, n_outputs=1), seed=1)
    net = pop.genome(0).network()
    for dtype in (np.float32, np.int64):
        out = np.zeros(1, dtype=dtype)
        with pytest.raises(TypeError, match="out: a float64 array"):
            net.step_into(np.array([0.5, -0.25]), out)
    out = np.zeros(1)
    with pytest.raises(TypeError, match="out: a float64 array"):
        net.step_into(np.array([0.5, -0.25]), out[::1].reshape(1, 1))
    ro = np.zeros(1)
    ro.setflags(write=False)
    with pytest.raises(TypeError, match="writable"):
        net.step_into(np.array([0.5, -0.25]), ro)
    net.step_into(np.array([0.5, -0.25]), out)
    net.reset()
    assert out[0] == net.step([0.5, -0.25])[0]


def test_a_coevolution_that_does_not_fit_the_duel() -> None:
    coev = nd.Coevolution(nd.Params(pop_size=12, n_inputs=2, n_outputs=1, pop_stagnation=0), seed=1,
                          compare_configs=2)
    with pytest.raises(nd.ParamError, match="n_inputs = 2 and n_outputs = 1.*12 inputs and 3 outputs"):
        coev.step(nd.Duel(threads=1))


@pytest.mark.parametrize("call", [
    lambda: nd.Coevolution(duel_params(), seed=-1),
    lambda: nd.Population(nd.Params(pop_size=12, n_inputs=2, n_outputs=1), seed=-5),
    lambda: nd.Duel(threads=-2),
    lambda: small_coev().run(coin, -3),
])
def test_negative_counts_and_seeds_name_the_argument(call: Callable[[], Any]) -> None:
    with pytest.raises(ValueError, match="not negative|at least"):
        call()


def test_a_missing_file_is_an_oserror(tmp_path: pathlib.Path) -> None:
    missing = tmp_path / "nothing.ini"
    for load in (nd.Params.from_ini, nd.DuelConfig.from_ini, nd.Genome.load, nd.Network.load, nd.Population.load,
                 nd.Coevolution.load):
        with pytest.raises(FileNotFoundError):
            load(missing)  # a pathlib.Path: accepted where a path is


def test_paths_may_be_pathlib(tmp_path: pathlib.Path) -> None:
    coev = nd.Coevolution(nd.Params(pop_size=12, n_inputs=2, n_outputs=1, pop_stagnation=0), seed=1,
                          compare_configs=2)
    coev.save(tmp_path / "c.bin")
    assert nd.Coevolution.load(tmp_path / "c.bin").to_bytes() == coev.to_bytes()
    g = nd.Population(nd.Params(pop_size=8, n_inputs=2, n_outputs=1), seed=1).genome(0)
    g.save(tmp_path / "g.genome")
    assert nd.Genome.load(tmp_path / "g.genome").to_bytes() == g.to_bytes()
    cfg = nd.DuelConfig.from_ini(ROOT / "configs" / "quick.ini")
    assert cfg.generations > 0


def test_add_conn_prob_names_itself() -> None:
    with pytest.raises(nd.ParamError, match="add_conn_prob"):
        nd.Params(add_conn_prob=1.0)


def test_runs_set_may_be_one_string(tmp_path: pathlib.Path) -> None:
    r = runs.run(ROOT / "tests" / "tools" / "coev-small.ini", tmp_path / "r", generations=1, set="pop_size=16")
    assert "pop_size = 16" in (tmp_path / "r" / "config.ini").read_text()
    assert r.path == tmp_path / "r"


def test_runs_resume_can_shorten(tmp_path: pathlib.Path) -> None:
    runs.run(ROOT / "tests" / "tools" / "coev-small.ini", tmp_path / "r", generations=2, set=["pop_size=16"])
    with pytest.raises(runs.RunError, match="add --shorten"):
        runs.resume(tmp_path / "r", generations=1)
    # the flag reaches the command: the refusal is now the one for a run that played more than that
    with pytest.raises(runs.RunError, match="played 2 generations already, more than 1"):
        runs.resume(tmp_path / "r", generations=1, shorten=True)


def test_the_guides_files_ship_with_the_package() -> None:
    assert nd.Params.from_ini(nd.data_path("bench/xor.ini")).pop_size == 150
    assert nd.data_path("configs/quick.ini").read_bytes() == (ROOT / "configs" / "quick.ini").read_bytes()
    with pytest.raises(FileNotFoundError, match="configs/quick.ini"):
        nd.data_path("configs/nothing.ini")
    with pytest.raises(FileNotFoundError):
        nd.data_path("../../../etc/passwd")


def test_evaluations_go_on_after_a_checkpoint_load() -> None:
    def fit(g: nd.Genome) -> float:
        return sum(g.network().step([1.0, 0.0])) + 0.1

    params = nd.Params(pop_size=20, n_inputs=2, n_outputs=1)
    whole = nd.Population(params, seed=4).run(fit, 5)
    pop = nd.Population(params, seed=4)
    assert pop.best_ever is None
    first = pop.run(fit, 3)
    assert pop.best_ever is not None
    again = nd.Population.from_bytes(pop.to_bytes()).run(fit, 2)
    assert [r["evaluations"] for r in first + again] == [r["evaluations"] for r in whole] == [20, 40, 60, 80, 100]
    assert pop.run(fit, 1)[0]["evaluations"] == 80  # a second run of the same population goes on too


def test_overrides_schedule_is_not_ignored(tmp_path: pathlib.Path) -> None:
    """Issue 49 §3: a configuration with [overrides] (a resumed run's schedule) is refused by coevolution(), never
    started with generation 0's parameters alone and the schedule dropped."""
    ini = tmp_path / "o.ini"
    ini.write_text("[neat]\npop_size = 16\n[overrides]\nfrom 3 = add_node_prob=0.05\n")
    cfg = nd.DuelConfig.from_ini(ini)
    assert "from 3 = add_node_prob=0.05" in cfg.to_ini()
    with pytest.raises(nd.ParamError, match=r"\[overrides\]"):
        cfg.coevolution()
