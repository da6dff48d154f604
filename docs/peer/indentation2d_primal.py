#!/usr/bin/python3
"""Independent primal computation of the load of a rigid cylinder indenting an elastic block
(StressContact deck input/indentation2d.xml; docs/peer/README.md).

Peer code: GetFEM (Debian package python3-getfem), P2 displacements on straight triangles,
plane strain, E = 1000, nu = 0.3 (lambda = E nu/((1+nu)(1-2nu)), mu = E/(2(1+nu))), f = 0.

Scene: block [-2,2] x [-2,0]; bottom y = -2: u = 0 (by multipliers); left and right: free;
top y = 0: contact with the rigid circle |x - c| >= R, c = (0, 0.99), R = 1 (its lowest point
is 0.01 below the top: a prescribed indentation).

Linearised contact model, "obstacle normal" frame (StressContact docs/theory.md "Contact frame
and gap", Circle indenter): at a point x of the top,
    N(x) = (c - x)/|c - x|        (out of the body, towards the indenter's centre)
    g(x) = |x - c| - R            (negative where the top starts inside the circle)
    u.N <= g,  p >= 0,  p (u.N - g) = 0,  traction on the body -p N  (+ friction, see below).
P = the magnitude of the downward force of the indenter on the block = int_top p N_y ds; checked
against the reaction at the bottom (integral of the Dirichlet multiplier) and Px (~0).

Methods (r = E/h_min, the augmentation parameter; the contact conditions hold at the quadrature
points in an integral sense, so the discrete solution depends slightly on r: README, side checks):
  mult  : frictionless: p a P1 multiplier on the top, non-symmetric Alart-Curnier augmented
          Lagrangian written in GWFL:  p*(Test_u.N)  and  -(1/r)*(p - pos_part(p + r*(u.N - g)))*Test_p,
          with the exact N and g at the quadrature points.
          Coulomb: lambda a vector P1 multiplier (the traction on the body), GWFL
          -lambda.Test_u  and  -(1/r)*(lambda - Coulomb_friction_coupled_projection(lambda, N, u,
          g - u.N, mu_F, r)).Test_lambda  (one-step static Coulomb problem: the slip is u_T).
  brick : GetFEM's add_integral_contact_with_rigid_obstacle_brick (option 1, non-symmetric
          Alart-Curnier), the obstacle given by its signed distance sqrt(x^2+(y-0.99)^2) - 1
          (positive outside the circle) interpolated on a P<k> Lagrange FEM (--obs-degree), its
          normal -grad(d)/|grad d| and gap d taken from that interpolant; with a friction
          coefficient for Coulomb (vector multiplier).
Cases: 'frictionless' and 'coulomb' (mu_F = --mu, default 0.4).

Meshes: a Persson-Strang (distmesh) triangulation of the block graded towards (0,0) (and mildly
towards the two clamped bottom corners), size h(x) = min(HMAX, H0 + ALPHA*max(0, |x| - RZ),
HC + ALPHA*|x - corner|); level l:
  --mesh nested   (default) level 0 refined uniformly l times (each triangle into 4, nested
                  meshes: every size, the contact zone's included, halved per level);
  --mesh distmesh an independent distmesh per level with the size function scaled by 2^-l.

Usage:   nice -n 10 /usr/bin/python3 docs/peer/indentation2d_primal.py          (default run)
         ... --levels 0 1 2 3 --cases frictionless coulomb --methods mult brick
Writes docs/peer/indentation2d_primal.csv (next to this script) and prints the table and a
summary (lines '#S'): per case and method the sequence of P over the levels, the observed rate,
a Richardson limit and a conservative uncertainty.
"""
import argparse
import csv
import math
import os
import time

import numpy as np
from scipy.spatial import Delaunay

import getfem as gf

gf.util('trace level', 0)
gf.util('warning level', 0)

