#!/usr/bin/python3
"""Browser test of the viewer (docs/viewer.md, "Browser test"): headless Chromium loads the
page `openmss view` serves for the piston example, and the parts must be drawn where the
results put them, at frame 0 and at a later frame.

The page runs in its test mode: each moving part in one flat colour, white background, ground
hidden, a camera given in the URL. For each moving part a point inside its graphic (on the
cylinder's axis, half-way) is placed with the part's pose read here from the .res with
xml.etree (not the page's reader), projected with the same perspective camera, and the
screenshot's pixel there must have the part's colour. Between the two frames each part must
have moved: its colour is gone from its frame-0 pixel. Fails (never skips) without Chromium.

Usage: browser_test.py --openmss BIN --source DIR [--res FILE | --fixture] [--keep DIR]
Without --res the piston example is run (examples/piston/piston.acf) and its .res is used;
--fixture uses a .res written from the closed form instead.
"""

import argparse
import base64
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import piston_kinematics  # noqa: E402

CHROMIUM = "/usr/bin/chromium"
WIDTH, HEIGHT = 800, 600
# Camera on +Z looking at the mechanism's middle, the page's default up (+y).
EYE, TARGET, FOV = (6.0, 0.0, 40.0), (6.0, 0.0, 0.0), 30.0
COLORS = {2: (255, 0, 0), 3: (0, 160, 0), 4: (0, 0, 255)}
# A point inside each part's graphic, in its body (CM-marker) frame: half-way along the crank
# throw (1 in from the crank axis, at the CM), the rod's middle (its CM), and the piston
# body's middle (1 in behind the CM towards the skirt, along the CM marker's z = global X).
PROBES = {2: (0.0, 0.0, 0.0), 3: (0.0, 0.0, 0.0), 4: (0.0, 0.0, -1.0)}
# Points each part covers at frame 0 and has left by the later frame (t = 0.25, crank at 90
# degrees): near the crank pin (x = 1.8), the rod's first quarter (x = 3; the rod then passes
# 1.2 in above it) and the piston crown (x = 12.8; the crown is then at x = 10.75).
LEAVING = {2: (0.8, 0.0, 0.0), 3: (-3.0, 0.0, 0.0), 4: (0.0, 0.0, 1.8)}
# A flat unlit colour comes out exact from SwiftShader; 24 levels per channel allows for
# blending at a silhouette should a probe fall on one (it cannot by more than 3 px here).
COLOR_TOLERANCE = 24
# The .res poses against the closed form: ERROR=1e-5 in the command file, a driven mechanism;
# 1e-3 in is 1/30 of a pixel at this camera.
POSE_TOLERANCE = 1e-3


def res_frames(path):
    """Times and {part: [pose per frame]} from an XRF file: every Step but type="input"."""
    root = ET.parse(path).getroot()
    ns = lambda tag: ".//{*}" + tag  # noqa: E731
    parts = {}
    for e in root.iter():
        if e.tag.endswith("Entity") and e.get("entType") == "Part":
            name = (e.get("entity") or e.get("name")).removesuffix("_XFORM")
            digits = name[len(name.rstrip("0123456789")):]
            ids = {c.get("name"): int(c.get("id")) for c in e.findall("{*}Component")}
            parts[int(digits) if digits else int(e.get("objectId"))] = ids
    steps = [[float(v) for v in s.text.split()] for s in root.findall(ns("Step"))
             if s.get("type") != "input"]
    poses = {p: [[s[ids[k] - 1] for k in ("X", "Y", "Z", "PSI", "THETA", "PHI")] for s in steps]
             for p, ids in parts.items()}
    return [s[0] for s in steps], poses


def rotation(psi, theta, phi):
    """Body-fixed 3-1-3: Rz(psi) Rx(theta) Rz(phi) (docs/theory.md)."""
    def rz(a):
        return [[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]]

    def rx(a):
        return [[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]]

    def mul(a, b):
        return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return mul(mul(rz(psi), rx(theta)), rz(phi))


def world(pose, p):
    a = rotation(*pose[3:])
    return [pose[i] + sum(a[i][k] * p[k] for k in range(3)) for i in range(3)]


def project(p):
    """Pixel of world point p under the page's camera (three.js PerspectiveCamera.lookAt)."""
    sub = lambda a, b: [a[i] - b[i] for i in range(3)]  # noqa: E731
    dot = lambda a, b: sum(a[i] * b[i] for i in range(3))  # noqa: E731
    cross = lambda a, b: [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],  # noqa: E731
                          a[0] * b[1] - a[1] * b[0]]
    unit = lambda a: [x / math.sqrt(dot(a, a)) for x in a]  # noqa: E731
    f = unit(sub(TARGET, EYE))
    s = unit(cross(f, [0, 1, 0]))
    u = cross(s, f)
    d = sub(p, EYE)
    depth, half = dot(f, d), math.tan(math.radians(FOV) / 2)
    nx = dot(s, d) / (depth * half * WIDTH / HEIGHT)
    ny = dot(u, d) / (depth * half)
    return (nx + 1) / 2 * WIDTH, (1 - ny) / 2 * HEIGHT


