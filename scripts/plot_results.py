#!/usr/bin/python3
"""Plot dyncontact run histories against the exact (and Hertz) reference solutions.

Usage: plot_results.py RUN_DIR [RUN_DIR ...] [--output DIR] [--labels L1 L2 ...] [--tmin T] [--tmax T]
                       [--magnify M]

Each RUN_DIR holds history.csv and optionally exact.csv, hertz.csv and parameters.prm. Profiles
(profile_t<T>.csv, contact_pressure_t<T>.csv) are taken only at the run's own profile times, read
from its parameters.prm, so that files another run left in the directory are not drawn.
Writes tip_velocity.png, tip_acceleration.png, tip_displacement.png, contact_force.png
and energy.png, each with one panel per run side by side, and prints their paths. Each panel is
zoomed on the run's contact interval (the reference's, or the FE's if longer, plus 30 % on each
side); --tmin and --tmax choose the window instead.

Runs of the two-sphere impact (Taylor & Papadopoulos 1993, section 6.4), recognised by their
hertz.csv, get in addition:
  - contact_force.png with the FE against Hertz (paper Figs. 11 and 12);
  - contact_pressure.png (if contact_pressure_t<T>.csv exist): FE pressure of every contact pair
    (filled markers active, hollow inactive) at each profile time T with contact, against Hertz's
    p(r) = p0 sqrt(1 - r^2/a^2), a = sqrt(R* d), p0 = 3 F / (2 pi a^2). F(T) and the approach d(T)
    are interpolated in hertz.csv and R* is read from hertz_parameters.csv. FE pressures beyond
    the plotted range (e.g. on the axis from a code that divides the nodal force by the 2 pi r
    weighted tributary area, which vanishes there) are drawn at the edge and listed in the panel;
  - deformed_mesh_t<T>.png for every profile_t<T>.csv (if cells.csv exists; paper Fig. 13): the
    deformed cells X + u of all bodies, mirrored about the axis, full section and (two or more
    bodies) the contact region |r| <= 3, |z - z_contact| <= 2. --magnify M scales each body's
    displacement about that of its node nearest to the other bodies, so that bodies in contact
    stay touching (one body: about its rigid axial translation); the default M = 1 draws the true
    displacements.
"""
import argparse
import csv
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
ENERGIES = ['kinetic', 'strain', 'total', 'algorithmic']
SPAN_RATIO = 100.0  # y-ranges differing by more than this get independent limits
CONTACT_MARGIN = 0.3  # zoomed force plots: margin on each side, fraction of the contact interval
PRESSURE_RANGE = 1.5  # pressure plots: r up to this multiple of the largest Hertz contact radius
ZOOM_R, ZOOM_Z = 3.0, 2.0  # deformed mesh: contact region |r| <= ZOOM_R, |z - z_contact| <= ZOOM_Z
CELL_NODES = [f'node_{i}' for i in range(8)]
MARKERS = ['o', 's', 'D', '^', 'v', 'P', 'X']  # one per profile time in the pressure plots


class InputError(Exception):
    """A missing or malformed input file, reported without a traceback."""


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


def load_run(run_dir, tmax):
    """Load history.csv (required), exact.csv and hertz.csv (optional), clipped to t <= tmax."""
    history = os.path.join(run_dir, 'history.csv')
    if not os.path.isfile(history):
        raise InputError(f'{history}: no such file (is {run_dir} a run directory?)')
    run = {}
    for key in ('history', 'exact', 'hertz'):
        path = os.path.join(run_dir, key + '.csv')
        table = read_csv(path) if os.path.isfile(path) else {}
        if table and tmax is not None:
            table = clip(table, (-np.inf, tmax))
        run[key] = table
    if run['hertz'] and 'contact_force' not in run['hertz']:
        raise InputError(f'{os.path.join(run_dir, "hertz.csv")}: header lacks the column(s) '
                         'contact_force')
    return run


def clip(table, window):
    """The rows of `table` with window[0] <= time <= window[1] (all of it if window is None)."""
    if not table or window is None:
        return table
    keep = (table['time'] >= window[0]) & (table['time'] <= window[1])
    return {name: values[keep] for name, values in table.items()}


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


