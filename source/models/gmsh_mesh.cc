#include <dyncontact/models/gmsh_mesh.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gmsh.h>
#include <limits>
#include <set>
#include <sstream>
#include <tuple>
#include <unistd.h>

namespace dyncontact
{
namespace
{
/** `text` with every run of white space (line breaks included) replaced by one blank. */
std::string one_line(const std::string& text)
{
  std::istringstream words(text);
  std::string word, line;
  while (words >> word)
    line += (line.empty() ? "" : " ") + word;
  return line;
}

/** The numbers of `numbers`, ascending, separated by ", " (e.g. "2, 3"). */
std::string listed(const std::set<unsigned int>& numbers)
{
  std::string list;
  for (const unsigned int number : numbers)
    list += (list.empty() ? "" : ", ") + std::to_string(number);
  return list;
}

/** The ONELAB folder of the parameters of a .geo file (DefineConstant ... Name "Parameters/x"). */
const std::string parameter_folder = "Parameters/";

/** The cells dyncontact takes in `dim` dimensions: "quadrilaterals" or "hexahedra". */
std::string cell_kind(const int dim)
{
  return dim == 2 ? "quadrilaterals" : "hexahedra";
}

/** The gmsh physical group of a body in `dim` dimensions: "physical surface" or "physical volume".
 */
std::string body_group(const int dim)
{
  return dim == 2 ? "physical surface" : "physical volume";
}

/** The start of every message about `filename`. */
std::string about(const std::string& filename)
{
  return "Mesh file '" + filename + "': ";
}

/**
 * One session of the gmsh library: initialized on construction and finalized on destruction, so
 * the two stay balanced when an exception leaves the scope. gmsh prints nothing to the terminal;
 * its messages are logged for logged_errors(). gmsh has global state: only one session may exist
 * at a time, and no other code may use gmsh meanwhile.
 */
class GmshSession
{
public:
  GmshSession()
  {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::logger::start();
    // The ONELAB database (the .geo parameters) outlives gmsh::finalize(): start from scratch.
    gmsh::onelab::clear();
  }

  ~GmshSession()
  {
    gmsh::onelab::clear();
    gmsh::logger::stop();
    gmsh::finalize();
  }

  GmshSession(const GmshSession&)            = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /** gmsh's error messages so far, joined into one line ("" if there were none). */
  std::string logged_errors() const
  {
    std::vector<std::string> log;
    gmsh::logger::get(log);
    const std::string error_prefix = "Error: ";
    std::string errors;
    for (const std::string& message : log)
      if (message.compare(0, error_prefix.size(), error_prefix) == 0)
        errors += (errors.empty() ? "" : "; ") + one_line(message.substr(error_prefix.size()));
    return errors;
  }
};

/**
 * A new, empty file with a unique name in the system's temporary directory, removed when this
 * object is destroyed. It is not opened: others write and read it by name.
 */
class TemporaryFile
{
public:
  /** Creates the file; its name ends in `suffix` (e.g. ".msh"). */
  explicit TemporaryFile(const std::string& suffix)
  {
    std::string name_template =
        (std::filesystem::temp_directory_path() / ("dyncontact-mesh-XXXXXX" + suffix)).string();
    const int descriptor = mkstemps(name_template.data(), static_cast<int>(suffix.size()));
    AssertThrow(descriptor != -1,
                ExcMessage("Cannot create a temporary file " + name_template +
                           " for the mesh written by gmsh."));
    close(descriptor);
    path = name_template;
  }

  ~TemporaryFile()
  {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }

