"""Spence's self-similar stick zone for a rigid cylinder pressed into an elastic half-plane with
Coulomb friction, and an incremental half-plane computation that must approach it
(docs/contact.md "Monotone pressing in N steps: the half-space reference").

    python3 SpenceHalfPlane.py [--nu 0.28] [--mu 0.4] [--coupled] [--steps N ...]

Closed forms (Goodman's approximation: the normal pressure is not changed by the tangential
traction; docs/contact.md derives both from Johnson, Contact Mechanics (1985) eq. 2.25):
  monotone loading, the self-similar limit (Spence 1975):  beta/mu = K'(c/a) / K(c/a)
  one static step from the unloaded state:                 beta E(c/a) = mu J(c/a),
                                                            J(k) = int_k^1 sqrt((1-s^2)/(s^2-k^2)) ds
with beta = (1 - 2 nu)/(2 (1 - nu)) (a rigid obstacle), K, E the complete elliptic integrals of
modulus c/a and K'(k) = K(sqrt(1 - k^2)).

The computation: the half-plane under a rigid flat obstacle with a cylinder's gap x^2/(2R),
plane strain, piecewise constant p and q on a uniform grid of n cells over |x| < 1.15 a
(collocation at the cells' centres; the surface displacements of a uniform strip load, Johnson
(1985) §2.6), pressed to the load of a = 1 in N equal load steps with incremental Coulomb
friction (a stick cell keeps its tangential displacement of the step before; a slip cell has
q = +-mu p against its slip increment), each step solved by a primal-dual active set on contact
and stick. With --coupled the normal displacement of q is included (the exact half-plane problem,
no closed form); without, Goodman's approximation as in the closed forms.

Checks (Goodman, the default): one step within 0.006 of the static closed form (one cell: 0.0058 a);
the ratio growing with N by shrinking differences; and the last N's ratio, extrapolated in 1/N
from the last two (c(N) + (c(N) - c(N/2))), within 0.008 of Spence's value. Measured with n = 400
(2026-12-03): see the output. About 4 s, in the default suite (needs Debian's python3-scipy,
installed by scripts/common.sh; exit 77 without it).
"""

import argparse
import math
import sys

try:
    import numpy as np
    from scipy.integrate import quad
    from scipy.optimize import brentq
    from scipy.special import ellipe, ellipk
except ImportError as e:  # pragma: no cover
    print(f"skipped: {e}")
    sys.exit(77)


def spence_ratio(beta, mu):
    """c/a of the self-similar monotone loading: beta/mu = K'(k)/K(k)."""
    return brentq(lambda k: ellipk(1.0 - k * k) / ellipk(k * k) - beta / mu, 1e-9, 1.0 - 1e-15)


def static_ratio(beta, mu):
    """c/a of one static step: beta E(k) = mu int_k^1 sqrt((1-s^2)/(s^2-k^2)) ds."""
    def j(k):
        # s = sqrt(k^2 + (1 - k^2) sin^2 t) removes the endpoint singularity at s = k.
        f = lambda t: (1.0 - k * k) * math.cos(t) ** 2 / (k * k + (1.0 - k * k) * math.sin(t) ** 2) ** 0.5
        return quad(f, 0.0, math.pi / 2, limit=200)[0]
    return brentq(lambda k: beta * ellipe(k * k) - mu * j(k), 1e-6, 1.0 - 1e-9)


