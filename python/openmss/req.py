"""Reading request files (.req) written by ADAMS/Solver or by OpenMSS, in pure Python.

The layout is the one docs/output-files.md describes (and src/output/request_file_reader.cpp
reads in C++): a 3-line header, two directory lines per request, then for every output time a
time record and one record of six values per request (F2 F3 F4 F6 F7 F8), CRLF or LF."""

import numpy as np
import pandas as pd

from . import components

_WIDTH = 13  # each value is printed in 13 columns after one blank
_RECORD = 1 + 6 * _WIDTH


class RequestFileError(ValueError):
    """A malformed request file; the message is "path:line: what is wrong"."""


class RequestInfo:
    """A directory entry: id, kind ("displacement", ...), type code, I and J marker ids,
    comment, and the six column names of its records."""

    def __init__(self, id, type_code, i_marker, j_marker, comment):
        self.id = id
        self.type = type_code
        self.kind = components.KINDS.get(type_code, "expressions")
        self.i_marker = i_marker
        self.j_marker = j_marker
        self.comment = comment
        self.columns = components.req_names(self.kind)

    def __repr__(self):
        return f"RequestInfo(id={self.id}, kind={self.kind!r}, comment={self.comment!r})"


class RequestFile:
    """The contents of a .req: ``title``, ``stamp``, ``units`` (the token, e.g. M_KGS_N_RACA),
    ``length_scale``, ``entries`` (RequestInfo in file order), ``times`` (one per kept
    record), ``values`` (array [record, request, 6]) and ``requests`` (id -> DataFrame indexed
    by time, columns named as ADAMS names them)."""

    def __init__(self, path, title, stamp, units, length_scale, entries, times, values):
        self.path = path
        self.title = title
        self.stamp = stamp
        self.units = units
        self.length_scale = length_scale
        self.entries = entries
        self.times = times
        self.values = values
        self.requests = {}
        for k, e in enumerate(entries):
            frame = pd.DataFrame(values[:, k, :], index=pd.Index(times, name="time"),
                                 columns=e.columns)
            frame.attrs.update(request=e.id, kind=e.kind, comment=e.comment,
                               units={c: self.unit(e.id, c) for c in e.columns})
            self.requests[e.id] = frame

    def entry(self, request_id):
        for e in self.entries:
            if e.id == request_id:
                return e
        raise KeyError(f"{self.path}: no REQUEST/{request_id} (the file has "
                       f"{', '.join(str(e.id) for e in self.entries) or 'none'})")

    def unit(self, request_id, column):
        """Unit symbol of a column (by name, or 1..6 as in the record) of a request."""
        e = self.entry(request_id)
        k = column - 1 if isinstance(column, int) else e.columns.index(column)
        return components.unit_of(e.kind, components.REQ_COLUMNS[k], self.units)

    def __repr__(self):
        return (f"RequestFile({self.path!r}: {len(self.entries)} requests, "
                f"{len(self.times)} records)")


def _number(word, path, line):
    try:
        return float(word)
    except ValueError:
        raise RequestFileError(f"{path}:{line}: expected a number, found {word.strip()!r}")


def _record(text, path, line):
    # Fixed columns first: a value such as -1.00000E-300 fills its field and touches its
    # neighbour; a record whose trailing blanks were trimmed falls back to words.
    if len(text) >= _RECORD and not text[_RECORD:].strip():
        try:
            return [float(text[1 + k * _WIDTH:1 + (k + 1) * _WIDTH]) for k in range(6)]
        except ValueError:
            pass
    words = text.split()
    if len(words) != 6:
        raise RequestFileError(f"{path}:{line}: expected six numbers, found {len(words)} words")
    return [_number(w, path, line) for w in words]


def _header(lines, path):
    if not lines or not lines[0].strip().startswith("A.R3"):
        raise RequestFileError(f"{path}:1: not a request file: line 1 does not begin with A.R3")
    if len(lines) < 3:
        raise RequestFileError(f"{path}: the header is cut short")
    stamp = lines[0][9:28].strip()
    title = lines[1].rstrip(" ")
    words = lines[2].split()
    if len(words) != 3:
        raise RequestFileError(f"{path}:3: expected the number of requests, the units token "
                               "and the length scale")
    return title, stamp, int(words[0]), words[1], _number(words[2], path, 3)


def _directory(lines, at, count, path):
    entries = []
    for k in range(count):
        if at >= len(lines):
            raise RequestFileError(f"{path}: the directory ends after {k} of {count} requests")
        words = lines[at].split()
        if len(words) != 5:
            raise RequestFileError(f"{path}:{at + 1}: expected a directory record of five "
                                   "integers (id, type, I, J, comment words)")
        rid, code, i, j, nwords = (int(w) for w in words)
        at += 1
        comment = ""
        # A comment of zero words may be an empty record or no record at all.
        if nwords > 0 or (at < len(lines) and not lines[at].strip()):
            if at >= len(lines):
                raise RequestFileError(f"{path}: missing the comment record of REQUEST/{rid}")
            comment = lines[at].rstrip(" ")
            at += 1
        entries.append(RequestInfo(rid, code, i, j, comment))
    return entries, at


def read_req(path, keep="last"):
    """Reads a request file. keep="last" (default) keeps, of consecutive records with the same
    printed time, the last (a run with initial conditions writes t = 0 twice: the IC result,
    then the transient's first output); keep="all" keeps every record in file order."""
    if keep not in ("last", "all"):
        raise ValueError("keep must be 'last' or 'all'")
    path = str(path)
    with open(path, "rb") as f:
        text = f.read().decode("latin-1")
    lines = [line[:-1] if line.endswith("\r") else line for line in text.split("\n")]
    title, stamp, count, units, scale = _header(lines, path)
    entries, at = _directory(lines, 3, count, path)
    times, records = [], []
    while at < len(lines):
        line = lines[at]
        at += 1
        if not line.strip():
            continue
        words = line.split()
        if len(words) != 1:
            raise RequestFileError(f"{path}:{at}: expected a time record (one number) after "
                                   f"{len(times)} complete output steps")
        t = _number(words[0], path, at)
        rows = []
        for e in entries:
            if at >= len(lines) or not lines[at].strip():
                raise RequestFileError(f"{path}:{at}: output step at time {words[0]} is cut "
                                       f"short: no record for REQUEST/{e.id}")
            rows.append(_record(lines[at], path, at + 1))
            at += 1
        if keep == "last" and times and times[-1] == t:
            records[-1] = rows
        else:
            times.append(t)
            records.append(rows)
    values = np.array(records, dtype=float).reshape(len(times), len(entries), 6)
    return RequestFile(path, title, stamp, units, scale, entries, np.array(times), values)
