"""Genome: numpy views, files, dot, distance; Network: step, settle, q15, blobs."""
from __future__ import annotations

import pathlib
import subprocess

import numpy as np
import pytest

import neat_duel as nd


def evolved() -> nd.Genome:
    pop = nd.Population(nd.Params(pop_size=20, n_inputs=3, n_outputs=2, add_node_prob=0.3, add_conn_prob=0.5), seed=3)
    pop.run(lambda g: float(g.n_enabled), 5)
    g = pop.last_best
    assert g is not None
    return g


def test_views_are_the_genome() -> None:
    g = evolved()
    nodes, conns = g.nodes, g.conns
    assert nodes.dtype.names == ("id", "type") and conns.dtype.names == ("in", "out", "weight", "innov", "enabled")
    assert len(nodes) == 1 + 3 + 2 + g.n_hidden and list(nodes["type"][:6]) == [0, 1, 1, 1, 2, 2]
    assert int(conns["enabled"].sum()) == g.n_enabled
    assert np.all(np.diff(conns["innov"].astype(np.int64)) > 0) and np.all(np.diff(nodes["id"].astype(np.int64)) > 0)
    assert not nodes.flags.writeable and not conns.flags.writeable
    assert nodes.base is not None  # a view, not a copy
    del g
    assert int(conns["innov"][0]) == 0  # the view keeps the genome alive


def test_genome_files(tmp_path: pathlib.Path) -> None:
    g = evolved()
    f = tmp_path / "g.genome"
    g.save(str(f))
    h = nd.Genome.load(str(f))
    assert h.to_bytes() == g.to_bytes() == f.read_bytes()
    assert np.array_equal(h.conns, g.conns) and (h.n_inputs, h.n_outputs) == (3, 2)
    assert g.distance(h, nd.Params()) == 0.0
    assert h.network().blob == g.network().blob
    data = bytearray(f.read_bytes())
    data[-1] ^= 1
    with pytest.raises(nd.FormatError, match=r"<bytes>: .* at byte offset"):
        nd.Genome.from_bytes(bytes(data))
    with pytest.raises(nd.FormatError, match="at byte offset 0"):
        nd.Genome.from_bytes(b"not a genome")
    with pytest.raises(FileNotFoundError):
        nd.Genome.load(str(tmp_path / "none"))


def test_dot() -> None:
    dot = evolved().to_dot()
    assert dot.startswith("digraph genome {") and dot.rstrip().endswith("}")
    try:
        r = subprocess.run(["dot", "-Tsvg"], input=dot.encode(), capture_output=True)
    except FileNotFoundError:
        pytest.skip("no Graphviz here")
    assert r.returncode == 0 and b"<svg" in r.stdout


def test_network_steps() -> None:
    net = evolved().network()
    assert (net.n_inputs, net.n_outputs, net.step_mode) == (3, 2, "sync")
    a = net.step([0.5, -0.25, 1.0])
    net.reset()
    assert net.step((0.5, -0.25, 1.0)) == a
    net.reset()
    assert net.step(np.array([0.5, -0.25, 1.0])) == a
    net.reset()
    assert net.step(np.array([0.5, -0.25, 1.0], dtype=np.float32)) == a
    assert all(0.0 <= v < 1.0 for v in a)
    out = np.zeros(2)
    net.reset()
    net.step_into(np.array([0.5, -0.25, 1.0]), out)
    assert list(out) == a
    acts = net.activations
    assert acts.dtype == np.int16 and len(acts) == 1 + 3 + 2 + net.n_hidden and not acts.flags.writeable
    q = net.step_q15(np.array([nd.Q15_ONE, nd.q15(0.5), nd.q15(-0.25), nd.q15(1.0)], dtype=np.int16))
    assert q.dtype == np.int16 and len(q) == 2
    assert nd.from_q15(nd.q15(0.5)) == 0.5 and nd.q15(2.0) == 32767 and nd.q15(-3.0) == -32768
    assert nd.q15(float("nan")) == 0 and nd.q15(float("inf")) == 32767  # defined, the same on every machine
    net.reset()
    b = net.step([0.0, -0.25, 1.0])
    net.reset()
    assert net.step([float("nan"), -0.25, 1.0]) == b
    with pytest.raises(nd.ArgumentError, match="2 values for a network of 3 inputs"):
        net.step([1.0, 2.0])
    with pytest.raises(TypeError):
        net.step(["a", "b", "c"])
    with pytest.raises(nd.ArgumentError):
        nd.from_q15(40000)


def test_blobs(tmp_path: pathlib.Path) -> None:
    net = evolved().network()
    f = tmp_path / "n.blob"
    net.save(str(f))
    assert f.read_bytes() == net.blob
    m = nd.Network.load(str(f))
    assert m.blob == net.blob and repr(m) == repr(net)
    bad = bytearray(net.blob)
    bad[-1] ^= 1
    with pytest.raises(nd.FormatError, match="not a network blob this runtime loads"):
        nd.Network.from_blob(bytes(bad))
    with pytest.raises(nd.FormatError):
        nd.Network.from_blob(b"")


def test_from_genes_is_a_layered_network(tmp_path: pathlib.Path) -> None:
    """A two-layer perceptron written as genes computes sigmoid(4.9 x) layer by layer, in one propagate step."""
    rng = np.random.default_rng(5)
    ni, no, h = 12, 3, 6
    w1, b1, w2, b2 = rng.normal(0, 1, (h, ni)), rng.normal(0, 1, h), rng.normal(0, 1, (no, h)), rng.normal(0, 1, no)
    conns = [(0, 1 + ni + no + k, b1[k]) for k in range(h)]
    conns += [(1 + i, 1 + ni + no + k, w1[k, i]) for k in range(h) for i in range(ni)]
    conns += [(0, 1 + ni + o, b2[o]) for o in range(no)]
    conns += [(1 + ni + no + k, 1 + ni + o, w2[o, k]) for o in range(no) for k in range(h)]
    g = nd.Genome.from_genes(ni, no, h, conns, step="propagate")
    assert (g.n_inputs, g.n_outputs, g.n_hidden, g.n_enabled, g.step) == (ni, no, h, len(conns), "propagate")
    net = g.network()

    def sig(x: np.ndarray) -> np.ndarray:
        return 1 / (1 + np.exp(-4.9 * x))

    for _ in range(20):
        x = rng.uniform(-1, 1, ni)
        want = sig(w2 @ sig(w1 @ x + b1) + b2)
        net.reset()
        assert np.allclose(net.step(list(x)), want, atol=2e-3)  # Q15 activations, Q3.12 weights
    g.save(str(tmp_path / "mlp.genome"))
    assert nd.Genome.load(str(tmp_path / "mlp.genome")).n_enabled == len(conns)
    with pytest.raises(nd.ArgumentError, match="ends at the bias or an input"):
        nd.Genome.from_genes(2, 1, 0, [(0, 1, 1.0)])
    with pytest.raises(nd.ArgumentError, match="'sync' or 'propagate'"):
        nd.Genome.from_genes(2, 1, 0, [(0, 3, 1.0)], step="fast")
