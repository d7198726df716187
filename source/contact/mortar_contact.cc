#include <dyncontact/contact/face_patch.h>
#include <dyncontact/contact/mortar_contact.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace dyncontact
{
namespace
{
/// Gauss points per piece of a slave face: exact for polynomials of degree 11 (psi_j N_m times
/// the measure of a straight face, degree 4 in plane strain and 5 in axisymmetry).
constexpr unsigned int gauss_points = 6;
/// A slave node keeps the projected point if its dual area is below this fraction of its lumped
/// area: its psi_j integrates to (almost) nothing, and the weights M_jm / D_j would be ratios of
/// round-off (the axis vertex of an axisymmetric surface, whose D_j is zero).
constexpr double least_dual_area_fraction = 0.1;
/// A slave node keeps the projected point if less than this fraction of its dual area lies over
/// the master surface (its faces reach beyond the master surface's end). Above it, the weights
/// are normalized by the covered part, so that they sum to one: where both surfaces end together
/// (a block on a block of the same width, rod ends) round-off leaves a sliver uncovered, and the
/// pair must stay the mortar pair.
constexpr double least_coverage = 0.5;
/// Pieces of a slave face shorter than this (in its parameter) are not integrated.
constexpr double shortest_piece = 1e-14;

/** sum_i N_i(xi) normals[i]: the slave face's interpolated normal (not normalized). */
template <int dim>
Tensor<1, dim> interpolated_normal(const std::array<Tensor<1, dim>, 3>& normals, const double xi)
{
  const auto N = QuadraticFace<dim>::shape_values(xi);
  Tensor<1, dim> normal;
  for (unsigned int i = 0; i < 3; ++i)
    normal += N[i] * normals[i];
  return normal;
}

/**
 * The parameter xi in [0, 1] of slave face `face` (its nodal `normals`) whose interpolated-normal
 * ray passes through `point`: the root of h(xi) = (point - x(xi)) . t(xi), t the normal turned a
 * quarter toward the face's tangent, so that h > 0 where the point lies ahead of the ray. h
 * decreases along the face; 0 if the point lies behind the ray at xi = 0, 1 if ahead of it at
 * xi = 1; else bisection to 1e-15.
 */
template <int dim>
double slave_parameter(const QuadraticFace<dim>& face,
                       const std::array<Tensor<1, dim>, 3>& normals,
                       const Point<dim>& point)
{
  const auto ahead = [&](const double xi)
  {
    Tensor<1, dim> along = cross_product_2d(interpolated_normal(normals, xi));
    if (along * face.tangent(xi) < 0.)
      along = -along;
    return (point - face.point(xi)) * along;
  };
  double behind = 0., before = 1.;
  if (ahead(behind) <= 0.)
    return 0.;
  if (ahead(before) >= 0.)
    return 1.;
  while (before - behind > 1e-15)
  {
    const double middle = 0.5 * (behind + before);
    if (middle <= behind || middle >= before)
      break;
    (ahead(middle) > 0. ? behind : before) = middle;
  }
  return 0.5 * (behind + before);
}

/** Where a master face lies under a slave face: the slave parameters of its two end points. */
struct Overlap
{
  unsigned int master_face;
  double xi_at_start, xi_at_end; ///< the slave parameters of the master face's xi = 0 and 1

  double lowest() const { return std::min(xi_at_start, xi_at_end); }
  double highest() const { return std::max(xi_at_start, xi_at_end); }
};
} // namespace

template <int dim>
MortarContact<dim>::MortarContact(const ContactSurface<dim>& slave_surface,
                                  const ContactSurface<dim>& master_surface,
                                  const Kinematics<dim>& kinematics,
                                  const double penalty_stiffness_per_area,
                                  const double search_radius,
                                  const double touching_tolerance)
    : point_projection(slave_surface,
                       master_surface,
                       penalty_stiffness_per_area,
                       search_radius,
                       touching_tolerance),
      kinematics(kinematics), master_faces_of_slave_face(slave_surface.face_nodes().size()),
      candidate_pairs(point_projection.pairs())
{
  std::vector<std::vector<unsigned int>> faces_of_node(slave_surface.nodes().size());
  for (unsigned int k = 0; k < candidate_pairs.size(); ++k)
    faces_of_node[point_projection.slave_node(k)] = point_projection.candidate_faces(k);
  for (unsigned int face = 0; face < slave_surface.face_nodes().size(); ++face)
  {
    auto& faces = master_faces_of_slave_face[face];
    for (const unsigned int node : slave_surface.face_nodes()[face])
      faces.insert(faces.end(), faces_of_node[node].begin(), faces_of_node[node].end());
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  }

  mortar_pairs = apply_mortar_weights(
      slave_surface.reference_positions(), master_surface.reference_positions(), candidate_pairs);
  for (unsigned int k = 0; k < candidate_pairs.size(); ++k)
  {
    ContactPair<dim>& pair = candidate_pairs[k];
    // The node's own position, not the point node-to-segment contact may have moved it onto.
    if (mortar_pairs[k])
      pair.slave.position = slave_surface.nodes()[point_projection.slave_node(k)].position;
    // As node-to-segment contact: touching bodies start closed, overlapping ones are refused.
    const double gap = pair.reference_gap();
    if (std::abs(gap) <= touching_tolerance)
      pair.slave.position += gap * pair.normal;
    if (pair.reference_gap() < -touching_tolerance)
      throw overlap_at_start(pair, touching_tolerance);
  }
}

template <int dim>
void MortarContact<dim>::integrate_face(const unsigned int face,
                                        const std::vector<Point<dim>>& slave_positions,
                                        const std::vector<Tensor<1, dim>>& slave_normals,
                                        const std::vector<Point<dim>>& master_positions,
                                        std::vector<MortarRow>& rows) const
{
  const std::vector<unsigned int>& nodes = slave_surface().face_nodes()[face];
  const QuadraticFace<dim> slave_face    = face_patch<dim>(nodes, slave_positions);
  std::array<Tensor<1, dim>, 3> normals;
  for (unsigned int a = 0; a < 3; ++a)
    normals[a] = slave_normals[nodes[a]];
  const types::material_id body = slave_surface().nodes()[nodes[0]].body;
  const auto measure            = [&](const double xi)
  { return slave_face.tangent(xi).norm() * kinematics.measure_factor(slave_face.point(xi), body); };
  const QGauss<1> rule(gauss_points);

  // The dual basis psi_a = sum_b A_ab N_b with A = D M^-1, M_ab = int N_a N_b, D = diag(int N_a):
  // then int psi_a N_b = delta_ab D_a (Popp, Gee & Wall 2009, eq. 21).
  Tensor<2, 3> mass;
  std::array<double, 3> dual_area{};
  for (unsigned int q = 0; q < rule.size(); ++q)
  {
    const double xi = rule.point(q)[0];
    const auto N    = QuadraticFace<dim>::shape_values(xi);
    const double dA = measure(xi) * rule.weight(q);
    for (unsigned int a = 0; a < 3; ++a)
    {
      dual_area[a] += N[a] * dA;
      for (unsigned int b = 0; b < 3; ++b)
        mass[a][b] += N[a] * N[b] * dA;
    }
  }
  const Tensor<2, 3> inverse_mass = invert(mass);
  for (unsigned int a = 0; a < 3; ++a)
    rows[nodes[a]].dual_area += dual_area[a];

  // The pieces: the slave face cut where the rays through the master faces' end points leave it.
  std::vector<Overlap> overlaps;
  std::vector<double> cuts = {0., 1.};
  for (const unsigned int master : master_faces_of_slave_face[face])
  {
    const auto master_face =
        face_patch<dim>(master_surface().face_nodes()[master], master_positions);
    const Overlap overlap{master,
                          slave_parameter(slave_face, normals, master_face.points[0]),
                          slave_parameter(slave_face, normals, master_face.points[1])};
    if (overlap.highest() - overlap.lowest() <= shortest_piece)
      continue;
    overlaps.push_back(overlap);
    cuts.push_back(overlap.lowest());
    cuts.push_back(overlap.highest());
  }
  std::sort(cuts.begin(), cuts.end());

  const std::array<Tensor<1, dim>, 3> along_slave_normal{}; // the ray along the slave normal
  for (unsigned int piece = 0; piece + 1 < cuts.size(); ++piece)
  {
    const double length = cuts[piece + 1] - cuts[piece];
    if (length <= shortest_piece)
      continue;
    for (unsigned int q = 0; q < rule.size(); ++q)
    {
      const double xi                = cuts[piece] + length * rule.point(q)[0];
      const Point<dim> slave_point   = slave_face.point(xi);
      const Tensor<1, dim> direction = interpolated_normal(normals, xi);
      // The master face the ray meets nearest to the slave point.
      std::optional<std::pair<unsigned int, double>> hit;
      double nearest = std::numeric_limits<double>::max();
      for (const Overlap& overlap : overlaps)
      {
        if (xi < overlap.lowest() || xi > overlap.highest())
          continue;
        const auto master_face =
            face_patch<dim>(master_surface().face_nodes()[overlap.master_face], master_positions);
        const double guess = (xi - overlap.xi_at_start) / (overlap.xi_at_end - overlap.xi_at_start);
        const auto eta     = master_face.ray_point(
            slave_point, direction, along_slave_normal, std::clamp(guess, 0., 1.));
        if (!eta)
          continue;
        const double distance = master_face.point(*eta).distance(slave_point);
        if (distance < nearest)
        {
          nearest = distance;
          hit     = std::make_pair(overlap.master_face, *eta);
        }
      }
      if (!hit)
        continue;
      const auto N        = QuadraticFace<dim>::shape_values(xi);
      const auto N_master = QuadraticFace<dim>::shape_values(hit->second);
      const double dA     = measure(xi) * rule.weight(q) * length;
      for (unsigned int a = 0; a < 3; ++a)
      {
        double psi = 0.;
        for (unsigned int b = 0; b < 3; ++b)
          psi += dual_area[a] * inverse_mass[a][b] * N[b];
        MortarRow& row = rows[nodes[a]];
        row.covered_area += psi * dA;
        for (unsigned int m = 0; m < 3; ++m)
          row.master_integrals[master_surface().face_nodes()[hit->first][m]] +=
              psi * N_master[m] * dA;
      }
    }
  }
}

template <int dim>
bool MortarContact<dim>::MortarRow::defined(const double lumped_area) const
{
  // Written so that NaN integrals (a collapsed face) keep the projected point too.
  bool defined = dual_area >= least_dual_area_fraction * lumped_area &&
                 covered_area >= least_coverage * dual_area;
  for (const auto& master : master_integrals)
    defined = defined && std::isfinite(master.second);
  return defined;
}

template <int dim>
std::vector<typename MortarContact<dim>::MortarRow>
MortarContact<dim>::mortar_rows(const std::vector<Point<dim>>& slave_positions,
                                const std::vector<Point<dim>>& master_positions) const
{
  const auto slave_normals = slave_surface().normals(slave_positions);
  std::vector<MortarRow> rows(slave_surface().nodes().size());
  for (unsigned int face = 0; face < master_faces_of_slave_face.size(); ++face)
    if (!master_faces_of_slave_face[face].empty())
      integrate_face(face, slave_positions, slave_normals, master_positions, rows);
  return rows;
}

template <int dim>
std::vector<bool>
MortarContact<dim>::apply_mortar_weights(const std::vector<Point<dim>>& slave_positions,
                                         const std::vector<Point<dim>>& master_positions,
                                         std::vector<ContactPair<dim>>& pairs) const
{
  const std::vector<MortarRow> rows = mortar_rows(slave_positions, master_positions);
  const std::vector<double> lumped  = slave_surface().lumped_areas(slave_positions);
  std::vector<bool> mortar(pairs.size(), false);
  for (unsigned int k = 0; k < pairs.size(); ++k)
  {
    const unsigned int node = point_projection.slave_node(k);
    const MortarRow& row    = rows[node];
    if (!row.defined(lumped[node]))
      continue;
    pairs[k].masters.clear();
    for (const auto& [master, integral] : row.master_integrals)
      pairs[k].masters.push_back({master_surface().nodes()[master], integral / row.covered_area});
    mortar[k] = true;
  }
  return mortar;
}

template <int dim>
void MortarContact<dim>::update_pairs(const BorderDisplacement<dim>& displacement,
                                      std::vector<ContactPair<dim>>& pairs) const
{
  point_projection.update_pairs(displacement, pairs);
  mortar_pairs = apply_mortar_weights(slave_surface().current_positions(displacement),
                                      master_surface().current_positions(displacement),
                                      pairs);
}

template <int dim>
void MortarContact<dim>::update_master_points(const BorderDisplacement<dim>& displacement,
                                              std::vector<ContactPair<dim>>& pairs,
                                              const bool move_normals) const
{
  // The mortar rows first: the projection is needed only where they are not defined.
  if (move_normals)
    mortar_pairs = apply_mortar_weights(slave_surface().current_positions(displacement),
                                        master_surface().current_positions(displacement),
                                        pairs);
  AssertDimension(mortar_pairs.size(), pairs.size());
  std::vector<bool> projected = mortar_pairs;
  projected.flip();
  point_projection.update_master_points(displacement, pairs, move_normals, projected);
}

template <int dim>
std::vector<Node<dim>> MortarContact<dim>::coupled_nodes(const unsigned int k) const
{
  std::vector<Node<dim>> nodes  = point_projection.coupled_nodes(k);
  const unsigned int slave_node = point_projection.slave_node(k);
  const auto& slave_faces       = slave_surface().face_nodes();
  for (unsigned int face = 0; face < slave_faces.size(); ++face)
    if (std::count(slave_faces[face].begin(), slave_faces[face].end(), slave_node) > 0)
      for (const unsigned int master : master_faces_of_slave_face[face])
        for (const unsigned int node : master_surface().face_nodes()[master])
          nodes.push_back(master_surface().nodes()[node]);
  return nodes;
}

template <int dim>
std::vector<Node<dim>> MortarContact<dim>::surface_nodes() const
{
  return point_projection.surface_nodes();
}

template <int dim>
std::vector<double>
MortarContact<dim>::contact_pressures(const BorderDisplacement<dim>& displacement,
                                      const std::vector<double>& multipliers) const
{
  const auto slave_positions = slave_surface().current_positions(displacement);
  const std::vector<MortarRow> rows =
      mortar_rows(slave_positions, master_surface().current_positions(displacement));
  const std::vector<double> lumped = slave_surface().lumped_areas(slave_positions);
  std::vector<double> pressures(multipliers.size());
  std::vector<unsigned int> projected; // the pairs without a mortar row
  for (unsigned int k = 0; k < pressures.size(); ++k)
  {
    const unsigned int node = point_projection.slave_node(k);
    if (rows[node].defined(lumped[node]))
      pressures[k] = multipliers[k] / rows[node].dual_area;
    else
      projected.push_back(k);
  }
  // The consistent recovery's zone solve only where it is used.
  if (!projected.empty())
  {
    const std::vector<double> recovered =
        point_projection.contact_pressures(displacement, multipliers);
    for (const unsigned int k : projected)
      pressures[k] = recovered[k];
  }
  return pressures;
}

// 2D only, as NodeToSegmentContact: its face patch is a 3-node line.
template class MortarContact<2>;
} // namespace dyncontact