def incremental(nu, mu, steps, n=400, half=1.15, coupled=False, max_sets=200):
    """c/a (stick cells / contact cells) at the final load of N equal steps (E = 1, R = 1)."""
    e_star = 1.0 / (1.0 - nu * nu)
    load = math.pi * e_star / 4.0  # a = 1 (2D Hertz: a^2 = 4 P R / (pi E*))
    h = 2.0 * half / n
    x = -half + h * (np.arange(n) + 0.5)
    d = x[:, None] - x[None, :]

    def strip_log(t):  # antiderivative of ln|t|
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(t == 0.0, 0.0, t * np.log(np.abs(t)) - t)

    log_int = strip_log(d + h / 2) - strip_log(d - h / 2)       # int over the cell of ln|x - s| ds
    sign_int = np.clip(d + h / 2, 0.0, h) - np.clip(h / 2 - d, 0.0, h)  # int of sign(x - s) ds
    c_log, c_1 = 2.0 * (1.0 - nu * nu) / math.pi, (1.0 - 2.0 * nu) * (1.0 + nu)
    # Surface displacements (u_z into the body, u_x along x) of uniform p and q on each cell.
    uzp, uxq = -c_log * log_int, -c_log * log_int
    uxp = -0.5 * c_1 * sign_int
    uzq = 0.5 * c_1 * sign_int if coupled else np.zeros_like(sign_int)
    gap0 = x * x / 2.0
    ux_prev = np.zeros(n)
    contact = np.abs(x) < h  # the two middle cells
    stick = contact.copy()
    sign = np.zeros(n)
    p = q = ux = None
    for k in range(1, steps + 1):
        target = load * k / steps
        for _ in range(max_sets):
            C = np.where(contact)[0]
            m = len(C)
            A = np.zeros((2 * m + 1, 2 * m + 1))
            b = np.zeros(2 * m + 1)
            A[:m, :m] = uzp[np.ix_(C, C)]
            A[:m, m:2 * m] = uzq[np.ix_(C, C)]
            A[:m, 2 * m] = -1.0
            b[:m] = -gap0[C]
            for r, i in enumerate(C):
                if stick[i]:
                    A[m + r, :m] = uxp[i, C]
                    A[m + r, m:2 * m] = uxq[i, C]
                    b[m + r] = ux_prev[i]
                else:
                    A[m + r, m + r] = 1.0
                    A[m + r, r] = -sign[i] * mu
            A[2 * m, :m] = h
            b[2 * m] = target
            sol = np.linalg.solve(A, b)
            p, q = np.zeros(n), np.zeros(n)
            p[C], q[C] = sol[:m], sol[m:2 * m]
            gap = gap0 - sol[2 * m] + uzp @ p + uzq @ q
            ux = uxp @ p + uxq @ q
            slip = ux - ux_prev
            new_contact = np.where(contact, p > 0.0, gap < 0.0)
            new_stick, new_sign = stick.copy(), sign.copy()
            for i in np.where(new_contact)[0]:
                if not contact[i]:
                    new_stick[i], new_sign[i] = False, math.copysign(1.0, x[i])
                elif stick[i] and abs(q[i]) > mu * p[i]:
                    new_stick[i], new_sign[i] = False, math.copysign(1.0, q[i])
                elif not stick[i] and sign[i] * slip[i] > 0.0:  # slips along its traction
                    new_stick[i] = True
            new_stick &= new_contact
            same = (np.array_equal(new_contact, contact) and np.array_equal(new_stick, stick) and
                    np.array_equal(new_sign[new_contact & ~new_stick], sign[new_contact & ~new_stick]))
            contact, stick, sign = new_contact, new_stick, new_sign
            if same:
                break
        else:
            raise RuntimeError(f"step {k}: the active set did not settle in {max_sets} solves")
        ux_prev = ux
    a = contact.sum() * h / 2.0
    return (stick & contact).sum() * h / 2.0 / a, a


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--nu", type=float, default=0.28)
    parser.add_argument("--mu", type=float, default=0.4)
    parser.add_argument("--cells", type=int, default=400)
    parser.add_argument("--coupled", action="store_true")
    parser.add_argument("--steps", type=int, action="append", default=[])
    args = parser.parse_args()
    steps = args.steps or [1, 10, 20, 40]
    beta = (1.0 - 2.0 * args.nu) / (2.0 * (1.0 - args.nu))
    spence, static = spence_ratio(beta, args.mu), static_ratio(beta, args.mu)
    print(f"nu = {args.nu}, mu_F = {args.mu}: beta = {beta:.6f}, beta/mu = {beta / args.mu:.6f}")
    print(f"closed forms (Goodman): static c/a = {static:.4f}, Spence's self-similar c/a = {spence:.4f}")
    ratios = {}
    for n in steps:
        ratios[n], a = incremental(args.nu, args.mu, n, args.cells, coupled=args.coupled)
        print(f"half-plane, {'coupled' if args.coupled else 'Goodman'}, {args.cells} cells, N = {n}: "
              f"c/a = {ratios[n]:.4f} (a = {a:.4f})", flush=True)
    if args.coupled:
        return 0  # no closed form to check against
    failed = 0

    def check(ok, text):
        nonlocal failed
        print(("ok      " if ok else "FAILED  ") + text)
        failed += 0 if ok else 1

    if 1 in ratios:
        check(abs(ratios[1] - static) <= 0.006, f"N = 1: {ratios[1]:.4f} against the static {static:.4f} (0.006)")
    many = sorted(n for n in ratios if n > 1)
    for n0, n1, n2 in zip(many, many[1:], many[2:]):
        d1, d2 = ratios[n1] - ratios[n0], ratios[n2] - ratios[n1]
        check(0.0 < d2 < d1, f"grows with N by shrinking differences: {n0} -> {n1}: {d1:+.4f}, {n1} -> {n2}: {d2:+.4f}")
    if len(many) >= 2 and many[-1] == 2 * many[-2]:
        extrapolated = 2.0 * ratios[many[-1]] - ratios[many[-2]]
        check(abs(extrapolated - spence) <= 0.008,
              f"N -> infinity (from N = {many[-2]}, {many[-1]}): {extrapolated:.4f} against Spence's {spence:.4f} (0.008)")
    print(f"{failed} check(s) failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
