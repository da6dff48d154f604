#!/usr/bin/python3
"""Independent primal computation of the Cattaneo-Mindlin deck input/cattaneo_mindlin2d.xml with
incremental Coulomb friction (docs/peer/README.md, "Cattaneo-Mindlin"; docs/contact.md "Load steps").

Peer code: GetFEM (Debian package python3-getfem). Scene as the deck: half disc x^2 + (y-1)^2 < 1,
y < 1; plane strain E = 20600, nu = 0.4999; top y = 1: u = (0, -0.01) in step 1, (0.0043321, -0.01)
in step 2 (Dirichlet by multipliers); arc faces below y = 0.3: contact with the rigid plane y = 0
in the obstacle frame (N = (0, -1) out of the body, gap g = y: u.N <= g), Coulomb friction
mu_F = 0.4; the rest of the arc free.

Friction on the slip increment: step 1 is the static problem (slip = u - 0, as StressContact's
first step); step 2 uses the slip u - u_1, u_1 the displacement at the end of step 1 (GetFEM's
Coulomb_friction_coupled_projection with the slip argument u - u_prev; its normal part is the
Alart-Curnier projection of the gap g - u.N).

Discretisation: isoparametric P2 triangles of docs/peer/hertz2d_primal.py (the same distmesh
family graded towards (0,0), levels 0-3, h at the contact 0.008 * 2^-level), IM_TRIANGLE(6), MUMPS.
  --elem th  (default) Taylor-Hood: u P2, pressure P1 (continuous); elasticity with mu only plus
             GetFEM's linear incompressibility brick with the penalty 1/lambda (the same
             continuum problem, free of volumetric locking at nu = 0.4999)
  --elem p2  pure P2 displacement (side check: P2 locks mildly at nu -> 1/2)
Contact: the traction on the body t as a vector P1 multiplier on the contact faces, non-symmetric
Alart-Curnier augmented Lagrangian in GWFL, r = E/h_min:
    -t.Test_u   and   -(1/r)*(t - Coulomb_friction_coupled_projection(t, N, u - u_prev, g - u.N, f, r)).Test_t
  --method brick: GetFEM's add_integral_contact_with_rigid_obstacle_brick with friction (option 1)
             and its 'alpha'/'WT' data (WT = u_prev: the brick's friction acts on u - WT), obstacle
             level set y on P2: a separate, hand-coded implementation of the same formulation.

Outputs per level and step: P = int t_y (vertical force on the body), Q = -int t_x (the top's
reaction along x, as StressContact's Q; checked against the top multiplier), the contact
half-width a (outermost nodes with p > 1e-6 p0, mean of both sides) and a_mom =
2 sqrt(int p x^2 / int p) (exact for a semi-ellipse), and the stick zone's ends
from the nodal values (P1 vertices) of the contact block: stick iff |t_x - r du_x| <= mu_F p, the
nodal Alart-Curnier indicator (du_x the slip increment of the step: the argument of the friction
projection lies in the ball), ends midway between the outermost stick node and the next node beyond
it (StressContact's convention, docs/output.md), half-width (c+ - c-)/2, centre (c+ + c-)/2
(columns stick_*; node resolution h_min); and, for comparison, |t_x| < 0.95 mu_F p alone with the
outermost stick node as the end ('_trac': it misses stick nodes where |t_x| is within 5% of mu_F p).

With --deck-steps mindlin-deresiewicz the steps of input/mindlin_deresiewicz2d.xml instead: top
u = (0, -0.01), (0.0043321, -0.01), (0.00216605, -0.01), (-0.0043321, -0.01), each step's friction
on the slip from the step before (docs/peer/README.md "Mindlin-Deresiewicz"); with
mindlin-deresiewicz-loop the 13 steps of input/mindlin_deresiewicz_loop2d.xml.

Usage: nice -n 10 /usr/bin/python3 docs/peer/cattaneo_mindlin2d_primal.py [--levels 0 1 2 3]
                                   [--deck-steps cattaneo-mindlin|mindlin-deresiewicz]
Writes docs/peer/cattaneo_mindlin2d_primal.csv (mindlin_deresiewicz2d_primal.csv) and prints the
table and a summary ('#S').
"""
import argparse
import csv
import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hertz2d_primal as hz  # noqa: E402  (mesh generator only: distmesh, isoparametric P2 mesh)
import getfem as gf  # noqa: E402

gf.util('trace level', 0)
gf.util('warning level', 0)

