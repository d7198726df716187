"""The pieces the CalculiX 2.20 decks of make_deck.py (axisymmetric, CAX8) and make_deck_3d.py
(quarter sphere, C3D20/C3D20R) share: gmsh in, msh 2.2 parsing, the material, the penalty
contact, and the two dynamic steps (the one-increment gravity launch, then the impact) with their
outputs. Stdlib only."""
import math
import os
import shutil
import subprocess
import sys


def hertz(R, E, nu, v, rho):
    """Hertz's sphere (radius R, density rho, speed v) on a rigid plane: E* = E/(1-nu^2),
    R* = R, m* = m."""
    m = rho * 4.0 / 3.0 * math.pi * R**3
    estar = E / (1.0 - nu**2)
    dmax = (15.0 * m * v**2 / (16.0 * estar * math.sqrt(R))) ** 0.4
    return {
        "mass": m,
        "delta_max": dmax,
        "contact_radius": math.sqrt(R * dmax),
        "peak": 4.0 / 3.0 * estar * math.sqrt(R) * dmax**1.5,
        "duration": 2.9432751843 * dmax / v,
        "impulse": 2.0 * m * v,
        "peak_pressure": 2.0 / math.pi * estar * math.sqrt(dmax / R),
    }


def run_gmsh(geo, msh, dim, parameters, tool="make_deck.py"):
    """gmsh -DIM -order 2 (serendipity: Mesh.SecondOrderIncomplete 1) of GEO with each of
    `parameters` (name -> value, in order) set by -setnumber, written as msh 2.2 to MSH."""
    gmsh = shutil.which("gmsh")
    if gmsh is None:
        sys.exit(f"{tool}: gmsh not found (apt-get install -y gmsh)")
    cmd = [gmsh, geo, f"-{dim}", "-order", "2", "-setnumber", "Mesh.SecondOrderIncomplete", "1"]
    for name, value in parameters.items():
        cmd += ["-setnumber", name, repr(value)]
    cmd += ["-format", "msh2", "-o", msh]
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0 or not os.path.exists(msh):
        sys.exit(f"{tool}: gmsh failed:\n" + out.stdout + out.stderr)


def read_msh2(path, types, dim=3):
    """Nodes {id: (x, y[, z])} (the first `dim` coordinates) and, for each gmsh element type in
    `types`, its elements [(physical tag, [node ids])] of an ASCII msh 2.2 file."""
    text = open(path).read()
    words = text.split("$Nodes")[1].split("$EndNodes")[0].split()
    nodes = {}
    for i in range(int(words[0])):
        k = 1 + 4 * i
        nodes[int(words[k])] = tuple(float(s) for s in words[k + 1:k + 1 + dim])
    elements = {t: [] for t in types}
    for line in text.split("$Elements")[1].split("$EndElements")[0].strip().split("\n")[1:]:
        f = [int(s) for s in line.split()]
        if f[1] in elements:
            ntags = f[2]
            elements[f[1]].append((f[3] if ntags else 0, f[3 + ntags:]))
    return nodes, elements


def lines_of(ids, per_line=8):
    ids = list(ids)
    return "\n".join(", ".join(str(i) for i in ids[k:k + per_line]) + ","
                     for k in range(0, len(ids), per_line))


def write_material(w, name, E, nu, rho):
    w(f"*MATERIAL, NAME={name}")
    w("*ELASTIC")
    w(f"{E:.15g}, {nu:.15g}")
    w("*DENSITY")
    w(f"{rho:.15g}")


def write_contact(w, slope, sigma_inf, c0, contact, small_sliding, slave="SSLAVE",
                  master="SMASTER"):
    """Penalty contact: ccx's smoothed linear pressure-overclosure law (slope, sigma_inf, c0;
    c0 <= 0: ccx's default), NODE TO SURFACE (contact "node") or SURFACE TO SURFACE."""
    w("*SURFACE INTERACTION, NAME=SINT")
    w("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR")
    w(f"{slope:.15g}, {sigma_inf:.15g}" + (f", {c0:.15g}" if c0 > 0 else ""))
    ctype = "NODE TO SURFACE" if contact == "node" else "SURFACE TO SURFACE"
    ss = ", SMALL SLIDING" if small_sliding else ""
    w(f"*CONTACT PAIR, INTERACTION=SINT, TYPE={ctype}{ss}")
    w(f"{slave}, {master}")