  TemporaryFile(const TemporaryFile&)            = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  /** The file's full name. */
  const std::string& name() const { return path; }

private:
  std::string path;
};

/**
 * Opens `file` (.geo or .msh) in the gmsh session; gmsh's complaints about it become an
 * InputError naming the file.
 */
void open_file(const GmshSession& session, const std::string& file)
{
  const std::string failure = std::filesystem::path(file).extension() == ".msh"
                                  ? "not a readable gmsh mesh: "
                                  : "gmsh failed: ";
  try
  {
    gmsh::open(file);
  }
  catch (const std::string& gmsh_error)
  {
    // gmsh throws its first error's text; the log holds it together with earlier ones.
    const std::string errors = session.logged_errors();
    throw InputError(about(file) + failure + (errors.empty() ? one_line(gmsh_error) : errors));
  }
  const std::string errors = session.logged_errors();
  if (!errors.empty())
    throw InputError(about(file) + failure + errors);
}

/** The parameters of the .geo file open in the session, sorted, without the ONELAB folder. */
std::vector<std::string> declared_parameters()
{
  std::vector<std::string> names;
  gmsh::onelab::getNames(names, parameter_folder + ".*");
  for (std::string& name : names)
    name = name.substr(parameter_folder.size());
  std::sort(names.begin(), names.end());
  return names;
}

/**
 * Checks the element types of the mesh in the session: `dim`-dimensional cells quadrilaterals
 * (dim 2) or hexahedra (dim 3) of any order, lower-dimensional elements on the boundary, nothing
 * else; throws InputError naming `filename` and the types found otherwise. Returns whether some
 * elements are of higher order than 1.
 */
bool check_element_types(const std::string& filename, const int cell_dim)
{
  const std::string allowed = cell_dim == 2 ? "Quadrilateral" : "Hexahedron";
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types);
  std::size_t n_cells = 0, n_other_cells = 0;
  std::string other_types;
  bool higher_order = false;
  for (const int type : types)
  {
    std::string name;
    int dim, order, n_nodes, n_primary_nodes;
    std::vector<double> local_coordinates;
    gmsh::model::mesh::getElementProperties(
        type, name, dim, order, n_nodes, local_coordinates, n_primary_nodes);
    std::vector<std::size_t> elements, nodes;
    gmsh::model::mesh::getElementsByType(type, elements, nodes);
    higher_order = higher_order || order > 1;
    if (dim < cell_dim)
      continue;
    n_cells += elements.size();
    if (dim > cell_dim || name.compare(0, allowed.size(), allowed) != 0)
    {
      n_other_cells += elements.size();
      other_types +=
          (other_types.empty() ? "" : ", ") + std::to_string(elements.size()) + " '" + name + "'";
    }
  }
  if (n_other_cells > 0)
    throw InputError(
        about(filename) + std::to_string(n_other_cells) + " of its " + std::to_string(n_cells) +
        " cells are not " + cell_kind(cell_dim) + " (" + other_types + "); only " +
        (cell_dim == 2 ? "quadrilaterals (4-, 8- or 9-node) are allowed (in a .geo file: "
                         "Transfinite and Recombine Surface)."
                       : "hexahedra (8-, 20- or 27-node) are allowed (in a .geo file: "
                         "Transfinite Volume and Recombine, or an Extrude with Layers and "
                         "Recombine)."));
  return higher_order;
}

/**
 * Prepares `mesh_file` for deal.II's reader, which takes first-order cells only, and returns the
 * name of the file it is to read. A .geo file is meshed in 2D with gmsh, after its parameters are
 * set, into linear quadrilaterals (recombined) and written to `msh_file` (ASCII format 4.1, the
 * elements of the physical groups): `msh_file` is returned. A .msh file is read by gmsh to check
 * its element types (check_element_types()); one of higher order is reduced to first order on
 * the same vertices (the mapping curves the boundary from the manifolds) and written, whole, to
 * `msh_file`, which is returned; a first-order one is returned as it is, for deal.II to read
 * directly (its tags element by element, as in gmsh format 2). It does not check cells and
 * groups; read_msh_file() and the checks after it do.
 */
std::string first_order_mesh(const std::string& mesh_file,
                             const std::map<std::string, double>& geo_parameters,
                             const std::string& msh_file,
                             const int dim)
{
  GmshSession session;
  const bool is_geo = std::filesystem::path(mesh_file).extension() == ".geo";
  // The first pass declares the parameters (with their defaults) in gmsh's ONELAB database;
  // the second reads the file again with the values set there.
  open_file(session, mesh_file);
  // A file of the other dimension would be meshed (or read) into cells of the wrong kind: a 3D
  // .geo meshed in 2D gives the quadrilaterals of its surfaces, at any z.
  const int file_dim = gmsh::model::getDimension();
  if (file_dim >= 2 && file_dim != dim)
    throw InputError(
        about(mesh_file) + "it is a " + std::to_string(file_dim) + "D geometry, but " +
        (dim == 2 ? "Problem/geometry = axisymmetric mesh and plane strain mesh take 2D ones (the "
                    "(r, z) or (x, y) plane: physical surface b = body b); 3D meshes are not a "
                    "Problem/geometry yet."
                  : "a 3D mesh needs volumes (physical volume b = body b)."));
  if (!geo_parameters.empty())
  {
    const std::vector<std::string> declared = declared_parameters();
    for (const auto& [name, value] : geo_parameters)
    {
      if (std::find(declared.begin(), declared.end(), name) == declared.end())
      {
        std::string allowed;
        for (const std::string& declared_name : declared)
          allowed += (allowed.empty() ? "" : ", ") + declared_name;
        throw InputError(about(mesh_file) + "it has no parameter '" + name +
                         "'; its parameters are: " + (allowed.empty() ? "none" : allowed) + ".");
      }
      gmsh::onelab::setNumber(parameter_folder + name, {value});
    }
    gmsh::clear();
    open_file(session, mesh_file);
  }

  try
  {
    if (is_geo)
    {
      gmsh::option::setNumber("Mesh.ElementOrder", 1);
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
      // gmsh meshes surfaces inside an OpenMP region, out of which its error exception (e.g. a
      // transfinite surface whose sides do not match) ended the process: while meshing, an error
      // only stops the meshing, and the errors it logged are reported below.
      gmsh::option::setNumber("General.AbortOnError", 1);
      gmsh::model::mesh::generate(dim);
    }
    const bool higher_order = check_element_types(mesh_file, dim);
    if (!is_geo && !higher_order)
      return mesh_file;
    if (higher_order)
      gmsh::model::mesh::setOrder(1);
    // A .msh file is written whole, so that cells outside the physical groups are found later.
    gmsh::option::setNumber("Mesh.SaveAll", is_geo ? 0 : 1);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::write(msh_file);
  }
  catch (const std::string& gmsh_error)
  {
    const std::string errors = session.logged_errors();
    throw InputError(about(mesh_file) +
                     "gmsh failed: " + (errors.empty() ? one_line(gmsh_error) : errors));
  }

  const std::string errors = session.logged_errors();
  if (!errors.empty())
    throw InputError(about(mesh_file) + "gmsh failed: " + errors);
  return msh_file;
}

/**
 * Reads the .msh file `msh_file` with deal.II's GridIn into the empty `triangulation`; messages
 * name `reported_file` (the file the user gave). Material and boundary ids are gmsh's physical
 * tags; untagged boundary faces get boundary id 0.
 */
template <int dim>
void read_msh_file(const std::string& msh_file,
                   const std::string& reported_file,
                   Triangulation<dim>& triangulation)
{
  std::ifstream input(msh_file);
  GridIn<dim> grid_in;
  grid_in.attach_triangulation(triangulation);
  try
  {
    grid_in.read_msh(input);
  }
  catch (const ExceptionBase& error)
  {
    std::ostringstream details;
    error.print_info(details);
    throw InputError(about(reported_file) + "not a readable gmsh mesh: " + one_line(details.str()));
  }
}

/**
 * Checks that the cells are all quadrilaterals (hexahedra in 3D), each in a physical surface
 * (volume), and that these are numbered 1, ..., n; turns physical group b + 1 into material id b.
 * Returns n.
 */
template <int dim>
unsigned int assign_bodies(const std::string& filename, Triangulation<dim>& triangulation)
{
  unsigned int n_other_cells = 0;
  std::set<unsigned int> body_tags;
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    if (cell->reference_cell() != ReferenceCells::get_hypercube<dim>())
      ++n_other_cells;
    body_tags.insert(cell->material_id());
  }
  if (n_other_cells > 0)
    throw InputError(about(filename) + std::to_string(n_other_cells) + " of its " +
                     std::to_string(triangulation.n_active_cells()) + " cells are not " +
                     cell_kind(dim) + "; only " + cell_kind(dim) + " are allowed.");
  if (body_tags.count(0) > 0)
    throw InputError(about(filename) + "some cells belong to no " + body_group(dim) +
                     "; every cell must be in " + body_group(dim) +
                     " b for its body b = 1, 2, ...");