E, NU = 1000.0, 0.3
LAM = E * NU / ((1 + NU) * (1 - 2 * NU))
MU = E / (2 * (1 + NU))
ESTAR = E / (1 - NU ** 2)
CX, CY, R = 0.0, 0.99, 1.0          # indenter centre and radius
X0, X1, Y0, Y1 = -2.0, 2.0, -2.0, 0.0  # block

# size function at level 0
H0, HMAX, ALPHA, RZ, HC = 0.008, 0.25, 0.3, 0.1, 0.02
MAXRES = 1e-9

N_EXPR = 'Normalized([%r - X(1); %r - X(2)])' % (CX, CY)            # (c - x)/|c - x|
G_EXPR = '(Norm([X(1) - %r; X(2) - %r]) - %r)' % (CX, CY, R)        # |x - c| - R
TOP, BOTTOM, LEFT, RIGHT = 1, 2, 3, 4


# ----------------------------------------------------------------------------------------- mesh
def fd(p):
    """signed distance to the rectangle (negative inside)"""
    return -np.minimum(np.minimum(np.minimum(p[:, 1] - Y0, Y1 - p[:, 1]), p[:, 0] - X0), X1 - p[:, 0])


def fh(p, s):
    r = np.hypot(p[:, 0], p[:, 1])
    h = np.minimum(HMAX, H0 + ALPHA * np.maximum(0.0, r - RZ))
    for cx in (X0, X1):
        h = np.minimum(h, HC + ALPHA * np.hypot(p[:, 0] - cx, p[:, 1] - Y0))
    return s * h


def walk(a, b, s):
    """points from a to b (a included, b included), steps following the size function, then
    stretched to end exactly at b; a should be the finer end"""
    a, b = np.asarray(a, float), np.asarray(b, float)
    L = np.hypot(*(b - a))
    e = (b - a) / L
    ts = [0.0]
    while ts[-1] < L:
        q = a + ts[-1] * e
        ts.append(ts[-1] + fh(q[None, :], s)[0])
    T = np.array(ts)
    if len(T) > 2 and (T[-1] - L) > 0.5 * (T[-1] - T[-2]):
        T = T[:-1]
    T = T * L / T[-1]
    return a[None, :] + T[:, None] * e[None, :]


def boundary_nodes(s):
    """fixed nodes on the four sides, symmetric about x = 0, a node at (0, 0)"""
    top = walk((0.0, Y1), (X1, Y1), s)                 # (0,0) ... (2,0)
    bot = walk((X1, Y0), (0.0, Y0), s)                 # (2,-2) ... (0,-2)
    side = walk((X1, Y0), (X1, Y1), s)                 # (2,-2) ... (2,0)
    pts = [top, top[1:] * [-1, 1], bot, bot[:-1] * [-1, 1], side[1:-1], side[1:-1] * [-1, 1]]
    P = np.vstack(pts)
    # unique (corners and (0,0) appear once by construction)
    _, idx = np.unique(np.round(P, 13), axis=0, return_index=True)
    return P[np.sort(idx)]


def quality(p, t):
    a = p[t]
    l = np.stack([np.hypot(*(a[:, 1] - a[:, 0]).T), np.hypot(*(a[:, 2] - a[:, 1]).T), np.hypot(*(a[:, 0] - a[:, 2]).T)], 1)
    ar = 0.5 * np.abs((a[:, 1, 0] - a[:, 0, 0]) * (a[:, 2, 1] - a[:, 0, 1]) - (a[:, 1, 1] - a[:, 0, 1]) * (a[:, 2, 0] - a[:, 0, 0]))
    return 4 * math.sqrt(3) * ar / np.sum(l ** 2, axis=1)