def screenshot(url, png, profile):
    """The page's 3-D view at `url` as a PIL image, saved to `png`. The page (test mode) puts
    its rendered canvas into <pre id="shot"> as a PNG data URL, read here with --dump-dom:
    the view's own pixels at the size asked for, independent of the headless window."""
    cmd = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
           "--no-first-run", "--disable-background-networking", "--disable-component-update",
           "--disable-sync", "--user-data-dir=" + profile, "--use-angle=swiftshader",
           "--enable-unsafe-swiftshader", "--window-size=%d,%d" % (WIDTH, HEIGHT),
           "--virtual-time-budget=15000", "--dump-dom", url]
    dom = subprocess.run(cmd, check=True, capture_output=True, text=True, timeout=120).stdout
    m = re.search(r"data:image/png;base64,([A-Za-z0-9+/=]+)", dom)
    if not m:
        title = re.search(r"<title>(.*?)</title>", dom)
        raise RuntimeError("the page rendered no picture (title %r)" % (title and title.group(1)))
    with open(png, "wb") as f:
        f.write(base64.b64decode(m.group(1)))
    from PIL import Image
    return Image.open(png).convert("RGB")


def same(got, color, what, xy, t):
    ok = max(abs(got[i] - color[i]) for i in range(3)) <= COLOR_TOLERANCE
    print("t=%.3f %s at pixel (%d, %d): %s, part colour %s: %s"
          % (t, what, xy[0], xy[1], got, color, "same" if ok else "different"))
    return ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--openmss", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--res")
    ap.add_argument("--fixture", action="store_true",
                    help="use a results file written from the closed form (piston_kinematics)")
    ap.add_argument("--keep", help="folder to keep the screenshots in")
    a = ap.parse_args()
    if not os.access(CHROMIUM, os.X_OK):
        print("FAIL: %s is missing: scripts/install-deps.sh installs Debian's chromium" % CHROMIUM)
        return 1
    work = tempfile.mkdtemp(prefix="openmss-browser-")
    acf = os.path.join(a.source, "examples", "piston", "piston.acf")
    res = a.res
    if a.fixture:
        res = os.path.join(work, "piston.res")
        piston_kinematics.write_res(res)
    if not res:
        subprocess.run([a.openmss, "run", acf, "--outdir", work, "--quiet"], check=True)
        res = os.path.join(work, "piston.res")
    if not os.path.exists(res):
        print("FAIL: no results file %s" % res)
        return 1
    server = subprocess.Popen([a.openmss, "view", acf, "--outdir", os.path.dirname(res),
                               "--port", "0"], stdout=subprocess.PIPE, text=True)
    failures, checks, worst = [], 0, 0.0
    try:
        line = server.stdout.readline().strip()
        if not line.startswith("OpenMSS viewer: http://127.0.0.1:"):
            print("FAIL: openmss view printed %r" % line)
            return 1
        base = line.split(": ", 1)[1]
        times, poses = res_frames(res)
        later = min(range(len(times)), key=lambda k: abs(times[k] - 0.25))
        if not (len(times) > later > 0 and all(p in poses for p in COLORS)):
            print("FAIL: the results hold %d frames and parts %s" % (len(times), sorted(poses)))
            return 1
        colors = ",".join("%d:%02x%02x%02x" % ((p,) + c) for p, c in COLORS.items())
        cam = ",".join("%g" % v for v in EYE + TARGET)
        for frame in (0, later):
            for p in COLORS:  # the results against the closed form (independent truth)
                exact = piston_kinematics.poses(times[frame])[p]
                err = max(abs(world(poses[p][frame], PROBES[p])[i] -
                              world(exact, PROBES[p])[i]) for i in range(3))
                checks += 1
                worst = max(worst, err)
                if err > POSE_TOLERANCE:
                    failures.append("part %d frame %d: .res is %.3g in from the closed form"
                                    % (p, frame, err))
            url = "%s?test=1&hideground=1&frame=%d&fov=%g&cam=%s&colors=%s&w=%d&h=%d" % (
                base, frame, FOV, cam, colors, WIDTH, HEIGHT)
            png = os.path.join(work, "frame%d.png" % frame)
            image = screenshot(url, png, tempfile.mkdtemp(dir=work))
            if a.keep:
                shutil.copy(png, os.path.join(a.keep, "frame%d.png" % frame))
            if image.size != (WIDTH, HEIGHT):
                failures.append("screenshot is %s, not %dx%d" % (image.size, WIDTH, HEIGHT))
                continue
            for p, color in COLORS.items():
                x, y = project(world(poses[p][frame], PROBES[p]))
                checks += 1
                if not same(image.getpixel((int(x), int(y))), color, "frame %d part %d" % (
                        frame, p), (x, y), times[frame]):
                    failures.append("frame %d part %d: not drawn at pixel (%d, %d)"
                                    % (frame, p, x, y))
                # Drawn where it was at frame 0, gone from there at the later frame.
                x, y = project(world(poses[p][0], LEAVING[p]))
                checks += 1
                covered = same(image.getpixel((int(x), int(y))), color,
                               "frame %d part %d (frame-0 place)" % (frame, p), (x, y), times[frame])
                if covered != (frame == 0):
                    failures.append("frame %d part %d: pixel (%d, %d) %s" % (
                        frame, p, x, y, "lost the part" if frame == 0 else "kept the part"))
    finally:
        server.terminate()
        server.wait(timeout=10)
    print("%d checks, %d failed; .res poses within %.2g in of the closed form (tolerance %g)"
          % (checks, len(failures), worst, POSE_TOLERANCE))
    for f in failures:
        print("FAIL: " + f)
    if checks != 18:  # 2 frames x 3 parts x (pose, drawn there, frame-0 place)
        print("FAIL: %d checks made, 18 expected" % checks)
        return 1
    if not failures:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