  const unsigned int n_bodies = *body_tags.rbegin();
  if (body_tags.size() != n_bodies)
    throw InputError(about(filename) + "its " + body_group(dim) + "s are " + listed(body_tags) +
                     ", but they must be numbered 1, 2, ..., one per body, without gaps.");

  for (const auto& cell : triangulation.active_cell_iterators())
    cell->set_material_id(cell->material_id() - 1);
  return n_bodies;
}

/** The boundary faces of one physical curve other than the axis, as collect_curves() found them. */
struct CurveFaces
{
  /** The bodies (0-based) of the faces' cells. */
  std::set<unsigned int> bodies;

  /** The two vertices of every face, face by face (shared vertices twice). */
  std::vector<Point<2>> vertices;

  /** Sum over the faces of the vector from the cell's centre to the face's: out of the body. */
  Tensor<1, 2> outward;
};

/**
 * Checks that every boundary face is in a physical curve, and for an axisymmetric mesh that it
 * lies in r >= 0, that the faces of physical curve 1 lie on the axis r = 0 and that all boundary
 * faces on r = 0 are in it (so curve 1 may be absent only if no boundary face lies on r = 0).
 * Returns the faces of every other physical curve (every curve in plane strain), by tag.
 */
std::map<types::boundary_id, CurveFaces> collect_curves(const std::string& filename,
                                                        const Triangulation<2>& triangulation,
                                                        const MeshSection section)
{
  const bool axisymmetric = section == MeshSection::axisymmetric;
  const double tolerance  = 1e-8 * GridTools::diameter(triangulation);
  if (axisymmetric)
    for (const Point<2>& vertex : triangulation.get_vertices())
      if (vertex[0] < -tolerance)
        throw InputError(about(filename) + "it has a vertex at r = x = " +
                         format_number(vertex[0]) + "; an axisymmetric mesh must lie in r >= 0.");

  bool has_axis = false;
  std::set<unsigned int> curves_on_axis;
  std::map<types::boundary_id, CurveFaces> curves;
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const auto& face : cell->face_iterators())
    {
      if (!face->at_boundary())
        continue;
      const types::boundary_id id = face->boundary_id();
      const bool on_axis          = axisymmetric && std::abs(face->vertex(0)[0]) <= tolerance &&
                           std::abs(face->vertex(1)[0]) <= tolerance;
      if (id == 0)
        throw InputError(about(filename) + "the boundary face of body " +
                         std::to_string(cell->material_id() + 1) + " from (" +
                         format_number(face->vertex(0)[0]) + ", " +
                         format_number(face->vertex(0)[1]) + ") to (" +
                         format_number(face->vertex(1)[0]) + ", " +
                         format_number(face->vertex(1)[1]) +
                         (axisymmetric ? ") (r, z) belongs to no physical curve; each boundary "
                                         "face must be in physical curve 1 (axis) or in a "
                                         "physical curve t >= 2 of one body."
                                       : ") (x, y) belongs to no physical curve; each boundary "
                                         "face must be in a physical curve t >= 1 of one body."));
      if (axisymmetric && id == SphereMeshIds::axis)
      {
        if (!on_axis)
          throw InputError(about(filename) + "physical curve " + std::to_string(id) +
                           " (the axis) has faces off the axis r = 0.");
        has_axis = true;
        continue;
      }
      if (on_axis)
        curves_on_axis.insert(id);
      CurveFaces& curve = curves[id];
      curve.bodies.insert(cell->material_id());
      curve.vertices.push_back(face->vertex(0));
      curve.vertices.push_back(face->vertex(1));
      curve.outward += face->center() - cell->center();
    }

  if (!curves_on_axis.empty())
  {
    const std::string curves_named =
        (curves_on_axis.size() == 1 ? "physical curve " : "physical curves ") +
        listed(curves_on_axis);
    throw InputError(about(filename) + (has_axis ? "the faces of " + curves_named +
                                                       " on the axis r = 0 belong in physical "
                                                       "curve 1 (the axis)."
                                                 : "physical curve 1 (the axis r = 0) is "
                                                   "missing; its faces are in " +
                                                       curves_named + "."));
  }
  return curves;
}

