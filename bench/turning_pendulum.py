#!/usr/bin/env python3
"""The turning one-body pendulum in OpenMSS, two ways (docs/integrators.md, "HHT on turning
bodies").

Usage: bench/turning_pendulum.py OPENMSS GENERATE [INTEGRATOR:ERROR ...]
  (default HHT:1e-6 HHT:1e-8; INTEGRATOR may carry options, e.g. "HHT, HMAX=1e-3:1e-6")

offset: `GENERATE chain-planar 1` given WZ = 9 rad/s, so that it turns over (the CM circles the
        pivot at 0.5 m).
torque: the same angle equation with the CM on the pivot: IP about the pivot, no gravity, and
        SFORCE/1, ROTATION, FUNCTION = -m g c SIN(AZ + 0.1) (the gravity moment), so only the
        orientation moves. The tip (MARKER/21) follows the same path in both.
Each model's reference is its own MERSON run at ERROR = 1e-12 (200 outputs over 10 s); the
table gives steps, tip distance at 10 s and the largest over the outputs, and the largest
times steps squared (for a second-order method about constant in the step: the per-step
accuracy, comparable across ERROR; the error at one time can be lucky, the largest less so).
"""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from a02_table import read_b0  # noqa: E402  (REQUEST/3 digits: DX, DY of MARKER/21)


def data_set(generate, torque):
    text = subprocess.run([generate, "chain-planar", "1"], capture_output=True, text=True,
                          check=True).stdout
    text = text.replace("PART/2, MASS=1, CM=20,", "PART/2, MASS=1, CM=20, WZ=9,")
    if torque:
        text = text.replace("CM=20, WZ", "CM=30, WZ").replace(
            "IP=0.0002,0.083433333333333345,0.083433333333333345",
            "IP=0.2502,0.33343333333333335,0.33343333333333335")  # + m c^2 = 0.25
        text = text.replace(
            "ACCGRAV/IGRAV=0, JGRAV=-9.80665, KGRAV=0",
            "ACCGRAV/IGRAV=0, JGRAV=0, KGRAV=0\n"
            "SFORCE/1, ROTATION, I=30, J=31, FUNCTION=-4.903325*SIN(AZ(30,31)+0.1)")
    return text


def run(openmss, workdir, name, integrator, error):
    with open(os.path.join(workdir, name + ".acf"), "w") as f:
        f.write(f"p.adm\n{name}\nINTEGRATOR/{integrator}, ERROR={error}\n"
                "SIMULATE/DYNAMIC, END=10, STEPS=200\nSTOP\n")
    proc = subprocess.run([openmss, "run", name + ".acf"], cwd=workdir, capture_output=True,
                          text=True)
    steps = None
    for line in (proc.stdout + proc.stderr).splitlines():
        if "integration steps" in line and "reached t" in line:
            steps = int(line.split(" with ")[1].split()[0])
    return read_b0(os.path.join(workdir, name + ".req")), steps


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 64
    openmss, generate = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    settings = sys.argv[3:] or ["HHT:1e-6", "HHT:1e-8"]
    print("| model | integrator | ERROR | steps | tip error at 10 s | largest | largest x steps^2 |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for torque in (False, True):
        model = "torque" if torque else "offset"
        with tempfile.TemporaryDirectory() as workdir:
            with open(os.path.join(workdir, "p.adm"), "w") as f:
                f.write(data_set(generate, torque))
            reference, _ = run(openmss, workdir, "ref", "MERSON", "1e-12")
            for k, setting in enumerate(settings):
                integrator, error = setting.rsplit(":", 1)
                rows, steps = run(openmss, workdir, f"run{k}", integrator, error)
                errors = [math.hypot(x - xr, y - yr)
                          for (_, x, y), (_, xr, yr) in zip(rows, reference)]
                scaled = f"{max(errors) * steps * steps:.2e}" if steps else "–"
                print(f"| {model} | {integrator} | {error} | {steps} | {errors[-1]:.2e} | "
                      f"{max(errors):.2e} | {scaled} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
