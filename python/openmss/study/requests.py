"""The few request histories a study's outputs read, straight from a request file.

``openmss.read_req`` builds a pandas DataFrame (with units) for every request of the file;
a study variant needs a handful of columns of a few requests, and on a short run that
reading cost as much as the solver. This reader walks the file with the same rules (the
layout of docs/output-files.md; header and directory read by openmss.req's own functions;
of consecutive records with the same time the last is kept, as ``read_req``'s default) but
converts only the records of the requests asked for, into NumPy arrays, and builds no
DataFrame. Every record is still checked to be present, so a file cut short is an error
here as it is there. python/tests/test_study_design.py checks it against ``read_req``.
"""

from __future__ import annotations

import numpy as np

from ..req import RequestFileError, _directory, _header, _number, _record


def read_requests(path, ids) -> tuple[np.ndarray, dict]:
    """``(times, {id: (kind, rows)})`` for the requests of ``ids`` that the file holds
    (``rows``: array [output time, 6], the columns F2 F3 F4 F6 F7 F8). An id the file lacks
    is left out: the caller says what is missing."""
    path = str(path)
    with open(path, "rb") as f:
        text = f.read().decode("latin-1")
    lines = text.split("\n")
    if "\r" in text:
        lines = [line[:-1] if line.endswith("\r") else line for line in lines]
    _title, _stamp, count, _units, _scale = _header(lines, path)
    entries, at = _directory(lines, 3, count, path)
    wanted = {k: e for k, e in enumerate(entries) if e.id in set(ids)}
    times: list[float] = []
    records: list[list] = []
    end = len(lines)
    while at < end:
        line = lines[at]
        at += 1
        if not line.strip():
            continue
        words = line.split()
        if len(words) != 1:
            raise RequestFileError(f"{path}:{at}: expected a time record (one number) after "
                                   f"{len(times)} complete output steps")
        t = _number(words[0], path, at)
        for k, e in enumerate(entries):
            if at + k >= end or not lines[at + k].strip():
                raise RequestFileError(f"{path}:{at + k + 1}: output step at time {words[0]} is "
                                       f"cut short: no record for REQUEST/{e.id}")
        rows = [_record(lines[at + k], path, at + k + 1) for k in wanted]
        at += count
        if times and times[-1] == t:
            records[-1] = rows
        else:
            times.append(t)
            records.append(rows)
    values = np.array(records, dtype=float).reshape(len(times), len(wanted), 6)
    return np.array(times), {e.id: (e.kind, values[:, j, :])
                             for j, e in enumerate(wanted.values())}
