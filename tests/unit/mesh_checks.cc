#include "mesh_checks.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <gmsh.h>
#include <gtest/gtest.h>
#include <iostream>
#include <limits>

namespace dyncontact::testing
{
std::string mesh_path(const std::string& name)
{
  return std::string(DYNCONTACT_SOURCE_DIR) + "/meshes/" + name;
}

double body_volume(const Triangulation<2>& triangulation, const types::material_id body)
{
  const MappingQ<2> mapping(2);
  const FE_Q<2> fe(1);
  FEValues<2> fe_values(mapping, fe, QGauss<2>(3), update_quadrature_points | update_JxW_values);
  double volume = 0;
  for (const auto& cell : triangulation.active_cell_iterators())
    if (cell->material_id() == body)
    {
      fe_values.reinit(cell);
      for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
        volume += 2 * numbers::PI * fe_values.quadrature_point(q)[0] * fe_values.JxW(q);
    }
  return volume;
}

double relative_sphere_volume_error(const Triangulation<2>& triangulation,
                                    const types::material_id body,
                                    const double radius)
{
  const double exact = 4. / 3. * numbers::PI * std::pow(radius, 3);
  return std::abs(body_volume(triangulation, body) - exact) / exact;
}

std::vector<Point<2>> boundary_vertices(const Triangulation<2>& triangulation,
                                        const types::boundary_id id)
{
  std::vector<bool> taken(triangulation.n_vertices(), false);
  std::vector<Point<2>> points;
  for (const auto& face : triangulation.active_face_iterators())
    if (face->at_boundary() && face->boundary_id() == id)
      for (unsigned int v = 0; v < 2; ++v)
        if (!taken[face->vertex_index(v)])
        {
          taken[face->vertex_index(v)] = true;
          points.push_back(face->vertex(v));
        }
  return points;
}

std::vector<Point<2>> boundary_q2_nodes(const Triangulation<2>& triangulation,
                                        const types::boundary_id id)
{
  std::vector<Point<2>> nodes = boundary_vertices(triangulation, id);
  for (const auto& face : triangulation.active_face_iterators())
    if (face->at_boundary() && face->boundary_id() == id)
      nodes.push_back(face->center(/*respect_manifold=*/true));
  return nodes;
}

double largest_mismatch(const std::vector<Point<2>>& points, const std::vector<Point<2>>& targets)
{
  double largest = 0;
  for (const Point<2>& point : points)
  {
    double nearest = std::numeric_limits<double>::max();
    for (const Point<2>& target : targets)
      nearest = std::min(nearest, point.distance(target));
    largest = std::max(largest, nearest);
  }
  return largest;
}

std::vector<Point<2>> facing_cap(const std::vector<Point<2>>& surface_points,
                                 const Point<2>& centre,
                                 const Tensor<1, 2>& approach)
{
  std::vector<Point<2>> cap;
  for (const Point<2>& point : surface_points)
    if ((point - centre) * approach >= 0.5 * point.distance(centre))
      cap.push_back(point);
  return cap;
}

unsigned int count_without_partner_across(const std::vector<Point<2>>& slave_nodes,
                                          const std::vector<Point<2>>& master_nodes,
                                          const double tolerance)
{
  unsigned int n_without = 0;
  for (const Point<2>& slave : slave_nodes)
    n_without += std::none_of(master_nodes.begin(),
                              master_nodes.end(),
                              [&](const Point<2>& master)
                              { return std::abs(master[0] - slave[0]) <= tolerance; });
  return n_without;
}

unsigned int count_nonpositive_jacobians(const Triangulation<2>& triangulation)
{
  const MappingQ<2> mapping(2);
  const FE_Q<2> fe(1);
  FEValues<2> fe_values(mapping, fe, QGauss<2>(3), update_jacobians);
  unsigned int n_bad = 0;
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    fe_values.reinit(cell);
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      if (!(determinant(Tensor<2, 2>(fe_values.jacobian(q))) > 0))
        ++n_bad;
  }
  return n_bad;
}

double boundary_edge_at(const Triangulation<2>& triangulation,
                        const types::boundary_id id,
                        const Point<2>& point)
{
  for (const auto& face : triangulation.active_face_iterators())
    if (face->at_boundary() && face->boundary_id() == id)
      for (unsigned int v = 0; v < 2; ++v)
        if (face->vertex(v).distance(point) < 1e-12)
          return face->vertex(0).distance(face->vertex(1));
  return 0;
}

std::vector<int> write_second_order_msh(const std::string& geo_file,
                                        const std::map<std::string, double>& parameters,
                                        const std::string& msh_file)
{
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  // The ONELAB database (the .geo parameters) outlives gmsh::finalize(): start from scratch. The
  // first reading declares the parameters, the second one uses the values set in between.
  gmsh::onelab::clear();
  gmsh::open(geo_file);
  if (!parameters.empty())
  {
    for (const auto& [name, value] : parameters)
      gmsh::onelab::setNumber("Parameters/" + name, {value});
    gmsh::clear();
    gmsh::open(geo_file);
  }
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::setOrder(2);
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 2);
  gmsh::write(msh_file);
  gmsh::onelab::clear();
  gmsh::finalize();
  return types;
}

ScratchDirectory::ScratchDirectory()
{
  std::string name_template =
      (std::filesystem::temp_directory_path() / "dyncontact-test-XXXXXX").string();
  path = mkdtemp(name_template.data());
}

ScratchDirectory::~ScratchDirectory()
{
  std::filesystem::remove_all(path);
}

std::string ScratchDirectory::file(const std::string& name) const
{
  return (path / name).string();
}

std::string ScratchDirectory::write(const std::string& name, const std::string& content) const
{
  std::ofstream(file(name)) << content;
  return file(name);
}

std::vector<SphereGeometry> read_spheres(const std::string& filename,
                                         const std::map<std::string, double>& parameters,
                                         Triangulation<2>& triangulation)
{
  const MeshGeometry geometry = read_gmsh_mesh(filename, parameters, triangulation);
  std::vector<SphereGeometry> spheres;
  for (unsigned int body = 0; body < geometry.n_bodies; ++body)
    if (const std::optional<SphereGeometry> sphere = geometry.sphere(body))
      spheres.push_back(*sphere);
    else
      ADD_FAILURE() << "body " << body + 1 << " of " << filename << " is not a sphere";
  return spheres;
}

void expect_input_error(const std::string& filename,
                        const std::map<std::string, double>& parameters,
                        const std::string& expected_text)
{
  Triangulation<2> triangulation;
  try
  {
    read_gmsh_mesh(filename, parameters, triangulation);
    ADD_FAILURE() << "no InputError for " << filename;
  }
  catch (const InputError& error)
  {
    const std::string message = error.what();
    std::cout << "  InputError: " << message << std::endl;
    EXPECT_NE(message.find(filename), std::string::npos) << message;
    EXPECT_NE(message.find(expected_text), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(triangulation.n_cells(), 0u);
  }
}
} // namespace dyncontact::testing
