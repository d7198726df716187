// Unit test of the node-to-node contact geometry on the paper's mirrored two-sphere mesh, apart
// from any time stepping: the pair normal n = (n_A - n_B) / |n_A - n_B| of every pair, off-axis
// ones included, against the exact normals of the configuration.
#include <dyncontact/contact/contact_factory.h>
#include <dyncontact/models/mesh_model.h>
#include <dyncontact/simulation/parameter_reader.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <gtest/gtest.h>

#include "case_run.h"

namespace dyncontact::testing
{
// The spheres are mirror images about z = 0 (body 1 below, body 2 above): at rest every pair's
// normal is the axis direction (0, 1) exactly, however far off the axis the pair lies, because
// the mirrored nodal normals differ only in their z component; a pair normal built from one side
// only, or with the sign of n_B flipped, is not. Bound 1e-11: round-off of the mirrored mesh, whose
// curved mid-side nodes come from two spherical manifolds about different centres (measured
// 4.6e-12 on the curved faces; a one-sided or flipped normal is off by 1e-3 or more).
TEST(NodeToNodeContact, PairNormalsOfMirroredSpheresAreTheAxisDirection)
{
  const RunParameters parameters =
      ParameterReader(source_path("prm/spheres_rho0.001.prm"), paper_coarse_spheres()).parameters();
  MeshModel model(parameters.mesh, parameters.bodies);
  Triangulation<2> triangulation;
  model.create_triangulation(triangulation);
  DoFHandler<2> dof_handler(triangulation);
  const FESystem<2> fe(FE_Q<2>(2), 2);
  dof_handler.distribute_dofs(fe);
  const MappingQ<2> mapping(2);
  const NodeIndex<2> nodes(dof_handler, mapping);
  const auto kinematics    = model.create_kinematics();
  const Contact<2> contact = create_contact(
      model.contact_description(nodes), dof_handler, *kinematics, nodes, parameters.contact);
  ASSERT_TRUE(contact.surfaces);
  const auto& pairs = contact.surfaces->pairs();
  ASSERT_GE(pairs.size(), 20u);

  const ContactBorder<2> border(contact.surfaces->surface_nodes());
  const auto moved_to = [&](const Vector<double>& displacement)
  {
    std::vector<ContactPair<2>> moved        = pairs;
    const Vector<double> border_displacement = border.gather(displacement);
    contact.surfaces->update_pairs(BorderDisplacement<2>{border, border_displacement}, moved);
    return moved;
  };
  unsigned int off_axis = 0;
  const auto at_rest    = moved_to(Vector<double>(dof_handler.n_dofs()));
  for (unsigned int k = 0; k < pairs.size(); ++k)
  {
    off_axis += pairs[k].slave.position[0] > 1.;
    EXPECT_NEAR(at_rest[k].normal[0], 0., 1e-11) << "pair at r = " << pairs[k].slave.position[0];
    EXPECT_NEAR(at_rest[k].normal[1], 1., 1e-11) << "pair at r = " << pairs[k].slave.position[0];
  }
  EXPECT_GE(off_axis, 10u); // the check covers pairs far from the axis

  // Body 2 (B) translated rigidly, also radially: its nodal normals do not turn, so neither may
  // the pair normals, although the pairs' nodes no longer face each other.
  Vector<double> translation(dof_handler.n_dofs());
  for (const auto& node : nodes.nodes())
    if (node.body == 1)
    {
      translation[node.dofs[0]] = 0.05;
      translation[node.dofs[1]] = -0.1;
    }
  const auto translated = moved_to(translation);
  for (unsigned int k = 0; k < pairs.size(); ++k)
  {
    EXPECT_NEAR(translated[k].normal[0], 0., 1e-11) << "pair at r = " << pairs[k].slave.position[0];
    EXPECT_NEAR(translated[k].normal[1], 1., 1e-11) << "pair at r = " << pairs[k].slave.position[0];
  }
}
} // namespace dyncontact::testing
