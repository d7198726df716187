#!/usr/bin/env python3
"""Elastic disc falling onto a rigid plane under gravity: GetFEM reference runs.

What it ports
-------------
The 2D case of GetFEM's Octave/Matlab demo
``interface/tests/matlab/demo_dynamic_contact.m`` (Y. Renard, F. Chouly;
repository getfem/getfem, version of commit 14fc43ef, 2017-11-05; since
GetFEM 5.4 the file lives in ``interface/tests/matlab-octave/``), rewritten
for GetFEM's Python interface (Debian bookworm package ``python3-getfem``,
GetFEM 5.4.2).  Only the parts used by the 2D case with
``singular_mass = 0`` and ``scheme = 2`` (Newmark) are kept; the plotting and
the 1D analytical-solution bookkeeping are dropped.

Problem (the demo's 2D parameters)
----------------------------------
* mesh: ``disc_P2_h2.mesh`` (GetFEM ``tests/meshes``, copied next to this
  script from tag v5.4.2): a disc of radius 20 centred at (0, 20), 1391
  nodes, 664 quadratic (GT_PK(2,2)) triangles; its lowest point is at y = 0.
* linearized isotropic elasticity, clambda = cmu = 20 (E = 50, nu = 0.25),
  density 1 (unit-density mass matrix), volumic force (0, -0.1).
* rigid obstacle: signed distance ``y`` (the plane y = 0); contact boundary
  GAMMAC = outer faces whose outward normal has y-component < -0.01.
* initial state: U0 = (0, 5) at every dof (disc 5 above the plane), V0 = 0,
  M A0 = FF - K U0.
* u: P2 (u_degree 2), contact multiplier: P1 (lambda_degree 1) restricted
  to the dofs of GAMMAC, integration: degree 4 in the bulk,
  IM_STRUCTURED_COMPOSITE(IM_TRIANGLE(4),4) for the contact terms.
* Newmark (demo scheme 2) beta = 1/4, gamma = 1/2, dt = 0.01, T = 40,
  GetFEM Newton with max_res 1e-8 and max_iter 100.

Variants (``--variants``)
-------------------------
* ``lm``          demo ``Nitsche = 0``: 'add integral contact with rigid
                  obstacle brick' (Alart-Curnier, option 1), augmentation
                  r = 10.
* ``nitsche``     'add Nitsche contact with rigid obstacle brick',
                  theta_N = -1, gamma0 = 1000.  The demo of commit 14fc43ef
                  writes gamma0_N = 0.001, but five days later (commit
                  2e8d01b9, "gamma -> 1/gamma") GetFEM inverted the meaning of
                  gamma0 in this brick and the demo changed its value to
                  1000.  GetFEM 5.4.2 uses the new meaning (augmentation
                  gamma0/h), so gamma0 = 1000 here is exactly the demo's
                  0.001 (old meaning, gamma = 0.001 h).
* ``nitsche_lit`` the same brick with gamma0 = 0.001 taken literally in
                  GetFEM 5.4.2 (augmentation 0.001/h: a contact 1e6 times
                  softer than intended).  Diagnostic only, not run by default.
* ``penalty``     'add penalized contact with rigid obstacle brick', penalty
                  r = 200 (contact pressure r * (penetration)).  This is the
                  same force law as the penalty option of the GetFEM 5.4.2
                  demo, a potential penalty_coeff * neg_part(gap)^2 with
                  penalty_coeff = 100.
* ``penalty_gwfl`` the 5.4.2 demo's penalty term itself ('add nonlinear
                  term' with that potential, penalty_coeff = 100); a
                  cross-check of ``penalty``, not run by default.

Measured quantities
-------------------
* energy per step exactly as in the demo,
  E = (V1' M V1 + U1' K U1)/2 - FF' U1
  (kinetic + elastic + gravity potential; no contact/penalty energy).
* contact force: resultant of the normal contact pressure on GAMMAC,
  integrated with the contact integration method (positive = pushing the
  disc up): lm: -int lambda; nitsche: int neg_part(lambda_n + (gamma0/h) gap)
  with lambda_n = (sigma(u) n).(0,-1), i.e. the Nitsche contact pressure the
  brick applies; penalty: int r neg_part(gap); gap = y + u_y.
  As a brick-independent cross-check the script also writes the vertical
  resultant of the discrete contact force M A1 - FF + K U1.
* active flag: contact force > 1e-8 W, W = 0.1 * area = 125.66 the disc's
  weight.  A contact episode is a maximal run of consecutive active steps
  (column ``episodes``).  Episodes are also counted with the coarser
  threshold contact force > 1e-3 W (``episodes_tol1e-3W``; a run can split
  into several where the force dips below it) and from the geometry, steps
  where some displacement dof of GAMMAC is below y = 0
  (``episodes_geometric``).

How to run
----------
  nice -n 19 /usr/bin/python3 bench/getfem/disc_gravity.py            # lm, nitsche, penalty
  nice -n 19 /usr/bin/python3 bench/getfem/disc_gravity.py --variants nitsche_lit penalty_gwfl
Options: --T, --dt, --mesh, --out, --penalty, --gamma0, --theta-N, --lm-r,
--tag (suffix for the variant names in the outputs), --max-wall (stop a
variant after that many seconds; the summary then reports the steps done),
--log-every, --quiet.  The sensitivity runs of README.md use --mesh with
GetFEM's disc_P2_h4 / disc_P2_h1 meshes and write to
bench/results/getfem_disc/sensitivity/.
Needs python3-getfem (GetFEM 5.4.2), numpy and scipy.

What it writes (in --out, default bench/results/getfem_disc/)
-------------------------------------------------------------
* ``<variant>.csv``: one row per step (t = 0 included): step, t, energy,
  contact_force (brick measure above), balance_force, min_gap (lowest
  GAMMAC displacement dof, y + u_y), active (0/1), centre_y (centre of mass
  height), centre_vy, newton_iters.
* ``summary.csv``: one row per variant run (rows of variants not re-run are
  kept): E(0), E after the first step, E(T), E(T)/E(dt), max E / E(dt),
  min E / E(dt), contact episodes (three definitions), first touch time
  (first active step), largest penetration (max of -(y + u_y) over the GAMMAC
  displacement dofs and steps), number of steps where Newton did not
  converge, steps done, total Newton iterations, wall time of the time loop
  in seconds.
"""