def write_steps(w, a, nsteps, grav, outputs, body="ESPHERE"):
    """The dynamic steps (HHT a.alpha, fixed step a.dt, a.end_time - a.start_time in all; NLGEOM
    if a.nlgeom). a.launch == "gravity": a first step of one increment with the body force
    `grav` = (g, direction x, y, z) on `body`, then the rest without it (see README.md: after
    it the body moves at g dt with u(dt) = g dt^2 / 2); else one step. outputs(): the *NODE
    PRINT requests, repeated in each step. a.controls (if there and not empty): the data line
    of *CONTROLS, PARAMETERS=TIME INCREMENTATION (I0, IR, IP, IC, IL, IG, IS, IA, ...) in each
    step."""
    nl = ", NLGEOM" if a.nlgeom else ""
    dyn = f"*DYNAMIC, DIRECT, ALPHA={a.alpha:g}"
    controls = getattr(a, "controls", None)
    outputs_only = outputs

    def outputs():
        if controls:
            w("*CONTROLS, PARAMETERS=TIME INCREMENTATION")
            w(controls)
        outputs_only()
    if a.launch == "gravity":
        g, dx, dy, dz = grav
        w(f"*STEP{nl}, INC=10")
        w(dyn)
        w(f"{a.dt:.15g}, {a.dt:.15g}")
        w("*DLOAD")
        w(f"{body}, GRAV, {g:.15g}, {dx:g}., {dy:g}., {dz:g}.")
        outputs()
        w("*END STEP")
        rest = a.end_time - a.start_time - a.dt
        w(f"*STEP{nl}, INC={nsteps + 10}")
        w(dyn)
        w(f"{a.dt:.15g}, {rest:.15g}")
        w("*DLOAD, OP=NEW")
        outputs()
        w("*END STEP")
    else:
        w(f"*STEP{nl}, INC={nsteps + 10}")
        w(dyn)
        w(f"{a.dt:.15g}, {a.end_time - a.start_time:.15g}")
        outputs()
        w("*END STEP")


def add_penalty_dynamics_options(ap, penalty, launch, launch_help):
    """The options both decks share: material law, penalty contact, HHT alpha, launch, output.
    `penalty` [E per length] and `launch` are the deck's defaults, `launch_help` its reason."""
    ap.add_argument("--nlgeom", action="store_true", help="geometrically nonlinear (*STEP, NLGEOM"
                    "; with *ELASTIC this is St Venant-Kirchhoff)")
    ap.add_argument("--penalty", type=float, default=penalty,
                    help="slope of the linear pressure-overclosure law in units of E per length")
    ap.add_argument("--sigma-inf", type=float, default=None, help="ccx's tension at large "
                    "clearance sigma_inf (sets the smoothing of the linear law; default 1e-4 of "
                    "the Hertz peak pressure)")
    ap.add_argument("--c0", type=float, default=0.0,
                    help="ccx's c0 (spring elements up to clearance c0 sqrt(slave area); 0: ccx's "
                    "default 1e-3)")
    ap.add_argument("--alpha", type=float, default=None,
                    help="HHT alpha of *DYNAMIC, in [-1/3, 0] (default 0, trapezoidal Newmark, for "
                    "the linear material; ccx's own default -0.05 with --nlgeom, where 0 diverges "
                    "in ccx 2.20 with DIRECT, see README.md)")
    ap.add_argument("--launch", choices=["gravity", "initial-velocity"], default=launch,
                    help="how the sphere gets its speed: a one-increment body-force step, or "
                    "*INITIAL CONDITIONS, TYPE=VELOCITY; " + launch_help)
    ap.add_argument("--contact", choices=["node", "surface"], default="node",
                    help="*CONTACT PAIR TYPE: NODE TO SURFACE (default) or SURFACE TO SURFACE")
    ap.add_argument("--small-sliding", action="store_true",
                    help="*CONTACT PAIR, SMALL SLIDING: pair the slave nodes once per increment "
                    "instead of in every iteration")
    ap.add_argument("--print-every", type=int, default=1, help="*NODE PRINT FREQUENCY")


def complete_options(a, h, R, E):
    """Fills the shared options' defaults from the Hertz figures `h` of a sphere of radius R and
    modulus E: alpha (0; -0.05 with --nlgeom), sigma_inf (1e-4 of the peak pressure), slave_depth
    (the height of the cap of radius 4 a + 0.5, at most R). Returns the penalty slope K = penalty E."""
    if a.alpha is None:
        a.alpha = -0.05 if a.nlgeom else 0.0
    if a.sigma_inf is None:
        a.sigma_inf = 1e-4 * h["peak_pressure"]
    if a.slave_depth is None:
        a.slave_depth = min(R, (4.0 * h["contact_radius"] + 0.5) ** 2 / (2 * R))
    return a.penalty * E


def write_sphere_and_plate(w, E, nu, rho):
    """The sphere's and the plate's materials (linear elastic, E, nu, rho) and solid sections."""
    write_material(w, "SPHERE", E, nu, rho)
    write_material(w, "PLATE", E, nu, rho)
    w("*SOLID SECTION, ELSET=ESPHERE, MATERIAL=SPHERE")
    w("*SOLID SECTION, ELSET=EPLATE, MATERIAL=PLATE")


def write_outputs(w, print_every):
    """The step's outputs: the plate's total reaction every `print_every` increments, the
    displacements of the pole and the far pole."""
    w(f"*NODE PRINT, NSET=NPLATE, TOTALS=ONLY, FREQUENCY={print_every}")
    w("RF")
    w("*NODE PRINT, NSET=POLE")
    w("U")
    w("*NODE PRINT, NSET=FARPOLE")
    w("U")
