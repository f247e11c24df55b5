"""The study file: reading and checking it (schema in docs/studies.md).

Every problem is reported as ``StudyError("study.yaml: parameters[2].range: ...")`` naming
the key to change; nothing unknown is ignored.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

DESIGNS = ("full_factorial", "zip", "latin_hypercube")
STATS = ("max", "min", "final", "at", "mean")
# STATEMENT/id.ARGUMENT or STATEMENT.ARGUMENT (statements without id, e.g. ACCGRAV); the
# solver's reader checks the names themselves (openmss run --set).
_SET = re.compile(r"^[A-Za-z_]+(/[0-9]+)?\.[A-Za-z_0-9]+$")
_NAME = re.compile(r"^[A-Za-z_][A-Za-z_0-9]*$")


class StudyError(ValueError):
    """A study file that cannot be run; the message names the file and key."""


@dataclass(frozen=True)
class Parameter:
    set: str  # STATEMENT/id.ARGUMENT
    values: tuple = ()  # levels (list or range), for full_factorial and zip
    low: float | None = None  # bounds, for latin_hypercube
    high: float | None = None
    template: str | None = None  # "POLY(VR(408,109),0,0,-{value})": the argument text


@dataclass(frozen=True)
class Output:
    name: str
    request: int | None = None
    component: str | None = None
    stat: str | None = None
    time: float | None = None
    expr: str | None = None


@dataclass
class Study:
    path: Path  # the study file
    name: str
    model: Path  # .acf or .adm, absolute
    run: dict  # .adm only: end, steps, dtout (openmss run options)
    design: str
    parameters: list[Parameter]
    outputs: list[Output]
    samples: int | None = None
    seed: int | None = None
    timeout: float | None = None  # seconds per variant
    raw: dict = field(default_factory=dict)


def _fail(where: str, message: str) -> None:
    raise StudyError(f"{where}: {message}")


def _keys(where: str, data: Any, allowed: set[str], required: set[str] = frozenset()) -> dict:
    if not isinstance(data, dict):
        _fail(where, "expected a mapping")
    unknown = sorted(set(data) - allowed)
    if unknown:
        _fail(where, f"unknown key(s) {', '.join(map(str, unknown))}; allowed: "
              f"{', '.join(sorted(allowed))}")
    missing = sorted(required - set(data))
    if missing:
        _fail(where, f"missing key(s) {', '.join(missing)}")
    return data


def _number(where: str, v: Any) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        _fail(where, f"expected a number, got {v!r}")
    return float(v)


def _range_values(where: str, r: Any) -> tuple:
    _keys(where, r, {"start", "stop", "num", "step"}, {"start", "stop"})
    start, stop = _number(f"{where}.start", r["start"]), _number(f"{where}.stop", r["stop"])
    if ("num" in r) == ("step" in r):
        _fail(where, "give exactly one of num (count, both ends included) and step")
    if "num" in r:
        num = r["num"]
        if not isinstance(num, int) or isinstance(num, bool) or num < 1:
            _fail(f"{where}.num", "expected a positive integer")
        if num == 1:
            return (start,)
        # start + k*(stop-start)/(num-1): the ends are exact, the levels the same on every run.
        return tuple(start + k * (stop - start) / (num - 1) for k in range(num - 1)) + (stop,)
    step = _number(f"{where}.step", r["step"])
    if step == 0 or (stop - start) / step < 0:
        _fail(f"{where}.step", "the step does not lead from start to stop")
    count = int(round((stop - start) / step * (1 + 1e-12))) + 1  # stop included when on the grid
    return tuple(start + k * step for k in range(count))


def _parameter(where: str, p: Any, design: str) -> Parameter:
    _keys(where, p, {"set", "values", "range", "low", "high", "template"}, {"set"})
    target = p["set"]
    if not isinstance(target, str) or not _SET.match(target.strip()):
        _fail(f"{where}.set",
              f"expected STATEMENT/id.ARGUMENT (e.g. SPRINGDAMPER/3.K), got {target!r}")
    template = p.get("template")
    if template is not None and (not isinstance(template, str) or "{value}" not in template):
        _fail(f"{where}.template", "expected a text containing {value}")
    if design == "latin_hypercube":
        if "low" not in p or "high" not in p or "values" in p or "range" in p:
            _fail(where, "a latin_hypercube parameter takes low and high (not values or range)")
        low, high = _number(f"{where}.low", p["low"]), _number(f"{where}.high", p["high"])
        if not high > low:
            _fail(where, "high must exceed low")
        return Parameter(target.strip(), low=low, high=high, template=template)
    if "low" in p or "high" in p:
        _fail(where, "low and high are for design: latin_hypercube; give values or range")
    if ("values" in p) == ("range" in p):
        _fail(where, "give exactly one of values and range")
    if "values" in p:
        vals = p["values"]
        if not isinstance(vals, list) or not vals:
            _fail(f"{where}.values", "expected a non-empty list")
        for k, v in enumerate(vals):
            if isinstance(v, bool) or not isinstance(v, (int, float, str)):
                _fail(f"{where}.values[{k}]", f"expected a number or a text, got {v!r}")
        values = tuple(vals)
    else:
        values = _range_values(f"{where}.range", p["range"])
    return Parameter(target.strip(), values=values, template=template)


def _output(where: str, o: Any) -> Output:
    _keys(where, o, {"name", "request", "component", "stat", "time", "expr"}, {"name"})
    name = o["name"]
    if not isinstance(name, str) or not _NAME.match(name):
        _fail(f"{where}.name", f"expected an identifier (letters, digits, _), got {name!r}")
    if "expr" in o:
        if set(o) - {"name", "expr"}:
            _fail(where, "an expr output takes only name and expr")
        if not isinstance(o["expr"], str):
            _fail(f"{where}.expr", "expected a text")
        return Output(name, expr=o["expr"])
    _keys(where, o, set(o), {"request", "component", "stat"})
    req = o["request"]
    if not isinstance(req, int) or isinstance(req, bool):
        _fail(f"{where}.request", "expected a REQUEST id")
    stat = o["stat"]
    if stat not in STATS:
        _fail(f"{where}.stat", f"expected one of {', '.join(STATS)}, got {stat!r}")
    if (stat == "at") != ("time" in o):
        _fail(where, "time is given with stat: at, and only then")
    time = _number(f"{where}.time", o["time"]) if "time" in o else None
    return Output(name, request=req, component=str(o["component"]).upper(), stat=stat, time=time)


def parse_study(data: Any, path: Path) -> Study:
    where = str(path)
    top = _keys(where, data, {"name", "model", "run", "design", "samples", "seed", "parameters",
                              "outputs", "timeout"}, {"model", "parameters", "outputs"})
    model = (path.parent / str(top["model"])).resolve()
    if model.suffix.lower() not in (".acf", ".adm"):
        _fail(f"{where}: model", "expected an .acf command file or an .adm data set")
    if not model.is_file():
        _fail(f"{where}: model", f"{model} does not exist")
    run = top.get("run", {}) or {}
    _keys(f"{where}: run", run, {"end", "steps", "dtout"})
    if run and model.suffix.lower() == ".acf":
        _fail(f"{where}: run", "the command file says what to simulate; run is for an .adm model")
    design = top.get("design", "full_factorial")
    if design not in DESIGNS:
        _fail(f"{where}: design", f"expected one of {', '.join(DESIGNS)}, got {design!r}")
    samples = seed = None
    if design == "latin_hypercube":
        samples, seed = top.get("samples"), top.get("seed")
        for key, v in (("samples", samples), ("seed", seed)):
            if not isinstance(v, int) or isinstance(v, bool) or v < (1 if key == "samples" else 0):
                _fail(f"{where}: {key}",
                      "latin_hypercube needs an integer samples >= 1 and seed >= 0")
    elif "samples" in top or "seed" in top:
        _fail(where, "samples and seed are for design: latin_hypercube")
    params = top["parameters"]
    if not isinstance(params, list) or not params:
        _fail(f"{where}: parameters", "expected a non-empty list")
    parameters = [_parameter(f"{where}: parameters[{k}]", p, design) for k, p in enumerate(params)]
    sets = [p.set.upper() for p in parameters]
    if len(set(sets)) != len(sets):
        _fail(f"{where}: parameters", "an argument is set twice")
    outs = top["outputs"]
    if not isinstance(outs, list) or not outs:
        _fail(f"{where}: outputs", "expected a non-empty list")
    outputs = [_output(f"{where}: outputs[{k}]", o) for k, o in enumerate(outs)]
    names = [o.name for o in outputs]
    if len(set(names)) != len(names):
        _fail(f"{where}: outputs", "two outputs have the same name")
    if design == "zip" and len({len(p.values) for p in parameters}) != 1:
        _fail(f"{where}: parameters", "design zip needs the same number of values for each")
    timeout = top.get("timeout")
    if timeout is not None:
        timeout = _number(f"{where}: timeout", timeout)
    return Study(path=path.resolve(), name=str(top.get("name", path.stem)), model=model,
                 run=dict(run), design=design, parameters=parameters, outputs=outputs,
                 samples=samples, seed=seed, timeout=timeout, raw=data)


def load_study(path: str | Path) -> Study:
    path = Path(path)
    try:
        text = path.read_text()
    except OSError as e:
        raise StudyError(f"{path}: cannot read the study file: {e.strerror}") from None
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as e:
        raise StudyError(f"{path}: not YAML: {e}") from None
    study = parse_study(data, path)
    from .outputs import check_expressions  # the expressions name outputs defined above

    check_expressions(study)
    return study
