"""neat_duel: NEAT and competitive coevolution (Stanley & Miikkulainen 2004) in C, for Python.

The C libraries do the work (libneat, the fixed-point runtime a microcontroller runs, the robot duel); this
package binds them. docs/python.md is the guide::

    import neat_duel as nd

    params = nd.Params(pop_size=150, n_inputs=2, n_outputs=1, allow_recurrent=False)
    pop = nd.Population(params, seed=1)
    records = pop.run(fitness, generations=100)   # fitness(genome) -> float
"""
from __future__ import annotations

from . import deploy, errors, gym, pages, runs
from .data import data_path
from ._core import (
    Q15_ONE,
    VERSION,
    Coevolution,
    Duel,
    DuelConfig,
    Genome,
    Network,
    Networks,
    Params,
    Population,
    duel_builtins,
    duel_compare,
    duel_play,
    from_q15,
    q15,
    seed_derive,
)
from .errors import (
    ArgumentError,
    CountersError,
    FitnessError,
    FormatError,
    NeatError,
    OutOfMemoryError,
    ParamError,
    StateError,
    TooBigError,
)

__version__ = VERSION

__all__ = [
    "Q15_ONE",
    "VERSION",
    "Coevolution",
    "Duel",
    "DuelConfig",
    "Genome",
    "Network",
    "Networks",
    "Params",
    "Population",
    "duel_builtins",
    "duel_compare",
    "duel_play",
    "from_q15",
    "q15",
    "seed_derive",
    "data_path",
    "deploy",
    "errors",
    "gym",
    "runs",
    "ArgumentError",
    "CountersError",
    "FitnessError",
    "FormatError",
    "NeatError",
    "OutOfMemoryError",
    "ParamError",
    "StateError",
    "TooBigError",
]
