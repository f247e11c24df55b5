#!/usr/bin/env python3
"""HHT on a turning pendulum in four formulations, fixed steps (docs/integrators.md, "HHT on
turning bodies").

Usage: bench/hht_turning_pendulum.py [N ...]    (steps over 10 s; default 1000 2000 4000)

The one-body pendulum of `openmss-generate chain-planar 1` (thin rod, m = 1 kg, L = 1 m, CM at
0.5 m, I_cm = 0.0834333 kg m^2) released at 0.1 rad with 9 rad/s, so that it turns over. HHT
(alpha = -0.3, beta = (1 - alpha)^2 / 4, gamma = 1/2 - alpha) with N equal steps, tip distance at
t = 10 s from classical RK4 (h = 1e-4 s) of the angle equation. Pure Python, no OpenMSS:

  1dof    Newmark on the angle of I_pivot th'' = -m g c sin th (the one-degree-of-freedom form).
  cart    HHT-I3 as OpenMSS integrates the multibody form: Newmark on the ground CM position r
          and the angle, constraint r = c (sin th, -cos th) exact, forces and reactions shifted
          (1 + alpha) at t_n+1, -alpha at t_n (hht_integrator.cpp).
  se2hht  the same, but Newmark on the body-frame twist (u = R^T v, w) and the pose advanced
          by its exponential, r_n+1 = r_n + R_n J(Theta) U: the Lie-group update with HHT's
          force shift kept. The shifted reactions are ground vectors taken at two orientations.
  se2ga   the Lie-group update in the generalized-alpha form of HHT (alpha_m = 0, alpha_f =
          -alpha; Arnold and Brüls): equations of motion exact at t_n+1, Newmark driven by the
          pseudo-acceleration a_n+1 = (1 - alpha_f) wdot_n+1 + alpha_f wdot_n.

Measured (docs/integrators.md): se2ga equals 1dof to three digits; cart is 2.8-5.5x worse
from 1000 to 16000 steps; se2hht does not converge (O(1) tip error).
"""
import math
import sys

M, ICM, RHO, G = 1.0, 0.083433333333333345, 0.5, 9.80665
IP = ICM + M * RHO * RHO
ALPHA = -0.3
BETA, GAMMA = (1 - ALPHA) ** 2 / 4, 0.5 - ALPHA
TH0, W0, T = 0.1, 9.0, 10.0


def f_angle(th):
    return -M * G * RHO * math.sin(th) / IP


def reference(h=1e-4):
    th, w, t = TH0, W0, 0.0
    while t < T - 1e-12:
        s = min(h, T - t)
        k1p, k1w = w, f_angle(th)
        k2p, k2w = w + s / 2 * k1w, f_angle(th + s / 2 * k1p)
        k3p, k3w = w + s / 2 * k2w, f_angle(th + s / 2 * k2p)
        k4p, k4w = w + s * k3w, f_angle(th + s * k3p)
        th += s / 6 * (k1p + 2 * k2p + 2 * k3p + k4p)
        w += s / 6 * (k1w + 2 * k2w + 2 * k3w + k4w)
        t += s
    return th


def solve(residual, x):
    """Newton with a forward-difference Jacobian and Gaussian elimination (5 unknowns)."""
    n = len(x)
    for _ in range(30):
        f = residual(x)
        cols = []
        for j in range(n):
            d = 1e-7 * max(1.0, abs(x[j]))
            xp = list(x)
            xp[j] += d
            fp = residual(xp)
            cols.append([(fp[i] - f[i]) / d for i in range(n)])
        a = [[cols[j][i] for j in range(n)] + [-f[i]] for i in range(n)]
        for c in range(n):
            p = max(range(c, n), key=lambda r: abs(a[r][c]))
            a[c], a[p] = a[p], a[c]
            for r in range(c + 1, n):
                k = a[r][c] / a[c][c]
                for cc in range(c, n + 1):
                    a[r][cc] -= k * a[c][cc]
        dx = [0.0] * n
        for r in range(n - 1, -1, -1):
            dx[r] = (a[r][n] - sum(a[r][cc] * dx[cc] for cc in range(r + 1, n))) / a[r][r]
        x = [x[i] + dx[i] for i in range(n)]
        if max(abs(v) for v in dx) < 1e-13 * (1 + max(abs(v) for v in x)):
            break
    return x


def run_angle(n_steps):
    h = T / n_steps
    th, w, a = TH0, W0, f_angle(TH0)
    for _ in range(n_steps):
        def residual(x):
            thn = th + h * w + h * h * ((0.5 - BETA) * a + BETA * x[0])
            return [x[0] - ((1 + ALPHA) * f_angle(thn) - ALPHA * f_angle(th))]
        an = solve(residual, [a])[0]
        th, w, a = (th + h * w + h * h * ((0.5 - BETA) * a + BETA * an),
                    w + h * ((1 - GAMMA) * a + GAMMA * an), an)
    return th


