#!/usr/bin/env python3
"""BDF on IFToMM A02's one-degree-of-freedom motion in three formulations, constant steps
(docs/integrators.md, "Order and formulation on A02").

Usage: bench/bdf_turning_point_mass.py [--bottom] [K:H ...]   (default 6:0.025 5:0.025 6:0.0125)

A02 at N = 40 (docs/validation.md) is phi'' = -k cos phi, k = g B / A, phi(0) = pi/2,
phi'(0) = -1 rad/s: a row of four-bars turning over about once per 2 s, 6.7 rad/s at the bottom.
The same motion is a point mass on a unit circle under a gravity k, which is how a multibody
program sees each rocker and coupler: Cartesian coordinates of points that turn. BDF of order K
at the constant step H (the history started from the exact solution, the corrector solved to
round-off), 20 s, against classical RK4 of the angle equation (h = 1e-4 s). Pure Python, no
OpenMSS:

  angle   BDF on phi' = w, w' = -k cos phi (the one-degree-of-freedom form).
  cart1   BDF on x' = u, u' = -2 lam x (y likewise, with -k), lam from the acceleration
          constraint (index 1, no projection).
  cart3   BDF on the index-3 form, x^2 + y^2 = 1 held exactly and lam an unknown of the
          corrector: GSTIFF I3 at a constant step and order (bdf_integrator.cpp).
  rk4     classical RK4 on cart1, each step's result projected onto the position and velocity
          constraints (merson_integrator.cpp is index 1 and projects too).
  merson  the same with Kutta-Merson's fourth-order formula, MERSON's (exact to fifth order on
          linear problems, which the turning Cartesian coordinates nearly are).

Prints the angle error and the relative energy error at 20 s. With --bottom, each cart3 and
angle step of the first bottom passage (t = 0.85-1.0 s): the step's error in phi and phi' from
the exact flow through its start and its energy change, in J of the N = 40 row (times A).
Measured (docs/integrators.md): cart3 reproduces GSTIFF I3's steps on A02 N = 40 at h = 0.025 s
and order 6 to two digits; at equal steps it is 200x less accurate than angle.
"""
import math
import sys

N = 40
A = (N + 1) / 3.0 + N
B = (N + 1) * 0.5 + N
K_GRAV = 9.81 * B / A
T_END = 20.0


def angle_rate(p, w):
    return w, -K_GRAV * math.cos(p)


def exact(p, w, dt, hmax=1e-4):
    n = max(1, int(math.ceil(dt / hmax - 1e-9)))
    h = dt / n
    for _ in range(n):
        k1 = angle_rate(p, w)
        k2 = angle_rate(p + h / 2 * k1[0], w + h / 2 * k1[1])
        k3 = angle_rate(p + h / 2 * k2[0], w + h / 2 * k2[1])
        k4 = angle_rate(p + h * k3[0], w + h * k3[1])
        p += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        w += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
    return p, w


def bdf_coefficients(k):
    """a_j with sum_j a_j y_n+1-j = h y'_n+1 at constant steps (derivative of the Lagrange
    polynomial through 0, -1, ..., -k at 0)."""
    nodes = [-j for j in range(k + 1)]
    out = []
    for j in range(k + 1):
        s = 0.0
        for m in range(k + 1):
            if m == j:
                continue
            prod = 1.0 / (nodes[j] - nodes[m])
            for i in range(k + 1):
                if i not in (j, m):
                    prod *= (0 - nodes[i]) / (nodes[j] - nodes[i])
            s += prod
        out.append(s)
    return out


def solve(m, b):
    """Gaussian elimination with partial pivoting (the systems are 2x2 to 5x5)."""
    n = len(b)
    a = [row[:] + [b[i]] for i, row in enumerate(m)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(a[r][c]))
        a[c], a[p] = a[p], a[c]
        for r in range(c + 1, n):
            f = a[r][c] / a[c][c]
            for cc in range(c, n + 1):
                a[r][cc] -= f * a[c][cc]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        x[r] = (a[r][n] - sum(a[r][cc] * x[cc] for cc in range(r + 1, n))) / a[r][r]
    return x


def newton(residual, y, jac_step=1e-7):
    """Newton with a difference Jacobian, to round-off."""
    for _ in range(40):
        f = residual(y)
        jac = [[0.0] * len(y) for _ in y]
        for c in range(len(y)):
            yy = y[:]
            yy[c] += jac_step
            fc = residual(yy)
            for r in range(len(y)):
                jac[r][c] = (fc[r] - f[r]) / jac_step
        d = solve(jac, [-v for v in f])
        y = [y[i] + d[i] for i in range(len(y))]
        if max(abs(v) for v in d) < 1e-14:
            break
    return y


def cartesian(p, w):
    return [math.cos(p), math.sin(p), -w * math.sin(p), w * math.cos(p)]


def to_angle(s):
    return math.atan2(s[1], s[0]), (s[0] * s[3] - s[1] * s[2]) / (s[0] ** 2 + s[1] ** 2)


def energy(p, w):
    return 0.5 * w * w + K_GRAV * math.sin(p)


