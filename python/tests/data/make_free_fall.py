"""Writes free_fall.res, the hand-made XRF fixture of test_res.py, in the layout real ADAMS
.res files have (docs/python.md): two parts whose ids are allocated by quantity block (all
positions, then all velocities, then all accelerations: PART_2 owns ids 2-7, 14-19, 26-31;
REQUEST/3 38-45),
one request of eight components, an "input" step, the initial conditions and a dynamic run.
PART_2 falls freely from rest in inch units (g = 9.80665 / 0.0254 in/s^2); PART_3 rests at
(1, 5, 0). Run it again only to change the fixture:  /usr/bin/python3 make_free_fall.py"""

G = 9.80665 / 0.0254  # standard gravity in inch/s^2
NAMES = {"pos": ["X", "Y", "Z", "PSI", "THETA", "PHI"], "vel": ["VX", "VY", "VZ", "WX", "WY", "WZ"],
         "acc": ["ACCX", "ACCY", "ACCZ", "WDX", "WDY", "WDZ"]}
UNITS = {"pos": ["inch"] * 3 + ["rad"] * 3, "vel": ["inch/sec"] * 3 + ["rad/sec"] * 3,
         "acc": ["inch/sec**2"] * 3 + ["rad/sec**2"] * 3}
REQ = [("mag", "inch"), ("x", "inch"), ("y", "inch"), ("z", "inch"), ("r_mag", "rad"),
       ("psi", "rad"), ("theta", "rad"), ("phi", "rad")]


def ids(block, part):  # part 0 is PART_2, 1 is PART_3
    return [2 + 12 * block + 6 * part + k for k in range(6)]


def values(t):
    y = -0.5 * G * t * t
    v = [0.0] * 45
    v[0] = t
    v[ids(0, 0)[1] - 1] = y
    v[ids(1, 0)[1] - 1] = -G * t
    v[ids(2, 0)[1] - 1] = -G
    v[ids(0, 1)[0] - 1], v[ids(0, 1)[1] - 1] = 1.0, 5.0
    v[38 - 1], v[40 - 1] = abs(y), y  # REQUEST/3: mag and y of PART_2's displacement
    return v


def step(kind, v):
    rows = [repr(v[0])] + [" ".join(repr(x) for x in v[i:i + 6]) for i in range(1, 37, 6)]
    rows.append(" ".join(repr(x) for x in v[37:45]))
    return f'<Step type="{kind}">\n' + "\n".join(rows) + "\n</Step>\n"


def comp(name, unit, i, label=None):
    extra = f' plotLabel="{label}"' if label is not None else ""
    return f'<Component name="{name}" unitsValue="{unit}"{extra} id="{i}" />\n'


def part(name, object_id, p):
    out = f'<Entity name="{name}_XFORM" entity="{name}" entType="Part" objectId="{object_id}">\n'
    for b, q in enumerate(("pos", "vel", "acc")):
        for n, u, i in zip(NAMES[q], UNITS[q], ids(b, p)):
            out += comp(n, u, i)
    return out + "</Entity>\n"


text = ('<?xml version="1.0" encoding="UTF-8"?>\n'
        '<Results xmlns="http://www.mscsoftware.com/:xrf10">\n'
        '<Bibliography>\n<File URI="file://free_fall.res" schema="xrf" version="2.0.0.0" />\n'
        '</Bibliography>\n'
        '<Analysis name="free_fall" executionDate="2000-01-01 00:00:00" '
        'Solver="hand-made test fixture" script="-unknown-">\n'
        '<ModelInfo title="free fall of one part, inch and pound-mass" />\n'
        '<Units angle="rad" length="inch" mass="pound_mass" time="sec" />\n'
        '<StepMap name="map_001">\n<Entity name="time">\n' + comp("TIME", "sec", 1) +
        "</Entity>\n" + part("PART_2", 2, 0) + part("PART_3", 3, 1) +
        '<Entity name="REQUEST_3" entity="REQUEST_3" entType="Request" objectId="3">\n' +
        "".join(comp(n, u, 38 + k, n.upper()) for k, (n, u) in enumerate(REQ)) +
        "</Entity>\n</StepMap>\n"
        '<Data name="modelInput_001" id="1">\n' + step("input", [9.0] * 45) + "</Data>\n"
        '<Data name="initialConditions_001" id="2">\n' + step("initialConditions", values(0.0)) +
        "</Data>\n"
        '<Data name="dynamic_001" id="3">\n' +
        "".join(step("dynamic", values(0.025 * k)) for k in range(11)) + "</Data>\n"
        '<TerminationStatus runTermObject="" runStatus="Successful" />\n'
        "</Analysis>\n</Results>\n")

if __name__ == "__main__":
    with open("free_fall.res", "w") as f:
        f.write(text)
