"""Exceptions of the openmss package (docs/python.md)."""

import re

# A statement and its id as the solver names them in messages: "PART/2", "SFORCE/7".
_STATEMENT = re.compile(r"\b([A-Z][A-Z_]*/\d+)\b")


class Diagnostic:
    """One diagnostic of the solver: where (file:line:col), the statement and its id, what is
    wrong and what to change. ``str(d)`` is the line the command-line program prints."""

    __slots__ = ("severity", "file", "line", "column", "statement", "message", "hint", "text")

    def __init__(self, severity="error", file="", line=0, column=0, statement="", message="",
                 hint="", text=""):
        self.severity = severity
        self.file = file
        self.line = line
        self.column = column
        self.statement = statement
        self.message = message
        self.hint = hint
        self.text = text or f"{file}:{line}:{column}: {severity}: {statement}: {message}. {hint}"

    @classmethod
    def from_dict(cls, d):
        return cls(**{k: d[k] for k in cls.__slots__})

    def __str__(self):
        return self.text

    def __repr__(self):
        return f"Diagnostic({self.text!r})"


class OpenMSSError(Exception):
    """Base class of the package's errors."""


class InputError(OpenMSSError):
    """A data set or command file has errors. ``errors`` lists every error of the one pass
    (Diagnostic objects); ``file``, ``line``, ``column``, ``statement``, ``message`` and
    ``hint`` are those of the first. The message holds every error line."""

    def __init__(self, diagnostics, path=""):
        self.diagnostics = list(diagnostics)
        self.errors = [d for d in self.diagnostics if d.severity == "error"]
        first = self.errors[0] if self.errors else Diagnostic(file=path, message="input error")
        self.file = first.file
        self.line = first.line
        self.column = first.column
        self.statement = first.statement
        self.hint = first.hint
        self.message = first.message
        lines = [str(d) for d in self.errors] or [str(first)]
        super().__init__(f"{len(self.errors)} error(s) in {path or first.file}:\n" + "\n".join(lines))


class SolverError(OpenMSSError):
    """An analysis failed. ``time`` is the simulated time reached; ``element`` the statement
    the failure is about: the one the diagnostic names, else the first its message names (the
    equation with the largest error: "PART/2"), "" when none; ``elements`` every statement the
    message names (e.g. also the largest applied force, "SFORCE/7"); ``diagnostics`` every
    diagnostic of the run; ``run`` the Run with the outputs written up to the failure."""

    def __init__(self, run, diagnostics):
        self.run = run
        self.time = run.time
        self.diagnostics = list(diagnostics)
        errors = [d for d in self.diagnostics if d.severity == "error"]
        self.errors = errors
        last = errors[-1] if errors else None
        named = _STATEMENT.findall(last.message) if last else []
        self.elements = ([last.statement] if last and last.statement else []) + named
        self.element = self.elements[0] if self.elements else ""
        self.file = last.file if last else ""
        self.line = last.line if last else 0
        self.message = last.message if last else "the analysis failed"
        lines = [str(d) for d in errors] or ["the analysis failed"]
        super().__init__(f"the analysis failed at t = {self.time:g}"
                         + (f" ({self.element})" if self.element else "") + ":\n"
                         + "\n".join(lines))
