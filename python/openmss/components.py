"""Component names and units of ADAMS requests (docs/python.md).

A request has eight columns F1..F8. For the four standard kinds ADAMS's tabular output names
them (REQUEST statement: DISPLACEMENT, VELOCITY, ACCELERATION, FORCE); columns 1 and 5 are
magnitudes, which the request file (.req) does not store: it holds F2 F3 F4 F6 F7 F8
(docs/output-files.md). Function-expression and user requests are named U1..U8 unless CNAMES
names them (in the .res)."""

# Request type codes of the .req directory (docs/output-files.md).
KINDS = {1: "displacement", 2: "velocity", 3: "acceleration", 4: "force", 5: "expressions"}

EIGHT = {
    # Column 5 of a displacement request has no ADAMS name (its tabular output has seven
    # columns); it is called F5 here.
    "displacement": ["DM", "X", "Y", "Z", "F5", "PSI", "THETA", "PHI"],
    "velocity": ["VM", "VX", "VY", "VZ", "WM", "WX", "WY", "WZ"],
    "acceleration": ["ACCM", "ACCX", "ACCY", "ACCZ", "WDTM", "WDTX", "WDTY", "WDTZ"],
    "force": ["FM", "FX", "FY", "FZ", "TM", "TX", "TY", "TZ"],
    "expressions": ["U1", "U2", "U3", "U4", "U5", "U6", "U7", "U8"],
}

# Columns of the eight that the .req stores (0-based): F2 F3 F4 F6 F7 F8.
REQ_COLUMNS = [1, 2, 3, 5, 6, 7]

# Physical quantity of each of the eight columns, by kind; angles of a displacement request are
# printed in degrees in the .req (docs/output-files.md).
_QUANTITY = {
    "displacement": ["length"] * 4 + ["angle"] * 4,
    "velocity": ["velocity"] * 4 + ["angular velocity"] * 4,
    "acceleration": ["acceleration"] * 4 + ["angular acceleration"] * 4,
    "force": ["force"] * 4 + ["torque"] * 4,
    "expressions": [""] * 8,
}

# Units token of the .req (docs/output-files.md, "Units token"): 2 characters length, 2 mass,
# 1 time, "_", 2 force.
_LENGTH = {"M_": "m", "MM": "mm", "CM": "cm", "IN": "in"}
_FORCE = {"N_": "N", "PF": "lbf"}


def req_names(kind):
    """The six column names of a .req record of a request of this kind."""
    return [EIGHT[kind][k] for k in REQ_COLUMNS]


def units_from_token(token):
    """(length, time, force) unit symbols of a .req units token, None where unknown."""
    token = token or ""
    length = _LENGTH.get(token[0:2])
    time = "s" if token[4:5] == "S" else None
    force = _FORCE.get(token[6:8])
    return length, time, force


def unit_of(kind, column, token, angles="deg"):
    """Unit symbol of column (0..7) of a request of `kind` in a file with units `token`;
    "" when not known (expressions, unknown unit codes)."""
    length, time, force = units_from_token(token)
    q = _QUANTITY[kind][column]
    t = time or "s"
    if q == "length":
        return length or ""
    if q == "angle":
        return angles
    if q == "velocity":
        return f"{length}/{t}" if length else ""
    if q == "acceleration":
        return f"{length}/{t}²" if length else ""
    if q == "angular velocity":
        return f"rad/{t}"
    if q == "angular acceleration":
        return f"rad/{t}²"
    if q == "force":
        return force or ""
    if q == "torque":
        return f"{force}·{length}" if force and length else ""
    return ""
