#!/usr/bin/python3
"""Independent primal verification of the Hertz 2D contact load (StressContact, docs/peer/README.md).

Peer code: GetFEM (Debian package python3-getfem), P2 displacements on isoparametric P2
(curved) triangles, plane strain, E = 20600, nu = 0.28.

Scene (docs/theory.md "Scenes"): half disc x^2 + (y-1)^2 < 1, y < 1; top edge y = 1: u = (0, -0.01);
lower arc: frictionless contact with the rigid plane y = 0; f = 0.

Two linearised contact models (gap measured from the undeformed arc):
  obstacle : N = (0,-1) (out of the body, minus the plane's normal), g = y,
             constraint u.N <= g  (i.e. u_y >= -y), traction on the body  -p N = (0, p).
  body     : N = n, the outward unit normal of the arc at x, g = y/(-n_y) (distance along n
             to y = 0), constraint u.n <= g, traction on the body -p n.
Two ways to impose the constraint:
  mult     : contact pressure p as a P1 multiplier on the contact boundary, non-symmetric
             Alart-Curnier augmented Lagrangian written in GWFL (the result does not depend on r).
  pen      : penalty  r * pos_part(u.N - g), swept in r to show the limit r -> inf.
P is the vertical force on the body: int p (-N_y) ds over the contact boundary; it is checked
against the reaction on the top edge (Dirichlet multiplier).

Meshes: Persson-Strang (distmesh) triangulations of the half disc graded towards (0,0) with the size
function h(x) = s * min(hmax, h0 + alpha * max(0, |x| - rz)); each level halves s. Mid-edge nodes
of arc edges are put on the circle (quadratic geometry, GT_PK(2,2)).

Usage:   nice -n 10 /usr/bin/python3 docs/peer/hertz2d_primal.py            (default run)
         ... --levels 0 1 2 3 --models obstacle body --methods mult pen
Writes docs/peer/hertz2d_primal.csv (next to this script) and prints the table.
"""
import argparse
import csv
import math
import os
import sys
import time

import numpy as np
from scipy.spatial import Delaunay

import getfem as gf

gf.util('trace level', 0)
gf.util('warning level', 0)

E, NU = 20600.0, 0.28
UD = 0.01
R = 1.0
LAM = E * NU / ((1 + NU) * (1 - 2 * NU))
MU = E / (2 * (1 + NU))
ESTAR = E / (1 - NU ** 2)

# size function at level 0 (s = 1); level l uses s = 2^-l
H0, HMAX, ALPHA, RZ = 0.008, 0.1, 0.3, 0.1
MAXRES = 1e-6
PROFILE = []
Y_CONTACT = 0.3  # arc faces below this height form the contact boundary (the rest is free)


# ----------------------------------------------------------------------------------------- mesh
def fd(p):
    """signed distance (approx.) to the half disc x^2 + (y-1)^2 < 1, y < 1"""
    r = np.sqrt(p[:, 0] ** 2 + (p[:, 1] - 1.0) ** 2) - 1.0
    return np.maximum(r, p[:, 1] - 1.0)


def fh(p, s):
    d = np.maximum(0.0, np.sqrt(p[:, 0] ** 2 + p[:, 1] ** 2) - RZ)
    return s * np.minimum(HMAX, H0 + ALPHA * d)


def boundary_nodes(s):
    """Fixed boundary nodes: the arc (sin phi, 1 - cos phi), phi in [-pi/2, pi/2], spaced by the size
    function and symmetric about x = 0 (a node at (0,0)), and the top edge y = 1, uniform."""
    phis = [0.0]
    while phis[-1] < math.pi / 2:
        ph = phis[-1]
        phis.append(ph + fh(np.array([[math.sin(ph), 1 - math.cos(ph)]]), s)[0] / R)
    n = len(phis) - 1
    S = np.array(phis)
    if n > 1 and (S[-1] - math.pi / 2) > 0.5 * (S[-1] - S[-2]):
        S = S[:-1]  # drop the last step and stretch the rest
    S = S * (math.pi / 2) / S[-1]
    ph = np.concatenate([-S[::-1], S[1:]])
    arc = np.column_stack([np.sin(ph), 1 - np.cos(ph)])
    arc[0] = [-1.0, 1.0]
    arc[-1] = [1.0, 1.0]
    ntop = int(math.ceil(2.0 / (s * HMAX)))
    xt = np.linspace(-1.0, 1.0, ntop + 1)[1:-1]
    top = np.column_stack([xt, np.ones_like(xt)])
    return np.vstack([arc, top])


