"""The main-effects plot: for each output (row) and parameter (column), the output's mean
over the successful variants at each level of the parameter. A parameter with more than
eight distinct levels (a Latin hypercube) is cut into five groups of equal count, each shown
at its mean level, with the variants themselves as dots."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only; no display on a cluster node or in CI
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .design import Variant  # noqa: E402
from .spec import Study  # noqa: E402


def _levels(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    distinct = np.unique(x)
    if len(distinct) <= 8:
        return distinct, np.array([y[x == level].mean() for level in distinct])
    groups = np.array_split(np.argsort(x, kind="stable"), 5)
    return (np.array([x[g].mean() for g in groups]), np.array([y[g].mean() for g in groups]))


def main_effects(study: Study, variants: list[Variant], results: dict, path: Path) -> bool:
    """Writes the PNG; False (nothing written) when no parameter is numeric or no variant
    succeeded."""
    ok = [v for v in variants if results.get(v.index, {}).get("status") == "ok"]
    numeric = [k for k, _ in enumerate(study.parameters)
               if ok and all(isinstance(v.values[k], (int, float)) for v in ok)]
    outs = [o.name for o in study.outputs]
    if not numeric or not ok:
        return False
    fig, axes = plt.subplots(len(outs), len(numeric), squeeze=False,
                             figsize=(3.2 * len(numeric), 2.4 * len(outs)))
    for row, name in enumerate(outs):
        y_all = np.array([results[v.index]["outputs"].get(name, np.nan) for v in ok], float)
        for col, k in enumerate(numeric):
            ax = axes[row][col]
            x_all = np.array([v.values[k] for v in ok], float)
            keep = np.isfinite(y_all)
            x, y = x_all[keep], y_all[keep]
            if len(x):
                ax.plot(x, y, ".", color="0.7", markersize=3)
                lx, ly = _levels(x, y)
                ax.plot(lx, ly, "o-", color="C0")
            if row == len(outs) - 1:
                ax.set_xlabel(study.parameters[k].set, fontsize=8)
            if col == 0:
                ax.set_ylabel(name, fontsize=8)
            ax.tick_params(labelsize=7)
    fig.suptitle(f"{study.name}: main effects ({len(ok)} of {len(variants)} variants ok)",
                 fontsize=9)
    fig.tight_layout(rect=(0, 0, 1, 0.97))  # room for the title
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return True
