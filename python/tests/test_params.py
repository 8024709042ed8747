"""Params: keywords, attributes, INI files through the C parser, checks and messages."""
from __future__ import annotations

import copy
import pathlib

import pytest

import neat_duel as nd
from conftest import ROOT


def test_defaults_are_appendix_a() -> None:
    p = nd.Params()
    assert p.pop_size == 256 and p.n_inputs == 12 and p.n_outputs == 3
    assert (p.c1, p.c2, p.c3, p.delta_t) == (1.0, 1.0, 2.0, 3.0)
    assert p.mode == "complexify" and p.allow_recurrent is True
    assert repr(p) == "Params()"


def test_keywords_and_attributes() -> None:
    p = nd.Params(pop_size=150, n_inputs=2, n_outputs=1, allow_recurrent=False, c3=0.4, mode="fixed")
    assert (p.pop_size, p.n_inputs, p.allow_recurrent, p.c3, p.mode) == (150, 2, False, 0.4, "fixed")
    p.weight_mut_prob = 0.5
    p.stagnation_rule = "improvement"
    assert p.get("weight_mut_prob") == 0.5 and p.stagnation_rule == "improvement"
    p.set("add_node_prob", 0.03)
    assert p.add_node_prob == 0.03
    assert nd.Params(**p.to_dict()) == p
    q = copy.deepcopy(p)
    q.pop_size = 10
    assert p.pop_size == 150 and q != p and p.copy() == p


def test_every_key_is_an_attribute() -> None:
    p = nd.Params()
    for k in nd.Params.keys():
        assert getattr(p, k) == p.get(k)
    assert len(nd.Params.keys()) == len(p.to_dict()) >= 35


@pytest.mark.parametrize(
    "kw, message",
    [
        ({"pop_sise": 3}, "unknown key 'pop_sise' (did you mean 'pop_size'?)"),
        ({"pop_size": 1}, "pop_size"),
        ({"pop_size": 2.5}, "an integer"),
        ({"c1": float("nan")}, "not a finite number"),
        ({"c1": "big"}, "a string for a number"),
        ({"mode": 1}, "a number for a name"),
        ({"mode": "grow"}, "mode"),
        ({"allow_recurrent": 1}, "a number for a bool"),
        ({"weight_max": 9.0}, "weight_max"),
        ({"c1": [1]}, "a value of type list"),
    ],
)
def test_bad_values(kw: dict[str, object], message: str) -> None:
    with pytest.raises(nd.ParamError, match=message.replace("(", r"\(").replace(")", r"\)").replace("?", r"\?")):
        nd.Params(**kw)


def test_a_bad_attribute_leaves_the_value() -> None:
    p = nd.Params()
    with pytest.raises(nd.ParamError):
        p.pop_size = 0
    assert p.pop_size == 256
    with pytest.raises(nd.ParamError):
        p.get("nope")


def test_ini_files_the_tools_read() -> None:
    p = nd.Params.from_ini(str(ROOT / "bench" / "xor.ini"))
    assert (p.pop_size, p.n_inputs, p.n_outputs, p.c3, p.stagnation_rule) == (150, 2, 1, 0.4, "improvement")
    q = nd.Params.from_ini(str(ROOT / "configs" / "paper.ini"))  # a duel_evolve configuration: [run], [world] ...
    assert q.pop_size == 256
    assert nd.Params.from_ini_text(p.to_ini(), "dump") == p
    assert p.to_ini().startswith("[neat]\npop_size = 150\n")


def test_ini_errors_name_file_and_line(tmp_path: pathlib.Path) -> None:
    f = tmp_path / "bad.ini"
    f.write_text("[neat]\npop_size = 10\nc1 = x\n")
    with pytest.raises(nd.ParamError, match=r"bad.ini:3: ") as e:
        nd.Params.from_ini(str(f))
    assert e.value.path == str(f)
    f.write_text("[nest]\npop_size = 10\n")
    with pytest.raises(nd.ParamError, match=r"bad.ini:2: unknown section \[nest\]"):
        nd.Params.from_ini(str(f))
    with pytest.raises(FileNotFoundError):
        nd.Params.from_ini(str(tmp_path / "missing.ini"))
    with pytest.raises(nd.FormatError, match="not a regular file"):
        nd.Params.from_ini(str(tmp_path))


def test_neat_cpp_profile_first_wherever_it_stands() -> None:
    # the profile sets NEAT C++ 1.2.1's rules; the other keywords refine it, before or after it
    p = nd.Params(add_conn_rule="any", profile="neat-cpp-1.2.1", add_node_prob=0.0025)
    assert p.profile == "neat-cpp-1.2.1" and p.add_conn_rule == "any" and p.add_node_prob == 0.0025
    assert (p.equal_fitness_rule, p.species_rep, p.speciate_rule, p.stagnation_rule) == (
        "smaller", "champion", "interleaved", "neat-cpp")
    assert p.dropoff_age == 1000 and p.recur_only_prob == 0.2 and p.pop_stagnation == 0
    assert nd.Params(**p.to_dict()) == p
    assert eval("nd." + repr(p)) == p
    # setting it as an attribute applies it then, over what was set before
    q = nd.Params(add_conn_rule="any")
    q.profile = "neat-cpp-1.2.1"
    assert q.add_conn_rule == "neat-cpp"
    q.profile = "default"
    assert q == nd.Params()
    with pytest.raises(nd.ParamError, match="expected one of default, neat-cpp-1.2.1"):
        nd.Params(profile="neat-cpp")