def distmesh(s, maxit=300, seed=1):
    """Persson & Strang, SIAM Review 46 (2004), with the size function fh and fixed boundary nodes
    (only the interior nodes move; they are kept at least h/4 inside); returns p, t (ccw), its."""
    rng = np.random.default_rng(seed)
    hmin = s * H0
    geps = 1e-3 * hmin
    dptol, ttol, Fscale, deltat = 1e-3, 0.1, 1.2, 0.2
    pfix = boundary_nodes(s)
    pts = []
    dy = hmin * math.sqrt(3) / 2
    ys = np.arange(Y0, Y1 + dy, dy)
    xs = np.arange(X0, X1 + hmin, hmin)
    for j0 in range(0, len(ys), 100):
        yy = ys[j0:j0 + 100]
        X, Y = np.meshgrid(xs, yy)
        X = X + (np.arange(j0, j0 + len(yy)) % 2)[:, None] * hmin / 2
        q = np.column_stack([X.ravel(), Y.ravel()])
        hq = fh(q, s)
        q = q[fd(q) < -0.5 * hq]
        q = q[rng.random(len(q)) < (hmin / fh(q, s)) ** 2]
        pts.append(q)
    p = np.vstack([pfix] + pts)
    nfix = len(pfix)
    pold = np.inf * np.ones_like(p)
    deps = 1e-9
    for it in range(maxit):
        if np.max(np.hypot(*(p - pold).T) / fh(p, s)) > ttol:
            pold = p.copy()
            t = Delaunay(p).simplices
            t = t[fd(p[t].mean(axis=1)) < -geps]
            bars = np.vstack([t[:, [0, 1]], t[:, [0, 2]], t[:, [1, 2]]])
            bars = np.unique(np.sort(bars, axis=1), axis=0)
        barvec = p[bars[:, 0]] - p[bars[:, 1]]
        L = np.hypot(barvec[:, 0], barvec[:, 1])
        hbars = fh((p[bars[:, 0]] + p[bars[:, 1]]) / 2, s)
        L0 = hbars * Fscale * math.sqrt(np.sum(L ** 2) / np.sum(hbars ** 2))
        F = np.maximum(L0 - L, 0.0)
        Fvec = (F / L)[:, None] * barvec
        Ftot = np.zeros_like(p)
        np.add.at(Ftot, bars[:, 0], Fvec)
        np.add.at(Ftot, bars[:, 1], -Fvec)
        Ftot[:nfix] = 0.0
        p = p + deltat * Ftot
        d = fd(p)
        hp = fh(p, s)
        ix = d > -0.25 * hp
        ix[:nfix] = False
        if ix.any():
            q = p[ix]
            dgx = (fd(q + [deps, 0]) - fd(q - [deps, 0])) / (2 * deps)
            dgy = (fd(q + [0, deps]) - fd(q - [0, deps])) / (2 * deps)
            corr = (d[ix] + 0.25 * hp[ix]) / np.maximum(dgx ** 2 + dgy ** 2, 1e-12)
            p[ix] -= np.column_stack([corr * dgx, corr * dgy])
        move = deltat * np.hypot(*Ftot[nfix:].T) / fh(p[nfix:], s)
        if move.size and move.max() < dptol:
            break
    t = Delaunay(p).simplices
    t = t[fd(p[t].mean(axis=1)) < -geps]
    a = p[t]
    ar = (a[:, 1, 0] - a[:, 0, 0]) * (a[:, 2, 1] - a[:, 0, 1]) - (a[:, 1, 1] - a[:, 0, 1]) * (a[:, 2, 0] - a[:, 0, 0])
    t[ar < 0] = t[ar < 0][:, [0, 2, 1]]
    t = t[quality(p, t) > 1e-6]   # drop degenerate boundary slivers, if any
    used = np.zeros(len(p), bool)
    used[t.ravel()] = True
    assert used.all(), 'a node lost all its triangles'
    return p, t, it + 1