def cart1_rate(s):
    x, y, u, v = s
    lam = (u * u + v * v - K_GRAV * y) / (2 * (x * x + y * y))
    return [u, v, -2 * lam * x, -K_GRAV - 2 * lam * y]


def explicit_step(form, s, h):
    """Classical RK4 or Kutta-Merson's fourth-order formula (merson_integrator.cpp) on cart1."""

    def at(*terms):
        return [s[i] + sum(c * t[i] for c, t in terms) for i in range(4)]

    k1 = cart1_rate(s)
    if form == "rk4":
        k2 = cart1_rate(at((h / 2, k1)))
        k3 = cart1_rate(at((h / 2, k2)))
        k4 = cart1_rate(at((h, k3)))
        return at((h / 6, k1), (h / 3, k2), (h / 3, k3), (h / 6, k4))
    k2 = cart1_rate(at((h / 3, k1)))
    k3 = cart1_rate(at((h / 6, k1), (h / 6, k2)))
    k4 = cart1_rate(at((h / 8, k1), (3 * h / 8, k3)))
    k5 = cart1_rate(at((h / 2, k1), (-1.5 * h, k3), (2 * h, k4)))
    return at((h / 6, k1), (4 * h / 6, k4), (h / 6, k5))


def run(form, k, h):
    """Returns the list of (phi, phi') at t = 0, h, 2h, ... up to T_END."""
    steps = int(round(T_END / h))
    p, w = math.pi / 2, -1.0
    states = []
    for _ in range(1 if form in ("rk4", "merson") else k):  # exact start-up history
        states.append([p, w] if form == "angle" else cartesian(p, w))
        p, w = exact(p, w, h)
    a = bdf_coefficients(k)
    lam = 0.0
    while len(states) <= steps:
        if form in ("rk4", "merson"):
            x, y, u, v = explicit_step(form, states[-1], h)
            r = math.hypot(x, y)  # projected onto the constraints, as MERSON's state is
            x, y = x / r, y / r
            radial = u * x + v * y
            states.append([x, y, u - radial * x, v - radial * y])
            continue
        n = len(states[-1])
        base = [sum(a[j] * states[-j][i] for j in range(1, k + 1)) for i in range(n)]
        rate = lambda y: [(a[0] * y[i] + base[i]) / h for i in range(n)]
        if form == "angle":
            res = lambda y: [d - f for d, f in zip(rate(y), angle_rate(*y))]
            states.append(newton(res, states[-1][:]))
        elif form == "cart1":
            res = lambda y: [d - f for d, f in zip(rate(y), cart1_rate(y))]
            states.append(newton(res, states[-1][:]))
        else:  # cart3: unknowns x, y, u, v, lam; the constraint row exact

            def res(y):
                d = rate(y[:4])
                x, yy, u, v, l = y
                return [d[0] - u, d[1] - v, d[2] + 2 * l * x, d[3] + K_GRAV + 2 * l * yy,
                        x * x + yy * yy - 1.0]

            y = newton(res, states[-1][:] + [lam])
            lam = y[4]
            states.append(y[:4])
    return [s if form == "angle" else list(to_angle(s)) for s in states]


def main():
    args = [a for a in sys.argv[1:] if a != "--bottom"]
    cases = [(int(a.split(":")[0]), float(a.split(":")[1])) for a in args] or [
        (6, 0.025), (5, 0.025), (6, 0.0125)]
    print("| formulation | order | h (s) | steps | phi error at 20 s (rad = B0 m) | energy error / E |")
    print("| --- | --- | --- | --- | --- | --- |")
    p_ref, w_ref = exact(math.pi / 2, -1.0, T_END)
    e0 = energy(math.pi / 2, -1.0)
    done = set()
    for k, h in cases:
        for form in ("angle", "cart1", "cart3", "rk4", "merson"):
            if form in ("rk4", "merson"):  # one fixed order: once per step size
                if (form, h) in done:
                    continue
                done.add((form, h))
            path = run(form, k, h)
            p, w = path[-1]
            err = (p - p_ref + math.pi) % (2 * math.pi) - math.pi
            order = 4 if form in ("rk4", "merson") else k
            print(f"| {form} | {order} | {h:g} | {len(path) - 1} | {err:+.2e} | "
                  f"{(energy(p, w) - e0) / abs(e0):+.2e} |", flush=True)
            if "--bottom" in sys.argv and form in ("angle", "cart3"):
                for i in range(len(path) - 1):
                    t = i * h
                    if 0.85 - 1e-9 <= t <= 1.0 + 1e-9:
                        pe, we = exact(path[i][0], path[i][1], h)
                        dp = (path[i + 1][0] - pe + math.pi) % (2 * math.pi) - math.pi
                        de = A * (energy(*path[i + 1]) - energy(*path[i]))
                        print(f"|   t = {t:.3f} | phi' = {path[i][1]:.3f} | dphi {dp:+.2e} | "
                              f"dphi' {path[i + 1][1] - we:+.2e} | dE {de:+.3e} J | |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
