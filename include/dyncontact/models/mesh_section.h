#pragma once

namespace dyncontact
{
/** How the (x, y) plane of a 2D mesh stands for a three-dimensional body. */
enum class MeshSection
{
  /// the meridian half plane (r, z) = (x, y), x >= 0, of a body of revolution: dV = 2 pi r dr dz,
  /// u_r = 0 on the axis (gmsh physical curve 1)
  axisymmetric,
  /// the cross-section of a long prism in plane strain: unit thickness (dV = dx dy), no
  /// out-of-plane strain, no axis
  plane_strain
};
} // namespace dyncontact
