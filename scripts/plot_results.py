#!/usr/bin/python3
"""Plot dyncontact runs against their exact, Hertz and finite-sphere references.

Usage: plot_results.py RUN_DIR [RUN_DIR ...] [--output DIR] [--labels L1 L2 ...] [--tmin T] [--tmax T]
                       [--magnify M] [--zscale S] [--data]

Each RUN_DIR holds history.csv and optionally exact.csv (bars), hertz.csv, finite_sphere.csv and
their *_parameters.csv (head-on sphere impacts), profile_t<T>.csv, contact_pressure_t<T>.csv,
cells.csv and parameters.prm. Profiles are taken only at the run's own profile times, read from its
parameters.prm, so that files another run left in the directory are not drawn. Every figure has a
panel per run side by side; the time histories are zoomed on the run's contact interval (the
references' or the FE's, whichever is longer, plus 30 % on each side) unless --tmin or --tmax
choose the window. The paths of the figures written are printed.

Every run:
  - tip_velocity.png, tip_acceleration.png: the monitor node of every body (history v_tip_<b>,
    a_tip_<b>; the monitor point of parameters.prm is in the legend), with the exact solution
    where there is one;
  - contact_force.png (unless no run has a contact force or a reference): the total contact force
    against the exact solution (bars) or against Hertz and the finite-sphere law (hertz.csv,
    finite_sphere.csv; their peaks from *_parameters.csv in the legend), with a second row
    FE - reference in per cent of Hertz's peak force;
  - energy.png: kinetic, strain, physical (kinetic + strain) and algorithmic energy, and a second
    row (E - E0)/E0 of the physical and the algorithmic energy, in %, ppm or as a plain ratio
    (stated on the axis), so that the energy error is visible;
  - tip_displacement.png: every run but those with hertz.csv whose monitor nodes touch each other
    during the contact (the contact poles of the shipped sphere files: flat lines; a note says so).
Head-on sphere impacts (hertz.csv):
  - approach.png: the approach of the bodies' centres of mass against Hertz's and the
    finite-sphere law's (the approach column of hertz.csv and finite_sphere.csv: the change of the
    distance of the centres, minus the initial gap; negative before the touch), and a second row
    FE - reference in per cent of Hertz's maximum approach. The FE centre of mass of body b moves
    with momentum_<b> / m_b, integrated in time by the trapezoidal rule (Newmark's exactly for
    gamma = 1/2, beta = 1/4; within dt^2 |beta - 1/4| max|a| for other beta); m_b = momentum_<b> /
    v_tip_<b> at t = 0 (uniform initial velocities), checked against the effective mass of
    hertz_parameters.csv;
  - contact_pressure.png (contact_pressure_t<T>.csv): the recovered pressure of every pair (filled
    markers active, hollow inactive) at each profile time with contact, against Hertz's
    p(r) = p0 sqrt(1 - r^2/a^2), a = sqrt(R* d), p0 = 3 F / (2 pi a^2), with F(T), d(T) from
    hertz.csv. A negative recovered pressure at an active pair is explained in a note: the
    pressure is recovered from the pairs' nodal forces by the consistent surface mass matrix of the
    contact zone's Q2 faces, which undershoots where the pressure drops to zero inside an element
    (node-to-node and node-to-segment pairs; a mortar pair's pressure lambda_j / D_j has the sign
    of its force);
  - deformed_contact_t<T>.png for every profile time T at which pairs are active (needs cells.csv):
    left, the deformed cells of the bodies near the contact, r within 3 contact radii (the larger
    of Hertz's and the FE's), mirrored about the axis, with z drawn S times enlarged about the
    contact plane (S: the window drawn half as high as wide, or --zscale), the axes in true
    coordinates: bodies that do not overlap are drawn without overlap, a flat zone is drawn flat.
    Dashed: each body's undeformed surface moved with its centre of mass, which the flattening
    removed where the dashed outlines overlap. Right, the deformed surface z(r) - z(0) of each body
    against Hertz's (each body taking its share (1 - nu^2)/E of Hertz's displacements).
Bars (profile_t<T>.csv with columns body, x, u, v, a):
  - profile_t<T>.png: displacement, velocity and stress along the bars at every profile time,
    against the exact wave solution (computed here by the algorithm of the run's own exact.csv,
    source/reference/exact_bar_solution.cc, from the bars of parameters.prm).
Other mesh runs:
  - deformed_mesh_t<T>.png at profile times without contact: the deformed cells, full section,
    each body's displacement relative to a reference displacement magnified by M (--magnify;
    default: chosen so that the largest such displacement is 5 % of the bodies' size and no cell
    edge is stretched or shortened by more than 30 %), the undeformed boundary dashed. With other
    bodies the reference is the displacement of the body's node nearest them, so that bodies in
    contact stay touching; one body: its rigid axial translation.

--data writes beside every PNG a CSV of the numbers drawn (columns panel, quantity, series, x, y;
the y values in the unit of the axis, the unit's factor in a series 'unit factor').
"""
import argparse
import bisect
import csv
import heapq
import math
import os
import re
import sys
import textwrap

import matplotlib
matplotlib.use('Agg')
import matplotlib.collections  # noqa: E402  (backend must be chosen first)
import matplotlib.lines  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

FE_COLOURS = ['tab:blue', 'tab:orange', 'tab:green', 'tab:purple', 'tab:brown']
EXACT_COLOURS = ['black', 'darkred', 'darkgreen', 'indigo', 'saddlebrown']
HERTZ_COLOUR, FINITE_COLOUR = 'tab:red', 'black'
SPAN_RATIO = 10.0  # y-ranges differing by more than this get independent limits
CONTACT_MARGIN = 0.3  # zoomed time histories: margin on each side, fraction of the contact interval
PRESSURE_RANGE = 1.5  # pressure plots: r up to this multiple of the largest Hertz contact radius
CONTACT_WINDOW = 3.0  # deformed contact: r within this many contact radii
CONTACT_ASPECT = 0.5  # deformed contact: height / width of the drawn window
MESH_MAGNIFIED = 0.05  # deformed mesh: default largest magnified displacement / size of the bodies
MESH_STRAIN = 0.3  # deformed mesh: default largest magnified strain of a cell edge
MASS_TOLERANCE = 1e-3  # masses from momentum / velocity against hertz_parameters' effective mass
CELL_NODES = [f'node_{i}' for i in range(8)]
MARKERS = ['o', 's', 'D', '^', 'v', 'P', 'X']  # one per profile time in the pressure plots


class InputError(Exception):
    """A missing or malformed input file, reported without a traceback."""


# ---------------------------------------------------------------------------------------------
# Input

def read_csv(path, required=('time',)):
    """Read a numeric CSV with a header line into a dict column name -> float array.

    Blank lines, '#' comment lines and a trailing comma are tolerated; non-finite
    values (diverged runs) become NaN so that they leave gaps in the plots. The columns
    `required` must be present.
    """
    names, rows = None, []
    try:
        with open(path, newline='') as f:
            reader = csv.reader(f)
            for row in reader:
                row = [field.strip() for field in row]
                if row and row[-1] == '':
                    row.pop()
                if not row or row[0].startswith('#'):
                    continue
                if names is None:
                    names = row
                    continue
                if len(row) != len(names):
                    raise InputError(f'{path}, line {reader.line_num}: {len(row)} fields, '
                                     f'but the header has {len(names)}')
                try:
                    rows.append([float(x) for x in row])
                except ValueError as e:
                    raise InputError(f'{path}, line {reader.line_num}: {e}') from None
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise InputError(f'cannot read {path}: {e}') from None
    if names is None or not rows:
        raise InputError(f'{path}: no header line or no data rows')
    missing = [name for name in required if name not in names]
    if missing:
        raise InputError(f'{path}: header lacks the column(s) ' + ', '.join(missing))
    if len(set(names)) != len(names):
        raise InputError(f'{path}: header repeats a column name')
    data = np.array(rows)
    data[~np.isfinite(data)] = np.nan
    return dict(zip(names, data.T))


def read_quantities(path):
    """The 'quantity,value' rows of a *_parameters.csv as a dict; empty if there is no file."""
    if not os.path.isfile(path):
        return {}
    values = {}
    try:
        with open(path, newline='') as f:
            for row in csv.DictReader(f):
                values[row['quantity']] = float(row['value'])
    except (OSError, UnicodeDecodeError, ValueError, TypeError, KeyError, csv.Error) as e:
        raise InputError(f'cannot read {path}: {e}') from None
    return values


def read_parameters(run_dir):
    """The entries of parameters.prm as a dict 'section/subsection/entry' (lower case) -> value;
    empty if the file is missing or unreadable."""
    sections, entries = [], {}
    try:
        with open(os.path.join(run_dir, 'parameters.prm')) as f:
            for line in f:
                line = line.split('#')[0]
                words = line.split()
                if words[:1] == ['subsection']:
                    sections.append(' '.join(words[1:]).lower())
                elif words[:1] == ['end'] and sections:
                    sections.pop()
                elif words[:1] == ['set'] and '=' in line:
                    name, value = line.split('=', 1)
                    name = ' '.join(name.split()[1:]).lower()
                    entries['/'.join(sections + [name])] = value.strip()
    except (OSError, UnicodeDecodeError):
        pass
    return entries


def clip(table, window):
    """The rows of `table` with window[0] <= time <= window[1] (all of it if window is None)."""
    if not table or window is None:
        return table
    keep = (table['time'] >= window[0]) & (table['time'] <= window[1])
    return {name: values[keep] for name, values in table.items()}


def load_run(run_dir, tmax):
    """history.csv (required), exact.csv, hertz.csv, finite_sphere.csv (optional, clipped to
    t <= tmax), the reference constants and parameters.prm of a run."""
    history = os.path.join(run_dir, 'history.csv')
    if not os.path.isfile(history):
        raise InputError(f'{history}: no such file (is {run_dir} a run directory?)')
    run = {'dir': run_dir}
    for key in ('history', 'exact', 'hertz', 'finite_sphere'):
        path = os.path.join(run_dir, key + '.csv')
        table = read_csv(path) if os.path.isfile(path) else {}
        if table and tmax is not None:
            table = clip(table, (-np.inf, tmax))
        run[key] = table
    for key in ('hertz', 'finite_sphere'):
        missing = [c for c in ('contact_force', 'approach') if run[key] and c not in run[key]]
        if missing:
            raise InputError(f'{os.path.join(run_dir, key + ".csv")}: header lacks the column(s) '
                             + ', '.join(missing))
    for key in ('hertz', 'finite_sphere'):
        run[key + '_parameters'] = read_quantities(os.path.join(run_dir, key + '_parameters.csv'))
    run['prm'] = read_parameters(run_dir)
    return run


def bodies_of(table, prefix):
    """The body numbers b of the columns <prefix>_<b> of a table, sorted."""
    return sorted(int(m.group(1)) for m in (re.fullmatch(prefix + r'_(\d+)', c) for c in table) if m)


# ---------------------------------------------------------------------------------------------
# Labels