import argparse
import csv
import os
import sys
import time

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

import getfem as gf

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_MESH = os.path.join(HERE, 'disc_P2_h2.mesh')
DEFAULT_OUT = os.path.normpath(os.path.join(HERE, '..', 'results', 'getfem_disc'))

# Demo parameters (2D case).
CLAMBDA = 20.0
CMU = 20.0
VERTICAL_FORCE = 0.1
R_AUG = 10.0           # augmentation parameter of the multiplier brick
GAMMA0_N = 1000.0      # GetFEM >= 2017-11-10 meaning (= demo's 0.001, old meaning)
THETA_N = -1.0
PENALTY_R = 200.0      # = 2 * penalty_coeff of the 5.4.2 demo (100)
BETA = 0.25
GAMMA = 0.5
NITER = 100
RESIDUAL = 1e-8
U_DEGREE = 2
LAMBDA_DEGREE = 1
GAMMAC = 1
LIFT = 5.0

ALL_VARIANTS = ['lm', 'nitsche', 'nitsche_lit', 'penalty', 'penalty_gwfl']
DEFAULT_VARIANTS = ['lm', 'nitsche', 'penalty']

SUMMARY_FIELDS = ['variant', 'contact_method', 'parameter', 'E_t0', 'E_first_step',
                  'E_final', 'ratio_final_initial', 'max_E_over_initial',
                  'min_E_over_initial', 'episodes', 'episodes_tol1e-3W', 'episodes_geometric',
                  'first_touch_time', 'max_penetration', 'newton_not_converged',
                  'steps', 'newton_iters_total', 'wall_time_s']


def spmat_to_scipy(A):
    """Convert a gf.Spmat to scipy CSC."""
    A = gf.Spmat('copy', A)
    A.to_csc()
    jc, ir = A.csc_ind()
    val = A.csc_val()
    n, m = A.size()
    return sp.csc_matrix((val, ir, jc), shape=(n, m))


