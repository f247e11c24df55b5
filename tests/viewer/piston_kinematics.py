"""Closed-form kinematics of the piston example (examples/piston/piston.adm) and a results
file written from them, for the viewer's browser test (docs/viewer.md, "Browser test").

The crank turns at 360 deg/s about global Z (MOTION/01, POLY(TIME, 0, 0, 360D)); crank radius
r = 2, rod length L = 8, the piston slides along X. At crank angle q the crank pin is
A = (r cos q, r sin q, 0) and the piston pin B = (r cos q + sqrt(L^2 - r^2 sin^2 q), 0, 0).
Each part's body frame is its CM marker (docs/theory.md): the crank's at 1 in along the throw,
axes turning with q; the rod's half-way between the pins, x along the rod; the piston's 1 in
beyond its pin, axes x=Y y=Z z=X (REULER 90D, 90D, 0) throughout.
"""

import math

R, L = 2.0, 8.0


def poses(t):
    """{part id: (x, y, z, psi, theta, phi)} of the moving parts at time t."""
    q = 2.0 * math.pi * t
    ax, ay = R * math.cos(q), R * math.sin(q)
    bx = ax + math.sqrt(L * L - ay * ay)
    rod = math.atan2(-ay, bx - ax)
    return {
        2: (0.5 * ax, 0.5 * ay, 0.0, q, 0.0, 0.0),
        3: (0.5 * (ax + bx), 0.5 * ay, 0.0, rod, 0.0, 0.0),
        4: (bx + 1.0, 0.0, 0.0, 0.5 * math.pi, 0.5 * math.pi, 0.0),
    }


def write_res(path, end=2.0, dtout=0.01):
    """A results file in the XRF layout (docs/output-files.md): part X..PHI and one request
    (the piston's CM displacement, REQUEST/11), one dynamic <Step> per output time."""
    parts = [2, 3, 4]
    names = ["X", "Y", "Z", "PSI", "THETA", "PHI"]
    lines = ['<?xml version="1.0" encoding="UTF-8"?>',
             '<Results xmlns="http://www.mscsoftware.com/:xrf10">',
             '<Analysis name="fixture">', '<ModelInfo title="PISTON COMPRESSOR (closed form)"/>',
             '<Units angle="rad" length="inch" mass="pound_mass" time="sec"/>',
             '<StepMap name="map_001">',
             '<Entity name="time"><Component name="TIME" unitsValue="sec" id="1"/></Entity>']
    cid = 2
    for p in parts:
        comps = "".join('<Component name="%s" id="%d"/>' % (n, cid + k) for k, n in enumerate(names))
        lines.append('<Entity name="PART_%d" entity="PART_%d" entType="Part" objectId="%d">%s'
                     '</Entity>' % (p, p, p, comps))
        cid += 6
    comps = "".join('<Component name="%s" id="%d"/>' % (n, cid + k)
                    for k, n in enumerate(["X", "Y", "Z"]))
    lines.append('<Entity name="REQUEST_11" entity="REQUEST_11" entType="Request" objectId="11">'
                 '%s</Entity>' % comps)
    lines += ['</StepMap>', '<Data name="dynamic_001" id="1">']
    n = int(round(end / dtout))
    for i in range(n + 1):
        t = i * dtout
        ps = poses(t)
        values = [t] + [v for p in parts for v in ps[p]] + [ps[4][0], 0.0, 0.0]
        lines.append('<Step type="dynamic">\n' + " ".join("%.17g" % v for v in values) + '\n</Step>')
    lines += ['</Data>', '</Analysis>', '</Results>']
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    import sys
    write_res(sys.argv[1])