def run_label(run_dir):
    """Label a run by its contact dynamics in parameters.prm (none: the classical Newmark,
    taylor-papadopoulos: the paper's modified Newmark; another integrator in place of Newmark),
    falling back to the directory name."""
    prm = read_parameters(run_dir)
    dynamics = prm.get('contact/dynamics')
    integrator = prm.get('time integration/integrator', 'newmark')
    scheme = 'Newmark' if integrator == 'newmark' else integrator
    names = {'none': f'classical {scheme}', 'taylor-papadopoulos': f'modified {scheme}'}
    if dynamics is None:
        return os.path.basename(os.path.normpath(run_dir))
    return names.get(dynamics, dynamics)


def coordinate_names(run_dirs):
    """The names of the mesh coordinates in the plots' labels: (x, y) if every run is plane strain
    (its x = 0 the symmetry plane of a half model), else the axisymmetric (r, z)."""
    plane = all(read_parameters(d).get('problem/geometry') == 'plane strain mesh' for d in run_dirs)
    return ('x', 'y') if plane and run_dirs else ('r', 'z')


def sphere_label(run_dir, label):
    """Panel title of a mesh run: the scheme and the run's own label (--labels entry or
    directory name), the latter left out if it only repeats the scheme."""
    scheme = run_label(run_dir)
    if label in (scheme, scheme.split()[0]):
        return scheme
    return f'{scheme} ({label})'


def case_description(run_dirs):
    """Short description of the runs' case for the figure titles, from parameters.prm (material
    data of the bodies or bars; differing runs are listed one after the other)."""
    cases = []
    for run_dir in run_dirs:
        prm = read_parameters(run_dir)
        sphere = os.path.isfile(os.path.join(run_dir, 'hertz.csv'))
        mesh = sphere or os.path.isfile(os.path.join(run_dir, 'cells.csv'))
        props = []
        for symbol, entry in (('ρ', 'density'), ('E', "young's modulus"), ('ν', "poisson's ratio")):
            values = []
            for body in range(1, 101):
                value = prm.get(f'bodies/body {body}/{entry}' if mesh
                                else f'geometry/bar {body}/{entry}')
                if value is None:
                    break
                if value not in values:
                    values.append(value)
            if values:
                props.append(f'{symbol}\u00a0=\u00a0{"/".join(values)}')  # no line break
        mesh_file = os.path.basename(prm.get('mesh/file', ''))
        if sphere:
            name = ('sphere impact' if os.path.isfile(os.path.join(run_dir, 'finite_sphere.csv'))
                    else 'head-on impact') + (f', {mesh_file}' if mesh_file else '')
        elif mesh:
            name = ('plane strain bodies' if prm.get('problem/geometry') == 'plane strain mesh'
                    else 'axisymmetric bodies') + (f', {mesh_file}' if mesh_file else '')
        elif prm.get('problem/geometry') == 'bars' or 'geometry/number of bars' in prm:
            name = 'bars' + (' on a rigid wall' if prm.get('geometry/rigid wall/enabled') == 'true'
                             else '')
        else:
            name = ''
        case = name + (f' ({", ".join(props)})' if props else '')
        if case and case not in cases:
            cases.append(case)
    return '; '.join(cases)


def monitor_description(run, body):
    """', monitor point (r, z)' of a mesh body from parameters.prm, or ''."""
    point = run['prm'].get(f'bodies/body {body}/monitor point')
    return f' at ({point})' if point else ''


def wrap_title(title, width):
    """Break the lines of a figure title longer than a figure `width` inches wide can hold."""
    return '\n'.join(textwrap.fill(line, int(10 * width)) for line in title.split('\n'))


def nice(value, digits=4):
    """A number for a legend: `digits` significant digits, no trailing zeros, no '-0'."""
    return f'{round(value, digits - 1 - int(math.floor(math.log10(abs(value))))) + 0:g}' \
        if value and np.isfinite(value) else f'{value:g}'


# ---------------------------------------------------------------------------------------------
# Data written beside the figures (--data)

class DataSheet:
    """The numbers of one figure: rows panel, quantity, series, x, y; written as CSV if enabled."""

    def __init__(self, enabled):
        self.enabled = enabled
        self.rows = []

    def add(self, panel, quantity, series, x, y):
        if not self.enabled:
            return
        x, y = np.broadcast_arrays(np.atleast_1d(np.asarray(x, float)),
                                   np.atleast_1d(np.asarray(y, float)))
        series = series.lstrip('_')  # matplotlib's mark of a series left out of the legend
        self.rows.extend((panel, quantity, series, a, b) for a, b in zip(x, y))

    def write(self, png_path):
        if not self.enabled:
            return
        with open(os.path.splitext(png_path)[0] + '.csv', 'w', newline='') as f:
            writer = csv.writer(f)
            writer.writerow(['panel', 'quantity', 'series', 'x', 'y'])
            for panel, quantity, series, x, y in self.rows:
                writer.writerow([panel, quantity, series, repr(float(x)), repr(float(y))])


# ---------------------------------------------------------------------------------------------
# Time windows

def contact_interval(time, force):
    """(last sample before, first sample after) the samples with a positive force, or None.
    Forces below 1e-9 of the largest count as zero."""
    positive = np.nan_to_num(force) > 1e-9 * np.nanmax(np.abs(force), initial=0)
    if not positive.any():
        return None
    first, last = np.flatnonzero(positive)[[0, -1]]
    return time[max(first - 1, 0)], time[min(last + 1, len(time) - 1)]


def contact_window(run):
    """Time window of the time-history plots: the contact interval of the references (Hertz, the
    finite-sphere law, the exact solution) or of the FE, whichever reaches further, plus
    CONTACT_MARGIN of its length on each side; None for runs without contact."""
    intervals = []
    for key in ('hertz', 'finite_sphere', 'exact', 'history'):
        table = run[key]
        if 'contact_force' in table:
            intervals.append(contact_interval(table['time'], table['contact_force']))
    intervals = [i for i in intervals if i is not None]
    if not intervals:
        return None
    start, end = min(i[0] for i in intervals), max(i[1] for i in intervals)
    margin = CONTACT_MARGIN * (end - start)
    return start - margin, end + margin


def zoom(run, window):
    """The run with its tables clipped to `window` (unchanged if window is None)."""
    return {key: clip(value, window) if key in ('history', 'exact', 'hertz', 'finite_sphere')
            else value for key, value in run.items()}


# ---------------------------------------------------------------------------------------------
# Curves: (x, y, style); style['label'] names the series in the legend and in the data