/**
 * The circle centred on the axis that fits `points` best (least squares in r^2 + (z - z_c)^2 =
 * R^2, linear in z_c and R^2 - z_c^2). Its radius is not finite if no such circle fits (points at
 * one z).
 */
SphereGeometry fit_circle_on_axis(const std::vector<Point<2>>& points)
{
  // Work in z relative to the mean, which decouples the two unknowns.
  double mean_z = 0;
  for (const Point<2>& point : points)
    mean_z += point[1] / points.size();
  double sum_z2 = 0, sum_z_rho2 = 0, mean_rho2 = 0;
  for (const Point<2>& point : points)
  {
    const double z    = point[1] - mean_z;
    const double rho2 = point[0] * point[0] + z * z;
    sum_z2 += z * z;
    sum_z_rho2 += z * rho2;
    mean_rho2 += rho2 / points.size();
  }
  // sum_z2 = 0 gives a centre and radius of inf or NaN.
  const double shifted_centre_z = sum_z_rho2 / (2 * sum_z2);

  SphereGeometry circle;
  circle.centre = Point<2>(0, mean_z + shifted_centre_z);
  circle.radius = std::sqrt(mean_rho2 + shifted_centre_z * shifted_centre_z);
  return circle;
}

/**
 * The circle of any centre that fits `points` best (Kasa's algebraic fit: least squares in
 * |p - c|^2 = R^2, linear in c and R^2 - |c|^2, about the points' mean). Its radius is not finite
 * if no circle fits (collinear points).
 */
