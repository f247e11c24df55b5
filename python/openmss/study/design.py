"""The variants of a study: full factorial, zip (one variant per position of equal-length
lists) or Latin hypercube with a seed.

Deterministic: the Latin hypercube draws from Python's ``random.Random(seed)``, whose
sequence for an integer seed is guaranteed across Python versions (unlike NumPy's Generator
methods, whose streams may change between releases), so a study file gives the same variants
on every machine.
"""

from __future__ import annotations

import itertools
import random
from dataclasses import dataclass

from .spec import Parameter, Study


@dataclass(frozen=True)
class Variant:
    index: int
    values: tuple  # one level per parameter (number or text), as in the table
    overrides: tuple  # "STATEMENT/id.ARGUMENT=text" for openmss run --set


def value_text(v) -> str:
    """A level as the solver reads it: integers as written, floats in the shortest text
    that reads back as the same double (repr), texts as given."""
    if isinstance(v, str):
        return v
    if isinstance(v, int):
        return str(v)
    return repr(float(v))


def override(p: Parameter, v) -> str:
    text = value_text(v)
    if p.template is not None:
        text = p.template.replace("{value}", text)
    return f"{p.set}={text}"


def _latin_hypercube(study: Study) -> list[tuple]:
    """``samples`` points: for each parameter the range is cut into ``samples`` equal strata,
    each stratum used once (a shuffled order), a uniform point drawn inside it."""
    n = study.samples
    rng = random.Random(study.seed)
    columns = []
    for p in study.parameters:
        order = list(range(n))
        rng.shuffle(order)
        columns.append([p.low + (order[i] + rng.random()) / n * (p.high - p.low)
                        for i in range(n)])
    return list(zip(*columns))


def variants(study: Study) -> list[Variant]:
    if study.design == "full_factorial":
        levels = list(itertools.product(*(p.values for p in study.parameters)))
    elif study.design == "zip":
        levels = list(zip(*(p.values for p in study.parameters)))
    else:
        levels = _latin_hypercube(study)
    return [Variant(k, tuple(vals), tuple(override(p, v) for p, v in zip(study.parameters, vals)))
            for k, vals in enumerate(levels)]
