"""Checks the ParaView output of a 3D run (issue 28, H) with VTK's own reader
(vtkXMLUnstructuredGridReader, python3-vtk9), on the last frame of DIRECTORY/solution.pvd and
DIRECTORY/contact_surface.pvd (one piece each: a one-rank run):

 - every solution cell is a VTK Lagrange hexahedron (type 72, 27 points: a Q2 cell is one curved
   cell, not eight linear ones) and every contact-surface cell a Lagrange quadrilateral (type 70);
 - the solution carries every field of a 2D run in its 3D form: displacement, velocity,
   acceleration and contact traction with 3 components; the 6 Cauchy stress and 6 Green-Lagrange
   strain components (xx, yy, zz, xy, xz, yz); von Mises stress; body; the surface its contact
   pressure, gap and active flag;
 - the run is tests/cases/block_3d_on_plane.prm (a box pressed onto a rigid plane by a uniform
   dead traction 1 per reference area, linear elastic, lateral strain nu / E = 3e-4): its exact
   stress is uniform, the load over the current cross-section: Cauchy sigma_zz = -1 / (1 + 3e-4)^2,
   every other component 0, von Mises 1 / (1 + 3e-4)^2, and the same contact pressure at every
   surface point, each within TOLERANCE (float32 output and the stress recovered from the
   displacement gradient: 1e-5 is far above both, and far below the 6e-4 that a stress on the
   reference area would be off).

Usage: check_vtu_3d.py DIRECTORY TOLERANCE. Exit 1 with the first failure, 0 otherwise."""
import sys
import xml.etree.ElementTree as ElementTree

import vtk
from vtk.util.numpy_support import vtk_to_numpy

VECTOR_FIELDS = ["displacement", "velocity", "acceleration", "contact_traction"]
COMPONENTS = ["xx", "yy", "zz", "xy", "xz", "yz"]
SCALAR_FIELDS = ["von_mises_stress", "body"] + [
    f"{quantity}_{c}" for quantity in ("cauchy_stress", "green_lagrange_strain")
    for c in COMPONENTS]
SURFACE_FIELDS = ["contact_pressure", "gap", "active"]


def fail(message):
    print("check_vtu_3d: " + message)
    sys.exit(1)


def last_frame(directory, name):
    """The last piece file that DIRECTORY/NAME.pvd lists, read by VTK's XML reader."""
    datasets = ElementTree.parse(f"{directory}/{name}.pvd").getroot().iter("DataSet")
    parallel = f"{directory}/{list(datasets)[-1].get('file')}"
    piece = ElementTree.parse(parallel).getroot().find(".//Piece").get("Source")
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(f"{directory}/{piece}")
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetNumberOfCells() == 0:
        fail(f"VTK read no cells from {directory}/{piece}")
    return f"{directory}/{piece}", grid


def check_cells(path, grid, cell_type, points_per_cell):
    types = {grid.GetCellType(i) for i in range(grid.GetNumberOfCells())}
    sizes = {grid.GetCell(i).GetNumberOfPoints() for i in range(grid.GetNumberOfCells())}
    if types != {cell_type} or sizes != {points_per_cell}:
        fail(f"{path}: cell types {types} with {sizes} points, expected only {cell_type} with "
             f"{points_per_cell}")


def field(path, grid, name, components):
    array = grid.GetPointData().GetArray(name)
    if array is None:
        fail(f"{path}: no point field '{name}'")
    if array.GetNumberOfComponents() != components:
        fail(f"{path}: '{name}' has {array.GetNumberOfComponents()} components, not {components}")
    return vtk_to_numpy(array)


def main():
    directory, tolerance = sys.argv[1], float(sys.argv[2])
    path, solution = last_frame(directory, "solution")
    check_cells(path, solution, vtk.VTK_LAGRANGE_HEXAHEDRON, 27)
    for name in VECTOR_FIELDS:
        field(path, solution, name, 3)
    values = {name: field(path, solution, name, 1) for name in SCALAR_FIELDS}
    current_load = 1. / (1. + 3e-4) ** 2
    exact = {f"cauchy_stress_{c}": 0. for c in COMPONENTS}
    exact["cauchy_stress_zz"] = -current_load
    exact["von_mises_stress"] = current_load
    for name, value in exact.items():
        error = abs(values[name] - value).max()
        print(f"check_vtu_3d: {name}: largest |value - {value:.8g}| = {error:.3g} over "
              f"{solution.GetNumberOfPoints()} points")
        if error > tolerance:
            fail(f"{path}: {name} is {value} in the exact solution, off by {error:.3g}")

    surface_path, surface = last_frame(directory, "contact_surface")
    check_cells(surface_path, surface, vtk.VTK_LAGRANGE_QUADRILATERAL, 9)
    field(surface_path, surface, "displacement", 3)
    for name in SURFACE_FIELDS:
        field(surface_path, surface, name, 1)
    pressure = field(surface_path, surface, "contact_pressure", 1)
    error = abs(pressure / current_load - 1.).max()
    print(f"check_vtu_3d: contact pressure: largest relative error {error:.3g} over "
          f"{surface.GetNumberOfPoints()} points")
    if error > tolerance:
        fail(f"{surface_path}: the contact pressure is off the uniform 1 / (1 + 3e-4)^2 by "
             f"{error:.3g}")
    print(f"check_vtu_3d: {path} and {surface_path} are VTK Lagrange cells with every field")


main()
