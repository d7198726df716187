#pragma once

#include <dyncontact/contact/quadratic_face.h>
#include <dyncontact/contact/quadratic_quad.h>

#include <deal.II/base/point.h>

#include <array>
#include <vector>

namespace dyncontact
{
/** The face patch of node-to-segment (2D) and node-to-surface (3D) contact, by dimension. */
template <int dim>
struct FacePatchOf;
template <>
struct FacePatchOf<2>
{
  using type = QuadraticFace<2>; ///< the 3-node line
};
template <>
struct FacePatchOf<3>
{
  using type = QuadraticQuad; ///< the 9-node quadrilateral
};
/** QuadraticFace<2> in 2D, QuadraticQuad in 3D. */
template <int dim>
using FacePatch = typename FacePatchOf<dim>::type;

/**
 * One flag per side of a face patch: its ends xi = 0, 1 in 2D, its sides xi = 0, xi = 1, eta = 0,
 * eta = 1 in 3D.
 */
template <int dim>
using FaceSides = std::array<bool, 2 * (dim - 1)>;

/**
 * Face `nodes` (FacePatch<dim>::n_nodes indices into `positions`, in the order of
 * ContactSurface::face_nodes()) of a surface whose nodes are at `positions`.
 */
template <int dim>
FacePatch<dim> face_patch(const std::vector<unsigned int>& nodes,
                          const std::vector<Point<dim>>& positions)
{
  FacePatch<dim> face;
  for (unsigned int i = 0; i < FacePatch<dim>::n_nodes; ++i)
    face.points[i] = positions[nodes[i]];
  return face;
}
} // namespace dyncontact
