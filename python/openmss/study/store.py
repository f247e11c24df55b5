"""Results on disk: one ``result.json`` per variant, written as soon as the variant finishes
(so an interrupted study loses nothing computed and a rerun runs only what is missing), and
the table gathered from them, sorted by variant, with a fixed number format, so that it is
byte-for-byte the same for any worker count and completion order.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import math
import os
from dataclasses import asdict
from pathlib import Path

from .design import Variant, value_text
from .spec import Study

TABLE = "results.csv"


def variant_dir(out: Path, index: int) -> Path:
    return out / "variants" / f"v{index:05d}"


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def study_key(study: Study) -> str:
    """What a variant's result depends on besides its overrides: the model file's content,
    the run options and the outputs asked for. A result with another key is run again."""
    data = {"model": str(study.model), "model_sha256": _digest(study.model), "run": study.run,
            "outputs": [asdict(o) for o in study.outputs]}
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()


def variant_key(base: str, v: Variant) -> str:
    return hashlib.sha256(json.dumps([base, list(v.overrides)]).encode()).hexdigest()


def load_result(out: Path, v: Variant, key: str) -> dict | None:
    """The stored result of ``v`` when it is there and was computed for this study."""
    path = variant_dir(out, v.index) / "result.json"
    try:
        data = json.loads(path.read_text())
    except (OSError, ValueError):
        return None
    if data.get("key") != key or data.get("status") == "task-error":
        return None  # another study's, or lost by the cluster (not the variant's fault)
    return data


def save_result(out: Path, v: Variant, key: str, result: dict) -> None:
    """Written to a temporary file and renamed: a study killed mid-write leaves either the
    whole result or none."""
    d = variant_dir(out, v.index)
    d.mkdir(parents=True, exist_ok=True)
    data = {"key": key, "index": v.index, "overrides": list(v.overrides), **result}
    tmp = d / "result.json.tmp"
    tmp.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")
    os.replace(tmp, d / "result.json")


def number_text(x) -> str:
    """Ten significant digits (the request file holds six): the same text on every run."""
    if x is None:
        return ""
    x = float(x)
    if math.isnan(x):
        return "nan"
    return format(x, ".10g")


def table_text(study: Study, variants: list[Variant], results: dict) -> str:
    """The CSV: one row per variant in index order: variant, the parameters (as set), the
    outputs, status and message (the .msg diagnosis of a failure)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["variant"] + [p.set for p in study.parameters] + [o.name for o in study.outputs]
               + ["status", "message"])
    for v in sorted(variants, key=lambda v: v.index):
        r = results.get(v.index, {"status": "missing", "message": "", "outputs": {}})
        w.writerow([v.index] + [value_text(x) for x in v.values]
                   + [number_text(r["outputs"].get(o.name)) for o in study.outputs]
                   + [r["status"], r["message"].replace("\n", " ")])
    return buf.getvalue()