E, NU, MUF = 20600.0, 0.4999, 0.4
LAM = E * NU / ((1 + NU) * (1 - 2 * NU))
MU = E / (2 * (1 + NU))
# The top's displacement per load step: input/cattaneo_mindlin2d.xml, or with --deck-steps
# mindlin-deresiewicz input/mindlin_deresiewicz2d.xml (pressed, delta*, back to delta*/2, on to -delta*).
STEP_TABLES = {'cattaneo-mindlin': [(0.0, -0.01), (0.0043321, -0.01)],
               'mindlin-deresiewicz': [(0.0, -0.01), (0.0043321, -0.01), (0.00216605, -0.01), (-0.0043321, -0.01)],
               # input/mindlin_deresiewicz_loop2d.xml: delta*/4 steps to delta*, delta*/2 steps to
               # -delta* and back to delta*
               'mindlin-deresiewicz-loop': [(0.0043321 * k / 4, -0.01) for k in (0, 1, 2, 3, 4, 2, 0, -2, -4, -2, 0, 2, 4)]}
STEPS = STEP_TABLES['cattaneo-mindlin']
H0 = 0.008
MAXRES = 1e-6
PROFILE = None


def solve_level(lev, elem, method, seed, verbose):
    s = 0.5 ** lev
    t0 = time.time()
    p, t, nit_m = hz.distmesh(s, seed=seed)
    m, TOP, ARC, CONTACT = hz.build_getfem_mesh(p, t)
    tmesh = time.time() - t0
    hmin = s * H0
    r = E / hmin
    mfu = gf.MeshFem(m, 2)
    mfu.set_classical_fem(2)
    mim = gf.MeshIm(m, gf.Integ('IM_TRIANGLE(6)'))
    md = gf.Model('real')
    md.add_fem_variable('u', mfu)
    md.add_initialized_data('mu', [MU])
    if elem == 'th':
        mfpr = gf.MeshFem(m, 1)
        mfpr.set_classical_fem(1)
        md.add_fem_variable('pr', mfpr)
        md.add_initialized_data('lambda', [0.0])
        md.add_isotropic_linearized_elasticity_brick(mim, 'u', 'lambda', 'mu')
        md.add_initialized_data('epsl', [1.0 / LAM])
        md.add_linear_incompressibility_brick(mim, 'u', 'pr', -1, 'epsl')
    else:
        md.add_initialized_data('lambda', [LAM])
        md.add_isotropic_linearized_elasticity_brick(mim, 'u', 'lambda', 'mu')
    md.add_initialized_data('uD', list(STEPS[0]))
    md.add_Dirichlet_condition_with_multipliers(mim, 'u', mfu, TOP, 'uD')
    md.add_initialized_data('r', [r])
    md.add_initialized_data('f', [MUF])
    md.add_initialized_fem_data('uprev', mfu, np.zeros(mfu.nbdof()))
    mfl = gf.MeshFem(m, 2)
    mfl.set_classical_fem(1)
    dofs = np.sort(np.asarray(mfl.basic_dof_on_region(CONTACT)).ravel())
    mfc = gf.MeshFem('partial', mfl, dofs)
    md.add_fem_variable('t', mfc)
    N, G = '[0;-1]', 'X(2)'
    if method == 'mult':
        md.add_nonlinear_term(mim, '-t.Test_u', CONTACT)
        md.add_nonlinear_term(
            mim, '-(1/r)*(t - Coulomb_friction_coupled_projection(t, %s, u - uprev, %s - u.%s, f, r)).Test_t'
            % (N, G, N), CONTACT)
    else:
        mfo = gf.MeshFem(m, 1)
        mfo.set_classical_fem(2)
        md.add_initialized_fem_data('obstacle', mfo, mfo.basic_dof_nodes()[1])
        md.add_initialized_data('alpha', [1.0])
        # brick: friction on the slip alpha*(u - WT)
        md.add_integral_contact_with_rigid_obstacle_brick(mim, 'u', 't', 'obstacle', 'r', 'f', CONTACT, 1,
                                                          'alpha', 'uprev')
    xy = mfl.basic_dof_nodes(dofs)
    x = xy[0][0::2]
    assert np.allclose(xy[0][1::2], x)
    order = np.argsort(x)
    x = x[order]
    mfP1 = gf.MeshFem(m, 2)
    mfP1.set_classical_fem(1)
    vd = np.asarray(mfP1.basic_dof_on_region(CONTACT)).ravel()
    vxy = mfP1.basic_dof_nodes(vd)
    key = {}
    for k in range(0, len(vd), 2):
        key[round(vxy[0, k], 13)] = (vd[k], vd[k + 1])
    ix = np.array([key[round(xx, 13)][0] for xx in x])
    rows = []
    U1 = np.zeros(mfu.nbdof())
    sgn = 1.0
    for step, uD in enumerate(STEPS, start=1):
        md.set_variable('uD', list(uD))
        md.set_variable('uprev', U1)
        ts = time.time()
        opts = ['max_iter', 40, 'max_res', MAXRES, 'lsolver', 'mumps']
        if verbose:
            opts = ['noisy'] + opts
        nit, conv = md.solve(*opts)
        Q1 = gf.asm_generic(mim, 0, 'mult_on_u', TOP, md)
        dP = float('inf')
        for _ in range(5):
            md.solve('max_iter', 2, 'max_res', 1e-30, 'lsolver', 'mumps')
            Q2 = gf.asm_generic(mim, 0, 'mult_on_u', TOP, md)
            dP = float(np.max(np.abs(Q2 - Q1)) / np.max(np.abs(Q2)))
            if dP < 1e-9:
                break
            Q1 = Q2
        tsol = time.time() - ts
        if method == 'brick' and step == 1:
            # the brick's multiplier is the traction on the body or its opposite: make it t
            sgn = 1.0 if gf.asm_generic(mim, 0, 't(2)', CONTACT, md) > 0 else -1.0
        tr = '(%g*t)' % sgn
        P = gf.asm_generic(mim, 0, '%s(2)' % tr, CONTACT, md)
        Q = -gf.asm_generic(mim, 0, '%s(1)' % tr, CONTACT, md)
        Rtop = gf.asm_generic(mim, 0, 'mult_on_u', TOP, md)
        U = np.asarray(md.variable('u')).copy()
        lam = np.asarray(md.variable('t')) * sgn
        tx, ty = lam[0::2][order], lam[1::2][order]
        pn = ty
        Ui = gf.compute_interpolate_on(mfu, U, mfP1)
        U1i = gf.compute_interpolate_on(mfu, U1, mfP1)
        du = (Ui - U1i)[ix]
        p0 = float(pn.max())
        ipk = int(np.argmax(pn))
        lo = ipk
        while lo > 0 and pn[lo - 1] > 1e-6 * p0:
            lo -= 1
        hi = ipk
        while hi < len(pn) - 1 and pn[hi + 1] > 1e-6 * p0:
            hi += 1
        a_m, a_p = x[lo], x[hi]
        a = 0.5 * (a_p - a_m)
        # a from the second moment of the pressure (exact for a semi-ellipse): the ends / a_mom
        M0 = gf.asm_generic(mim, 0, '%s(2)' % tr, CONTACT, md)
        M2 = gf.asm_generic(mim, 0, '%s(2)*sqr(X(1))' % tr, CONTACT, md)
        a_mom = 2 * math.sqrt(M2 / M0)
        blk = np.arange(lo, hi + 1)
        st = blk[np.abs(tx[blk]) < 0.95 * MUF * pn[blk]]
        c_m, c_p = (x[st].min(), x[st].max()) if st.size else (float('nan'),) * 2
        # the nodal Alart-Curnier indicator: stick iff |t_x - r du_x| <= mu_F p (the argument of the
        # projection lies in the friction ball), du the slip increment of this step; the ends
        # midway between the outermost stick node and the next node beyond it (StressContact's
        # convention for stick_zone_ends, docs/output.md)
        ind = np.abs(tx - r * du) / np.maximum(MUF * pn, 1e-300)
        sa = blk[ind[blk] <= 1.0]
        if sa.size:
            i0, i1 = sa.min(), sa.max()
            n_m, n_p = x[i0], x[i1]
            s_m = 0.5 * (x[i0] + x[i0 - 1]) if i0 > lo else x[i0]
            s_p = 0.5 * (x[i1] + x[i1 + 1]) if i1 < hi else x[i1]
        else:
            n_m = n_p = s_m = s_p = float('nan')
        if PROFILE and step > 1:
            with open(PROFILE, 'a') as fp:
                for i in blk:
                    fp.write('%d %s %.10g %.10g %.10g %.10g %.6f\n' % (lev, elem, x[i], pn[i], tx[i], du[i], ind[i]))
        row = dict(level=lev, elem=elem, method=method, step=step, h_min=hmin, triangles=len(t),
                   dofs=md.nbdof(), P=P, Q=Q, P_top=-Rtop[1], Q_top=Rtop[0], Q_over_muP=Q / (MUF * P),
                   a=a, a_mom=a_mom, a_minus=a_m, a_plus=a_p, p0=p0,
                   stick_minus_trac=c_m, stick_plus_trac=c_p, stick_half_trac=0.5 * (c_p - c_m),
                   stick_node_minus=n_m, stick_node_plus=n_p,
                   stick_minus=s_m, stick_plus=s_p, stick_half=0.5 * (s_p - s_m), stick_centre=0.5 * (s_p + s_m),
                   newton_it=nit, dP_rel=dP, solve_s=tsol, mesh_s=tmesh)
        rows.append(row)
        print(' '.join(fmt(row[k]) for k in HDR) + ('' if dP < 1e-9 else ' NOT-CONVERGED'), flush=True)
        U1 = U
    return rows


