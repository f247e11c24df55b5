"""The outputs of a variant, from its request file.

A request output is one component of one REQUEST reduced to a number: ``max``, ``min``,
``mean`` (trapezoidal time average), ``final`` (the last output time) or ``at`` a time
(linear interpolation between the two output times around it; an output time itself gives
its value exactly). Components are named as ADAMS names them (openmss.components): the six
columns F2 F3 F4 F6 F7 F8 a request file holds, by those names or by the names of the
request's kind (X Y Z PSI THETA PHI of a DISPLACEMENT, FX FY FZ TX TY TZ of a FORCE, U2 U3 U4
U6 U7 U8 of function expressions, ...), and the magnitudes F1 = |(F2,F3,F4)| and
F5 = |(F6,F7,F8)| (also DM, VM, ACCM, FM and WM, WDTM, TM).
An ``expr`` output is an arithmetic expression of outputs listed before it
(+ - * / **, abs, sqrt, exp, log, min, max; docs/studies.md), evaluated without ``eval``.
"""

from __future__ import annotations

import ast
import math
import operator

import numpy as np

from ..components import EIGHT, REQ_COLUMNS
from .spec import Output, Study, StudyError

COLUMNS = ("F2", "F3", "F4", "F6", "F7", "F8")
FUNCTIONS = {"abs": abs, "sqrt": math.sqrt, "exp": math.exp, "log": math.log, "min": min,
             "max": max}
_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
           ast.Div: operator.truediv, ast.Pow: operator.pow}
_UNARY = {ast.USub: operator.neg, ast.UAdd: operator.pos}


class OutputError(ValueError):
    """An output that cannot be computed from this variant's results."""


def component(kind: str, rows: np.ndarray, name: str) -> np.ndarray:
    """The history of component ``name`` of a request of ``kind`` whose six columns are
    ``rows``."""
    eight = EIGHT.get(kind, EIGHT["expressions"])
    stored = [eight[k] for k in REQ_COLUMNS]
    if name in COLUMNS:
        return rows[:, COLUMNS.index(name)]
    if name in stored:
        return rows[:, stored.index(name)]
    if name in ("F1", eight[0]):
        return np.sqrt((rows[:, 0:3] ** 2).sum(axis=1))
    if name in ("F5", eight[4]):
        return np.sqrt((rows[:, 3:6] ** 2).sum(axis=1))
    known = ", ".join(["F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8"] + eight)
    raise OutputError(f"no component {name} in this {kind} request; its components are {known}")


def reduce(times: np.ndarray, values: np.ndarray, o: Output) -> float:
    if len(times) == 0:
        raise OutputError("the request file has no output times")
    if o.stat == "max":
        return float(values.max())
    if o.stat == "min":
        return float(values.min())
    if o.stat == "final":
        return float(values[-1])
    if o.stat == "mean":
        if len(times) == 1 or times[-1] == times[0]:
            return float(values[0])
        area = float(np.sum((values[1:] + values[:-1]) * np.diff(times)) / 2.0)
        return area / float(times[-1] - times[0])
    t = o.time
    if t < times[0] or t > times[-1]:
        raise OutputError(f"time {t:g} is outside the output times {times[0]:g}..{times[-1]:g}")
    k = int(np.searchsorted(times, t, side="left"))
    if times[k] == t:
        return float(values[k])
    t0, t1 = times[k - 1], times[k]
    return float(values[k - 1] + (values[k] - values[k - 1]) * (t - t0) / (t1 - t0))


def _evaluate(node: ast.AST, env: dict) -> float:
    if isinstance(node, ast.Expression):
        return _evaluate(node.body, env)
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) \
            and not isinstance(node.value, bool):
        return float(node.value)
    if isinstance(node, ast.Name):
        if node.id not in env:
            raise OutputError(f"{node.id} is not an output defined before this one")
        return env[node.id]
    if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
        return _BINARY[type(node.op)](_evaluate(node.left, env), _evaluate(node.right, env))
    if isinstance(node, ast.UnaryOp) and type(node.op) in _UNARY:
        return _UNARY[type(node.op)](_evaluate(node.operand, env))
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
            and node.func.id in FUNCTIONS and not node.keywords:
        return float(FUNCTIONS[node.func.id](*(_evaluate(a, env) for a in node.args)))
    raise OutputError(f"'{ast.unparse(node)}' is not allowed: use numbers, outputs, "
                      "+ - * / **, and abs sqrt exp log min max")


def evaluate_expression(text: str, env: dict) -> float:
    """The value of ``text`` with the outputs of ``env``; every problem is an OutputError."""
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as e:
        raise OutputError(f"not an expression: {e.msg}") from None
    try:
        return float(_evaluate(tree, env))
    except OutputError:
        raise
    except (ArithmeticError, ValueError, TypeError) as e:  # 1/0, sqrt(-1), max() ...
        raise OutputError(f"{text}: {e}") from None


def check_expressions(study: Study) -> None:
    """Each expression is well formed and reads only outputs listed before it. Checked by
    evaluating it with every earlier output at 1.0: the form and the names are what is
    checked, so an arithmetic error at those values (1/(a-1)) does not count."""
    env: dict = {}
    for k, o in enumerate(study.outputs):
        if o.expr is not None:
            try:
                tree = ast.parse(o.expr, mode="eval")
            except SyntaxError as e:
                raise StudyError(f"{study.path}: outputs[{k}].expr: not an expression: "
                                 f"{e.msg}") from None
            try:
                _evaluate(tree, env)
            except OutputError as e:
                raise StudyError(f"{study.path}: outputs[{k}].expr: {e}") from None
            except (ArithmeticError, ValueError, TypeError):
                pass
        env[o.name] = 1.0


def compute(outputs: list[Output], times: np.ndarray, requests: dict) -> dict:
    """``requests``: id -> (kind, rows of six columns). Returns name -> value."""
    values: dict = {}
    for o in outputs:
        if o.expr is not None:
            values[o.name] = evaluate_expression(o.expr, values)
            continue
        if o.request not in requests:
            raise OutputError(f"output {o.name}: the request file has no REQUEST/{o.request}")
        kind, rows = requests[o.request]
        try:
            values[o.name] = reduce(times, component(kind, rows, o.component), o)
        except OutputError as e:
            raise OutputError(f"output {o.name} (REQUEST/{o.request}.{o.component}): {e}") from None
    return values