def fe_curve(t, y, label, colour):
    """FE solution: thin line with markers on every k-th step (k odd, so that markers
    do not alias with a period-2 ringing and sit on alternate extremes)."""
    return t, y, dict(label=label, color=colour, lw=1.0, marker='o', ms=3,
                      markevery=(len(t) // 60) | 1)


def reference_curve(t, y, label, colour, steps=False, ls='-', lw=1.6):
    """Reference (exact, Hertz, finite-sphere) solution: thicker line drawn on top of the FE."""
    return t, y, dict(label=label, color=colour, lw=lw, ls=ls, zorder=3,
                      drawstyle='steps-post' if steps else 'default')


def tip_curves(run, prefix, steps):
    """FE and exact curves of tip quantity `prefix` ('v_tip', ...) for every body."""
    history, exact = run['history'], run['exact']
    bodies = bodies_of(history, prefix)
    curves = []
    for i, body in enumerate(bodies):
        suffix = f', body {body}' if len(bodies) > 1 else ''
        column = f'{prefix}_{body}'
        curves.append(fe_curve(history['time'], history[column],
                               'FE' + suffix + monitor_description(run, body),
                               FE_COLOURS[i % len(FE_COLOURS)]))
        if column in exact:
            curves.append(reference_curve(exact['time'], exact[column], 'exact' + suffix,
                                          EXACT_COLOURS[i % len(EXACT_COLOURS)], steps))
    return curves


def peak_text(t, y):
    """', peak Y at t = T' of a curve (its largest value)."""
    if not np.isfinite(y).any():
        return ''
    i = int(np.nanargmax(y))
    return f', peak {nice(y[i])} at t = {nice(t[i], 6)}'


def force_curves(run):
    """FE contact force with the exact, Hertz and finite-sphere references where available."""
    history, exact = run['history'], run['exact']
    curves = []
    if 'contact_force' in history:
        t, f = history['time'], history['contact_force']
        curves.append(fe_curve(t, f, 'FE' + (peak_text(t, f) if run['hertz'] else ''),
                               FE_COLOURS[0]))
    if 'contact_force' in exact:
        curves.append(reference_curve(exact['time'], exact['contact_force'], 'exact', 'black', True))
    for key, name, colour, ls in (('hertz', 'Hertz', HERTZ_COLOUR, '--'),
                                  ('finite_sphere', 'finite-sphere law', FINITE_COLOUR, ':')):
        table = run[key]
        if 'contact_force' in table:
            # The law's own peak (*_parameters.csv), which may fall between the samples.
            peak = run[key + '_parameters'].get('peak_force')
            text = f', peak {nice(peak)}' if peak else peak_text(table['time'], table['contact_force'])
            curves.append(reference_curve(table['time'], table['contact_force'], name + text,
                                          colour, ls=ls))
    return curves


def difference_curves(t, y, run, column, scale):
    """(FE - reference) / scale in per cent for the Hertz and finite-sphere references."""
    curves = []
    for key, name, colour, ls in (('hertz', 'FE − Hertz', HERTZ_COLOUR, '--'),
                                  ('finite_sphere', 'FE − finite-sphere law', FINITE_COLOUR, '-')):
        table = run[key]
        if column in table and len(table['time']) and len(t):
            reference = np.interp(t, table['time'], table[column])
            difference = 100 * (y - reference) / scale
            extreme = difference[np.nanargmax(np.abs(difference))] if np.isfinite(difference).any() \
                else np.nan
            at_peak = difference[np.nanargmax(y)] if np.isfinite(y).any() else np.nan
            curves.append(reference_curve(t, difference,
                                          f'{name}: {nice(at_peak, 3)} % at the FE peak, largest '
                                          f'{nice(extreme, 3)} %', colour, ls=ls, lw=1.2))
    return curves


def energy_curves(run):
    """FE kinetic, strain, physical (kinetic + strain) and algorithmic energies, exact total."""
    history = run['history']
    curves = []
    for i, (column, name) in enumerate((('kinetic_energy', 'kinetic'),
                                        ('strain_energy', 'strain'),
                                        ('total_energy', 'physical (kinetic + strain)'))):
        if column in history:
            curves.append(fe_curve(history['time'], history[column], name, FE_COLOURS[i]))
    if 'algorithmic_energy' in history:
        curves.append(reference_curve(history['time'], history['algorithmic_energy'], 'algorithmic',
                                      FE_COLOURS[3], ls='--', lw=1.2))
    if 'total_energy' in run['exact']:
        curves.append(reference_curve(run['exact']['time'], run['exact']['total_energy'],
                                      'exact total', 'black', ls=':'))
    return curves


ENERGY_UNITS = ((10.0, 1.0, '(E − E0)/E0'), (1e-3, 1e2, '(E − E0)/E0 [%]'),
                (0.0, 1e6, '(E − E0)/E0 [ppm]'))


def energy_unit(largest):
    """(factor, axis label) for relative energy changes up to `largest` in magnitude: a plain
    ratio from 10 on, per cent from 1e-3, else parts per million."""
    for bound, factor, label in ENERGY_UNITS:
        if largest >= bound:
            return factor, label
    return ENERGY_UNITS[-1][1:]


def does_external_work(history):
    """Whether loads (tractions, body forces) did work in the run: its external_work column."""
    return 'external_work' in history and np.nanmax(np.abs(history['external_work']),
                                                     initial=0) > 0


def energy_error_curves(full_history, history):
    """(E - E0)/E0 of the physical and algorithmic energy, E0 the first row of the whole run; with
    external work W (does_external_work()) the energy guard's balance (E - E0 - W)/E_ref instead,
    E_ref the largest of |E0| and |W| over the run (E0 is zero for a body at rest under gravity).
    Returns the curves in relative units."""
    curves = []
    work = full_history['external_work'] if does_external_work(full_history) else None
    same = ('algorithmic_energy' in history and 'total_energy' in history and
            np.allclose(history['algorithmic_energy'], history['total_energy'],
                        rtol=1e-12, atol=0, equal_nan=True))
    for column, name, colour, style in (
            ('total_energy', 'physical (kinetic + strain)', FE_COLOURS[2], dict(lw=2.4)),
            ('algorithmic_energy', 'algorithmic' + (' (= physical here)' if same else ''),
             FE_COLOURS[3], dict(lw=1.2, ls='--'))):
        if column in history:
            e0 = full_history[column][0]
            if work is not None:
                scale = max(abs(e0), np.nanmax(np.abs(work)))
                relative = (history[column] - e0 - history['external_work']) / scale
            else:
                relative = ((history[column] - e0) / abs(e0) if e0
                            else np.full_like(history[column], np.nan))
            curves.append((history['time'], relative,
                           dict(label=name, color=colour, zorder=3, **style)))
    return curves


# ---------------------------------------------------------------------------------------------
# Centres of mass and the approach

def body_masses(run):
    """{body: mass} from momentum_<b> / v_tip_<b> at the first row (uniform initial velocity),
    a body at rest getting its mass from hertz_parameters' effective mass; checked against that
    effective mass (1/m* = sum of 1/m_b over the two bodies, m* = m_1 against a rigid plane).
    Returns (masses, None) or (None, reason)."""
    history = run['history']
    bodies = bodies_of(history, 'momentum')
    if not bodies or len(bodies) > 2:
        return None, f'{len(bodies)} bodies: which bodies meet is not known'
    masses = {}
    for body in bodies:
        p0, v0 = history[f'momentum_{body}'][0], history.get(f'v_tip_{body}', [np.nan])[0]
        if np.isfinite(v0) and v0 != 0 and np.isfinite(p0):
            masses[body] = p0 / v0
    effective = run['hertz_parameters'].get('effective_mass')
    unknown = [b for b in bodies if b not in masses]
    if unknown and effective:
        if len(bodies) == 1:
            masses[bodies[0]] = effective
        elif len(unknown) == 1:
            other = masses[[b for b in bodies if b != unknown[0]][0]]
            masses[unknown[0]] = 1 / (1 / effective - 1 / other)
    if len(masses) != len(bodies) or not all(m > 0 for m in masses.values()):
        return None, 'the body masses are not known (no initial velocity at the monitor nodes)'
    if effective:
        computed = 1 / sum(1 / m for m in masses.values())
        if abs(computed / effective - 1) > MASS_TOLERANCE:
            return None, (f'masses from momentum / velocity give m* = {computed:.6g}, '
                          f'not {effective:.6g} (hertz_parameters.csv): non-uniform initial velocity?')
    return masses, None


def centre_displacements(run):
    """{body: axial displacement of its centre of mass at every row of history.csv}: the mean
    velocity momentum_<b> / m_b integrated by the trapezoidal rule. (None, reason) if unknown."""
    masses, reason = body_masses(run)
    if masses is None:
        return None, reason
    history = run['history']
    t = history['time']
    displacements = {}
    for body, mass in masses.items():
        v = history[f'momentum_{body}'] / mass
        displacements[body] = np.concatenate([[0.0], np.cumsum(np.diff(t) * (v[1:] + v[:-1]) / 2)])
    return displacements, None


def fe_approach(run):
    """(time, approach of the centres of mass), in the convention of hertz.csv's approach column
    (change of the distance of the centres toward each other, minus the initial gap), or
    (None, reason). The direction is that in which the bodies first approach each other."""
    hertz, history = run['hertz'], run['history']
    if 'approach' not in hertz:
        return None, 'no hertz.csv'
    displacements, reason = centre_displacements(run)
    if displacements is None:
        return None, reason
    bodies = sorted(displacements)
    masses, _ = body_masses(run)
    velocity = [history[f'momentum_{b}'][0] / masses[b] for b in bodies]
    relative = displacements[bodies[0]] - (displacements[bodies[1]] if len(bodies) > 1 else 0)
    closing = velocity[0] - (velocity[1] if len(bodies) > 1 else 0)
    if not closing:
        return None, 'the bodies do not approach each other at the start'
    t = history['time']
    start = np.interp(t[0], hertz['time'], hertz['approach'])
    return (t, np.sign(closing) * relative + start), None


def monitors_touch(run):
    """Whether the monitor nodes of a run with hertz.csv keep touching each other (or the rigid
    plane) while the FE contact force is positive: their approach, in the convention of hertz.csv,
    stays within 1e-3 of Hertz's maximum approach of zero. Their displacements are then flat
    lines (the contact poles of the shipped sphere files)."""
    history, hertz = run['history'], run['hertz']
    if 'approach' not in hertz or 'contact_force' not in history:
        return False
    bodies = bodies_of(history, 'u_tip')
    if not 1 <= len(bodies) <= 2 or any(f'v_tip_{b}' not in history for b in bodies):
        return False
    closing = history[f'v_tip_{bodies[0]}'][0] - (history[f'v_tip_{bodies[1]}'][0]
                                                 if len(bodies) > 1 else 0)
    contact = np.nan_to_num(history['contact_force']) > 0
    scale = np.nanmax(hertz['approach'])
    if not (closing and contact.any() and scale > 0):
        return False
    relative = history[f'u_tip_{bodies[0]}'] - (history[f'u_tip_{bodies[1]}']
                                                if len(bodies) > 1 else 0)
    start = np.interp(history['time'][0], hertz['time'], hertz['approach'])
    monitor_approach = np.sign(closing) * (relative - relative[0]) + start
    return bool(np.nanmax(np.abs(monitor_approach[contact])) <= 1e-3 * scale)


def approach_curves(run, full):
    """FE approach of the centres of mass, Hertz's and the finite-sphere law's."""
    curves = []
    approach, reason = fe_approach(full)
    if approach is not None:
        t, d = approach
        keep = np.isin(t, run['history']['time'])
        maximum = peak_text(t, d).replace('peak', 'max')
        curves.append(fe_curve(t[keep], d[keep], 'FE, centres of mass' + maximum,
                               FE_COLOURS[0]))
    for key, name, colour, ls in (('hertz', 'Hertz', HERTZ_COLOUR, '--'),
                                  ('finite_sphere', 'finite-sphere law', FINITE_COLOUR, ':')):
        table = run[key]
        if 'approach' in table:
            curves.append(reference_curve(table['time'], table['approach'],
                                          name + peak_text(table['time'], table['approach'])
                                          .replace('peak', 'max'), colour, ls=ls))
    return curves, reason


# ---------------------------------------------------------------------------------------------
# Figures of time histories

def shared_limits(panels):
    """Whether the panels' y-data ranges are within SPAN_RATIO of each other."""
    values = [np.concatenate([np.asarray(y, float) for _, y, _ in curves] + [np.empty(0)])
              for curves in panels]
    spans = [np.ptp(v[np.isfinite(v)]) for v in values if np.isfinite(v).any()]
    spans = [s for s in spans if s > 0]
    return not (len(spans) > 1 and max(spans) > SPAN_RATIO * min(spans))


def plot_rows(path, title, rows, labels, data, notes=None):
    """One figure, a column per run and a row per entry of `rows` = (quantity, y label or a label
    per panel, curves per panel[, independent]). A row's panels share their y-limits unless their
    data ranges differ by more than SPAN_RATIO or `independent` is true (the title says so).
    `notes[row][panel]` is a text drawn in a panel. Returns False (writing nothing) if there is no curve at all."""
    if not any(any(row[2]) for row in rows):
        return False
    n_runs = len(labels)
    heights = [1.0] + [0.6] * (len(rows) - 1)
    fig, axes = plt.subplots(len(rows), n_runs, figsize=(5 * n_runs, 3.8 + 2.4 * (len(rows) - 1)),
                             squeeze=False, sharex='col',
                             gridspec_kw=dict(height_ratios=heights))
    independent_rows = []
    for r, (quantity, ylabel, panels, *forced) in enumerate(rows):
        shared = shared_limits(panels) and not (forced and forced[0])
        if not shared:
            independent_rows.append(quantity)
        limits = []
        for c, (curves, label) in enumerate(zip(panels, labels)):
            ax = axes[r][c]
            for x, y, style in curves:
                ax.plot(x, y, **style)
                data.add(label, quantity, style.get('label', ''), x, y)
            if curves:
                ax.legend(fontsize='x-small' if r else 'small')
            elif not any(row[2][c] for row in rows):
                ax.text(0.5, 0.5, 'no data', transform=ax.transAxes, ha='center', va='center')
            else:
                ax.text(0.5, 0.5, 'no reference', transform=ax.transAxes, ha='center',
                        va='center', color='grey')
            if notes and notes[r][c]:
                ax.text(0.02, 0.03, notes[r][c], transform=ax.transAxes, fontsize='x-small',
                        va='bottom', bbox=dict(facecolor='white', edgecolor='grey', alpha=0.9))
            if r == 0:
                ax.set_title(label)
            if r == len(rows) - 1:
                ax.set_xlabel('time t')
            panel_label = ylabel[c] if isinstance(ylabel, list) else ylabel
            if c == 0 or isinstance(ylabel, list) or not shared:
                ax.set_ylabel(panel_label)
            ax.grid(alpha=0.3)
            if r == 0:
                times = np.concatenate([np.asarray(x, float) for x, _, _ in curves] + [np.empty(0)])
                if times.size and np.nanmax(times) > np.nanmin(times):
                    ax.set_xlim(np.nanmin(times), np.nanmax(times))
            limits.append(ax.get_ylim() if curves else None)
        if shared and any(limits):
            low = min(lim[0] for lim in limits if lim)
            high = max(lim[1] for lim in limits if lim)
            for c in range(n_runs):
                axes[r][c].set_ylim(low, high)
    if independent_rows:
        title += (f' (independent y-limits of {", ".join(independent_rows)}: ranges differ by more '
                  f'than {SPAN_RATIO:g}x)')
    fig.suptitle(wrap_title(title, fig.get_figwidth()))
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
    data.write(path)
    return True


# ---------------------------------------------------------------------------------------------
# Profiles: times and files

def run_profile_times(run_dir):
    """The set of T of the profile_t<T>.csv and contact_pressure_t<T>.csv files the run in run_dir
    wrote, named as dyncontact names them: each entry of Output/profile times in its
    parameters.prm moved to the nearest step, step = lround(T / dt), and printed as C++ prints
    step * dt (%g, 6 significant digits); times after the last step are left out, as the run
    leaves them out. None if parameters.prm does not give the time step, end time and profile
    times."""
    prm = read_parameters(run_dir)
    try:
        dt = float(prm['time integration/time step'])
        end = float(prm['time integration/end time'])
        requested = [float(t) for t in prm['output/profile times'].split(',') if t.strip()]
    except (KeyError, ValueError):
        return None
    if not (dt > 0 and end > 0):
        return None
    n_steps = math.ceil(end / dt - 1e-9)
    names = set()
    for time in requested:
        if time > (n_steps + 0.5) * dt:
            continue
        steps = time / dt
        step = int(steps) + (1 if steps - int(steps) >= 0.5 else 0)  # lround for steps >= 0
        names.add(f'{step * dt:g}')
    return names


def profile_files(run_dir, prefix, tmax):
    """{T: path} of the files <prefix><T>.csv in run_dir whose T is a number <= tmax and one of
    the run's own profile times (run_profile_times()): a file left in the directory by another
    run is skipped with a note. Without the run's parameters.prm every such file is taken."""
    try:
        names = os.listdir(run_dir)
    except OSError as e:
        raise InputError(f'cannot list {run_dir}: {e}') from None
    own_times = run_profile_times(run_dir)
    found = {}
    for name in sorted(names):
        match = re.fullmatch(re.escape(prefix) + r'(.+)\.csv', name)
        if not match:
            continue
        try:
            time = float(match.group(1))
        except ValueError:
            continue
        if own_times is not None and match.group(1) not in own_times:
            print(f'{os.path.basename(sys.argv[0])}: note: {os.path.join(run_dir, name)} is not '
                  'a result of this run (not one of the profile times of its parameters.prm); '
                  'skipped', file=sys.stderr)
            continue
        if np.isfinite(time) and (tmax is None or time <= tmax):
            found[match.group(1)] = os.path.join(run_dir, name)
    return found


def by_time(times):
    """Profile time strings sorted by their value."""
    return sorted(times, key=float)


def hertz_state(run, time):
    """(a, p0, d) of Hertz at `time`: contact radius a = sqrt(R* d), central pressure
    p0 = 3 F / (2 pi a^2), approach d, from hertz.csv and R* of hertz_parameters.csv; None without
    Hertz contact at that time."""
    hertz = run['hertz']
    radius = run['hertz_parameters'].get('effective_radius')
    if not hertz or not radius:
        return None
    force = np.interp(float(time), hertz['time'], hertz['contact_force'])
    approach = np.interp(float(time), hertz['time'], hertz['approach'])
    if not (force > 0 and approach > 0):
        return None
    a = np.sqrt(radius * approach)
    return a, 3 * force / (2 * np.pi * a**2), approach


# ---------------------------------------------------------------------------------------------
# Contact pressure

def pressure_profiles(run_dir, run, tmax):
    """(T, FE table, Hertz (a, p0) or None) for every contact_pressure_t<T>.csv of the run that
    has an active pair or a nonzero pressure."""
    files = profile_files(run_dir, 'contact_pressure_t', tmax)
    if files and run['hertz'] and 'effective_radius' not in run['hertz_parameters']:
        raise InputError(f'{os.path.join(run_dir, "hertz_parameters.csv")}: no row gives the '
                         'effective radius (quantity effective_radius)')
    profiles = []
    for time in by_time(files):
        table = read_csv(files[time], required=('x', 'pressure', 'active'))
        if not ((table['active'] > 0).any() or (np.nan_to_num(table['pressure']) != 0).any()):
            continue
        state = hertz_state(run, time)
        profiles.append((time, table, state[:2] if state else None))
    return profiles


def negative_pressure(profiles):
    """(note, r, p) of the most negative recovered pressure at an active pair, or None. The note
    is one line: the value, where, the pair's nodal force and why it is not a tension (the
    pressure is recovered from the nodal forces by the consistent surface mass matrix of the
    contact zone's Q2 faces, ContactSurface::consistent_pressures(), which undershoots where the
    pressure falls to zero inside an element; not a mortar pair's, lambda_j / D_j)."""
    worst = None
    for time, table, _ in profiles:
        active = table['active'] > 0
        pressure = np.where(active, table['pressure'], np.inf)
        if not active.any() or np.nanmin(pressure) >= 0:
            continue
        i = int(np.nanargmin(pressure))
        if worst is None or pressure[i] < worst[1]:
            outermost = table['x'][i] >= np.nanmax(table['x'][active])
            force = table['multiplier'][i] if 'multiplier' in table else np.nan
            worst = (time, pressure[i], table['x'][i], outermost, force)
    if worst is None:
        return None
    time, p, r, outermost, force = worst
    where = 'edge pair' if outermost else 'active pair'
    if np.isfinite(force) and force < 0:
        return (f'p = {nice(p, 3)} (t = {time}, {where}): its nodal force {nice(force, 3)} is '
                'tensile', r, p)
    force_text = f'nodal force {nice(force, 2)} ≥ 0' if np.isfinite(force) else 'nodal force ≥ 0'
    return (f'p = {nice(p, 3)} (t = {time}, {where}, {force_text}): Q2 recovery undershoot, '
            'not tension', r, p)


def plot_pressure(path, title, panels, have_hertz, labels, data, names=('r', 'z')):
    """Contact pressure profiles p(r), one panel per run, each profile time in its own colour:
    FE pairs as markers (hollow: inactive), Hertz's ellipse as a line. r runs to PRESSURE_RANGE
    times the largest Hertz contact radius (further if FE pairs are active beyond). FE values
    outside the y-range are drawn at its edge and listed in the panel; a negative recovered
    pressure at an active pair is explained in a note. Returns False (writing nothing) if no run
    has a pressure profile."""
    if not any(panels):
        return False
    radii = [ref[0] for profiles in panels for _, _, ref in profiles if ref]
    active_r = [np.nanmax(table['x'][table['active'] > 0], initial=0)
                for profiles in panels for _, table, _ in profiles]
    rmax = max([PRESSURE_RANGE * max(radii, default=0)] + [1.1 * r for r in active_r])
    if not rmax > 0:
        rmax = max(np.nanmax(table['x']) for profiles in panels for _, table, _ in profiles)
    values = [ref[1] for profiles in panels for _, _, ref in profiles if ref]
    for profiles in panels:
        for _, table, _ in profiles:
            x, pressure = table['x'], table['pressure']
            keep = (x > 1e-6 * rmax) & (x <= rmax) & np.isfinite(pressure)
            values.extend(pressure[keep])
    top = 1.15 * max(max(values, default=0), 1e-300)
    bottom = min(-0.08 * top, 1.15 * min(values, default=0))
    colours = plt.get_cmap('tab10').colors
    fig, axes = plt.subplots(1, len(panels), figsize=(5.5 * len(panels), 4.4),
                             sharex=True, sharey=True, squeeze=False)
    for ax, (profiles, hertz), label in zip(axes[0], zip(panels, have_hertz), labels):
        handles, notes = [], []
        for i, (time, table, reference) in enumerate(profiles):
            colour, marker = colours[i % len(colours)], MARKERS[i % len(MARKERS)]
            x, pressure, active = table['x'], table['pressure'], table['active'] > 0
            data.add(label, f'pressure t = {time}', 'FE active', x[active], pressure[active])
            data.add(label, f'pressure t = {time}', 'FE inactive', x[~active], pressure[~active])
            shown = x <= 1.02 * rmax
            inside = (pressure >= bottom) & (pressure <= top)
            for mask, face in ((active, colour), (~active, 'none')):
                select = shown & inside & mask
                ax.plot(x[select], pressure[select], ls='none', marker=marker, color=colour,
                        ms=max(9 - 1.5 * i, 4), mfc=face, zorder=4)  # earlier times larger
            for r, p in zip(x[shown], pressure[shown]):
                if not bottom <= p <= top:  # also NaN
                    ax.plot(r, bottom if p < bottom else top, ls='none', ms=8, color=colour,
                            marker='v' if p < bottom else '^', zorder=5, clip_on=False)
                    notes.append(f't = {time}: p = {p:.4g} at r = {r:.2g}')
            if reference:
                a, p0 = reference
                r = np.linspace(0, a, 200)
                ax.plot(np.append(r, rmax), np.append(p0 * np.sqrt(1 - (r / a)**2), 0),
                        color=colour, lw=1.4, zorder=3)
                data.add(label, f'pressure t = {time}', 'Hertz', np.append(r, rmax),
                         np.append(p0 * np.sqrt(1 - (r / a)**2), 0))
            text = f't = {time}' + ('' if reference or not hertz else ' (Hertz: no contact)')
            handles.append(matplotlib.lines.Line2D([], [], color=colour, marker=marker, label=text))
        handles += [matplotlib.lines.Line2D([], [], color='grey', ls='none', marker='o',
                                            label='FE pair, active'),
                    matplotlib.lines.Line2D([], [], color='grey', ls='none', marker='o', mfc='none',
                                            label='FE pair, inactive')]
        if hertz:
            handles.append(matplotlib.lines.Line2D([], [], color='grey', lw=1.4, label='Hertz p(r)'))
        if profiles:
            ax.legend(handles=handles, fontsize='small', loc='upper right')
        else:
            ax.text(0.5, 0.5, 'no data', transform=ax.transAxes, ha='center', va='center')
        texts = []
        if notes:
            texts.append('off scale (drawn at the edge):\n' + '\n'.join(notes))
        negative = negative_pressure(profiles)
        if negative:
            note, r, p = negative
            ax.annotate(note, xy=(r, p), xytext=(0.02, 0.03), textcoords='axes fraction',
                        fontsize='x-small', va='bottom', color='darkred',
                        arrowprops=dict(arrowstyle='->', color='darkred', lw=0.8),
                        bbox=dict(facecolor='white', edgecolor='darkred', alpha=0.9))
            data.add(label, 'negative pressure', note, r, p)
        if texts:
            ax.text(0.02, 0.15 if negative else 0.03, '\n'.join(texts), transform=ax.transAxes,
                    fontsize='x-small', va='bottom',
                    bbox=dict(facecolor='white', edgecolor='grey', alpha=0.9))
        ax.axhline(0, color='black', lw=0.6)
        ax.set_title(label)
        ax.set_xlabel(('radius r' if names[0] == 'r' else 'x') + ' (current, node of body 1)')
        ax.grid(alpha=0.3)
    axes[0][0].set_xlim(-0.02 * rmax, rmax)  # the pair on the axis in full
    axes[0][0].set_ylim(bottom - 0.15 * (top - bottom), top)  # room for the notes
    axes[0][0].set_ylabel('contact pressure p')
    fig.suptitle(wrap_title(title, fig.get_figwidth()))
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
    data.write(path)
    return True


# ---------------------------------------------------------------------------------------------
# Meshes

def read_mesh(run_dir, profile_path):
    """Bodies (per cell), node indices (cells x 8, in order around the cell, vertices at even
    positions) and the profile of a run at one profile time; raises InputError on bad indices."""
    cells_path = os.path.join(run_dir, 'cells.csv')
    cells = read_csv(cells_path, required=['body'] + CELL_NODES)
    profile = read_csv(profile_path, required=('body', 'x', 'y', 'u_x', 'u_y'))
    rows = len(profile['x'])
    index = np.column_stack([cells[name] for name in CELL_NODES])
    if not (np.isfinite(index).all() and (index == np.round(index)).all()
            and (index >= 0).all() and (index < rows).all()):
        raise InputError(f'{cells_path}: node indices must be integers from 0 to {rows - 1} '
                         f'(the data rows of {profile_path})')
    index = index.astype(int)
    if (profile['body'][index] != cells['body'][:, None]).any():
        raise InputError(f'{cells_path}: a cell uses nodes of another body of {profile_path}')
    return cells['body'], index, profile


def nearest_node(nodes, positions, others):
    """The node of `nodes` whose position is nearest to any of the points `others` (k x 2)."""
    best, best_distance = nodes[0], np.inf
    for start in range(0, len(nodes), 1000):  # chunks keep the distance matrix small
        chunk = nodes[start:start + 1000]
        distance = np.min(np.linalg.norm(positions[chunk][:, None, :] - others[None, :, :], axis=2),
                          axis=1)
        i = int(np.argmin(distance))
        if distance[i] < best_distance:
            best, best_distance = chunk[i], distance[i]
    return best


def reference_displacements(bodies, index, profile):
    """Per node, the displacement each body's magnification is taken about: with other bodies
    that of the body's node nearest them (bodies in contact stay touching), a single body its
    rigid axial translation (the mean axial displacement of its cells weighted by their volume,
    area times centroid r by Pappus; the plain mean if that weight vanishes)."""
    X = np.column_stack([profile['x'], profile['y']])
    u = np.column_stack([profile['u_x'], profile['u_y']])
    current = X + u
    body_ids = np.unique(bodies)
    node_sets = {body: np.unique(index[bodies == body]) for body in body_ids}
    shift = np.zeros_like(u)
    for body in body_ids:
        nodes = node_sets[body]
        if len(body_ids) > 1:
            others = np.concatenate([current[node_sets[b]] for b in body_ids if b != body])
            shift[nodes] = u[nearest_node(nodes, current, others)]
        else:
            cells = index[bodies == body]
            x, y = X[cells, 0], X[cells, 1]
            cross = x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y
            moment = ((x + np.roll(x, -1, axis=1)) * cross).sum(axis=1) / 6  # area * centroid r
            weight = np.abs(moment) if np.abs(moment).sum() > 0 else np.ones(len(cells))
            shift[nodes] = [0, np.sum(weight * u[cells, 1].mean(axis=1)) / weight.sum()]
    return shift


def automatic_magnification(bodies, index, profile):
    """The magnification that makes the largest displacement relative to the reference
    displacement MESH_MAGNIFIED of the bodies' size, but keeps the magnified strain of every cell
    edge below MESH_STRAIN (so that small cells do not fold over), rounded down to 1, 2 or 5 times
    a power of ten, and at least 1."""
    X = np.column_stack([profile['x'], profile['y']])
    u = np.column_stack([profile['u_x'], profile['u_y']])
    relative = np.linalg.norm(u - reference_displacements(bodies, index, profile), axis=1)
    nodes = np.unique(index)
    size = np.ptp(X[nodes], axis=0).max()
    largest = relative[nodes].max()
    following = np.roll(index, -1, axis=1)
    lengths = np.linalg.norm(X[following] - X[index], axis=2)
    stretch = np.linalg.norm(u[following] - u[index], axis=2)
    strain = np.max(stretch[lengths > 0] / lengths[lengths > 0], initial=0)
    if not (largest > 0 and size > 0):
        return 1.0
    wanted = MESH_MAGNIFIED * size / largest
    if strain > 0:
        wanted = min(wanted, MESH_STRAIN / strain)
    if wanted <= 1:
        return 1.0
    power = 10 ** math.floor(math.log10(wanted))
    return max(m * power for m in (1, 2, 5) if m * power <= wanted)


def deformed_outlines(bodies, index, profile, magnify):
    """Current cell outlines X + t + magnify (u - t) (cells x 9 x 2, closed), t the reference
    displacements of reference_displacements()."""
    X = np.column_stack([profile['x'], profile['y']])
    u = np.column_stack([profile['u_x'], profile['u_y']])
    if magnify != 1:
        shift = reference_displacements(bodies, index, profile)
        u = shift + magnify * (u - shift)
    current = (X + u)[index]
    return np.concatenate([current, current[:, :1]], axis=1)


def plot_mesh(path, title, meshes, labels, names=('r', 'z')):
    """Deformed meshes at one time, full section mirrored about r = 0, one panel per run, with the
    undeformed boundary dashed. `meshes` holds per run (bodies, outlines, undeformed boundary
    curves), or a message saying why there is none."""
    fig, axes = plt.subplots(1, len(meshes), figsize=(5 * len(meshes), 6.5), squeeze=False,
                             layout='constrained')
    for ax, mesh, label in zip(axes[0], meshes, labels):
        ax.set_title(label)
        if isinstance(mesh, str):
            ax.text(0.5, 0.5, mesh, transform=ax.transAxes, ha='center', va='center')
            ax.axis('off')
            continue
        bodies, outlines, undeformed = mesh
        ax.add_collection(matplotlib.collections.LineCollection(
            np.concatenate([undeformed, undeformed * np.array([-1, 1])]), colors='grey', lw=0.8,
            linestyles='--'))
        handles = [matplotlib.lines.Line2D([], [], color='grey', lw=0.8, ls='--',
                                           label='undeformed, moved rigidly')]
        for i, body in enumerate(np.unique(bodies)):
            colour = FE_COLOURS[i % len(FE_COLOURS)]
            lines = outlines[bodies == body]
            ax.add_collection(matplotlib.collections.LineCollection(
                np.concatenate([lines, lines * np.array([-1, 1])]), colors=colour, lw=0.5))
            handles.append(matplotlib.lines.Line2D([], [], color=colour, label=f'body {int(body)}'))
        ax.axvline(0, color='grey', lw=0.6, ls='-.')
        ax.set_aspect('equal')
        ax.autoscale_view()
        ax.set_xlabel(f'{names[0]} (mirrored for {names[0]} < 0)')
        ax.set_ylabel(names[1])
        ax.legend(handles=handles, fontsize='small', loc='upper right')
        ax.grid(alpha=0.3)
    fig.suptitle(wrap_title(title, fig.get_figwidth()))
    fig.savefig(path, dpi=150)
    plt.close(fig)


# ---------------------------------------------------------------------------------------------
# The deformed contact zone

def quadratic_edges(index):
    """The cells' edges as node triples (vertex, mid-side, vertex), cells x 4 x 3."""
    return np.stack([index[:, [0, 1, 2]], index[:, [2, 3, 4]], index[:, [4, 5, 6]],
                     index[:, [6, 7, 0]]], axis=1)


def boundary_edges(index):
    """The edges (node triples) that belong to one cell only: the boundary of the cells."""
    edges = quadratic_edges(index).reshape(-1, 3)
    keys = np.sort(edges[:, [0, 2]], axis=1)
    _, inverse, counts = np.unique(keys, axis=0, return_inverse=True, return_counts=True)
    return edges[counts[inverse.ravel()] == 1]


def sample_edges(edges, points, n=9):
    """Points along quadratic edges through their three nodes (edges x n x 2)."""
    xi = np.linspace(0, 1, n)[:, None]
    shape = [2 * (xi - 0.5) * (xi - 1), 4 * xi * (1 - xi), 2 * xi * (xi - 0.5)]
    p = points[edges]  # edges x 3 x 2
    return sum(shape[k][None] * p[:, k][:, None, :] for k in range(3))


def surface_curve(edges, points, centre, reach):
    """The boundary edges of one body near the contact centre (within `reach` in r and z, not on
    the axis) as one curve sorted by r: (nodes r, nodes z, sampled r, sampled z)."""
    near = (np.abs(points[edges][:, :, 0]).max(axis=1) <= reach) & \
           (np.abs(points[edges][:, :, 1] - centre).max(axis=1) <= reach)
    on_axis = np.abs(points[edges][:, :, 0]).max(axis=1) <= 1e-9 * max(reach, 1e-300)
    edges = edges[near & ~on_axis]
    if not len(edges):
        return None
    nodes = np.unique(edges)
    order = np.argsort(points[nodes, 0])
    samples = sample_edges(edges, points).reshape(-1, 2)
    sample_order = np.argsort(samples[:, 0], kind='stable')
    return (points[nodes[order], 0], points[nodes[order], 1],
            samples[sample_order, 0], samples[sample_order, 1])


def hertz_surface_displacement(r, a, effective_radius):
    """The sum over both bodies of Hertz's normal surface displacements at r (toward each body's
    own centre): d - r^2/(2 R*) inside the contact radius a, (1/(pi R*))((2a^2 - r^2) asin(a/r)
    + a sqrt(r^2 - a^2)) outside, d = a^2/R* (Johnson, Contact Mechanics, section 4.2)."""
    r = np.abs(np.asarray(r, float))
    inside = r <= a
    outside = np.where(inside, 2 * a, r)  # any value > a, masked below
    far = ((2 * a**2 - outside**2) * np.arcsin(a / outside)
           + a * np.sqrt(outside**2 - a**2)) / (np.pi * effective_radius)
    return np.where(inside, a**2 / effective_radius - r**2 / (2 * effective_radius), far)


def compliance(prm, body):
    """(1 - nu^2)/E of a mesh body from parameters.prm, or None."""
    try:
        nu = float(prm[f'bodies/body {body}/poisson\'s ratio'])
        return (1 - nu**2) / float(prm[f'bodies/body {body}/young\'s modulus'])
    except (KeyError, ValueError, ZeroDivisionError):
        return None


def contact_view(run_dir, run, time, profile_path, pressure_path, scale):
    """Everything the contact panels at one profile time draw, or a message why there is none:
    a dict with the window, the vertical scale, per body its cells, surface, undeformed surface
    moved with its centre of mass and Hertz's surface."""
    bodies, index, profile = read_mesh(run_dir, profile_path)
    body_ids = [int(b) for b in np.unique(bodies)]
    if len(body_ids) > 2:
        return f'{len(body_ids)} bodies: no single contact to draw'
    pressure = read_csv(pressure_path, required=('x', 'y', 'active')) if pressure_path else None
    X = np.column_stack([profile['x'], profile['y']])
    current = X + np.column_stack([profile['u_x'], profile['u_y']])
    active = pressure['active'] > 0 if pressure is not None else np.zeros(0, bool)
    if not active.any():
        return 'no active contact pair'
    a_fe = np.nanmax(pressure['x'][active])
    centre = pressure['y'][active][np.argmin(pressure['x'][active])]  # the contact on the axis
    state = hertz_state(run, time)
    a_hertz = state[0] if state else None
    a_window = max(a_fe, a_hertz or 0)
    if not a_window > 0:  # only the pair on the axis is active
        a_window = np.nanmin(pressure['x'][pressure['x'] > 0], initial=np.inf)
        if not np.isfinite(a_window):
            return 'no contact radius'
    half_width = CONTACT_WINDOW * a_window
    reach = 1.3 * half_width
    displacements, _ = centre_displacements(run)
    t_history = run['history']['time']
    view = dict(a_fe=a_fe, a_hertz=a_hertz, centre=centre, half_width=half_width, bodies={},
                hertz_state=state)
    for body in body_ids:
        cells = index[bodies == body]
        edges = boundary_edges(cells)
        edges = edges[np.abs(X[edges][:, :, 0]).max(axis=1) > 1e-9 * np.ptp(X[:, 1])]  # not the axis
        deformed = surface_curve(edges, current, centre, reach)
        if deformed is None:
            return f'body {body} has no surface near the contact'
        # The side of the contact the body lies on: +1 above (z > centre), -1 below.
        side = 1.0 if np.nanmean(current[np.unique(cells), 1]) > centre else -1.0
        entry = dict(cells=cells, deformed=deformed, side=side)
        if displacements is not None and body in displacements:
            rigid = np.interp(float(time), t_history, displacements[body])
            moved = X + np.array([0.0, rigid])
            entry['undeformed'] = surface_curve(edges, moved, centre, reach)
        # Curvature k of the undeformed surface at the pole: least squares of |Z - Z_pole| = k r^2/2
        # over the boundary nodes near the contact.
        entry['curvature'] = None
        ref_nodes = np.unique(edges)
        ref_near = ref_nodes[(np.abs(current[ref_nodes, 0]) <= half_width) &
                             (np.abs(current[ref_nodes, 1] - centre) <= reach)]
        if len(ref_near) >= 3:
            r0 = X[ref_near, 0]
            pole = X[ref_near, 1][np.argmin(r0)]
            distance = np.abs(X[ref_near, 1] - pole)
            weight = r0**2 / 2
            if (weight > 0).any():
                entry['curvature'] = float(np.sum(distance * weight) / np.sum(weight**2))
        view['bodies'][body] = entry
    # Hertz's surfaces: each body's share of the displacements is its compliance's share.
    if state:
        a, _, d = state
        shares = {b: compliance(run['prm'], b) for b in body_ids}
        if len(body_ids) == 1:
            shares = {body_ids[0]: 1.0}
        elif all(s is not None for s in shares.values()) and sum(shares.values()) > 0:
            total = sum(shares.values())
            shares = {b: s / total for b, s in shares.items()}
        else:
            shares = None
        effective_radius = run['hertz_parameters']['effective_radius']
        r = np.linspace(0, half_width * 1.05, 400)
        total_displacement = hertz_surface_displacement(r, a, effective_radius)
        for body, entry in view['bodies'].items():
            if shares is None or entry['curvature'] is None:
                continue
            share = shares[body]
            gap = entry['curvature'] * r**2 / 2 - share * d + share * total_displacement
            entry['hertz'] = (r, centre + entry['side'] * gap)
    # The window: r within +-half_width; z over the bodies' surfaces there, plus a margin.
    z_values = []
    for entry in view['bodies'].values():
        r_s, z_s = entry['deformed'][2], entry['deformed'][3]
        keep = np.abs(r_s) <= half_width
        z_values.append(z_s[keep])
    z_values = np.concatenate(z_values + [np.array([centre])])
    low, high = np.nanmin(z_values), np.nanmax(z_values)
    if len(body_ids) == 1:  # the rigid plane: as much room on its side
        extent = max(high - centre, centre - low)
        low, high = centre - extent, centre + extent
    margin = 0.15 * (high - low) if high > low else half_width * 0.1
    view['z_limits'] = (low - margin, high + margin)
    width = 2 * half_width
    height = view['z_limits'][1] - view['z_limits'][0]
    view['scale'] = scale if scale else max(1.0, CONTACT_ASPECT * width / height)
    view['current'] = current
    return view


def plot_contact(path, title, views, labels, data, names=('r', 'z')):
    """The deformed contact zone at one time, a row per run: the exaggerated picture and the
    surface profiles against Hertz (contact_view())."""
    fig, axes = plt.subplots(len(views), 2, figsize=(14, 4.6 * len(views)), squeeze=False,
                             gridspec_kw=dict(width_ratios=[1.6, 1]), layout='constrained')
    for (picture, profile), view, label in zip(axes, views, labels):
        if isinstance(view, str):
            for ax in (picture, profile):
                ax.text(0.5, 0.5, view, transform=ax.transAxes, ha='center', va='center')
                ax.set_title(label)
                ax.axis('off')
            continue
        half_width, centre, scale = view['half_width'], view['centre'], view['scale']
        extent = 'radius' if names[0] == 'r' else 'half-width'
        low, high = view['z_limits']
        current = view['current']
        data.add(label, 'window', 'limits (x: r, y: z)', [-half_width, half_width], [low, high])
        data.add(label, 'window', 'vertical scale', scale, scale)
        data.add(label, 'window', 'contact radius FE', view['a_fe'], centre)
        if view['a_hertz']:
            data.add(label, 'window', 'contact radius Hertz', view['a_hertz'], centre)
        handles = []
        for i, (body, entry) in enumerate(sorted(view['bodies'].items())):
            colour = FE_COLOURS[i % len(FE_COLOURS)]
            # Cells with a node in the window, their edges curved through the mid-side node.
            cells = entry['cells']
            inside = (np.abs(current[cells, 0]) <= 1.3 * half_width) & \
                     (current[cells, 1] >= low - (high - low)) & \
                     (current[cells, 1] <= high + (high - low))
            edges = quadratic_edges(cells[inside.any(axis=1)]).reshape(-1, 3)
            curves = sample_edges(edges, current)
            picture.add_collection(matplotlib.collections.LineCollection(
                np.concatenate([curves, curves * np.array([-1, 1])]), colors=colour, lw=0.5,
                alpha=0.8))
            _, _, r_s, z_s = entry['deformed']
            r_full = np.concatenate([-r_s[::-1], r_s])
            z_full = np.concatenate([z_s[::-1], z_s])
            edge = low if entry['side'] < 0 else high
            picture.fill_between(r_full, z_full, edge, color=colour, alpha=0.15, lw=0)
            picture.plot(r_full, z_full, color=colour, lw=1.6)
            handles.append(matplotlib.lines.Line2D([], [], color=colour, lw=1.6,
                                                   label=f'body {body}, deformed'))
            r_n, z_n = entry['deformed'][0], entry['deformed'][1]
            keep = r_n <= 1.05 * half_width
            profile.plot(r_n[keep], z_n[keep] - centre, ls='none', marker='o', ms=3, color=colour)
            keep_s = r_s <= 1.05 * half_width
            profile.plot(r_s[keep_s], z_s[keep_s] - centre, color=colour, lw=1.2,
                         label=f'body {body}, FE')
            data.add(label, 'surface', f'body {body} FE', r_n[keep], z_n[keep])
            data.add(label, 'surface', f'body {body} FE curve', r_s[keep_s], z_s[keep_s])
            if entry.get('undeformed'):
                _, _, r_u, z_u = entry['undeformed']
                picture.plot(np.concatenate([-r_u[::-1], r_u]), np.concatenate([z_u[::-1], z_u]),
                             color=colour, lw=1.0, ls='--')
                keep_u = r_u <= 1.05 * half_width
                profile.plot(r_u[keep_u], z_u[keep_u] - centre, color=colour, lw=0.9, ls='--')
                data.add(label, 'surface', f'body {body} undeformed, moved with its centre of mass',
                         r_u[keep_u], z_u[keep_u])
            if entry.get('hertz'):
                r_h, z_h = entry['hertz']
                profile.plot(r_h, z_h - centre, color=HERTZ_COLOUR, lw=1.0,
                             label='Hertz' if i == 0 else None, zorder=4)
                data.add(label, 'surface', f'body {body} Hertz', r_h, z_h)
        if any(e.get('undeformed') for e in view['bodies'].values()):
            handles.append(matplotlib.lines.Line2D([], [], color='grey', lw=1.0, ls='--',
                                                   label='undeformed, moved with the centre of mass'))
        if len(view['bodies']) == 1:
            picture.axhline(centre, color='black', lw=2.0)
            handles.append(matplotlib.lines.Line2D([], [], color='black', lw=2, label='rigid plane'))
        for radius, colour, name in ((view['a_fe'], 'tab:green', 'FE'),
                                     (view['a_hertz'], HERTZ_COLOUR, 'Hertz')):
            if radius:
                for ax, sides in ((picture, (-1, 1)), (profile, (1,))):
                    for s in sides:
                        ax.axvline(s * radius, color=colour, lw=0.8, ls=':')
                handles.append(matplotlib.lines.Line2D([], [], color=colour, lw=0.8, ls=':',
                                                       label=f'contact {extent}, {name}: '
                                                             f'{nice(radius, 3)}'))
        picture.set_xlim(-half_width, half_width)
        picture.set_ylim(low, high)
        picture.set_aspect(scale)
        picture.set_xlabel(f'{names[0]} (mirrored for {names[0]} < 0)')
        picture.set_ylabel(f'{names[1]}   (drawn ×{nice(scale, 2)})')
        picture.set_title(f'{label}: deformed, {names[1]} enlarged ×{nice(scale, 2)} about the '
                          'contact')
        picture.legend(handles=handles, fontsize='x-small', loc='upper right', framealpha=0.9)
        profile.axhline(0, color='grey', lw=0.6)
        profile.set_xlim(0, half_width)
        profile.set_xlabel(names[0])
        profile.set_ylabel(f'{names[1]} − {names[1]}({names[0]} = 0)')
        profile.set_title('surfaces: FE (dots at nodes), Hertz; dashed: undeformed', fontsize='small')
        profile.legend(fontsize='x-small', loc='best')
        profile.grid(alpha=0.3)
    fig.suptitle(wrap_title(title, fig.get_figwidth()))
    fig.savefig(path, dpi=150)
    plt.close(fig)
    data.write(path)


# ---------------------------------------------------------------------------------------------
# The exact solution of the bars (a port of source/reference/exact_bar_solution.cc)

class StepFunction:
    """A right-continuous, piecewise-constant function of time, breakpoints appended in order."""

    def __init__(self, initial):
        self.initial, self.times, self.values, self.running = initial, [], [], []

    def value(self, t, tolerance):
        k = bisect.bisect_right(self.times, t + tolerance)
        return self.initial if k == 0 else self.values[k - 1]

    def update(self, t, value, threshold):
        current = self.values[-1] if self.values else self.initial
        if abs(value - current) <= threshold:
            return False
        self.running.append(self.running[-1] + (t - self.times[-1]) * self.values[-1]
                            if self.times else 0.0)
        self.times.append(t)
        self.values.append(value)
        return True

    def antiderivative(self, t):
        if not self.times or t < self.times[0]:
            return (t - (self.times[0] if self.times else 0.0)) * self.initial
        k = bisect.bisect_right(self.times, t) - 1
        return self.running[k] + (t - self.times[k]) * self.values[k]

    def integral(self, lower, upper):
        return self.antiderivative(upper) - self.antiderivative(lower)


class ExactBars:
    """Linear elastic waves in bars on the x axis in frictionless contact with each other and a
    rigid wall, tracked along characteristics exactly as ExactBarSolution does (same events, same
    tolerances): the Riemann invariants R = v - N/z (speed +c) emitted at left ends and
    L = v + N/z (speed -c) emitted at right ends, z = rho c A."""

    def __init__(self, bars, wall, end_time, clamped=False):
        self.bars = []
        length_scale = abs(wall) if wall is not None else 0.0
        velocity_scale = 0.0
        for left, length, modulus, density, area, velocity in bars:
            c = math.sqrt(modulus / density)
            self.bars.append(dict(left=left, length=length, c=c, z=density * c * area, area=area,
                                  travel=length / c, right_going=StepFunction(velocity),
                                  left_going=StepFunction(velocity)))
            length_scale = max(length_scale, abs(left) + length)
            velocity_scale = max(velocity_scale, abs(velocity))
        self.shortest = min(b['travel'] for b in self.bars)
        self.end_time = end_time
        length_tolerance = 1e-12 * length_scale
        self.signal_tolerance = 1e-14 * velocity_scale
        order = sorted(range(len(bars)), key=lambda i: bars[i][0])
        interfaces, gaps = [], []
        for k in range(len(order) - 1):
            gap = bars[order[k + 1]][0] - (bars[order[k]][0] + bars[order[k]][1])
            interfaces.append((order[k], order[k + 1]))
            gaps.append(0.0 if gap <= length_tolerance else gap)
        if wall is not None:
            gap = wall - (bars[order[-1]][0] + bars[order[-1]][1])
            interfaces.append((order[-1], None))
            gaps.append(0.0 if gap <= length_tolerance else gap)
        self.track(order[0], order[-1], wall is not None, clamped, interfaces, gaps)

    def tolerance(self, t):
        return 1e-14 * (t + self.shortest)

    def track(self, leftmost, rightmost, has_wall, clamped, interfaces, gaps):
        arrivals = []
        closing = [0.0] * len(interfaces)
        end = self.end_time + self.tolerance(self.end_time)

        def emit(wave, bar, t, value):
            if wave.update(t, value, self.signal_tolerance) and t + bar['travel'] <= end:
                heapq.heappush(arrivals, t + bar['travel'])

        def at_left(bar, t):
            return bar['left_going'].value(t - bar['travel'], self.tolerance(t))

        def at_right(bar, t):
            return bar['right_going'].value(t - bar['travel'], self.tolerance(t))

        t = 0.0
        while True:
            first = self.bars[leftmost]
            emit(first['right_going'], first, t, (-1.0 if clamped else 1.0) * at_left(first, t))
            if not has_wall:
                last = self.bars[rightmost]
                emit(last['left_going'], last, t, at_right(last, t))
            for i, (left_index, right_index) in enumerate(interfaces):
                left = self.bars[left_index]
                right = self.bars[right_index] if right_index is not None else None
                incoming_r = at_right(left, t)
                incoming_l = at_left(right, t) if right else 0.0
                right_compliance = 1.0 / right['z'] if right else 0.0
                force = (incoming_l - incoming_r) / (1.0 / left['z'] + right_compliance)
                contact = gaps[i] <= 0.0 and force <= 0.0
                emit(left['left_going'], left, t,
                     incoming_r + 2.0 * force / left['z'] if contact else incoming_r)
                if right:
                    emit(right['right_going'], right, t,
                         incoming_l - 2.0 * force * right_compliance if contact else incoming_l)
                closing[i] = 0.0 if contact else incoming_r - incoming_l
                if contact:
                    gaps[i] = 0.0
            next_time = arrivals[0] if arrivals else math.inf
            for i in range(len(interfaces)):
                if closing[i] > 0.0:
                    next_time = min(next_time, t + gaps[i] / closing[i])
            if next_time > end:
                break
            group = 0.5 * self.tolerance(next_time)
            while arrivals and arrivals[0] <= next_time + group:
                heapq.heappop(arrivals)
            for i in range(len(interfaces)):
                closes = closing[i] > 0.0 and t + gaps[i] / closing[i] <= next_time + group
                gaps[i] = 0.0 if closes else gaps[i] - closing[i] * (next_time - t)
            t = next_time

    def fields(self, bar_index, X, t):
        """(u, v, N) at the reference coordinates X (array) of a bar at time t."""
        bar = self.bars[bar_index]
        u, v, n = [], [], []
        for x in np.atleast_1d(X):
            from_left = (x - bar['left']) / bar['c']
            from_right = (bar['left'] + bar['length'] - x) / bar['c']
            u.append(0.5 * (bar['right_going'].integral(-from_left, t - from_left) +
                            bar['left_going'].integral(-from_right, t - from_right)))
            r = bar['right_going'].value(t - from_left, self.tolerance(t))
            l_ = bar['left_going'].value(t - from_right, self.tolerance(t))
            v.append(0.5 * (r + l_))
            n.append(0.5 * bar['z'] * (l_ - r))
        return np.array(u), np.array(v), np.array(n)


def exact_bars(prm, end_time):
    """ExactBars of the bars of a run's parameters.prm up to end_time, or None if the file does
    not give them."""
    try:
        count = int(prm['geometry/number of bars'])
        bars = []
        for b in range(1, count + 1):
            entry = lambda name: float(prm[f'geometry/bar {b}/{name}'])  # noqa: E731
            bars.append((entry('left end'), entry('length'), entry("young's modulus"),
                         entry('density'), entry('cross-section area'), entry('initial velocity')))
        wall = (float(prm['geometry/rigid wall/position'])
                if prm.get('geometry/rigid wall/enabled') == 'true' else None)
        clamped = prm.get('geometry/clamped left end') == 'true'
    except (KeyError, ValueError):
        return None
    return ExactBars(bars, wall, end_time, clamped)


def bar_profile_panels(run, time, path):
    """The curves of displacement, velocity and stress along the bars at one profile time:
    FE (nodes; the stress constant per element, E du/dX) and exact."""
    profile = read_csv(path, required=('body', 'x', 'u', 'v'))
    prm = run['prm']
    exact = exact_bars(prm, float(time))
    rows = {'u': [], 'v': [], 'sigma': []}
    for i, body in enumerate(np.unique(profile['body']).astype(int)):
        colour = FE_COLOURS[i % len(FE_COLOURS)]
        suffix = f', bar {body}' if len(np.unique(profile['body'])) > 1 else ''
        mine = profile['body'] == body
        order = np.argsort(profile['x'][mine])
        x, u, v = (profile[c][mine][order] for c in ('x', 'u', 'v'))
        for key, y in (('u', u), ('v', v)):
            rows[key].append(fe_curve(x, y, 'FE' + suffix, colour))
        try:
            modulus = float(prm[f'geometry/bar {body}/young\'s modulus'])
        except (KeyError, ValueError):
            modulus = None
        if modulus is not None and len(x) > 1:
            stress = modulus * np.diff(u) / np.diff(x)
            rows['sigma'].append((np.repeat(x, 2)[1:-1], np.repeat(stress, 2),
                                  dict(label='FE' + suffix + ' (per element)', color=colour, lw=1.0,
                                       marker='o', ms=2, markevery=(2 * len(stress) // 60) | 1)))
        if exact is not None:
            dense = np.unique(np.concatenate([np.linspace(x[0], x[-1], 2001), x]))
            eu, ev, en = exact.fields(body - 1, dense, float(time))
            area = exact.bars[body - 1]['area']
            black = EXACT_COLOURS[i % len(EXACT_COLOURS)]
            rows['u'].append(reference_curve(dense, eu, 'exact' + suffix, black, lw=1.2))
            rows['v'].append(reference_curve(dense, ev, 'exact' + suffix, black, lw=1.2))
            rows['sigma'].append(reference_curve(dense, en / area, 'exact' + suffix, black, lw=1.2))
    return rows, exact is not None


def plot_bar_profiles(path, title, panels, labels, data):
    """Displacement, velocity and stress along the bars, a column per run (panels: per run the
    rows of bar_profile_panels() or a message)."""
    names = (('u', 'displacement u'), ('v', 'velocity v'), ('sigma', 'stress σ (tension > 0)'))
    fig, axes = plt.subplots(3, len(panels), figsize=(5.5 * len(panels), 9), squeeze=False,
                             sharex='col', layout='constrained')
    for c, (rows, label) in enumerate(zip(panels, labels)):
        for r, (key, name) in enumerate(names):
            ax = axes[r][c]
            if isinstance(rows, str):
                ax.text(0.5, 0.5, rows, transform=ax.transAxes, ha='center', va='center')
                ax.axis('off')
                continue
            for x, y, style in rows[key]:
                ax.plot(x, y, **style)
                data.add(label, key, style['label'], x, y)
            ax.legend(fontsize='x-small')
            ax.grid(alpha=0.3)
            ax.set_ylabel(name)
            if r == 0:
                ax.set_title(label)
            if r == 2:
                ax.set_xlabel('x (reference)')
    fig.suptitle(wrap_title(title, fig.get_figwidth()))
    fig.savefig(path, dpi=150)
    plt.close(fig)
    data.write(path)


# ---------------------------------------------------------------------------------------------

def parse_args(argv):
    """Parse the command line; argparse itself exits with code 2 on misuse."""
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('run_dirs', nargs='+', metavar='RUN_DIR', help='simulation output directory')
    parser.add_argument('--output', metavar='DIR',
                        help='where to write the PNGs (default: the first RUN_DIR)')
    parser.add_argument('--labels', nargs='+', metavar='L', help='panel titles, one per RUN_DIR')
    parser.add_argument('--tmin', type=float, metavar='T',
                        help='start the time axis at T (default: the time-history plots are '
                             'zoomed on the contact)')
    parser.add_argument('--tmax', type=float, metavar='T', help='clip the time axis at T')
    parser.add_argument('--magnify', type=float, metavar='M',
                        help='deformed_mesh_t*.png: scale each body\'s displacement by M about that '
                             'of its node nearest the other bodies (one body: about its rigid '
                             'axial translation); default: the largest scaled displacement is '
                             f'{100 * MESH_MAGNIFIED:g} %% of the bodies\' size')
    parser.add_argument('--zscale', type=float, metavar='S',
                        help='deformed_contact_t*.png: draw z S times enlarged about the contact '
                             f'(default: the window {CONTACT_WINDOW:g} contact radii wide is drawn '
                             f'{CONTACT_ASPECT:g} times as high as wide)')
    parser.add_argument('--data', action='store_true',
                        help='write beside every PNG a CSV of the numbers drawn (panel, quantity, '
                             'series, x, y)')
    args = parser.parse_args(argv)
    if args.labels and len(args.labels) != len(args.run_dirs):
        parser.error(f'{len(args.labels)} labels given for {len(args.run_dirs)} run directories')
    for name in ('magnify', 'zscale'):
        value = getattr(args, name)
        if value is not None and not (np.isfinite(value) and value > 0):
            parser.error(f'--{name} must be a positive number, not {value:g}')
    return args


def energy_rows(runs, zoomed):
    """The two rows of energy.png: the energies, and (E - E0)/E0 in a unit chosen to show it."""
    errors = [energy_error_curves(run['history'], z['history']) for run, z in zip(runs, zoomed)]
    largest = [max((np.nanmax(np.abs(y), initial=0) for _, y, _ in curves), default=0)
               for curves in errors]
    nonzero = [v for v in largest if v > 0]
    independent = len(nonzero) > 1 and max(nonzero) > SPAN_RATIO * min(nonzero)
    scaled, ylabels = [], []
    for curves, big in zip(errors, largest):
        factor, ylabel = energy_unit(big if independent else max(largest, default=0))
        panel = []
        for t, y, style in curves:
            extreme = y[np.nanargmax(np.abs(y))] if np.isfinite(y).any() else np.nan
            style = dict(style, label=f'{style["label"]}, largest {nice(factor * extreme, 3)}'
                                      f'{ylabel.split("[")[1].rstrip("]") if "[" in ylabel else ""}')
            style['label'] = style['label'].replace('%', ' %').replace('ppm', ' ppm')
            panel.append((t, factor * y, style))
        if curves:
            panel.append((np.array([np.nan]), np.array([factor]),
                          dict(label='_unit factor', color='none')))
        scaled.append(panel)
        if does_external_work(runs[len(ylabels)]['history']):
            ylabel = ylabel.replace('(E − E0)/E0', '(E − E0 − W)/E_ref')
        ylabels.append(ylabel)
    return [('energy', 'energy', [energy_curves(z) for z in zoomed]),
            ('relative energy change', ylabels, scaled, independent)]


def main(argv=None):
    """Load all runs, write the figures and print their paths; return the exit code."""
    args = parse_args(argv)
    labels = args.labels or [run_label(d) for d in args.run_dirs]
    if not args.labels and len(set(labels)) < len(labels):  # e.g. two time steps, same scheme
        labels = [f'{label} ({os.path.basename(os.path.normpath(d))})'
                  for label, d in zip(labels, args.run_dirs)]
    output = args.output or args.run_dirs[0]
    names = args.labels or [os.path.basename(os.path.normpath(d)) for d in args.run_dirs]
    mesh_labels = [sphere_label(d, name) for d, name in zip(args.run_dirs, names)]

    def sheet():
        return DataSheet(args.data)

    try:
        runs = [load_run(d, args.tmax) for d in args.run_dirs]
        spheres = [bool(run['hertz']) for run in runs]
        panel_labels = [m if s else label for m, s, label in zip(mesh_labels, spheres, labels)]
        # Every time-history plot shows the contact unless --tmin or --tmax chooses the window.
        if args.tmin is None and args.tmax is None:
            windows = [contact_window(run) for run in runs]
        else:
            windows = [(-np.inf if args.tmin is None else args.tmin, np.inf)] * len(runs)
        zoomed = [zoom(run, window) for run, window in zip(runs, windows)]
        case = case_description(args.run_dirs)
        suffix = f': {case}' if case else ''
        os.makedirs(output, exist_ok=True)

        def save(name, title, rows, run_labels=panel_labels, notes=None):
            path = os.path.join(output, name)
            if plot_rows(path, title, rows, run_labels, sheet(), notes):
                print(path)

        for name, title, prefix, steps in (
                ('tip_velocity.png', 'Velocity of the monitor nodes (v_tip)', 'v_tip', True),
                ('tip_acceleration.png', 'Acceleration of the monitor nodes (a_tip)', 'a_tip', True)):
            ylabel = title.split(' of ')[0].lower()
            save(name, title + suffix,
                 [(prefix, ylabel, [tip_curves(z, prefix, steps) for z in zoomed])])
        # Monitor nodes that touch each other (the contact poles of the shipped sphere files) only
        # show that they touch: such runs are left out; approach.png shows the centres instead.
        plain = [i for i, run in enumerate(runs) if not monitors_touch(run)]
        for i in sorted(set(range(len(runs))) - set(plain)):
            print(f'{os.path.basename(sys.argv[0])}: note: the monitor nodes of {args.run_dirs[i]} '
                  'touch during the contact (contact poles): no tip_displacement.png '
                  'panel, approach.png shows the approach of the centres', file=sys.stderr)
        if plain:
            save('tip_displacement.png', 'Displacement of the monitor nodes (u_tip)' + suffix,
                 [('u_tip', 'displacement u', [tip_curves(zoomed[i], 'u_tip', False) for i in plain])],
                 [panel_labels[i] for i in plain])

        force_rows = [('contact force', 'total contact force F', [force_curves(z) for z in zoomed])]
        if any(spheres):
            differences = []
            for run, z in zip(runs, zoomed):
                history = z['history']
                peak = run['hertz_parameters'].get('peak_force')
                differences.append(difference_curves(history['time'], history['contact_force'], z,
                                                     'contact_force', peak)
                                   if peak and 'contact_force' in history else [])
            force_rows.append(('force difference', 'F − reference\n[% of Hertz\'s peak]',
                               differences))
        # Without any contact force or reference (e.g. a free vibration) the figure shows nothing.
        # The finite-sphere law is written for whole spheres only (not for a spherical end).
        references = ('Hertz and the finite-sphere law' if any(run['finite_sphere'] for run in runs)
                      else 'Hertz')
        if any(run['exact'] or run['hertz'] or
               np.nanmax(np.abs(run['history'].get('contact_force', np.zeros(1))), initial=0) > 0
               for run in runs):
            save('contact_force.png',
                 'Contact force' + suffix + (f'\nFE vs {references}' if any(spheres) else ''),
                 force_rows)

        if any(spheres):
            approach_panels, difference_panels, notes = [], [], []
            for run, z in zip(runs, zoomed):
                if not run['hertz']:
                    approach_panels.append([])
                    difference_panels.append([])
                    notes.append('')
                    continue
                curves, reason = approach_curves(z, run)
                approach_panels.append(curves)
                notes.append(f'no FE approach: {reason}' if reason else '')
                approach, _ = fe_approach(run)
                scale = np.nanmax(run['hertz']['approach'])
                if approach is not None and scale > 0:
                    t, d = approach
                    keep = np.isin(t, z['history']['time'])
                    difference_panels.append(difference_curves(t[keep], d[keep], z, 'approach', scale))
                else:
                    difference_panels.append([])
            save('approach.png',
                 'Approach of the centres (change of their distance minus the initial gap)' + suffix
                 + f'\nFE vs {references}',
                 [('approach', 'approach d', approach_panels),
                  ('approach difference', 'd − reference\n[% of Hertz\'s max]', difference_panels)],
                 notes=[notes, [''] * len(runs)])

        save('energy.png', 'Energy' + suffix + '\nphysical = kinetic + strain; algorithmic = '
             'physical + (β − γ/2)(dt²/2) aᵀMa (Hughes)', energy_rows(runs, zoomed))

        path = os.path.join(output, 'contact_pressure.png')
        if plot_pressure(path, 'Contact pressure' + suffix + (', FE vs Hertz' if any(spheres) else ''),
                         [pressure_profiles(d, run, args.tmax) for d, run in zip(args.run_dirs, runs)],
                         spheres, mesh_labels, sheet(), coordinate_names(args.run_dirs)):
            print(path)

        # Profiles along the bars against the exact solution.
        bar_profiles = [profile_files(d, 'profile_t', args.tmax)
                        if not os.path.isfile(os.path.join(d, 'cells.csv')) else {}
                        for d in args.run_dirs]
        for time in by_time(set().union(*bar_profiles)):
            panels = []
            for run, files in zip(runs, bar_profiles):
                if time in files:
                    rows, with_exact = bar_profile_panels(run, time, files[time])
                    panels.append(rows)
                else:
                    panels.append(f'no profile_t{time}.csv')
            path = os.path.join(output, f'profile_t{time}.png')
            plot_bar_profiles(path, f'Profiles along the bars at t = {time}' + suffix +
                              ', FE vs exact', panels, labels, sheet())
            print(path)

        # Meshes: the contact zone where pairs are active, else the whole section.
        profiles = [profile_files(d, 'profile_t', args.tmax)
                    if os.path.isfile(os.path.join(d, 'cells.csv')) else {} for d in args.run_dirs]
        pressures = [profile_files(d, 'contact_pressure_t', args.tmax)
                     if os.path.isfile(os.path.join(d, 'cells.csv')) else {} for d in args.run_dirs]
        mesh_runs = [i for i, files in enumerate(profiles) if files]
        for time in by_time(set().union(*profiles)):
            views = []
            for i in mesh_runs:
                if time in profiles[i]:
                    views.append(contact_view(args.run_dirs[i], runs[i], time, profiles[i][time],
                                              pressures[i].get(time), args.zscale))
                else:
                    views.append(f'no profile_t{time}.csv')
            if any(not isinstance(v, str) for v in views):
                path = os.path.join(output, f'deformed_contact_t{time}.png')
                plot_contact(path, f'Deformed contact zone at t = {time}' + suffix, views,
                             [mesh_labels[i] for i in mesh_runs], sheet(),
                             coordinate_names([args.run_dirs[i] for i in mesh_runs]))
                print(path)
                continue
            meshes, magnifications = [], []
            for i in mesh_runs:
                if time in profiles[i]:
                    bodies, index, profile = read_mesh(args.run_dirs[i], profiles[i][time])
                    magnify = args.magnify or automatic_magnification(bodies, index, profile)
                    magnifications.append(magnify)
                    # The undeformed boundary moved with each body's reference displacement.
                    moved = (np.column_stack([profile['x'], profile['y']]) +
                             reference_displacements(bodies, index, profile))
                    meshes.append((bodies, deformed_outlines(bodies, index, profile, magnify),
                                   sample_edges(boundary_edges(index), moved)))
                else:
                    end = np.nanmax(runs[i]['history']['time'], initial=-np.inf)
                    meshes.append(f'no profile_t{time}.csv' +
                                  (f' (the run ends at t = {end:g})' if end < float(time) else ''))
            scale = ', '.join(sorted({f'×{m:g}' for m in magnifications}))
            scale = ('displacements not magnified' if scale == '×1' else
                     f'displacements relative to each body\'s rigid motion magnified {scale}')
            path = os.path.join(output, f'deformed_mesh_t{time}.png')
            plot_mesh(path, f'Deformed mesh at t = {time}' + suffix + f'\n{scale}', meshes,
                      [mesh_labels[i] for i in mesh_runs],
                      coordinate_names([args.run_dirs[i] for i in mesh_runs]))
            print(path)
    except (InputError, OSError) as e:
        print(f'{os.path.basename(sys.argv[0])}: error: {e}', file=sys.stderr)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main())