def run_label(run_dir):
    """Label a run by its contact dynamics in parameters.prm (none: the classical Newmark,
    taylor-papadopoulos: the paper's modified Newmark), falling back to the directory name."""
    dynamics = read_parameters(run_dir).get('contact/dynamics')
    names = {'none': 'classical Newmark', 'taylor-papadopoulos': 'modified Newmark'}
    if dynamics is None:
        return os.path.basename(os.path.normpath(run_dir))
    return names.get(dynamics, dynamics)


def sphere_label(run_dir, label):
    """Panel title of a sphere run: the scheme and the run's own label (--labels entry or
    directory name), the latter left out if it only repeats the scheme."""
    scheme = run_label(run_dir)
    if label in (scheme, scheme.split()[0]):
        return scheme
    return f'{scheme} ({label})'


def sphere_case(run_dirs):
    """Short description of the mesh runs' case for the figure titles, from parameters.prm
    (material data of the bodies; differing runs are listed one after the other). Runs with
    neither hertz.csv nor cells.csv (bars) are left out."""
    cases = []
    for run_dir in run_dirs:
        sphere = os.path.isfile(os.path.join(run_dir, 'hertz.csv'))
        if not (sphere or os.path.isfile(os.path.join(run_dir, 'cells.csv'))):
            continue
        prm = read_parameters(run_dir)
        props = []
        for symbol, entry in (('ρ', 'density'), ('E', "young's modulus"), ('ν', "poisson's ratio")):
            values = []
            for body in range(1, 101):
                value = prm.get(f'bodies/body {body}/{entry}')
                if value is None:
                    break
                if value not in values:
                    values.append(value)
            if values:
                props.append(f'{symbol}\u00a0=\u00a0{"/".join(values)}')  # no line break
        name = 'two-sphere impact' if sphere else 'axisymmetric bodies'
        case = name + (f' ({", ".join(props)})' if props else '')
        if case not in cases:
            cases.append(case)
    return '; '.join(cases)


def hertz_radius(run_dir):
    """R*, the effective radius, from hertz_parameters.csv (quantity,value rows)."""
    path = os.path.join(run_dir, 'hertz_parameters.csv')
    try:
        with open(path, newline='') as f:
            for row in csv.DictReader(f):
                if row.get('quantity') == 'effective_radius':
                    return float(row['value'])
    except (OSError, UnicodeDecodeError, ValueError, TypeError) as e:
        raise InputError(f'cannot read {path}: {e}') from None
    raise InputError(f'{path}: no row gives the effective radius (quantity effective_radius)')


def contact_interval(time, force):
    """(last sample before, first sample after) the samples with a positive force, or None.
    Forces below 1e-9 of the largest count as zero."""
    positive = np.nan_to_num(force) > 1e-9 * np.nanmax(np.abs(force), initial=0)
    if not positive.any():
        return None
    first, last = np.flatnonzero(positive)[[0, -1]]
    return time[max(first - 1, 0)], time[min(last + 1, len(time) - 1)]


def contact_window(run):
    """Time window of the time-history plots: the contact interval of the reference (Hertz or the
    exact solution), or of the FE if it reaches further, plus CONTACT_MARGIN of its length on each
    side; None for runs without contact."""
    intervals = []
    for key in ('hertz', 'exact', 'history'):
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
    return {key: clip(table, window) for key, table in run.items()}