SphereGeometry fit_circle(const std::vector<Point<2>>& points)
{
  Point<2> mean;
  for (const Point<2>& point : points)
    mean += point / static_cast<double>(points.size());
  // Normal equations of (x, y, 1) . (2 c_x, 2 c_y, R^2 - |c|^2) = x^2 + y^2 in shifted
  // coordinates, where the mean of x and y vanishes and the 3x3 system splits into 2x2 and 1x1.
  double s_xx = 0, s_xy = 0, s_yy = 0, s_xq = 0, s_yq = 0, mean_q = 0;
  for (const Point<2>& point : points)
  {
    const Tensor<1, 2> d = point - mean;
    const double q       = d.norm_square();
    s_xx += d[0] * d[0];
    s_xy += d[0] * d[1];
    s_yy += d[1] * d[1];
    s_xq += d[0] * q;
    s_yq += d[1] * q;
    mean_q += q / points.size();
  }
  const double determinant = s_xx * s_yy - s_xy * s_xy;
  const Tensor<1, 2> shifted_centre({(s_yy * s_xq - s_xy * s_yq) / (2 * determinant),
                                     (s_xx * s_yq - s_xy * s_xq) / (2 * determinant)});
  SphereGeometry circle;
  circle.centre = mean + shifted_centre;
  circle.radius = std::sqrt(mean_q + shifted_centre.norm_square());
  return circle;
}

/**
 * The straight line that fits `points` best (total least squares: through their mean, along the
 * principal direction of their scatter), as the mean and the unit normal, and its length: the
 * extent of the points along it.
 */
std::tuple<Point<2>, Tensor<1, 2>, double> fit_line(const std::vector<Point<2>>& points)
{
  Point<2> mean;
  for (const Point<2>& point : points)
    mean += point / static_cast<double>(points.size());
  double s_rr = 0, s_rz = 0, s_zz = 0;
  for (const Point<2>& point : points)
  {
    const Tensor<1, 2> d = point - mean;
    s_rr += d[0] * d[0];
    s_rz += d[0] * d[1];
    s_zz += d[1] * d[1];
  }
  const double angle = 0.5 * std::atan2(2 * s_rz, s_rr - s_zz);
  const Tensor<1, 2> direction({std::cos(angle), std::sin(angle)});
  const Tensor<1, 2> normal({-std::sin(angle), std::cos(angle)});
  double lowest = 0, highest = 0;
  for (const Point<2>& point : points)
  {
    lowest  = std::min(lowest, (point - mean) * direction);
    highest = std::max(highest, (point - mean) * direction);
  }
  return {mean, normal, highest - lowest};
}

/**
 * Physical curve `id` with the faces `faces`, classified: its body (all faces must bound cells of
 * one body), a straight line if every vertex lies within 1e-6 of the curve's length from the
 * best-fit line (the normal oriented out of the body), else a circle centred on the axis if every
 * vertex lies within 1e-6 R of the best-fit one. Throws InputError naming `filename` otherwise.
 */
BoundaryCurve classify_curve(const std::string& filename,
                             const types::boundary_id id,
                             const CurveFaces& faces,
                             const MeshSection section)
{
  const bool axisymmetric = section == MeshSection::axisymmetric;
  const std::string curve = "physical curve " + std::to_string(id);
  if (faces.bodies.size() > 1)
  {
    std::set<unsigned int> bodies;
    for (const unsigned int body : faces.bodies)
      bodies.insert(body + 1);
    throw InputError(
        about(filename) + curve + " bounds cells of bodies " + listed(bodies) +
        (axisymmetric ? "; each physical curve other than the axis (1) must bound one body only."
                      : "; each physical curve must bound one body only."));
  }
  BoundaryCurve classified;
  classified.id   = id;
  classified.body = *faces.bodies.begin();

  const auto [mean, normal, length] = fit_line(faces.vertices);
  double line_deviation             = 0;
  for (const Point<2>& point : faces.vertices)
    line_deviation = std::max(line_deviation, std::abs((point - mean) * normal));
  if (line_deviation <= 1e-6 * length)
  {
    classified.line = {mean, normal * faces.outward > 0 ? normal : -normal};
    return classified;
  }

  const SphereGeometry circle =
      axisymmetric ? fit_circle_on_axis(faces.vertices) : fit_circle(faces.vertices);
  double circle_deviation = 0;
  for (const Point<2>& point : faces.vertices)
    circle_deviation =
        std::max(circle_deviation, std::abs(point.distance(circle.centre) - circle.radius));
  if (std::isfinite(circle.radius) && circle_deviation <= 1e-6 * circle.radius)
  {
    classified.circle = circle;
    return classified;
  }
  throw InputError(
      about(filename) + curve + " (of body " + std::to_string(classified.body + 1) +
      (axisymmetric ? ") is neither a circle centred on the axis r = 0 nor a straight line; the "
                      "best-fit line "
                    : ") is neither a circle nor a straight line; the best-fit line ") +
      "misses a vertex by " + format_number(line_deviation) + " (allowed: 1e-6 of its length " +
      format_number(length) + ")" +
      (std::isfinite(circle.radius)
           ? ", the best-fit circle, centre (" + format_number(circle.centre[0]) + ", " +
                 format_number(circle.centre[1]) + ")" + " and radius " +
                 format_number(circle.radius) + ", by " + format_number(circle_deviation) +
                 " (allowed: 1e-6 of the radius)"
           : "") +
      "; put its straight and circular parts (e.g. a striker's side and its spherical end) in "
      "physical curves of their own.");
}