def red_refine(p, t):
    """each triangle into 4 (edge midpoints); ccw kept"""
    e = np.vstack([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    es = np.sort(e, axis=1)
    uniq, inv = np.unique(es, axis=0, return_inverse=True)
    mid = len(p) + inv.reshape(3, len(t))   # m01, m12, m20
    pn = np.vstack([p, 0.5 * (p[uniq[:, 0]] + p[uniq[:, 1]])])
    m01, m12, m20 = mid
    v0, v1, v2 = t.T
    tn = np.vstack([np.column_stack([v0, m01, m20]), np.column_stack([v1, m12, m01]),
                    np.column_stack([v2, m20, m12]), np.column_stack([m01, m12, m20])])
    return pn, tn


def build_getfem_mesh(p, t):
    m = gf.Mesh('empty', 2)
    gt = gf.GeoTrans('GT_PK(2,1)')
    PTS = np.ascontiguousarray(np.transpose(p[t], (2, 1, 0)))  # 2 x 3 x M
    cvids = np.asarray(m.add_convex(gt, PTS)).ravel()
    assert len(cvids) == len(t) and np.all(cvids == np.arange(len(t))), 'unexpected convex ids'
    of = m.outer_faces()
    cv, f = of[0], of[1]
    others = {0: (1, 2), 1: (0, 2), 2: (0, 1)}   # face f is opposite local vertex f
    va = np.array([t[c, others[ff][0]] for c, ff in zip(cv, f)])
    vb = np.array([t[c, others[ff][1]] for c, ff in zip(cv, f)])
    for reg, k, val in ((TOP, 1, Y1), (BOTTOM, 1, Y0), (LEFT, 0, X0), (RIGHT, 0, X1)):
        sel = (p[va, k] == val) & (p[vb, k] == val)
        m.set_region(reg, np.vstack([cv[sel], f[sel]]))
    return m


def make_meshes(levels, kind, seed):
    """yields (level, h_min, p, t, info)"""
    base = None
    for lev in sorted(levels):
        t0 = time.time()
        if kind == 'distmesh':
            p, t, nit = distmesh(0.5 ** lev, seed=seed)
            info = 'distmesh_it=%d' % nit
        else:
            if base is None:
                p0, t0_, nit = distmesh(1.0, seed=seed)
                base = (p0, t0_, nit)
            p, t, nit = base
            for _ in range(lev):
                p, t = red_refine(p, t)
            info = 'distmesh_it(level 0)=%d, %d uniform refinements' % (nit, lev)
        # h_min: the shortest top edge at (0,0)
        yield lev, H0 * 0.5 ** lev, p, t, info, time.time() - t0


# ------------------------------------------------------------------------------------ solver
def solve(m, case, method, r, mu_f, obs_degree, verbose=False):
    mfu = gf.MeshFem(m, 2)
    mfu.set_classical_fem(2)
    mim = gf.MeshIm(m, gf.Integ('IM_TRIANGLE(6)'))
    md = gf.Model('real')
    md.add_fem_variable('u', mfu)
    md.add_initialized_data('lambda', [LAM])
    md.add_initialized_data('mu', [MU])
    md.add_isotropic_linearized_elasticity_brick(mim, 'u', 'lambda', 'mu')
    md.add_initialized_data('uD', [0.0, 0.0])
    md.add_Dirichlet_condition_with_multipliers(mim, 'u', mfu, BOTTOM, 'uD')
    md.add_initialized_data('r', [r])
    md.add_initialized_data('f', [mu_f])
    qd = 1 if case == 'frictionless' else 2
    mfp = gf.MeshFem(m, qd)
    mfp.set_classical_fem(1)
    dofs = np.sort(np.asarray(mfp.basic_dof_on_region(TOP)).ravel())
    mfc = gf.MeshFem('partial', mfp, dofs)
    N, G = N_EXPR, G_EXPR
    md.add_fem_variable('p', mfc)
    if method == 'mult':
        if case == 'frictionless':
            md.add_nonlinear_term(mim, 'p*(Test_u.%s)' % N, TOP)
            md.add_nonlinear_term(mim, '-(1/r)*(p - pos_part(p + r*(u.%s - %s)))*Test_p' % (N, G), TOP)
        else:
            # p is here the traction vector on the body (lambda of GetFEM's documentation)
            md.add_nonlinear_term(mim, '-p.Test_u', TOP)
            md.add_nonlinear_term(
                mim, '-(1/r)*(p - Coulomb_friction_coupled_projection(p, %s, u, %s - u.%s, f, r)).Test_p'
                % (N, G, N), TOP)
    else:
        mfo = gf.MeshFem(m, 1)
        mfo.set_classical_fem(obs_degree)
        xy = mfo.basic_dof_nodes()
        md.add_initialized_fem_data('obstacle', mfo, np.hypot(xy[0] - CX, xy[1] - CY) - R)
        if case == 'frictionless':
            md.add_integral_contact_with_rigid_obstacle_brick(mim, 'u', 'p', 'obstacle', 'r', TOP, 1)
        else:
            md.add_integral_contact_with_rigid_obstacle_brick(mim, 'u', 'p', 'obstacle', 'r', 'f', TOP, 1)
    t0 = time.time()
    # the vertical force of the contact on the body: the integral of the reaction at the bottom
    # (sign: see below) is the independent check; the contact's own integral is formed after
    opts = ['max_iter', 100, 'max_res', MAXRES, 'lsolver', 'mumps']
    if verbose:
        opts = ['noisy'] + opts
    nit, conv = md.solve(*opts)
    # semismooth Newton: after the residual test, up to 5 x 2 more steps; the change of the
    # bottom reaction across them is the convergence check dP_rel
    Pb1 = gf.asm_generic(mim, 0, 'mult_on_u(2)', BOTTOM, md)
    dP = float('inf')
    for _ in range(5):
        md.solve('max_iter', 2, 'max_res', 1e-30, 'lsolver', 'mumps')
        Pb2 = gf.asm_generic(mim, 0, 'mult_on_u(2)', BOTTOM, md)
        dP = abs(Pb2 - Pb1) / max(abs(Pb2), 1e-300)
        if dP < 1e-9:
            break
        Pb1 = Pb2
    conv = dP < 1e-9
    tsol = time.time() - t0
    ndof = md.nbdof()
    # traction on the body t and pressure p_n = -t.N (N the exact obstacle normal)
    if case == 'frictionless':
        if method == 'mult':
            sgn = 1.0           # p >= 0 is the pressure, traction -p N
        else:
            # the brick's multiplier is the normal traction (<= 0): make it the pressure
            sgn = 1.0 if gf.asm_generic(mim, 0, 'p', TOP, md) > 0 else -1.0
        traction = '(-(%g*p)*%s)' % (sgn, N)
        pv = np.asarray(md.variable('p')) * sgn
    else:
        if method == 'mult':
            sgn = 1.0           # p is the traction on the body
        else:
            # the brick's vector multiplier is the contact traction on the body, or its opposite
            sgn = 1.0 if gf.asm_generic(mim, 0, 'p.%s' % N, TOP, md) < 0 else -1.0
        traction = '(%g*p)' % sgn
        pv = None
    # P = downward force on the block = -int t_y ; Px = int t_x ; bottom reaction
    P = -gf.asm_generic(mim, 0, '%s(2)' % traction, TOP, md)
    Px = gf.asm_generic(mim, 0, '%s(1)' % traction, TOP, md)
    Rb = gf.asm_generic(mim, 0, 'mult_on_u', BOTTOM, md)
    # moments of the vertical force density over the top (dx = ds)
    M0 = -gf.asm_generic(mim, 0, '%s(2)' % traction, TOP, md)
    M2 = -gf.asm_generic(mim, 0, '%s(2)*sqr(X(1))' % traction, TOP, md)
    a_mom = 2 * math.sqrt(max(M2 / M0, 0.0))
    # nodal profile on the P1 multiplier nodes (vertices of the top)
    xy = mfp.basic_dof_nodes(dofs)   # the partial FEM keeps the order of dofs
    if case == 'frictionless':
        x = xy[0]
        pn = pv
        qt = np.zeros_like(pn)
    else:
        lam = np.asarray(md.variable('p')) * sgn
        x = xy[0][0::2]
        assert np.allclose(xy[0][1::2], x)
        tx, ty = lam[0::2], lam[1::2]
        nx, ny = CX - x, CY - xy[1][0::2]
        nn = np.hypot(nx, ny)
        nx, ny = nx / nn, ny / nn
        pn = -(tx * nx + ty * ny)               # pressure
        qt = tx * (-ny) + ty * nx               # tangential traction along T = (-N_y, N_x)
    order = np.argsort(x)
    x, pn, qt = x[order], pn[order], qt[order]
    p0 = float(pn.max())
    tol = 1e-6 * p0
    ipk = int(np.argmax(pn))
    lo = ipk
    while lo > 0 and pn[lo - 1] > tol:
        lo -= 1
    hi = ipk
    while hi < len(pn) - 1 and pn[hi + 1] > tol:
        hi += 1
    nstray = int(np.sum(pn > tol)) - (hi - lo + 1)
    # contact half-width from the profile: the zero of the line through p^2 at the last two contact
    # nodes of each side (p ~ sqrt(a - |x|) near the edge), clipped to the next node
    a_edge = []
    for i, j, k in ((hi, hi - 1, hi + 1), (lo, lo + 1, lo - 1)):
        xa = abs(x[i])
        if 0 <= j < len(x) and 0 <= k < len(x):
            q2i, q2j = pn[i] ** 2, pn[j] ** 2
            s2i, s2j = x[i] ** 2, x[j] ** 2
            if q2j > q2i and s2i != s2j:
                s0 = s2i + q2i * (s2i - s2j) / (q2j - q2i)
                xa = min(math.sqrt(max(s0, 0.0)), abs(x[k]))
        a_edge.append(xa)
    a_edge = 0.5 * sum(a_edge)
    # stick zone (Coulomb), indicative only: the nodes of the contact block [lo, hi] with
    # |q| < 0.95 mu_F p (the integral conditions hold weakly: in the slip zones the nodal |q|/(mu_F p)
    # scatters by a few % about 1); half-width = the mean over both sides of the outermost stick
    # node's |x| (node resolution)
    c_stick = float('nan')
    if case != 'frictionless':
        blk = np.arange(lo, hi + 1)
        stick = blk[np.abs(qt[blk]) < 0.95 * mu_f * pn[blk]]
        if stick.size:
            c_stick = 0.5 * (abs(x[stick].max()) + abs(x[stick].min()))
    prof = list(zip(x, pn, qt))
    return dict(P=P, Px=Px, Pbot_x=Rb[0], Pbot_y=Rb[1], a_mom=a_mom, a_edge=a_edge, p0=p0,
                c_stick=c_stick, ndof=ndof, nit=nit, conv=conv, dP=dP, tsol=tsol,
                nact=hi - lo + 1, nstray=nstray, profile=prof)


# ---------------------------------------------------------------------------------- summary
HDR = ('case', 'method', 'level', 'h_min', 'elements', 'dofs', 'r', 'mu_F', 'P', 'P_bottom', 'Px',
       'Px_bottom', 'a_mom', 'a_edge', 'p0', 'a_H', 'p0_H', 'a_mom/a_H', 'p0/p0_H', 'c_stick',
       'newton_it', 'dP_rel', 'solve_s')


def summarize(rows):
    """Per case and method: P over the levels, the last two differences, the observed rate, a
    Richardson limit and a conservative uncertainty (the largest of the last two changes between
    levels and of the extrapolation step). Prints lines starting with '#S'."""
    ix = {h: i for i, h in enumerate(HDR)}
    keys = []
    for row in rows:
        k = (row[0], row[1])
        if k not in keys:
            keys.append(k)
    out = {}
    for case, method in keys:
        sel = sorted([r for r in rows if r[0] == case and r[1] == method], key=lambda r: int(r[ix['level']]))
        seq = [(int(r[ix['level']]), int(r[ix['dofs']]), float(r[ix['P']])) for r in sel]
        print('#S %s %s: %s' % (case, method, ', '.join('L%d (%d dofs) %.5f' % s_ for s_ in seq)))
        Ps = [p for _, _, p in seq]
        if len(Ps) >= 3:
            d1, d2 = Ps[-2] - Ps[-3], Ps[-1] - Ps[-2]
            q = math.log2(abs(d1 / d2)) if d2 != 0 and d1 != 0 else float('nan')
            if d1 * d2 > 0 and q > 0.3:
                Pinf = Ps[-1] + d2 / (2 ** q - 1)
            else:
                Pinf = Ps[-1]
            unc = max(abs(Pinf - Ps[-1]), abs(d1), abs(d2))
            print('#S   last differences %.2e, %.2e; observed rate (in h) %.2f; limit %.5f +- %.5f (%.4f%%)'
                  % (d1, d2, q, Pinf, unc, 100 * unc / Pinf))
            out[(case, method)] = (Pinf, unc)
        elif len(Ps) == 2:
            out[(case, method)] = (Ps[-1], abs(Ps[-1] - Ps[-2]))
            print('#S   last difference %.2e' % (Ps[-1] - Ps[-2]))
    # method agreement per level
    for case in sorted(set(k[0] for k in keys)):
        a = {int(r[ix['level']]): float(r[ix['P']]) for r in rows if r[0] == case and r[1] == 'mult'}
        b = {int(r[ix['level']]): float(r[ix['P']]) for r in rows if r[0] == case and r[1] == 'brick'}
        common = sorted(set(a) & set(b))
        if common:
            print('#S %s brick/mult - 1 per level: %s' % (case, ', '.join('L%d %.2e' % (l, b[l] / a[l] - 1) for l in common)))
    if ('frictionless', 'mult') in out and ('coulomb', 'mult') in out:
        (P0, u0), (P1, u1) = out[('frictionless', 'mult')], out[('coulomb', 'mult')]
        print('#S P_coulomb/P_frictionless (mult) = %.5f +- %.5f' % (P1 / P0, (P1 / P0) * (u0 / P0 + u1 / P1)))
    return out


def read_csv(path):
    with open(path) as f:
        rd = csv.reader(f)
        next(rd)
        return [row for row in rd]


# ------------------------------------------------------------------------------------- main
def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--levels', type=int, nargs='+', default=[0, 1, 2, 3])
    ap.add_argument('--cases', nargs='+', default=['frictionless', 'coulomb'], choices=['frictionless', 'coulomb'])
    ap.add_argument('--methods', nargs='+', default=['mult', 'brick'], choices=['mult', 'brick'],
                    help='mult: GWFL Alart-Curnier with a P1 multiplier and the exact N, g; brick: GetFEM integral rigid-obstacle brick')
    ap.add_argument('--brick-levels', type=int, nargs='+', default=None,
                    help='levels on which the brick is run (default: all)')
    ap.add_argument('--mu', type=float, default=0.4, help='Coulomb friction coefficient of the coulomb case')
    ap.add_argument('--obs-degree', type=int, default=2, help='degree of the Lagrange FEM of the brick\'s obstacle level set')
    ap.add_argument('--r-factor', type=float, default=1.0,
                    help='augmentation parameter r = factor * E / h_min (side check of the r-dependence of the discrete solution)')
    ap.add_argument('--mesh', default='nested', choices=['nested', 'distmesh'],
                    help='nested: level 0 refined uniformly; distmesh: an independent distmesh per level')
    ap.add_argument('--seed', type=int, default=1, help='seed of the initial point cloud of distmesh')
    ap.add_argument('--csv', default=os.path.join(os.path.dirname(os.path.abspath(__file__)), 'indentation2d_primal.csv'))
    ap.add_argument('--profile', metavar='FILE', help='write the nodal pressure profile of the last solve')
    ap.add_argument('--verbose', action='store_true')
    ap.add_argument('--summarize', metavar='CSV', help='only print the summary of an existing CSV')
    args = ap.parse_args()
    if args.summarize:
        summarize(read_csv(args.summarize))
        return
    brick_levels = args.brick_levels if args.brick_levels is not None else args.levels
    rows = []
    print(' '.join(HDR), flush=True)
    T0 = time.time()
    for lev, hmin, p, t, info, tmesh in make_meshes(args.levels, args.mesh, args.seed):
        q = quality(p, t)
        m = build_getfem_mesh(p, t)
        mim = gf.MeshIm(m, gf.Integ('IM_TRIANGLE(6)'))
        ltop = gf.asm_generic(mim, 0, '1', TOP)
        lbot = gf.asm_generic(mim, 0, '1', BOTTOM)
        lside = gf.asm_generic(mim, 0, '1', LEFT) + gf.asm_generic(mim, 0, '1', RIGHT)
        area = gf.asm_generic(mim, 0, '1', -1)
        top = np.sort(p[p[:, 1] == Y1, 0])
        htop0 = np.min(np.diff(top)[np.abs(top[:-1]) < 0.1]) if len(top) > 1 else float('nan')
        print('# level %d (%s mesh): h_min=%g (shortest top edge at |x|<0.1: %.3g) nodes=%d triangles=%d %s '
              'q_min=%.3f q_mean=%.3f top nodes in |x|<0.07: %d |top|-4=%.1e |bottom|-4=%.1e |sides|-4=%.1e '
              'area-8=%.1e mesh_s=%.1f'
              % (lev, args.mesh, hmin, htop0, len(p), len(t), info, q.min(), q.mean(),
                 int(np.sum(np.abs(top) < 0.07)), ltop - 4, lbot - 4, lside - 4, area - 8, tmesh), flush=True)
        r = args.r_factor * E / hmin
        for case in args.cases:
            for method in args.methods:
                if method == 'brick' and lev not in brick_levels:
                    continue
                mu_f = args.mu if case == 'coulomb' else 0.0
                res = solve(m, case, method, r, mu_f, args.obs_degree, verbose=args.verbose)
                P = res['P']
                aH = math.sqrt(4 * P * R / (math.pi * ESTAR))
                p0H = 2 * P / (math.pi * aH)
                # bottom reaction: mult_on_u is the force of the body on the support; P_bottom =
                # -(its y component) is the downward load carried, Px_bottom its x component
                row = (case, method, lev, hmin, len(t), res['ndof'], r, mu_f, P, -res['Pbot_y'], res['Px'],
                       res['Pbot_x'], res['a_mom'], res['a_edge'], res['p0'], aH, p0H, res['a_mom'] / aH,
                       res['p0'] / p0H, res['c_stick'], res['nit'], res['dP'], res['tsol'])
                rows.append(row)
                print('%s %s %d %.5g %d %d %.3e %g %.6f %.6f %.1e %.1e %.5f %.5f %.3f %.5f %.3f %.4f %.4f %.4f %s %.1e %.1f'
                      % row + ('' if res['conv'] else ' NOT-CONVERGED')
                      + ('' if res['nstray'] == 0 else ' (%d stray contact nodes)' % res['nstray']), flush=True)
                if args.profile:
                    with open(args.profile, 'w') as fp:
                        fp.write('# %s %s level %d: x p_n q_t\n' % (case, method, lev))
                        for xx, pp, qq in res['profile']:
                            fp.write('%.8f %.8e %.8e\n' % (xx, pp, qq))
    with open(args.csv, 'w', newline='') as fcsv:
        w = csv.writer(fcsv)
        w.writerow(HDR)
        for row in rows:
            w.writerow(row)
    summarize([[str(x) for x in row] for row in rows])
    print('# wrote %s; total %.1f s' % (args.csv, time.time() - T0))


if __name__ == '__main__':
    main()
