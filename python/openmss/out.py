"""Reading the tabular output file (.out) OpenMSS writes, in pure Python.

The layout is OpenMSS's own (ADAMS's is not public), described in docs/output-files.md, "The
tabular output file (.out)": pages of at most 50 output times, each page one table per
REQUEST (a `REQUEST/id  TYPE ...` line, a comment line, the column names, the units, then one
row of white-space separated numbers per output time). The rows of one request are joined
page after page, in file order."""

import numpy as np
import pandas as pd


class TabularFileError(ValueError):
    """A malformed .out; the message is "path:line: what is wrong"."""


class TabularFile:
    """The contents of a .out: ``title``, ``status`` ("Successful" or "Failed"), ``blocks``
    (analysis block names in order) and ``requests`` (id -> DataFrame indexed by time, the
    columns named as the file names them; ``attrs`` hold ``type``, ``comment`` and ``units``)."""

    def __init__(self, path, title, status, blocks, requests):
        self.path = path
        self.title = title
        self.status = status
        self.blocks = blocks
        self.requests = requests


def read_out(path):
    """Reads a .out written by OpenMSS. Raises TabularFileError when the file is malformed."""
    path = str(path)
    title, status, blocks = "", "", []
    tables = {}  # id -> dict(type, comment, names, units, rows)
    table, header = None, 0
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\r\n")

            def fail(what):
                raise TabularFileError(f"{path}:{number}: {what}")

            if line.startswith("Title: ") and number == 2:
                title = line[7:]
            elif line.startswith(" Analysis "):
                name = line[10:line.index(",")] if "," in line else fail("bad page header")
                if not blocks or blocks[-1] != name:
                    blocks.append(name)
                table = None
            elif line.startswith(" End of the run: "):
                status = line[17:].strip()
                table = None
            elif line.startswith(" REQUEST/"):
                words = line[9:].split()
                rid = int(words[0])
                table = tables.setdefault(rid, {"type": words[1], "comment": "", "names": None,
                                                "units": None, "rows": []})
                header = 3
            elif table is not None and header > 0:
                if header == 3:
                    table["comment"] = line[len(" Comment: "):]
                elif header == 2:
                    names = line.split()
                    if table["names"] not in (None, names):
                        fail("the columns of a table changed between pages")
                    table["names"] = names
                else:
                    table["units"] = line.split()
                header -= 1
            elif table is not None and line.startswith(" "):
                values = [float(v) for v in line.split()]
                if len(values) != len(table["names"]):
                    fail(f"{len(values)} values for {len(table['names'])} columns")
                table["rows"].append(values)
            else:
                table = None
    requests = {}
    for rid, t in tables.items():
        rows = np.array(t["rows"], dtype=float).reshape(-1, len(t["names"]))
        frame = pd.DataFrame(rows[:, 1:], index=pd.Index(rows[:, 0], name="time"),
                             columns=t["names"][1:])
        frame.attrs.update(request=rid, type=t["type"], comment=t["comment"],
                           units=dict(zip(t["names"][1:], t["units"][1:])))
        requests[rid] = frame
    return TabularFile(path, title, status, blocks, requests)