/**
 * Sets the manifold ids of read_gmsh_mesh(): each circular curve's id on its faces, and
 * SphereMeshIds::interior_manifold on the cells with a face on one (attach_manifolds() then gives
 * them their manifolds).
 */
void set_manifold_ids(const MeshGeometry& geometry, Triangulation<2>& triangulation)
{
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const auto& face : cell->face_iterators())
      if (face->at_boundary())
      {
        const BoundaryCurve* curve = geometry.curve(face->boundary_id());
        if (curve != nullptr && curve->circle)
        {
          face->set_manifold_id(curve->id);
          cell->set_manifold_id(SphereMeshIds::interior_manifold);
        }
      }
}
/**
 * Reads `filename` (.geo meshed in `dim` dimensions, or .msh) in first order into the empty
 * `triangulation` (see read_gmsh_mesh()); the file's existence and extension are checked first.
 * Throws InputError naming the file, the triangulation left empty.
 */
template <int dim>
void read_first_order_mesh(const std::string& filename,
                           const std::map<std::string, double>& geo_parameters,
                           Triangulation<dim>& triangulation)
{
  Assert(triangulation.n_cells() == 0, ExcMessage("The triangulation must be empty."));
  std::error_code file_status_error;
  if (!std::filesystem::is_regular_file(filename, file_status_error) || !std::ifstream(filename))
    throw InputError(about(filename) + "it does not exist or cannot be read.");
  const std::string extension = std::filesystem::path(filename).extension().string();
  if (extension != ".geo" && extension != ".msh")
    throw InputError(about(filename) + "unknown extension '" + extension +
                     "'; allowed are .geo (meshed by gmsh) and .msh (a gmsh mesh).");
  if (extension == ".msh" && !geo_parameters.empty())
    throw InputError(about(filename) + "a .msh file is a finished mesh and takes no parameters (" +
                     geo_parameters.begin()->first +
                     " was given); parameters apply to .geo files.");
  try
  {
    const TemporaryFile msh_file(".msh");
    read_msh_file(
        first_order_mesh(filename, geo_parameters, msh_file.name(), dim), filename, triangulation);
  }
  catch (const InputError&)
  {
    triangulation.clear();
    throw;
  }
}

/**
 * The plane that fits `points` best (through their mean, normal along the direction of least
 * scatter) and the largest distance of a point from it.
 */
std::tuple<Point<3>, Tensor<1, 3>, double> fit_plane(const std::vector<Point<3>>& points)
{
  Point<3> mean;
  for (const Point<3>& point : points)
    mean += point / static_cast<double>(points.size());
  SymmetricTensor<2, 3> scatter;
  for (const Point<3>& point : points)
    scatter += symmetrize(outer_product(point - mean, point - mean));
  // eigenvectors() sorts by descending eigenvalue: the last is the normal.
  const Tensor<1, 3> normal = eigenvectors(scatter)[2].second;
  double deviation          = 0.;
  for (const Point<3>& point : points)
    deviation = std::max(deviation, std::abs((point - mean) * normal));
  return {mean, normal, deviation};
}

/**
 * Attaches the TransfiniteInterpolationManifold (SphereMeshIds::interior_manifold) of the cells
 * with a face on a curved boundary; it interpolates from the cells' boundaries, so the boundary
 * manifolds must be in place.
 */
template <int dim>
void attach_interior_manifold(Triangulation<dim>& triangulation)
{
  TransfiniteInterpolationManifold<dim> interior;
  interior.initialize(triangulation);
  triangulation.set_manifold(SphereMeshIds::interior_manifold, interior);
}

/**
 * The sphere that fits `points` best in the algebraic least-squares sense (|p|^2 = 2 c.p + d,
 * d = R^2 - |c|^2) and the largest distance of a point from it; a radius of 0 if the points do
 * not determine one (all on a plane or a line).
 */
