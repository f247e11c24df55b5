"""`openmss plot`: one request component against time, from a .req or .res, optionally over
another file's (ADAMS's .req against ours), written as a PNG with matplotlib's Agg backend.

    openmss plot RESULT --request ID --component N|NAME [--vs OTHER] [-o OUT.png]

--component is ADAMS's column number 1..8 (F1..F8: 2 is X, 6 is PSI of a displacement
request; the .req stores 2 3 4 6 7 8) or a component name (X, VZ, FX, ...). docs/python.md."""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from . import components  # noqa: E402
from .req import read_req  # noqa: E402
from .res import read_res  # noqa: E402

# 8 x 4.5 inches at 100 dots per inch: 800 x 450 pixels (the tests check the size).
FIGSIZE = (8.0, 4.5)
DPI = 100


class Series:
    """One component of one request of one file: times, values, name, unit, title, label."""

    def __init__(self, times, values, name, unit, title, label):
        self.times, self.values = times, values
        self.name, self.unit, self.title, self.label = name, unit, title, label


def _column(names, component, eight, path, request):
    """Index into `names` of `component`: a name (any case), or an ADAMS column 1..8."""
    if isinstance(component, str) and not component.isdigit():
        upper = [n.upper() for n in names]
        if component.upper() not in upper:
            raise SystemExit(f"openmss plot: {path}: REQUEST/{request} has no component "
                             f"{component!r} (it has {', '.join(names)})")
        return upper.index(component.upper())
    n = int(component)
    if not 1 <= n <= 8:
        raise SystemExit(f"openmss plot: --component {n}: give 1..8 (F1..F8) or a name")
    if eight:
        if n > len(names):
            raise SystemExit(f"openmss plot: {path}: REQUEST/{request} has {len(names)} "
                             "components")
        return n - 1
    if n - 1 not in components.REQ_COLUMNS:
        raise SystemExit(f"openmss plot: {path}: column {n} (F{n}) is a magnitude, which a "
                         ".req does not store; give 2 3 4 6 7 or 8, or plot the .res")
    return components.REQ_COLUMNS.index(n - 1)


def load_series(path, request, component, label=None):
    """The Series of REQUEST/`request`, `component`, of a .req or .res file."""
    path = str(path)
    label = label or os.path.basename(path)
    if path.lower().endswith(".res"):
        f = read_res(path)
        try:
            e = f.request_entity(request)
        except KeyError as err:
            raise SystemExit(f"openmss plot: {err.args[0]}")
        frame = f.entity(e.name)
        names = list(frame.columns)
        k = _column(names, component, True, path, request)
        unit = e.components[k].units
        title = f"REQUEST/{request} {e.entity}"
    else:
        f = read_req(path)
        try:
            entry = f.entry(request)
        except KeyError as err:
            raise SystemExit(f"openmss plot: {err.args[0]}")
        frame = f.requests[request]
        names = list(frame.columns)
        k = _column(names, component, False, path, request)
        unit = f.unit(request, names[k])
        title = f"REQUEST/{request}" + (f" {entry.comment}" if entry.comment else "")
    return Series(frame.index.to_numpy(), frame.iloc[:, k].to_numpy(), names[k], unit, title,
                  label)


def plot(result, request, component, vs=None, output=None, label=None, vs_label=None):
    """Plots and writes the PNG. Returns (figure, axes, lines): lines[0] is `result`'s
    component, lines[1] `vs`'s when given."""
    ours = load_series(result, request, component, label)
    series = [ours]
    if vs is not None:
        series.append(load_series(vs, request, component, vs_label))
    fig, ax = plt.subplots(figsize=FIGSIZE, dpi=DPI)
    styles = [dict(color="tab:blue", linewidth=1.6), dict(color="tab:red", linestyle="--",
                                                          linewidth=1.2)]
    lines = []
    for s, style in zip(series, styles):
        (line,) = ax.plot(s.times, s.values, label=s.label, **style)
        lines.append(line)
    unit = f" [{ours.unit}]" if ours.unit else ""
    ax.set_xlabel("time [s]" if _seconds(result) else "time")
    ax.set_ylabel(f"{ours.name}{unit}")
    ax.set_title(ours.title)
    ax.grid(True, alpha=0.3)
    if vs is not None:
        ax.legend()
    fig.tight_layout()
    if output is None:
        stem = os.path.splitext(os.path.basename(str(result)))[0]
        output = f"{stem}_request{request}_{ours.name}.png"
    fig.savefig(output, dpi=DPI)
    fig.openmss_output = output  # the path written, for the command line's message
    return fig, ax, lines


def _seconds(path):
    # Every unit system the .req token names has the second as its time unit
    # (docs/output-files.md); a .res states its own.
    if str(path).lower().endswith(".res"):
        return read_res(path).units.get("time", "sec") in ("sec", "second", "s")
    return True


def main(argv=None):
    p = argparse.ArgumentParser(prog="openmss plot", description=__doc__.split("\n\n")[0])
    p.add_argument("result", help="a .req or .res file")
    p.add_argument("--request", type=int, required=True, help="REQUEST id")
    p.add_argument("--component", required=True,
                   help="ADAMS column 1..8 (F1..F8) or a component name (X, VZ, FX, ...)")
    p.add_argument("--vs", help="another .req or .res to overlay (e.g. ADAMS's)")
    p.add_argument("-o", "--output", help="PNG to write (default RESULT_requestID_NAME.png)")
    p.add_argument("--label", help="legend label of RESULT (default: its file name)")
    p.add_argument("--vs-label", help="legend label of --vs (default: its file name)")
    a = p.parse_args(argv)
    for path in [a.result] + ([a.vs] if a.vs else []):
        if not os.path.isfile(path):
            print(f"openmss plot: {path}: no such file", file=sys.stderr)
            return 1
    try:
        fig, _, lines = plot(a.result, a.request, a.component, a.vs, a.output, a.label,
                             a.vs_label)
    except SystemExit as e:
        print(e.code, file=sys.stderr)
        return 1
    except ValueError as e:  # a malformed file (RequestFileError, ResultsFileError)
        print(f"openmss plot: {e}", file=sys.stderr)
        return 1
    print(f"openmss plot: wrote {fig.openmss_output} ({len(lines[0].get_xdata())} points)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
