#!/usr/bin/env python3
"""The tutorial doc/tutorial.md as ctests (tests/tutorial/CMakeLists.txt).

  tutorial.py run   MARKDOWN WORK DYNCONTACT SOURCE
      Runs every ```sh block of MARKDOWN, in order, in one bash shell started in WORK, as a reader
      pastes them into a terminal at the root of a built clone. WORK is made to look like one:
      WORK/build/dyncontact is a link to the DYNCONTACT under test and WORK/scripts to
      SOURCE/scripts; the PATH is the test's own, so a python3 without matplotlib first on it
      fails here as it would for the reader (the page writes /usr/bin/python3, Debian's). The
      commands themselves are not changed. The shell stops at the
      first command that fails (bash -e -o pipefail): a block may fail only if its fence says so,
      ```sh expect-exit=N, and then it must exit with exactly N (such a block runs in a child
      shell, so that it changes nothing for the blocks after it).
  tutorial.py hertz MARKDOWN WORK
      The tutorial's runs against an independent Hertz reference (see check_hertz()).
  tutorial.py units MARKDOWN WORK
      The steel striker in SI units and in mm, t, s, N, MPa: the same forces in N at the same
      times in s.
  tutorial.py shown MARKDOWN WORK
      Every file of the runs that the tutorial names (`run/...`, `plots/...`) exists, and every
      block whose fence says compare=FILE shows FILE as the run wrote it: the same table, every
      number within 0.2 % (+ 2e-4 absolute, for the relative differences near zero) of the run's.
  tutorial.py geo   MARKDOWN SHIPPED_GEO
      The .geo the tutorial writes equals SHIPPED_GEO (meshes/tutorial_striker_on_plate.geo)
      without its header (the leading // comment lines and the blank line after them).

The runs live in WORK/RUN_ROOT, the directory the tutorial works in.
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

RUN_ROOT = os.path.join("output", "striker")


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def blocks(markdown):
    """The fenced blocks of MARKDOWN: (line of the fence, language, {attribute: value}, text)."""
    result, block = [], None
    with open(markdown) as file:
        for number, line in enumerate(file, 1):
            if block is None:
                match = re.match(r"^```(\w*)(.*)$", line.rstrip("\n"))
                if match:
                    attributes = dict(re.findall(r"([\w-]+)=(\S+)", match.group(2)))
                    block = (number, match.group(1), attributes, [])
            elif line.rstrip("\n") == "```":
                result.append(block[:3] + ("".join(block[3]),))
                block = None
            else:
                block[3].append(line)
    if block is not None:
        fail(f"{markdown}:{block[0]}: the block is not closed")
    return result


def run(markdown, work, dyncontact, source):
    shutil.rmtree(work, ignore_errors=True)
    for link, target in [("build/dyncontact", dyncontact), ("scripts", os.path.join(source, "scripts"))]:
        os.makedirs(os.path.dirname(os.path.join(work, link)), exist_ok=True)
        os.symlink(target, os.path.join(work, link))
    lines = ["set -e -o pipefail"]
    shell_blocks = [b for b in blocks(markdown) if b[1] == "sh"]
    if not shell_blocks:
        fail(f"{markdown} has no ```sh blocks")
    for line, _, attributes, text in shell_blocks:
        where = f"{os.path.basename(markdown)}:{line}"
        if "expect-exit" in attributes:
            expected = attributes["expect-exit"]
            block_file = os.path.join(work, f".block_{line}.sh")
            with open(block_file, "w") as file:
                file.write(text)
            lines += [f"echo '=== {where} (must exit {expected})'",
                      f"__status=0; bash -e -o pipefail '{block_file}' || __status=$?",
                      f"if [ $__status != {expected} ]; then",
                      f"  echo '{where}: the block exited with' $__status', not {expected}' >&2; exit 1",
                      "fi"]
        else:
            lines += [f"echo '=== {where}'", text.rstrip("\n")]
    lines.append("echo '=== every block ran'")
    script = os.path.join(work, ".tutorial.sh")
    with open(script, "w") as file:
        file.write("\n".join(lines) + "\n")
    status = subprocess.call(["bash", script], cwd=work)
    if status != 0:
        fail(f"the tutorial's commands stopped with exit code {status} in the block named last above")
    print(f"{len(shell_blocks)} blocks ran as expected")


def read_csv(path):
    if not os.path.exists(path):
        fail(f"{path} is missing")
    with open(path) as file:
        return list(csv.DictReader(file))


def column(rows, name):
    return [float(row[name]) for row in rows]


def parameters(path):
    """The 'Section/entry' -> value of a parameters.prm written by a run."""
    values, sections = {}, []
    with open(path) as file:
        for line in file:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                sections.append(line[len("subsection "):].strip())
            elif line == "end":
                sections.pop()
            elif line.startswith("set "):
                name, value = line[4:].split("=", 1)
                values["/".join(sections + [name.strip()])] = value.strip()
    return values


def geo_parameters(run_directory):
    """The .geo's parameters in effect in a run: its DefineConstant defaults, then the
    run's Mesh/geo parameters."""
    prm = parameters(os.path.join(run_directory, "parameters.prm"))
    with open(prm["Mesh/file"]) as file:
        text = file.read()
    values = {name: float(value) for name, value in re.findall(r"(\w+)\s*=\s*\{\s*([-+0-9.eE]+)\s*,", text)}
    for pair in filter(None, prm["Mesh/geo parameters"].split(",")):
        name, value = pair.split(":")
        values[name.strip()] = float(value)
    return prm, values