std::tuple<Point<3>, double, double> fit_sphere(const std::vector<Point<3>>& points)
{
  // In coordinates relative to the points' mean, scaled by their spread, so that the normal
  // equations do not lose digits far from the origin.
  Point<3> mean;
  for (const Point<3>& point : points)
    mean += point / static_cast<double>(points.size());
  double scale = 0.;
  for (const Point<3>& point : points)
    scale = std::max(scale, point.distance(mean));
  if (!(scale > 0.))
    return {mean, 0., std::numeric_limits<double>::infinity()};
  FullMatrix<double> normal_matrix(4, 4);
  Vector<double> right_hand_side(4), coefficients(4);
  for (const Point<3>& point : points)
  {
    const Tensor<1, 3> q = (point - mean) / scale;
    const std::array<double, 4> row{{2. * q[0], 2. * q[1], 2. * q[2], 1.}};
    for (unsigned int i = 0; i < 4; ++i)
    {
      for (unsigned int j = 0; j < 4; ++j)
        normal_matrix(i, j) += row[i] * row[j];
      right_hand_side(i) += row[i] * q.norm_square();
    }
  }
  normal_matrix.gauss_jordan();
  normal_matrix.vmult(coefficients, right_hand_side);
  const Tensor<1, 3> centre_offset({coefficients(0), coefficients(1), coefficients(2)});
  const double radius_squared = coefficients(3) + centre_offset.norm_square();
  // Singular equations (points on a plane or a line) give no finite, positive radius.
  if (!(radius_squared > 0.) || !std::isfinite(radius_squared))
    return {mean, 0., std::numeric_limits<double>::infinity()};
  const Point<3> centre = mean + scale * centre_offset;
  const double radius   = scale * std::sqrt(radius_squared);
  double deviation      = 0.;
  for (const Point<3>& point : points)
    deviation = std::max(deviation, std::abs(point.distance(centre) - radius));
  return {centre, radius, deviation};
}
} // namespace

SolidMeshGeometry read_gmsh_solid_mesh(const std::string& filename,
                                       const std::map<std::string, double>& geo_parameters,
                                       Triangulation<3>& triangulation)
{
  read_first_order_mesh(filename, geo_parameters, triangulation);
  try
  {
    SolidMeshGeometry geometry;
    geometry.n_bodies = assign_bodies(filename, triangulation);
    // The faces of each physical surface: their bodies, vertices and outward direction.
    struct SurfaceFaces
    {
      std::set<unsigned int> bodies;
      std::vector<Point<3>> vertices;
      Tensor<1, 3> outward;
      std::map<unsigned int, unsigned int> faces_at_vertex; ///< by vertex index
    };
    std::map<types::boundary_id, SurfaceFaces> surfaces;
    for (const auto& cell : triangulation.active_cell_iterators())
      for (const auto& face : cell->face_iterators())
        if (face->at_boundary())
        {
          if (face->boundary_id() == 0)
            throw InputError(about(filename) + "a boundary face of body " +
                             std::to_string(cell->material_id() + 1) + " at (" +
                             format_number(face->center()[0]) + ", " +
                             format_number(face->center()[1]) + ", " +
                             format_number(face->center()[2]) +
                             ") belongs to no physical surface; each boundary face must be in a "
                             "physical surface t >= 1 of one body.");
          SurfaceFaces& faces = surfaces[face->boundary_id()];
          faces.bodies.insert(cell->material_id());
          for (const unsigned int v : face->vertex_indices())
          {
            faces.vertices.push_back(face->vertex(v));
            ++faces.faces_at_vertex[face->vertex_index(v)];
          }
          faces.outward += face->center() - cell->center();
        }
    const double size = GridTools::diameter(triangulation);
    for (const auto& [id, faces] : surfaces)
    {
      const std::string surface = "physical surface " + std::to_string(id);
      if (faces.bodies.size() > 1)
        throw InputError(about(filename) + surface +
                         " bounds cells of more than one body; each "
                         "physical surface must bound one body only.");
      const unsigned int body               = *faces.bodies.begin();
      const auto [point, normal, deviation] = fit_plane(faces.vertices);
      if (deviation <= 1e-6 * size)
      {
        geometry.surfaces.push_back(
            {id,
             body,
             SurfacePlane{point, normal * faces.outward > 0 ? normal : -normal},
             std::nullopt});
        continue;
      }
      const auto [centre, radius, sphere_deviation] = fit_sphere(faces.vertices);
      // Vertices all on the surface's boundary (one layer of faces) may lie on two coaxial circles,
      // which one sphere always passes through: a cylinder or a cone is no sphere. A sphere needs
      // a vertex inside the surface (at least three of its faces around it).
      const bool has_inner_vertex =
          std::any_of(faces.faces_at_vertex.begin(),
                      faces.faces_at_vertex.end(),
                      [](const auto& vertex) { return vertex.second >= 3; });
      if (!has_inner_vertex)
        throw InputError(about(filename) + surface + " (of body " + std::to_string(body + 1) +
                         ") is not a plane (a vertex lies " + format_number(deviation) +
                         " from its best-fit plane), and it has no vertex inside it, so it cannot "
                         "be told from a cylinder or cone: a curved surface must be a sphere "
                         "meshed with at least two layers of faces.");
      if (!(sphere_deviation <= 1e-6 * radius))
        throw InputError(about(filename) + surface + " (of body " + std::to_string(body + 1) +
                         ") is neither a plane (a vertex lies " + format_number(deviation) +
                         " from its best-fit plane) nor a sphere (" +
                         (radius > 0. ? "a vertex lies " + format_number(sphere_deviation) +
                                            " from its best-fit sphere"
                                      : std::string("no sphere fits")) +
                         "): split it into physical surfaces of these two kinds.");
      geometry.surfaces.push_back({id, body, std::nullopt, SurfaceSphere{centre, radius}});
    }
    // A plane meeting a sphere along an edge must pass through its centre: the spherical
    // manifold puts the edge's mid-side nodes on a great circle, off any other plane.
    for (const BoundarySurface& sphere : geometry.surfaces)
      for (const BoundarySurface& plane : geometry.surfaces)
        if (sphere.sphere && plane.plane && sphere.body == plane.body)
        {
          const auto& sphere_vertices = surfaces.at(sphere.id).faces_at_vertex;
          bool shares_a_vertex        = false;
          for (const auto& vertex : surfaces.at(plane.id).faces_at_vertex)
            shares_a_vertex = shares_a_vertex || sphere_vertices.count(vertex.first) > 0;
          const double offset =
              std::abs((sphere.sphere->centre - plane.plane->point) * plane.plane->normal);
          if (shares_a_vertex && offset > 1e-6 * sphere.sphere->radius)
            throw InputError(about(filename) + "physical surface " + std::to_string(plane.id) +
                             " (a plane) meets the sphere of physical surface " +
                             std::to_string(sphere.id) + " but misses its centre by " +
                             format_number(offset) +
                             ": a plane next to a sphere must pass through its centre (their "
                             "common edges are curved along great circles).");
        }
    for (const auto& cell : triangulation.active_cell_iterators())
      for (const auto& face : cell->face_iterators())
        if (face->at_boundary() && geometry.surface(face->boundary_id())->sphere)
        {
          face->set_all_manifold_ids(face->boundary_id());
          cell->set_manifold_id(SphereMeshIds::interior_manifold);
        }
    attach_manifolds(geometry, triangulation);
    return geometry;
  }
  catch (const InputError&)
  {
    triangulation.clear();
    throw;
  }
}