def count_episodes(flags):
    flags = np.asarray(flags, dtype=bool)
    if flags.size == 0:
        return 0
    starts = flags[1:] & ~flags[:-1]
    return int(starts.sum() + (1 if flags[0] else 0))


def build(mesh_file):
    m = gf.Mesh('load', mesh_file)
    border = m.outer_faces()
    normals = m.normal_of_faces(border)
    contact_boundary = border[:, np.nonzero(normals[1] < -0.01)[0]]
    m.set_region(GAMMAC, contact_boundary)
    return m


def run_variant(variant, args, log):
    dt, T = args.dt, args.T
    nsteps = int(round(T / dt))
    m = build(args.mesh)
    d = m.dim()

    mfu = gf.MeshFem(m, d); mfu.set_classical_fem(U_DEGREE)
    mfd = gf.MeshFem(m, 1); mfd.set_classical_fem(U_DEGREE)
    mflambda = gf.MeshFem(m, 1); mflambda.set_classical_fem(LAMBDA_DEGREE)
    mim = gf.MeshIm(m, 4)
    mim_c = gf.MeshIm(m, gf.Integ('IM_STRUCTURED_COMPOSITE(IM_TRIANGLE(4),4)'))

    nbdofu = mfu.nbdof()
    nbdofd = mfd.nbdof()

    M_gf = gf.asm_mass_matrix(mim, mfu)
    M = spmat_to_scipy(M_gf)
    M_lu = spla.splu(M.tocsc())

    F = np.zeros((d, nbdofd)); F[d - 1, :] = -VERTICAL_FORCE

    md = gf.Model('real')
    md.add_fem_variable('u', mfu)
    md.add_initialized_data('cmu', [CMU])
    md.add_initialized_data('clambda', [CLAMBDA])
    md.add_isotropic_linearized_elasticity_brick(mim, 'u', 'clambda', 'cmu')
    Mexp = gf.Spmat('copy', M_gf)
    Mexp.scale(1.0 / (dt * dt * BETA))
    md.add_explicit_matrix('u', 'u', Mexp)
    ind_rhs = md.add_explicit_rhs('u', np.zeros(nbdofu))
    md.add_initialized_fem_data('volumicload', mfd, F)
    md.add_source_term_brick(mim, 'u', 'volumicload')

    OBS = mfd.eval('y')
    md.add_initialized_fem_data('obstacle', mfd, OBS)
    gap = '(obstacle + u.Normalized(Grad_obstacle))'   # = y + u_y

    if variant == 'lm':
        method, param = 'integral contact brick (Alart-Curnier, option 1)', 'r=%g' % args.lm_r
        ldof = mflambda.basic_dof_on_region(GAMMAC)
        mfl_part = gf.MeshFem('partial', mflambda, ldof)
        md.add_fem_variable('lambda', mfl_part)
        md.add_initialized_data('r', [args.lm_r])
        md.add_integral_contact_with_rigid_obstacle_brick(mim_c, 'u', 'lambda', 'obstacle', 'r',
                                                          GAMMAC, 1)
        force_expr = '-lambda'
    elif variant in ('nitsche', 'nitsche_lit'):
        g0 = args.gamma0 if variant == 'nitsche' else 0.001
        method = 'Nitsche contact brick, theta_N=%g' % args.theta_N
        param = 'gamma0=%g (GetFEM 5.4 meaning: augmentation gamma0/h)' % g0
        md.add_initialized_data('gamma0', [g0])
        expr_N = md.Neumann_term('u', GAMMAC)
        md.add_Nitsche_contact_with_rigid_obstacle_brick(mim_c, 'u', expr_N, 'obstacle', 'gamma0',
                                                         GAMMAC, args.theta_N)
        force_expr = ('neg_part((%s).(-Normalized(Grad_obstacle)) + (gamma0/element_size)*%s)'
                      % (expr_N, gap))
    elif variant == 'penalty':
        method, param = 'penalized contact brick', 'r=%g' % args.penalty
        md.add_initialized_data('r', [args.penalty])
        md.add_penalized_contact_with_rigid_obstacle_brick(mim_c, 'u', 'obstacle', 'r', GAMMAC)
        force_expr = 'r*neg_part(%s)' % gap
    elif variant == 'penalty_gwfl':
        pc = args.penalty / 2.0
        method = 'nonlinear term penalty_coeff*sqr(neg_part(gap)) (5.4.2 demo)'
        param = 'penalty_coeff=%g' % pc
        md.add_initialized_data('penalty_coeff', [pc])
        md.add_nonlinear_term(mim_c, 'penalty_coeff*sqr(neg_part(%s))' % gap, GAMMAC)
        force_expr = '2*penalty_coeff*neg_part(%s)' % gap
    else:
        raise ValueError(variant)

    def contact_force():
        return float(gf.asm_generic(mim_c, 0, force_expr, GAMMAC, md))

    # Initial state (as in the demo).
    U0 = np.zeros(nbdofu); U0[d - 1::d] = LIFT
    MU0 = M @ U0
    MV0 = np.zeros(nbdofu)
    FF = gf.asm_volumic_source(mim, mfu, mfd, F)
    K = spmat_to_scipy(gf.asm_linear_elasticity(mim, mfu, mfd, np.full(nbdofd, CLAMBDA),
                                                np.full(nbdofd, CMU)))
    MA0 = FF - K @ U0
    weight = -FF[d - 1::d].sum()
    mass = (M @ np.ones(nbdofu))[d - 1::d].sum()
    tol_active = 1e-8 * weight
    tol_loose = 1e-3 * weight

    cdofs = mfu.basic_dof_on_region(GAMMAC)
    cdofs_y = cdofs[(cdofs % d) == d - 1]
    ynodes = mfu.basic_dof_nodes()[d - 1][cdofs_y]

    md.set_variable('u', U0)
    E0 = float((U0 @ (K @ U0)) / 2 - FF @ U0)
    rows = [dict(step=0, t=0.0, energy=E0, contact_force=0.0, balance_force=0.0,
                 min_gap=float((ynodes + U0[cdofs_y]).min()), active=0,
                 centre_y=20.0 + (MU0[d - 1::d].sum()) / mass, centre_vy=0.0, newton_iters=0)]
    not_conv = 0
    t_start = time.time()
    for n in range(1, nsteps + 1):
        t = n * dt
        LL = (MU0 + dt * MV0 + dt * dt * (0.5 - BETA) * MA0) / (BETA * dt * dt)
        md.set_private_rhs(ind_rhs, LL)
        res = md.solve('max_res', RESIDUAL, 'max_iter', NITER)
        if isinstance(res, (tuple, list)):
            nbit, conv = int(res[0]), bool(res[1])
        else:
            nbit, conv = int(res), True
        if not conv:
            not_conv += 1
        U1 = np.asarray(md.variable('u')).copy()
        MU1 = M @ U1
        MA1 = (MU1 - MU0 - dt * MV0 - dt * dt * (0.5 - BETA) * MA0) / (dt * dt * BETA)
        MV1 = MV0 + dt * (GAMMA * MA1 + (1 - GAMMA) * MA0)
        V1 = M_lu.solve(MV1)
        E = float((V1 @ MV1 + U1 @ (K @ U1)) / 2 - FF @ U1)
        fc = contact_force()
        fbal = float((MA1 - FF + K @ U1)[d - 1::d].sum())
        rows.append(dict(step=n, t=t, energy=E, contact_force=fc, balance_force=fbal,
                         min_gap=float((ynodes + U1[cdofs_y]).min()),
                         active=int(fc > tol_active),
                         centre_y=20.0 + MU1[d - 1::d].sum() / mass,
                         centre_vy=MV1[d - 1::d].sum() / mass, newton_iters=nbit))
        if not args.quiet and (n % args.log_every == 0 or n == nsteps):
            log('  %-12s t=%6.2f E=%.6f Fc=%.4g min_gap=%.4g it=%d' %
                (variant, t, E, fc, rows[-1]['min_gap'], nbit))
        U0, MU0, MV0, MA0 = U1, MU1, MV1, MA1
        if args.max_wall and time.time() - t_start > args.max_wall:
            log('  %s: stopped at t=%.2f, wall-time limit %g s reached' % (variant, t, args.max_wall))
            break
    wall = time.time() - t_start

    fcs = np.array([r['contact_force'] for r in rows[1:]])
    gaps = np.array([r['min_gap'] for r in rows[1:]])
    Es = np.array([r['energy'] for r in rows])
    act = fcs > tol_active
    E_ref = Es[1]
    first = np.nonzero(act)[0]
    summ = dict(variant=variant + args.tag, contact_method=method, parameter=param,
                E_t0='%.10g' % E0, E_first_step='%.10g' % E_ref, E_final='%.10g' % Es[-1],
                ratio_final_initial='%.8g' % (Es[-1] / E_ref),
                max_E_over_initial='%.8g' % (Es.max() / E_ref),
                min_E_over_initial='%.8g' % (Es.min() / E_ref),
                episodes=count_episodes(act),
                **{'episodes_tol1e-3W': count_episodes(fcs > tol_loose)},
                episodes_geometric=count_episodes(gaps < 0),
                first_touch_time=('%.2f' % rows[first[0] + 1]['t']) if first.size else '',
                max_penetration='%.4g' % max(0.0, -gaps.min()),
                newton_not_converged=not_conv, steps=len(rows) - 1, newton_iters_total=sum(r['newton_iters'] for r in rows),
                wall_time_s='%.1f' % wall)
    info = dict(nodes=m.nbpts(), elements=m.nbcvs(), nbdofu=nbdofu, weight=weight, mass=mass,
                contact_faces=len(m.region(GAMMAC)[0]))
    return rows, summ, info