def distmesh(s, maxit=300, seed=1):
    """Persson & Strang, SIAM Review 46 (2004), with the size function fh and fixed boundary nodes
    (only the interior nodes move; they are kept at least h/4 inside); returns p, t (ccw)."""
    rng = np.random.default_rng(seed)
    hmin = s * H0
    geps = 1e-3 * hmin
    dptol, ttol, Fscale, deltat = 1e-3, 0.1, 1.2, 0.2
    pfix = boundary_nodes(s)
    # initial points: hexagonal lattice of spacing hmin, thinned with probability ~ 1/h^2, built in
    # bands of y to keep the memory small
    pts = []
    dy = hmin * math.sqrt(3) / 2
    ys = np.arange(0.0, 1.0 + dy, dy)
    xs = np.arange(-1.0, 1.0 + hmin, hmin)
    for j0 in range(0, len(ys), 200):
        yy = ys[j0:j0 + 200]
        X, Y = np.meshgrid(xs, yy)
        X = X + (np.arange(j0, j0 + len(yy)) % 2)[:, None] * hmin / 2
        q = np.column_stack([X.ravel(), Y.ravel()])
        hq = fh(q, s)
        q = q[fd(q) < -0.5 * hq]
        r0 = (hmin / fh(q, s)) ** 2
        q = q[rng.random(len(q)) < r0]
        pts.append(q)
    p = np.vstack([pfix] + pts)
    nfix = len(pfix)
    pold = np.inf * np.ones_like(p)
    t = None
    deps = 1e-9
    for it in range(maxit):
        if np.max(np.hypot(*(p - pold).T) / fh(p, s)) > ttol:
            pold = p.copy()
            t = Delaunay(p).simplices
            pmid = p[t].mean(axis=1)
            t = t[fd(pmid) < -geps]
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
        # keep the interior nodes at least h/4 inside
        d = fd(p)
        hp = fh(p, s)
        ix = d > -0.25 * hp
        ix[:nfix] = False
        if ix.any():
            q = p[ix]
            dgx = (fd(q + [deps, 0]) - fd(q - [deps, 0])) / (2 * deps)
            dgy = (fd(q + [0, deps]) - fd(q - [0, deps])) / (2 * deps)
            corr = (d[ix] + 0.25 * hp[ix]) / (dgx ** 2 + dgy ** 2)
            p[ix] -= np.column_stack([corr * dgx, corr * dgy])
        move = deltat * np.hypot(*Ftot[nfix:].T) / fh(p[nfix:], s)
        if move.size and move.max() < dptol:
            break
    # final triangulation
    t = Delaunay(p).simplices
    pmid = p[t].mean(axis=1)
    t = t[fd(pmid) < -geps]
    # ccw orientation
    a = p[t]
    ar = (a[:, 1, 0] - a[:, 0, 0]) * (a[:, 2, 1] - a[:, 0, 1]) - (a[:, 1, 1] - a[:, 0, 1]) * (a[:, 2, 0] - a[:, 0, 0])
    t[ar < 0] = t[ar < 0][:, [0, 2, 1]]
    # drop degenerate triangles of three collinear top-edge nodes (area 0), if any
    q = quality(p, t)
    t = t[q > 1e-6]
    used = np.zeros(len(p), bool)
    used[t.ravel()] = True
    assert used.all(), 'a node lost all its triangles'
    return p, t, it + 1


def quality(p, t):
    a = p[t]
    l = np.stack([np.hypot(*(a[:, 1] - a[:, 0]).T), np.hypot(*(a[:, 2] - a[:, 1]).T), np.hypot(*(a[:, 0] - a[:, 2]).T)], 1)
    ar = 0.5 * np.abs((a[:, 1, 0] - a[:, 0, 0]) * (a[:, 2, 1] - a[:, 0, 1]) - (a[:, 1, 1] - a[:, 0, 1]) * (a[:, 2, 0] - a[:, 0, 0]))
    # 4 sqrt(3) A / sum l^2  (1 for equilateral)
    return 4 * math.sqrt(3) * ar / np.sum(l ** 2, axis=1)