def applied(th, lam):
    """Applied minus constraint forces on (x, y, th); constraint x - c sin th, y + c cos th."""
    return [-lam[0], -M * G - lam[1], RHO * math.cos(th) * lam[0] + RHO * math.sin(th) * lam[1]]


def to_body(t, p):
    c, s = math.cos(t), math.sin(t)
    return [c * p[0] + s * p[1], -s * p[0] + c * p[1]]


def to_ground(t, p):
    c, s = math.cos(t), math.sin(t)
    return [c * p[0] - s * p[1], s * p[0] + c * p[1]]


def exp_translation(th, theta, big_u):
    """r increment of the SE(2) exponential: R(th) J(Theta) U."""
    if abs(theta) < 1e-8:
        j = [[1.0, -theta / 2], [theta / 2, 1.0]]
    else:
        s, c = math.sin(theta) / theta, (1 - math.cos(theta)) / theta
        j = [[s, -c], [c, s]]
    return to_ground(th, [j[0][0] * big_u[0] + j[0][1] * big_u[1],
                          j[1][0] * big_u[0] + j[1][1] * big_u[1]])


def run_multibody(form, n_steps):
    h = T / n_steps
    lie, shifted_forces = form.startswith("se2"), form in ("cart", "se2hht")
    af = 0.0 if shifted_forces else -ALPHA
    c0, s0 = math.cos(TH0), math.sin(TH0)
    r, th, w = [RHO * s0, -RHO * c0], TH0, W0
    v = [w * RHO * c0, w * RHO * s0]
    thdd = f_angle(TH0)
    ar = [RHO * (c0 * thdd - s0 * w * w), RHO * (s0 * thdd + c0 * w * w)]
    lam = [-M * ar[0], -M * G - M * ar[1]]
    if lie:  # body-frame velocity and its rate u' = R^T v' - w x u
        vel = to_body(th, v)
        acc = [a - b for a, b in zip(to_body(th, ar), [-w * vel[1], w * vel[0]])] + [thdd]
    else:
        vel, acc = v, ar + [thdd]
    pseudo = list(acc)
    for _ in range(n_steps):
        def advance(x):
            an = [(1 - af) * x[k] + af * acc[k] for k in range(3)]
            theta = h * w + h * h * ((0.5 - BETA) * pseudo[2] + BETA * an[2])
            big_u = [h * vel[k] + h * h * ((0.5 - BETA) * pseudo[k] + BETA * an[k])
                     for k in range(2)]
            d = exp_translation(th, theta, big_u) if lie else big_u
            veln = [vel[k] + h * ((1 - GAMMA) * pseudo[k] + GAMMA * an[k]) for k in range(2)]
            wn = w + h * ((1 - GAMMA) * pseudo[2] + GAMMA * an[2])
            vdot = (to_ground(th + theta, [x[0] - wn * veln[1], x[1] + wn * veln[0]]) if lie
                    else x[0:2])
            return [r[0] + d[0], r[1] + d[1]], th + theta, veln, wn, vdot, an

        def residual(x):
            rn, thn, _, _, vdot, _ = advance(x)
            qn, qo = applied(thn, x[3:5]), applied(th, lam)
            if shifted_forces:
                q = [(1 + ALPHA) * qn[k] - ALPHA * qo[k] for k in range(3)]
            else:
                q = qn
            return [M * vdot[0] - q[0], M * vdot[1] - q[1], ICM * x[2] - q[2],
                    (rn[0] - RHO * math.sin(thn)) / (h * h), (rn[1] + RHO * math.cos(thn)) / (h * h)]

        x = solve(residual, acc + lam)
        r, th, vel, w, _, pseudo = advance(x)
        acc, lam = x[0:3], x[3:5]
    return th


def main():
    steps = [int(a) for a in sys.argv[1:]] or [1000, 2000, 4000]
    exact = reference()
    tip = lambda th: (math.sin(th), -math.cos(th))
    print("| steps | 1dof | cart | se2hht | se2ga |")
    print("| --- | --- | --- | --- | --- |")
    for n in steps:
        cells = []
        for form in ("1dof", "cart", "se2hht", "se2ga"):
            th = run_angle(n) if form == "1dof" else run_multibody(form, n)
            cells.append(f"{math.dist(tip(th), tip(exact)):.2e}")
        print(f"| {n} | " + " | ".join(cells) + " |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