def measure_impact(times, force):
    """measure_impact() of include/dyncontact/reference/impact_measures.h, restated: the peak of
    the parabola through the largest sample and its neighbours, the contact start and end where
    F^(2/3) extrapolates linearly to zero, the trapezoidal impulse."""
    inside = [n for n, f in enumerate(force) if f > 0]
    if len(inside) < 2:
        fail("the run has fewer than 2 samples in contact")
    first, last = inside[0], inside[-1]

    def zero(n, m, bound):  # F^(2/3) through samples n and m (m the outer one) extrapolated to 0
        a, b = force[n] ** (2 / 3), force[m] ** (2 / 3)
        if a <= b:
            return bound
        crossing = times[m] - b * (times[n] - times[m]) / (a - b)
        return crossing if min(bound, times[m]) <= crossing <= max(bound, times[m]) else bound

    start = zero(first + 1, first, times[first - 1]) if first > 0 else times[0]
    end = zero(last - 1, last, times[last + 1]) if last + 1 < len(force) else times[-1]
    n = max(range(len(force)), key=lambda k: force[k])
    peak = force[n]
    if 0 < n < len(force) - 1:
        (t0, t1, t2), (f0, f1, f2) = times[n - 1:n + 2], force[n - 1:n + 2]
        d = (t0 - t1) * (t0 - t2) * (t1 - t2)
        a = (t2 * (f1 - f0) + t1 * (f0 - f2) + t0 * (f2 - f1)) / d
        b = (t2 * t2 * (f0 - f1) + t1 * t1 * (f2 - f0) + t0 * t0 * (f1 - f2)) / d
        c = (t1 * t2 * (t1 - t2) * f0 + t2 * t0 * (t2 - t0) * f1 + t0 * t1 * (t0 - t1) * f2) / d
        if a < 0:
            peak = c - b * b / (4 * a)
    impulse = sum(0.5 * (force[k] + force[k + 1]) * (times[k + 1] - times[k]) for k in range(len(force) - 1))
    return {"peak_force": peak, "contact_start": start, "duration": end - start, "impulse": impulse}


def hertz(run_directory):
    """Hertz's impact of a sphere of the end's radius R on an elastic flat body, both bodies
    rigid masses: the striker's (a cylinder of radius R and length L on a hemisphere of radius R)
    and the plate's, from the .geo's parameters and the run's parameters.prm."""
    prm, geo = geo_parameters(run_directory)
    body = lambda b, entry: float(prm[f"Bodies/Body {b}/{entry}"])
    velocity = [float(v) for v in prm["Bodies/Body 1/Initial velocity/Function expression"].split(";")]
    if velocity[0] != 0 or prm["Bodies/Body 2/Initial velocity/Function expression"].replace(" ", "") != "0;0":
        fail("the check assumes the striker moves along the axis and the plate is at rest")
    length = lambda name: geo[name] * geo.get("Scale", 1.)  # the .geo's lengths in the run's unit
    R, L = length("R"), length("L")
    m1 = body(1, "density") * math.pi * R ** 2 * (L + 2 * R / 3)
    m2 = body(2, "density") * math.pi * length("PlateRadius") ** 2 * length("PlateThickness")
    mass = m1 * m2 / (m1 + m2)
    modulus = 1 / sum((1 - body(b, "Poisson's ratio") ** 2) / body(b, "Young's modulus") for b in (1, 2))
    speed = -velocity[1]
    approach = (15 * mass * speed ** 2 / (16 * modulus * math.sqrt(R))) ** 0.4
    coefficient = 0.8 * math.gamma(0.4) * math.sqrt(math.pi) / math.gamma(0.9)  # 2.9432
    return {"peak_force": 4 / 3 * modulus * math.sqrt(R) * approach ** 1.5,
            "contact_start": length("Gap") / speed, "duration": coefficient * approach / speed,
            "impulse": 2 * mass * speed}, {"m1": m1, "m2": m2, "a": math.sqrt(R * approach),
                                           "c0": math.sqrt(body(1, "Young's modulus") / body(1, "density")),
                                           "R": R, "L": L}