void attach_manifolds(const SolidMeshGeometry& geometry, Triangulation<3>& triangulation)
{
  for (const BoundarySurface& surface : geometry.surfaces)
    if (surface.sphere)
      triangulation.set_manifold(surface.id, SphericalManifold<3>(surface.sphere->centre));
  attach_interior_manifold(triangulation);
}

const BoundarySurface* SolidMeshGeometry::surface(const types::boundary_id id) const
{
  for (const BoundarySurface& candidate : surfaces)
    if (candidate.id == id)
      return &candidate;
  return nullptr;
}

const BoundaryCurve* MeshGeometry::curve(const types::boundary_id id) const
{
  const auto found = std::lower_bound(curves.begin(),
                                      curves.end(),
                                      id,
                                      [](const BoundaryCurve& curve, const types::boundary_id key)
                                      { return curve.id < key; });
  return found != curves.end() && found->id == id ? &*found : nullptr;
}

std::optional<SphereGeometry> MeshGeometry::sphere(const unsigned int body) const
{
  const BoundaryCurve* only = nullptr;
  unsigned int n_curves     = 0;
  for (const BoundaryCurve& curve : curves)
    if (curve.body == body)
    {
      only = &curve;
      ++n_curves;
    }
  return n_curves == 1 ? only->circle : std::nullopt;
}

void attach_manifolds(const MeshGeometry& geometry, Triangulation<2>& triangulation)
{
  for (const BoundaryCurve& curve : geometry.curves)
    if (curve.circle)
      triangulation.set_manifold(curve.id, SphericalManifold<2>(curve.circle->centre));
  attach_interior_manifold(triangulation);
}

MeshGeometry read_gmsh_mesh(const std::string& filename,
                            const std::map<std::string, double>& geo_parameters,
                            Triangulation<2>& triangulation,
                            const MeshSection section)
{
  read_first_order_mesh(filename, geo_parameters, triangulation);
  try
  {
    MeshGeometry geometry;
    geometry.n_bodies = assign_bodies(filename, triangulation);
    for (const auto& [id, faces] : collect_curves(filename, triangulation, section))
      geometry.curves.push_back(classify_curve(filename, id, faces, section));
    set_manifold_ids(geometry, triangulation);
    attach_manifolds(geometry, triangulation);
    return geometry;
  }
  catch (const InputError&)
  {
    triangulation.clear();
    throw;
  }
}

std::vector<std::string> geo_file_parameters(const std::string& geo_file)
{
  GmshSession session;
  open_file(session, geo_file);
  return declared_parameters();
}
} // namespace dyncontact
