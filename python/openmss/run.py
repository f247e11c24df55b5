"""The results of one run of the solver: the output files on disk and DataFrames read from
them (docs/python.md)."""

import os

from .errors import Diagnostic
from .req import read_req
from .res import read_res


class Run:
    """A finished (or failed) run. ``status`` is "completed", "failed" or "input_error";
    ``time`` the simulated time reached; ``outdir``, ``msg``, ``req``, ``res`` the paths of its
    files ("" for one not written); ``messages`` the text of the .msg; ``diagnostics`` every
    diagnostic (Diagnostic objects). ``requests[id]`` is a DataFrame indexed by time with
    ADAMS's component names: the eight components of the .res when the run wrote one, else
    the six of the .req."""

    def __init__(self, info):
        self.status = info["status"]
        self.time = info["time"]
        self.steps = info["steps"]
        self.output_steps = info["output_steps"]
        self.analysis = info["analysis"]
        self.outdir = info["outdir"]
        self.prefix = info["prefix"]
        self.msg = info["msg"]
        self.req = info["req"]
        self.res = info["res"]
        self.diagnostics = [Diagnostic.from_dict(d) for d in info["diagnostics"]]
        self._requests = None
        self._file = None

    @property
    def messages(self):
        """The text of the message file (.msg), "" when none was written."""
        if not self.msg or not os.path.exists(self.msg):
            return ""
        with open(self.msg, encoding="utf-8", errors="replace") as f:
            return f.read()

    @property
    def results(self):
        """The ResultsFile (.res) or RequestFile (.req) the requests come from; None when the
        run wrote neither."""
        if self._file is None:
            if self.res and os.path.exists(self.res):
                self._file = read_res(self.res)
            elif self.req and os.path.exists(self.req):
                self._file = read_req(self.req)
        return self._file

    @property
    def requests(self):
        if self._requests is None:
            f = self.results
            self._requests = dict(f.requests) if f is not None else {}
        return self._requests

    def request_array(self, request_id):
        """REQUEST/id as a NumPy array [output time, 1 + components]: column 0 the time, then
        the components in the order of ``requests[id].columns``."""
        frame = self.requests[request_id]
        return frame.reset_index().to_numpy()

    def __repr__(self):
        return (f"Run(status={self.status!r}, time={self.time:g}, outdir={self.outdir!r}, "
                f"requests={sorted(self.requests)})")