# The bounds of check_hertz(), with the measured figures (doc/tutorial.md, "What agreement to expect").
BOUNDS = {"peak_force": 0.03, "duration": 0.03, "impulse": 0.005}


def check_hertz(work):
    """Each run of the tutorial: its peak force and contact duration (measured from its
    history.csv as the code measures them) and the impulse the striker received (its momentum
    change) within BOUNDS of Hertz computed here from the inputs; the contact starts at first
    touch (Gap / v) within a step; and the run's own impact_summary.csv, complete, states the same
    figures: its computed column within 1e-6 of the measures here, its hertz column within 1e-4
    of the Hertz here (the code takes the masses from the meshed volumes), and its relative
    difference is the one of these two columns."""
    root = os.path.join(work, RUN_ROOT)
    runs = sorted(d for d in os.listdir(root) if os.path.exists(os.path.join(root, d, "history.csv")))
    if "run" not in runs:
        fail(f"no run in {root}")
    for name in runs:
        directory = os.path.join(root, name)
        rows = read_csv(os.path.join(directory, "history.csv"))
        computed = measure_impact(column(rows, "time"), column(rows, "contact_force"))
        momentum = column(rows, "momentum_1")
        computed["impulse"] = momentum[-1] - momentum[0]  # upward, on the falling striker
        reference, extra = hertz(directory)
        step = float(parameters(os.path.join(directory, "parameters.prm"))["Time integration/time step"])
        print(f"{name}: striker mass {extra['m1']:.6g}, plate mass {extra['m2']:.6g}, Hertz contact radius "
              f"{extra['a']:.4g} (a/R = {extra['a'] / extra['R']:.3f}), contact duration / the striker's "
              f"wave round trip 2 (L + R) / c0 = {reference['duration'] * extra['c0'] / (2 * (extra['L'] + extra['R'])):.3g}")
        for quantity in ["peak_force", "duration", "impulse"]:
            difference = computed[quantity] / reference[quantity] - 1
            print(f"  {quantity:10s} computed {computed[quantity]:.6g}, Hertz {reference[quantity]:.6g}: "
                  f"{100 * difference:+.2f} % (bound {100 * BOUNDS[quantity]:g} %)")
            if abs(difference) > BOUNDS[quantity]:
                fail(f"{name}: {quantity} differs from Hertz by {100 * difference:+.2f} %")
        if abs(computed["contact_start"] - reference["contact_start"]) > step:
            fail(f"{name}: contact starts at {computed['contact_start']}, first touch is {reference['contact_start']}")
        summary = {row["quantity"]: row for row in read_csv(os.path.join(directory, "impact_summary.csv"))}
        for quantity in ["peak_force", "duration", "impulse"]:
            row = summary[quantity]
            own, hertz_column = float(row["computed"]), float(row["hertz"])
            if row["status"] != "complete":
                fail(f"{name}/impact_summary.csv: status '{row['status']}'")
            if abs(own - computed[quantity]) > 1e-6 * abs(computed[quantity]):
                fail(f"{name}/impact_summary.csv: {quantity} computed {own}, measured here {computed[quantity]}")
            if abs(hertz_column - reference[quantity]) > 1e-4 * abs(reference[quantity]):
                fail(f"{name}/impact_summary.csv: {quantity} Hertz {hertz_column}, computed here {reference[quantity]}")
            if abs(float(row["relative_difference"]) - (own / hertz_column - 1)) > 1e-9:
                fail(f"{name}/impact_summary.csv: {quantity}'s relative difference is not computed / Hertz - 1")
        print("  impact_summary.csv agrees with both")