def write_csv(path, fields, rows):
    with open(path, 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=fields, restval='', extrasaction='ignore')
        w.writeheader()
        for r in rows:
            w.writerow(r)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--variants', nargs='+', default=DEFAULT_VARIANTS, choices=ALL_VARIANTS)
    ap.add_argument('--mesh', default=DEFAULT_MESH)
    ap.add_argument('--out', default=DEFAULT_OUT)
    ap.add_argument('--dt', type=float, default=0.01)
    ap.add_argument('--T', type=float, default=40.0)
    ap.add_argument('--penalty', type=float, default=PENALTY_R,
                    help='penalty r of the penalized brick (pressure = r * penetration)')
    ap.add_argument('--gamma0', type=float, default=GAMMA0_N,
                    help='gamma0 of the nitsche variant (GetFEM 5.4 meaning)')
    ap.add_argument('--theta-N', dest='theta_N', type=float, default=THETA_N,
                    help='theta of the Nitsche variants')
    ap.add_argument('--lm-r', dest='lm_r', type=float, default=R_AUG,
                    help='augmentation r of the multiplier brick')
    ap.add_argument('--tag', default='',
                    help='suffix appended to the variant names in the outputs')
    ap.add_argument('--max-wall', dest='max_wall', type=float, default=0.0,
                    help='stop a variant after this many seconds (0: no limit); the summary '
                         'then reports the steps done and E_final is at the last step')
    ap.add_argument('--log-every', dest='log_every', type=int, default=500)
    ap.add_argument('--quiet', action='store_true')
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    gf.util_trace_level(0)

    def log(s):
        print(s, flush=True)

    summ_path = os.path.join(args.out, 'summary.csv')
    old = {}
    if os.path.exists(summ_path):
        with open(summ_path) as f:
            for r in csv.DictReader(f):
                old[r['variant']] = r
    for v in args.variants:
        log('variant %s' % v)
        rows, summ, info = run_variant(v, args, log)
        log('  mesh: %(nodes)d nodes, %(elements)d elements, %(contact_faces)d contact faces, '
            '%(nbdofu)d u dofs, mass %(mass).4f, weight %(weight).4f' % info)
        log('  ' + ', '.join('%s=%s' % (k, summ[k]) for k in SUMMARY_FIELDS[3:]))
        write_csv(os.path.join(args.out, v + args.tag + '.csv'),
                  ['step', 't', 'energy', 'contact_force', 'balance_force', 'min_gap', 'active',
                   'centre_y', 'centre_vy', 'newton_iters'],
                  [{k: (('%.10g' % x) if isinstance(x, float) else x) for k, x in r.items()}
                   for r in rows])
        old[v + args.tag] = summ
        write_csv(summ_path, SUMMARY_FIELDS, [old[x] for x in old])


if __name__ == '__main__':
    main()