HDR = ['level', 'elem', 'method', 'step', 'h_min', 'triangles', 'dofs', 'P', 'Q', 'P_top', 'Q_top',
       'Q_over_muP', 'a', 'a_mom', 'a_minus', 'a_plus', 'p0', 'stick_minus_trac', 'stick_plus_trac',
       'stick_half_trac', 'stick_node_minus', 'stick_node_plus', 'stick_minus', 'stick_plus', 'stick_half',
       'stick_centre', 'newton_it',
       'dP_rel', 'solve_s', 'mesh_s']


def fmt(v):
    if isinstance(v, float):
        return '%.10g' % v
    return str(v)


def summarize(rows):
    keys = []
    for rw in rows:
        k = (rw['elem'], rw['method'], int(rw['step']))
        if k not in keys:
            keys.append(k)
    for k in keys:
        sel = sorted([rw for rw in rows if (rw['elem'], rw['method'], int(rw['step'])) == k],
                     key=lambda rw: int(rw['level']))
        for q in ('P', 'Q', 'Q_over_muP', 'a', 'a_mom', 'stick_minus_trac', 'stick_plus_trac', 'stick_half_trac',
                  'stick_minus', 'stick_plus', 'stick_half', 'stick_centre'):
            v = [float(rw[q]) for rw in sel]
            if all(math.isnan(x) for x in v):
                continue
            txt = ', '.join('%.7g' % x for x in v)
            extra = ''
            if len(v) >= 3:
                d1, d2 = v[-2] - v[-3], v[-1] - v[-2]
                if d1 * d2 > 0 and abs(d2) < abs(d1) and math.log2(abs(d1 / d2)) > 0.3:
                    qr = math.log2(abs(d1 / d2))
                    lim = v[-1] + d2 / (2 ** qr - 1)
                else:  # no regular rate: the last value, with the larger of the last two changes
                    qr, lim = float('nan'), v[-1]
                unc = max(abs(lim - v[-1]), abs(d1), abs(d2))
                extra = '; last differences %.2e, %.2e; rate %.2f; limit %.7g +- %.2e' % (d1, d2, qr, lim, unc)
            print('#S %s %s step %d %s: %s%s' % (k + (q, txt, extra)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--levels', type=int, nargs='+', default=[0, 1, 2, 3])
    ap.add_argument('--elem', nargs='+', default=['th'], choices=['th', 'p2'])
    ap.add_argument('--methods', nargs='+', default=['mult'], choices=['mult', 'brick'])
    ap.add_argument('--seed', type=int, default=1)
    ap.add_argument('--deck-steps', choices=sorted(STEP_TABLES), default='cattaneo-mindlin',
                    help="the load steps: input/cattaneo_mindlin2d.xml's (default) or "
                         "input/mindlin_deresiewicz2d.xml's")
    ap.add_argument('--csv', help='default: docs/peer/cattaneo_mindlin2d_primal.csv, or '
                                  'mindlin_deresiewicz2d_primal.csv, mindlin_deresiewicz_loop2d_primal.csv '
                                  'with --deck-steps')
    ap.add_argument('--verbose', action='store_true')
    ap.add_argument('--summarize', metavar='CSV')
    ap.add_argument('--profile', metavar='FILE', help='append the step-2 nodal profile (level elem x p t_x du_x)')
    args = ap.parse_args()
    global PROFILE, STEPS
    PROFILE = args.profile
    STEPS = STEP_TABLES[args.deck_steps]
    if args.csv is None:
        stem = {'mindlin-deresiewicz-loop': 'mindlin_deresiewicz_loop'}.get(args.deck_steps,
                                                                          args.deck_steps.replace('-', '_'))
        args.csv = os.path.join(os.path.dirname(os.path.abspath(__file__)), stem + '2d_primal.csv')
    if args.summarize:
        with open(args.summarize) as f:
            summarize(list(csv.DictReader(f)))
        return
    print(' '.join(HDR), flush=True)
    T0 = time.time()
    rows = []
    for elem in args.elem:
        for method in args.methods:
            for lev in args.levels:
                rows += solve_level(lev, elem, method, args.seed, args.verbose)
    with open(args.csv, 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=HDR)
        w.writeheader()
        for rw in rows:
            w.writerow({k: fmt(rw[k]) for k in HDR})
    summarize([{k: fmt(rw[k]) for k in HDR} for rw in rows])
    print('# wrote %s; total %.1f s' % (args.csv, time.time() - T0))


if __name__ == '__main__':
    main()