def check_units(work):
    root = os.path.join(work, RUN_ROOT)
    si, mm = (read_csv(os.path.join(root, name, "history.csv")) for name in ("run_si", "run_mm"))
    if len(si) != len(mm):
        fail(f"run_si has {len(si)} rows, run_mm {len(mm)}")
    time_si, time_mm = column(si, "time"), column(mm, "time")
    force_si, force_mm = column(si, "contact_force"), column(mm, "contact_force")
    peak = max(force_si)
    time_error = max(abs(a - b) for a, b in zip(time_si, time_mm)) / time_si[-1]
    force_error = max(abs(a - b) for a, b in zip(force_si, force_mm)) / peak
    # Displacements: m against mm.
    tip_error = max(abs(1000 * a - b) for a, b in zip(column(si, "u_tip_1"), column(mm, "u_tip_1"))) / \
        max(abs(b) for b in column(mm, "u_tip_1"))
    print(f"SI against mm-t-s-N-MPa over {len(si)} rows: times {time_error:.2g} of the end time, forces "
          f"{force_error:.2g} of the peak {peak:.6g} N, striker tip displacement (x 1000) {tip_error:.2g}")
    # Newton stops each run within its relative tolerance 1e-10 of the force scale; 1e-6 bounds the
    # difference of two such solutions of the same scaled problem with room.
    if time_error > 1e-12 or force_error > 1e-6 or tip_error > 1e-6:
        fail("the runs in SI and in mm-t-s-N-MPa differ")


def numbers(text):
    return [[float(cell) if re.fullmatch(r"[-+0-9.eE]+|nan|inf", cell.strip()) else cell.strip()
             for cell in line.split(",")] for line in text.strip().splitlines()]


def check_shown(markdown, work):
    root = os.path.join(work, RUN_ROOT)
    with open(markdown) as file:
        named = sorted(set(re.findall(r"`((?:run|run_si|run_mm|plots)/[^`\s]+)`", file.read())))
    for path in named:
        if not os.path.exists(os.path.join(root, path)):
            fail(f"{markdown} names {path}, which the runs did not write")
    print(f"the {len(named)} files that {os.path.basename(markdown)} names exist: {', '.join(named)}")
    shown = [b for b in blocks(markdown) if "compare" in b[2]]
    if not shown:
        fail(f"{markdown} shows no run file (no block with compare=FILE)")
    for line, _, attributes, text in shown:
        path = os.path.join(root, attributes["compare"])
        with open(path) as file:
            actual = numbers(file.read())
        expected = numbers(text)
        where = f"{os.path.basename(markdown)}:{line}"
        if len(actual) != len(expected) or any(len(a) != len(e) for a, e in zip(actual, expected)):
            fail(f"{where}: the table has another shape than {attributes['compare']} of the run:\n" + open(path).read())
        for a_row, e_row in zip(actual, expected):
            for a, e in zip(a_row, e_row):
                if isinstance(a, str) or isinstance(e, str):
                    if a != e:
                        fail(f"{where}: '{e}' shown, '{a}' in the run's {attributes['compare']}")
                elif abs(a - e) > 2e-3 * abs(a) + 2e-4:
                    fail(f"{where}: {e} shown, {a} in the run's {attributes['compare']}:\n" + open(path).read())
        print(f"{where}: {attributes['compare']} as shown")


def check_geo(markdown, shipped):
    written = [b for b in blocks(markdown) if b[1] == "sh" and "cat > striker_on_plate.geo <<'EOF'" in b[3]]
    if len(written) != 1:
        fail(f"{markdown}: no single block writes striker_on_plate.geo")
    text = written[0][3]
    geo = text[text.index("<<'EOF'\n") + len("<<'EOF'\n"):text.rindex("EOF")]
    with open(shipped) as file:
        lines = file.readlines()
    header = 0
    while header < len(lines) and lines[header].startswith("//"):
        header += 1
    if header == 0 or lines[header].strip():
        fail(f"{shipped}: expected a header of // lines and a blank line")
    if "".join(lines[header + 1:]) != geo:
        fail(f"{shipped} (after its header) differs from the .geo that {markdown} writes")
    print(f"{shipped} is the tutorial's .geo with a header of {header} lines")


if __name__ == "__main__":
    command, arguments = sys.argv[1], sys.argv[2:]
    if command == "run":
        run(*arguments)
    elif command == "hertz":
        check_hertz(arguments[1])
    elif command == "units":
        check_units(arguments[1])
    elif command == "shown":
        check_shown(*arguments)
    elif command == "geo":
        check_geo(*arguments)
    else:
        fail(f"unknown command {command}")