def build_getfem_mesh(p, t):
    """P2 (isoparametric) GetFEM mesh; arc mid-edge nodes on the circle. Returns mesh, regions."""
    # GetFEM GT_PK(2,2) node order: (0,0) (1/2,0) (1,0) (0,1/2) (1/2,1/2) (0,1)
    #                          -> v0, m01, v1, m02, m12, v2
    def mid(i, j):
        q = 0.5 * (p[t[:, i]] + p[t[:, j]])
        # boundary edge on the arc: both ends on the circle and not both on the top edge
        ri = np.hypot(p[t[:, i], 0], p[t[:, i], 1] - 1.0)
        rj = np.hypot(p[t[:, j], 0], p[t[:, j], 1] - 1.0)
        arc = (np.abs(ri - 1) < 1e-12) & (np.abs(rj - 1) < 1e-12) & ~((p[t[:, i], 1] == 1.0) & (p[t[:, j], 1] == 1.0))
        rq = np.hypot(q[:, 0], q[:, 1] - 1.0)
        # only edges that are boundary edges: an interior edge joining two arc points would be a
        # chord crossing the body, which distmesh does not produce except on tiny slivers; we
        # check boundary status below
        return q, arc, rq
    M = len(t)
    e = np.vstack([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    es = np.sort(e, axis=1)
    uniq, inv, cnt = np.unique(es, axis=0, return_inverse=True, return_counts=True)
    once = cnt[inv] == 1  # per (triangle edge) in the stacked order
    once = once.reshape(3, M)  # [edge01, edge12, edge20]
    pts = np.zeros((M, 6, 2))
    pts[:, 0] = p[t[:, 0]]
    pts[:, 2] = p[t[:, 1]]
    pts[:, 5] = p[t[:, 2]]
    for slot, (i, j), k in ((1, (0, 1), 0), (4, (1, 2), 1), (3, (0, 2), 2)):
        q, arc, rq = mid(i, j)
        arc &= once[k]
        q[arc, 0] /= rq[arc]
        q[arc, 1] = 1.0 + (q[arc, 1] - 1.0) / rq[arc]
        pts[:, slot] = q
    m = gf.Mesh('empty', 2)
    gt = gf.GeoTrans('GT_PK(2,2)')
    PTS = np.ascontiguousarray(np.transpose(pts, (2, 1, 0)))  # 2 x 6 x M
    cvids = m.add_convex(gt, PTS)
    cvids = np.asarray(cvids).ravel()
    assert len(cvids) == M and np.all(cvids == np.arange(M)), "unexpected convex ids"
    # boundary faces; GetFEM face f of a triangle is opposite local vertex f
    of = m.outer_faces()
    cv, f = of[0], of[1]
    # vertices of face f: the two others
    others = {0: (1, 2), 1: (0, 2), 2: (0, 1)}
    va = np.array([t[c, others[ff][0]] for c, ff in zip(cv, f)])
    vb = np.array([t[c, others[ff][1]] for c, ff in zip(cv, f)])
    top = (p[va, 1] == 1.0) & (p[vb, 1] == 1.0)
    ymax = np.maximum(p[va, 1], p[vb, 1])
    contact = (~top) & (ymax < Y_CONTACT)
    TOP, ARC, CONTACT = 1, 2, 3
    m.set_region(TOP, np.vstack([cv[top], f[top]]))
    m.set_region(ARC, np.vstack([cv[~top], f[~top]]))
    m.set_region(CONTACT, np.vstack([cv[contact], f[contact]]))
    return m, TOP, ARC, CONTACT


# ------------------------------------------------------------------------------------ solver
BODY_GAP = 'along_n'


def normal_and_gap(model, normal):
    if model == 'obstacle':
        return '[0;-1]', 'X(2)'
    if normal == 'discrete':
        n = 'Normal'
    else:
        n = '(Normalized([X(1);X(2)-1]))'
    if BODY_GAP == 'height':  # side check only: u.n <= y (first-order equal, differs by O(slope^2))
        return n, 'X(2)'
    return n, '(X(2)/(-(%s)(2)))' % n


def solve(m, regs, model, method, r, normal='exact', U0=None, verbose=False):
    TOP, ARC, CONTACT = regs
    mfu = gf.MeshFem(m, 2)
    mfu.set_classical_fem(2)
    mfp = gf.MeshFem(m, 1)
    mfp.set_classical_fem(1)
    mim = gf.MeshIm(m, gf.Integ('IM_TRIANGLE(6)'))
    md = gf.Model('real')
    md.add_fem_variable('u', mfu)
    md.add_initialized_data('lambda', [LAM])
    md.add_initialized_data('mu', [MU])
    md.add_isotropic_linearized_elasticity_brick(mim, 'u', 'lambda', 'mu')
    md.add_initialized_data('uD', [0.0, -UD])
    md.add_Dirichlet_condition_with_multipliers(mim, 'u', mfu, TOP, 'uD')
    md.add_initialized_data('r', [r])
    N, g = normal_and_gap(model, normal)
    if method == 'mult':
        dofs = np.sort(np.asarray(mfp.basic_dof_on_region(CONTACT)).ravel())
        mfc = gf.MeshFem('partial', mfp, dofs)
        md.add_fem_variable('p', mfc)
        md.add_nonlinear_term(mim, 'p*(Test_u.%s)' % N, CONTACT)
        md.add_nonlinear_term(mim, '-(1/r)*(p - pos_part(p + r*(u.%s - %s)))*Test_p' % (N, g), CONTACT)
        pexpr = 'p'
    elif method == 'brick':
        # GetFEM's own brick (obstacle normal only): integral Alart-Curnier contact with a rigid
        # obstacle given by its level set (here y, interpolated on P2), multiplier P1
        assert model == 'obstacle', 'the GetFEM rigid-obstacle brick uses the obstacle normal'
        dofs = np.sort(np.asarray(mfp.basic_dof_on_region(CONTACT)).ravel())
        mfc = gf.MeshFem('partial', mfp, dofs)
        md.add_fem_variable('p', mfc)
        mfo = gf.MeshFem(m, 1)
        mfo.set_classical_fem(2)
        md.add_initialized_fem_data('obstacle', mfo, mfo.basic_dof_nodes()[1])
        md.add_integral_contact_with_rigid_obstacle_brick(mim, 'u', 'p', 'obstacle', 'r', CONTACT, 1)
        pexpr = 'BRICK'
    else:
        md.add_nonlinear_term(mim, 'r*pos_part(u.%s - %s)*(Test_u.%s)' % (N, g, N), CONTACT)
        pexpr = 'r*pos_part(u.%s - %s)' % (N, g)
    if U0 is not None:
        md.set_variable('u', U0)
    t0 = time.time()
    # semismooth Newton; the residual stagnates at a round-off floor (~1e-8, growing with r and
    # the DOFs) once the active set is fixed, so: solve to MAXRES, then two more Newton steps and
    # the change of P across them is the convergence check (dP, relative)
    Pexpr = '%s*(-(%s)(2))' % ('p' if method == 'mult' else 'r*pos_part(u.%s - %s)' % (N, g), N)
    if method == 'brick':
        Pexpr = 'p'
    opts = ['max_iter', 100, 'max_res', MAXRES, 'lsolver', 'mumps']
    if verbose:
        opts = ['noisy'] + opts
    nit, conv = md.solve(*opts)
    P1 = gf.asm_generic(mim, 0, Pexpr, CONTACT, md)
    for _ in range(5):
        md.solve('max_iter', 2, 'max_res', 1e-30, 'lsolver', 'mumps')
        P2 = gf.asm_generic(mim, 0, Pexpr, CONTACT, md)
        dP = abs(P2 - P1) / abs(P2) if P2 != 0 else float('inf')
        if dP < 1e-8:
            break
        P1 = P2
    conv = dP < 1e-8
    tsol = time.time() - t0
    ndof = md.nbdof()
    if method == 'brick':
        # the sign convention of the brick's multiplier: make p the (positive) pressure
        sgn = 1.0 if gf.asm_generic(mim, 0, 'p', CONTACT, md) > 0 else -1.0
        pexpr = '(%g*p)' % sgn
    # P: vertical force on the body from the contact pressure
    Pc = gf.asm_generic(mim, 0, '%s*(-(%s)(2))' % (pexpr, N), CONTACT, md)
    Px = gf.asm_generic(mim, 0, '%s*(-(%s)(1))' % (pexpr, N), CONTACT, md)
    # reaction on the top edge: Dirichlet multiplier (force the constraint exerts on u)
    Ptop = gf.asm_generic(mim, 0, 'mult_on_u(2)', TOP, md)
    # moments over x (dx = -n_y ds on the arc; use the exact arc normal for the measure)
    dxw = '(-(Normalized([X(1);X(2)-1]))(2))'
    pN = '%s' % pexpr
    # the normal pressure p; for the vertical-force weighted moments use p*(-N_y)
    M0 = gf.asm_generic(mim, 0, '%s*(-(%s)(2))' % (pN, N), CONTACT, md)
    M2 = gf.asm_generic(mim, 0, '%s*(-(%s)(2))*sqr(X(1))' % (pN, N), CONTACT, md)
    a_mom = 2 * math.sqrt(M2 / M0)
    # nodal pressure profile: interpolate p on P1 nodes of the contact boundary
    dofs = np.sort(np.asarray(mfp.basic_dof_on_region(CONTACT)).ravel())
    xy = mfp.basic_dof_nodes(dofs)
    if method in ('mult', 'brick'):
        pv = np.asarray(md.variable('p')) * (sgn if method == 'brick' else 1.0)
        assert len(pv) == len(dofs)
    else:
        U = md.variable('u')
        # interpolate the displacement at the P1 nodes (vertices) and evaluate the penalty pressure
        mfP1 = gf.MeshFem(m, 2)
        mfP1.set_classical_fem(1)
        Ui = gf.compute_interpolate_on(mfu, U, mfP1)
        vd = mfP1.basic_dof_on_region(CONTACT)
        # vector dofs come in (x,y) pairs; map scalar node -> components
        vxy = mfP1.basic_dof_nodes(vd)
        ux = {}
        for k in range(0, len(vd), 2):
            ux[(round(vxy[0, k], 14), round(vxy[1, k], 14))] = (Ui[vd[k]], Ui[vd[k + 1]])
        pv = np.zeros(xy.shape[1])
        for k in range(xy.shape[1]):
            x, y = xy[0, k], xy[1, k]
            u = ux[(round(x, 14), round(y, 14))]
            if model == 'obstacle':
                nn = np.array([0.0, -1.0]); gg = y
            else:
                nn = np.array([x, y - 1.0]) / math.hypot(x, y - 1.0)
                gg = y if BODY_GAP == 'height' else y / (-nn[1])
            pv[k] = r * max(0.0, u[0] * nn[0] + u[1] * nn[1] - gg)
    x = xy[0]
    order = np.argsort(x)
    x, pv = x[order], pv[order]
    p0 = float(pv.max())
    # contact half-width from the nodal profile: outermost nodes with p > 0 on each side, refined
    # by the zero of the line through p^2 at the last two contact nodes (p^2 ~ linear near the edge)
    # the contact zone: the block of nodes with p > 1e-6 p0 around the peak
    tol = 1e-6 * p0
    ipk = int(np.argmax(pv))
    lo = ipk
    while lo > 0 and pv[lo - 1] > tol:
        lo -= 1
    hi = ipk
    while hi < len(pv) - 1 and pv[hi + 1] > tol:
        hi += 1
    act = np.arange(lo, hi + 1)
    nstray = int(np.sum(pv > tol)) - len(act)
    a_edge = []
    for side in (+1, -1):
        if side > 0:
            i = act.max(); j = i - 1; k = i + 1
        else:
            i = act.min(); j = i + 1; k = i - 1
        xa = abs(x[i])
        if 0 <= j < len(x) and 0 <= k < len(x):
            q2i, q2j = pv[i] ** 2, pv[j] ** 2
            s2i, s2j = x[i] ** 2, x[j] ** 2
            if q2j > q2i and s2i != s2j:
                s0 = s2i + q2i * (s2i - s2j) / (q2j - q2i)
                xa = min(math.sqrt(max(s0, 0.0)), abs(x[k]))
        a_edge.append(xa)
    a_edge = 0.5 * sum(a_edge)
    nact = len(act)
    PROFILE.clear(); PROFILE.extend(zip(x, pv))
    return dict(P=Pc, Px=Px, Ptop=Ptop, a_mom=a_mom, a_edge=a_edge, p0=p0, ndof=ndof, nit=nit,
                conv=conv, dP=dP, tsol=tsol, nact=nact, nstray=nstray,
                U=np.asarray(md.variable('u')).copy())


# ---------------------------------------------------------------------------------- summary
def summarize(rows):
    """Refinement sequences of P: per model and method, the differences between levels, the
    observed rate, a Richardson estimate of the limit; for the penalty, P extrapolated in 1/r from
    the two largest r of each level. Prints lines starting with '#S'."""
    out = {}
    keys = []
    for row in rows:
        k = (row[0], row[1])
        if k not in keys:
            keys.append(k)
    for model, method in keys:
        sel = [r for r in rows if r[0] == model and r[1] == method]
        levels = sorted(set(int(r[2]) for r in sel))
        seq = []
        for lev in levels:
            rl = sorted([r for r in sel if int(r[2]) == lev], key=lambda r: float(r[6]))
            if method == 'pen':
                if len(rl) < 2:
                    continue
                Pa, Pb = float(rl[-2][7]), float(rl[-1][7])
                fr = float(rl[-1][6]) / float(rl[-2][6])
                P = Pb + (Pb - Pa) / (fr - 1.0)  # P(r) = P_inf - C/r
            else:
                P = float(rl[-1][7])
            seq.append((lev, int(rl[-1][5]), P))
        if not seq:
            continue
        txt = ', '.join('L%d (%d dofs) %.4f' % s_ for s_ in seq)
        print('#S %s %s%s: %s' % (model, method, ' (r->inf)' if method == 'pen' else '', txt))
        Ps = [p for _, _, p in seq]
        if len(Ps) >= 3:
            d1, d2 = Ps[-2] - Ps[-3], Ps[-1] - Ps[-2]
            q = math.log2(abs(d1 / d2)) if d2 != 0 and d1 != 0 else float('nan')
            if d1 * d2 > 0 and q > 0.3:
                Pinf = Ps[-1] + d2 / (2 ** q - 1)
            else:
                Pinf = Ps[-1]
            # conservative: the largest of the last two changes between levels
            unc = max(abs(Pinf - Ps[-1]), abs(d1), abs(d2))
            print('#S   last differences %.2e, %.2e; observed rate (in h) %.2f; limit %.4f +- %.4f (%.3f%%)'
                  % (d1, d2, q, Pinf, unc, 100 * unc / Pinf))
            out[(model, method)] = (Pinf, unc)
        elif len(Ps) == 2:
            d2 = Ps[-1] - Ps[-2]
            print('#S   last difference %.2e' % d2)
            out[(model, method)] = (Ps[-1], abs(d2))
    for method in ('mult', 'pen'):
        if ('obstacle', method) in out and ('body', method) in out:
            (Po, uo), (Pb, ub) = out[('obstacle', method)], out[('body', method)]
            rt = Po / Pb
            print('#S P_obstacle/P_body (%s) = %.5f +- %.5f' % (method, rt, rt * (uo / Po + ub / Pb)))
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
    ap.add_argument('--models', nargs='+', default=['obstacle', 'body'])
    ap.add_argument('--methods', nargs='+', default=['mult', 'pen', 'brick'],
                    help='mult: GWFL Alart-Curnier with a P1 multiplier; pen: penalty sweep; brick: GetFEM integral rigid-obstacle brick (obstacle model only)')
    ap.add_argument('--pen-levels', type=int, nargs='+', default=None,
                    help='levels on which the penalty sweep is run (default: all)')
    ap.add_argument('--pen-factors', type=float, nargs='+', default=[1e0, 1e1, 1e2, 1e3, 1e4],
                    help='penalty r = factor * E / h_min')
    ap.add_argument('--normal', default='exact', choices=['exact', 'discrete'],
                    help='body normal: exact circle normal at the point, or GWFL Normal of the P2 face')
    ap.add_argument('--body-gap', default='along_n', choices=['along_n', 'height'],
                    help='body model gap: along n to the plane (the model verified here) or, as a side '
                         'check of the model sensitivity, the height y')
    ap.add_argument('--seed', type=int, default=1, help='seed of the initial point cloud of distmesh')
    ap.add_argument('--csv', default=os.path.join(os.path.dirname(os.path.abspath(__file__)), 'hertz2d_primal.csv'))
    ap.add_argument('--verbose', action='store_true')
    ap.add_argument('--summarize', metavar='CSV', help='only print the summary of an existing CSV')
    args = ap.parse_args()
    global BODY_GAP
    BODY_GAP = args.body_gap
    if args.summarize:
        summarize(read_csv(args.summarize))
        return
    pen_levels = args.pen_levels if args.pen_levels is not None else args.levels
    rows = []
    hdr = ('model', 'method', 'level', 'h_min', 'elements', 'dofs', 'r', 'P', 'P_top', 'Px', 'a_mom',
           'a_edge', 'p0', 'a_H', 'p0_H', 'a_mom/a_H', 'p0/p0_H', 'newton_it', 'dP_rel', 'solve_s')
    print(' '.join('%s' % h for h in hdr), flush=True)
    T0 = time.time()
    for lev in args.levels:
        s = 0.5 ** lev
        t0 = time.time()
        p, t, nit = distmesh(s, seed=args.seed)
        q = quality(p, t)
        m, TOP, ARC, CONTACT = build_getfem_mesh(p, t)
        mim = gf.MeshIm(m, gf.Integ('IM_TRIANGLE(6)'))
        larc = gf.asm_generic(mim, 0, '1', ARC)
        ltop = gf.asm_generic(mim, 0, '1', TOP)
        area = gf.asm_generic(mim, 0, '1', -1)
        print('# level %d: s=%g h_min=%g nodes=%d triangles=%d distmesh_it=%d q_min=%.3f q_mean=%.3f '
              '|arc|-pi=%.2e |top|-2=%.2e area-pi/2=%.2e mesh_s=%.1f'
              % (lev, s, s * H0, len(p), len(t), nit, q.min(), q.mean(), larc - math.pi, ltop - 2,
                 area - math.pi / 2, time.time() - t0), flush=True)
        hmin = s * H0
        for model in args.models:
            U0 = None
            for method in args.methods:
                if method == 'brick' and model != 'obstacle':
                    continue
                if method in ('mult', 'brick'):
                    rlist = [E / hmin]
                else:
                    if lev not in pen_levels:
                        continue
                    rlist = [f * E / hmin for f in args.pen_factors]
                for r in rlist:
                    # the penalty Newton starts from the previous solution of the same model
                    # (multiplier, then the previous r): from u = 0 it cycles
                    res = solve(m, (TOP, ARC, CONTACT), model, method, r, normal=args.normal,
                                U0=U0 if method == 'pen' else None, verbose=args.verbose)
                    U0 = res['U']
                    P = res['P']
                    aH = math.sqrt(4 * P * R / (math.pi * ESTAR))
                    p0H = 2 * P / (math.pi * aH)
                    row = (model, method, lev, hmin, len(t), res['ndof'], r, P, res['Ptop'],
                           res['Px'], res['a_mom'], res['a_edge'], res['p0'], aH, p0H, res['a_mom'] / aH,
                           res['p0'] / p0H, res['nit'], res['dP'], res['tsol'])
                    rows.append(row)
                    print('%s %s %d %.5g %d %d %.3e %.5f %.5f %.2e %.5f %.5f %.3f %.5f %.3f %.4f %.4f %s %.1e %.1f'
                          % row + ('' if res['conv'] else ' NOT-CONVERGED'), flush=True)
    with open(args.csv, 'w', newline='') as fcsv:
        w = csv.writer(fcsv)
        w.writerow(hdr)
        for row in rows:
            w.writerow(row)
    summarize([[str(x) for x in row] for row in rows])
    print('# wrote %s; total %.1f s' % (args.csv, time.time() - T0))


if __name__ == '__main__':
    main()