def fe_curve(table, column, label, colour):
    """FE solution: thin line with markers on every k-th step (k odd, so that markers
    do not alias with a period-2 ringing and sit on alternate extremes)."""
    t = table['time']
    return t, table[column], dict(label=label, color=colour, lw=1.0, marker='o', ms=3,
                                  markevery=(len(t) // 60) | 1)


def reference_curve(table, column, label, colour, steps, ls='-'):
    """Reference (exact or Hertz) solution: thicker line drawn on top of the FE curves."""
    return table['time'], table[column], dict(label=label, color=colour, lw=1.6, ls=ls, zorder=3,
                                              drawstyle='steps-post' if steps else 'default')


def tip_curves(run, prefix, steps):
    """FE and exact curves of tip quantity `prefix` ('v_tip', ...) for every body."""
    history, exact = run['history'], run['exact']
    bodies = sorted(int(m.group(1)) for m in (re.fullmatch(prefix + r'_(\d+)', c) for c in history) if m)
    curves = []
    for i, body in enumerate(bodies):
        suffix = f', body {body}' if len(bodies) > 1 else ''
        column = f'{prefix}_{body}'
        curves.append(fe_curve(history, column, 'FE' + suffix, FE_COLOURS[i % len(FE_COLOURS)]))
        if column in exact:
            curves.append(reference_curve(exact, column, 'exact' + suffix,
                                          EXACT_COLOURS[i % len(EXACT_COLOURS)], steps))
    return curves


def force_curves(run):
    """FE contact force with the exact and Hertz references where available."""
    history, exact, hertz = run['history'], run['exact'], run['hertz']
    curves = []
    if 'contact_force' in history:
        curves.append(fe_curve(history, 'contact_force', 'FE', FE_COLOURS[0]))
    if 'contact_force' in exact:
        curves.append(reference_curve(exact, 'contact_force', 'exact', 'black', True))
    if 'contact_force' in hertz:
        curves.append(reference_curve(hertz, 'contact_force', 'Hertz', 'tab:red', False, '--'))
    return curves


def energy_curves(run):
    """FE kinetic, strain, total and algorithmic energies, and the exact total energy."""
    curves = [fe_curve(run['history'], f'{name}_energy', name, FE_COLOURS[i])
              for i, name in enumerate(ENERGIES) if f'{name}_energy' in run['history']]
    if 'total_energy' in run['exact']:
        curves.append(reference_curve(run['exact'], 'total_energy', 'exact total', 'black', False, '--'))
    return curves


def wrap_title(title, width):
    """Break the lines of a figure title longer than a figure `width` inches wide can hold."""
    return '\n'.join(textwrap.fill(line, int(10 * width)) for line in title.split('\n'))


def plot_figure(path, title, ylabel, panels, labels):
    """Draw one figure with a panel per run; return False (writing nothing) if there is no data.

    The panels share their y-limits unless the runs' data ranges differ by more than
    SPAN_RATIO, in which case the figure title says so.
    """
    if not any(panels):
        return False
    values = [np.concatenate([y for _, y, _ in curves] + [np.empty(0)]) for curves in panels]
    spans = [np.ptp(v[np.isfinite(v)]) for v in values if np.isfinite(v).any()]
    spans = [s for s in spans if s > 0]
    independent = len(spans) > 1 and max(spans) > SPAN_RATIO * min(spans)
    fig, axes = plt.subplots(1, len(panels), figsize=(5 * len(panels), 3.8),
                             sharey=not independent, squeeze=False)
    for ax, curves, label in zip(axes[0], panels, labels):
        for t, y, style in curves:
            ax.plot(t, y, **style)
        times = np.concatenate([t for t, _, _ in curves] + [np.empty(0)])
        if times.size and np.nanmax(times) > np.nanmin(times):
            ax.set_xlim(np.nanmin(times), np.nanmax(times))
        if curves:
            ax.legend(fontsize='small')
        else:
            ax.text(0.5, 0.5, 'no data', transform=ax.transAxes, ha='center', va='center')
        ax.set_title(label)
        ax.set_xlabel('time t')
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel(ylabel)
    if independent:
        title += f' (independent y-limits: ranges differ by more than {SPAN_RATIO:g}x)'
    fig.suptitle(wrap_title(title, fig.get_figwidth()))
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return True


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


def pressure_profiles(run_dir, run, tmax):
    """(T, FE table, Hertz (a, p0) or None) for every contact_pressure_t<T>.csv of the run that
    has an active pair or a nonzero pressure. Hertz's F and approach d are interpolated in
    hertz.csv at T; R* comes from hertz_parameters.csv."""
    files = profile_files(run_dir, 'contact_pressure_t', tmax)
    hertz = run['hertz']
    radius = None
    if files and hertz:
        if 'approach' not in hertz:
            raise InputError(f'{os.path.join(run_dir, "hertz.csv")}: header lacks the column(s) '
                             'approach')
        radius = hertz_radius(run_dir)
    profiles = []
    for time in by_time(files):
        table = read_csv(files[time], required=('x', 'pressure', 'active'))
        if not ((table['active'] > 0).any() or (np.nan_to_num(table['pressure']) != 0).any()):
            continue
        reference = None
        if radius is not None:
            force = np.interp(float(time), hertz['time'], hertz['contact_force'])
            approach = np.interp(float(time), hertz['time'], hertz['approach'])
            if force > 0 and approach > 0:
                a = np.sqrt(radius * approach)
                reference = (a, 3 * force / (2 * np.pi * a**2))
        profiles.append((time, table, reference))
    return profiles


def plot_pressure(path, title, panels, have_hertz, labels):
    """Contact pressure profiles p(r), one panel per run, each profile time in its own colour:
    FE pairs as markers (hollow: inactive), Hertz's ellipse as a line. r runs to PRESSURE_RANGE
    times the largest Hertz contact radius (further if FE pairs are active beyond). The y-range
    is set by Hertz and the FE pairs off the axis; FE values outside it (e.g. a pair on the axis,
    where a pressure from nodal force / tributary area is ill-defined because that area vanishes)
    are drawn at its edge and listed in the panel. Returns False (writing nothing) if no run has
    a pressure profile."""
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
    fig, axes = plt.subplots(1, len(panels), figsize=(5.5 * len(panels), 4.2),
                             sharex=True, sharey=True, squeeze=False)
    for ax, (profiles, hertz), label in zip(axes[0], zip(panels, have_hertz), labels):
        handles, notes = [], []
        for i, (time, table, reference) in enumerate(profiles):
            colour, marker = colours[i % len(colours)], MARKERS[i % len(MARKERS)]
            x, pressure, active = table['x'], table['pressure'], table['active'] > 0
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
        if notes:
            ax.text(0.05, 0.03, 'off scale (drawn at the edge):\n' + '\n'.join(notes),
                    transform=ax.transAxes, fontsize='x-small', va='bottom',
                    bbox=dict(facecolor='white', edgecolor='grey', alpha=0.9))
        ax.axhline(0, color='black', lw=0.6)
        ax.set_title(label)
        ax.set_xlabel('radius r (current, node of body 1)')
        ax.grid(alpha=0.3)
    axes[0][0].set_xlim(-0.02 * rmax, rmax)  # the pair on the axis in full
    axes[0][0].set_ylim(bottom, top)
    axes[0][0].set_ylabel('contact pressure p')
    fig.suptitle(wrap_title(title, fig.get_figwidth()))
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return True


def read_mesh(run_dir, profile_path):
    """Bodies (per cell) and current outlines (cells x 9 x 2, closed) of the cells of a run at one
    profile time, from cells.csv and the profile; raises InputError on bad indices."""
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


def deformed_outlines(bodies, index, profile, magnify):
    """Current cell outlines X + u (cells x 9 x 2, closed). For magnify != 1 each body's
    displacement is scaled about a reference displacement t: X + t + magnify (u - t). With other
    bodies, t is the displacement of the body's node nearest to them, so that bodies in contact
    stay touching there; a single body uses its rigid axial translation, the mean axial
    displacement of its cells weighted by their volume (area times centroid r, Pappus; the plain
    mean if that weight vanishes)."""
    X = np.column_stack([profile['x'], profile['y']])
    u = np.column_stack([profile['u_x'], profile['u_y']])
    if magnify != 1:
        current = X + u
        body_ids = np.unique(bodies)
        node_sets = {body: np.unique(index[bodies == body]) for body in body_ids}
        scaled = u.copy()
        for body in body_ids:
            nodes = node_sets[body]
            if len(body_ids) > 1:
                others = np.concatenate([current[node_sets[b]] for b in body_ids if b != body])
                shift = u[nearest_node(nodes, current, others)]
            else:
                cells = index[bodies == body]
                x, y = X[cells, 0], X[cells, 1]
                cross = x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y
                moment = ((x + np.roll(x, -1, axis=1)) * cross).sum(axis=1) / 6  # area * centroid r
                weight = np.abs(moment) if np.abs(moment).sum() > 0 else np.ones(len(cells))
                shift = np.array([0, np.sum(weight * u[cells, 1].mean(axis=1)) / weight.sum()])
            scaled[nodes] = shift + magnify * (u[nodes] - shift)
        u = scaled
    current = (X + u)[index]
    return np.concatenate([current, current[:, :1]], axis=1)


def contact_plane(bodies, outlines):
    """z of the contact plane between bodies 1 and 2 near the axis (|r| <= ZOOM_R): halfway
    between their facing extremes; None with fewer than two bodies."""
    z = []
    for body in (1, 2):
        points = outlines[bodies == body].reshape(-1, 2)
        points = points[np.abs(points[:, 0]) <= ZOOM_R]
        if not len(points):
            return None
        z.append(points[:, 1])
    if np.nanmean(z[0]) < np.nanmean(z[1]):
        return (np.nanmax(z[0]) + np.nanmin(z[1])) / 2
    return (np.nanmin(z[0]) + np.nanmax(z[1])) / 2


def plot_mesh(path, title, meshes, labels):
    """Deformed meshes at one time, one row per run: the full section mirrored about r = 0 and,
    for two or more bodies, the contact region. `meshes` holds per run (bodies, outlines), or a
    message saying why there is none."""
    zoom = any(not isinstance(m, str) and len(np.unique(m[0])) > 1 for m in meshes)
    fig, axes = plt.subplots(len(meshes), 2 if zoom else 1, figsize=(11 if zoom else 5, 6 * len(meshes)),
                             squeeze=False, layout='constrained',
                             gridspec_kw=dict(width_ratios=[1, 1.8] if zoom else [1]))
    for row, mesh, label in zip(axes, meshes, labels):
        if isinstance(mesh, str):
            for ax in row:
                ax.text(0.5, 0.5, mesh, transform=ax.transAxes, ha='center', va='center')
                ax.set_title(label)
                ax.axis('off')
            continue
        bodies, outlines = mesh
        plane = contact_plane(bodies, outlines)
        for column, ax in enumerate(row):
            handles = []
            for i, body in enumerate(np.unique(bodies)):
                colour = FE_COLOURS[i % len(FE_COLOURS)]
                lines = outlines[bodies == body]
                mirrored = lines * np.array([-1, 1])
                ax.add_collection(matplotlib.collections.LineCollection(
                    np.concatenate([lines, mirrored]), colors=colour, lw=0.5 if column == 0 else 0.9))
                if column == 1:
                    nodes = np.concatenate([lines, mirrored])[:, :-1].reshape(-1, 2)
                    ax.plot(nodes[:, 0], nodes[:, 1], ls='none', marker='.', ms=2.5, color=colour)
                handles.append(matplotlib.lines.Line2D([], [], color=colour, label=f'body {int(body)}'))
            ax.axvline(0, color='grey', lw=0.6, ls='-.')
            ax.set_aspect('equal')
            ax.set_xlabel('r (mirrored for r < 0)')
            ax.set_ylabel('z')
            if column == 0:
                ax.autoscale_view()
                ax.set_title(f'{label}: full section')
                ax.legend(handles=handles, fontsize='small', loc='upper right')
            elif plane is None:
                ax.text(0.5, 0.5, 'one body: no contact region', transform=ax.transAxes,
                        ha='center', va='center')
                ax.set_title(label)
            else:
                ax.set_xlim(-ZOOM_R, ZOOM_R)
                ax.set_ylim(plane - ZOOM_Z, plane + ZOOM_Z)
                ax.axhline(plane, color='grey', lw=0.6, ls=':')
                ax.set_title(f'{label}: contact region (z = {round(plane, 6) + 0:.3g} dotted)')
            ax.grid(alpha=0.3)
    fig.suptitle(wrap_title(title, fig.get_figwidth()))
    fig.savefig(path, dpi=150)
    plt.close(fig)


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
    parser.add_argument('--magnify', type=float, default=1.0, metavar='M',
                        help='deformed meshes: scale each body\'s displacement by M about that '
                             'of its node nearest the other bodies, so bodies in contact stay '
                             'touching (one body: about its rigid axial translation; default 1: '
                             'true displacements)')
    args = parser.parse_args(argv)
    if args.labels and len(args.labels) != len(args.run_dirs):
        parser.error(f'{len(args.labels)} labels given for {len(args.run_dirs)} run directories')
    if not (np.isfinite(args.magnify) and args.magnify > 0):
        parser.error(f'--magnify must be a positive number, not {args.magnify:g}')
    return args


def main(argv=None):
    """Load all runs, write the figures and print their paths; return the exit code."""
    args = parse_args(argv)
    labels = args.labels or [run_label(d) for d in args.run_dirs]
    if not args.labels and len(set(labels)) < len(labels):  # e.g. two time steps, same scheme
        labels = [f'{label} ({os.path.basename(os.path.normpath(d))})'
                  for label, d in zip(labels, args.run_dirs)]
    output = args.output or args.run_dirs[0]
    figures = [('tip_velocity.png', 'Tip velocity', 'tip velocity v',
                lambda r: tip_curves(r, 'v_tip', True)),
               ('tip_acceleration.png', 'Tip acceleration', 'tip acceleration a',
                lambda r: tip_curves(r, 'a_tip', True)),
               ('tip_displacement.png', 'Tip displacement', 'tip displacement u',
                lambda r: tip_curves(r, 'u_tip', False)),
               ('contact_force.png', 'Contact force', 'contact force', force_curves),
               ('energy.png', 'Energy', 'energy', energy_curves)]
    names = args.labels or [os.path.basename(os.path.normpath(d)) for d in args.run_dirs]
    mesh_labels = [sphere_label(d, name) for d, name in zip(args.run_dirs, names)]
    try:
        runs = [load_run(d, args.tmax) for d in args.run_dirs]
        spheres = [bool(run['hertz']) for run in runs]
        # Every time-history plot shows the contact unless --tmin or --tmax chooses the window.
        if args.tmin is None and args.tmax is None:
            windows = [contact_window(run) for run in runs]
        else:
            windows = [(-np.inf if args.tmin is None else args.tmin, np.inf)] * len(runs)
        zoomed = [zoom(run, window) for run, window in zip(runs, windows)]
        case = sphere_case(args.run_dirs)
        os.makedirs(output, exist_ok=True)
        for name, title, ylabel, make_curves in figures:
            path = os.path.join(output, name)
            panel_labels = labels
            if name == 'contact_force.png' and any(spheres):
                title = (f'Contact force: {case}\nFE vs Hertz, zoomed on the contact '
                         '(Taylor & Papadopoulos 1993, section 6.4)')
                ylabel = 'total contact force F'
                panel_labels = [m if s else label for m, s, label in zip(mesh_labels, spheres, labels)]
            if plot_figure(path, title, ylabel, [make_curves(run) for run in zoomed], panel_labels):
                print(path)
        path = os.path.join(output, 'contact_pressure.png')
        if plot_pressure(path, f'Contact pressure: {case}' + (', FE vs Hertz' if any(spheres) else ''),
                         [pressure_profiles(d, run, args.tmax) for d, run in zip(args.run_dirs, runs)],
                         spheres, mesh_labels):
            print(path)
        profiles = [profile_files(d, 'profile_t', args.tmax)
                    if os.path.isfile(os.path.join(d, 'cells.csv')) else {} for d in args.run_dirs]
        scale = ('displacements not magnified' if args.magnify == 1 else
                 f'displacements magnified x{args.magnify:g} about each body\'s point nearest the others')
        for time in by_time(set().union(*profiles)):
            meshes = []
            for d, files, run in zip(args.run_dirs, profiles, runs):
                if time in files:
                    bodies, index, profile = read_mesh(d, files[time])
                    meshes.append((bodies, deformed_outlines(bodies, index, profile, args.magnify)))
                else:
                    end = np.nanmax(run['history']['time'], initial=-np.inf)
                    meshes.append(f'no profile_t{time}.csv' +
                                  (f' (the run ends at t = {end:g})' if end < float(time) else ''))
            path = os.path.join(output, f'deformed_mesh_t{time}.png')
            plot_mesh(path, f'Deformed mesh at t = {time}: {case}\n{scale}', meshes, mesh_labels)
            print(path)
    except (InputError, OSError) as e:
        print(f'{os.path.basename(sys.argv[0])}: error: {e}', file=sys.stderr)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main())
