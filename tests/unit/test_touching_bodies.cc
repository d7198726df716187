// Geometry checks with a tolerance: bars and a wall typed as touching touch (0.1 + 0.2 is
// 0.30000000000000004 in floating point, but a bar there touches one at 0.3), with a reference gap
// of exactly zero, also far from the origin; an overlap beyond 1e-9 of an element is rejected
// with the digits that show it.
#include <dyncontact/contact/contact_factory.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/models/bar_model.h>
#include <dyncontact/simulation/parameter_reader.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "case_run.h"

namespace dyncontact::testing
{
namespace
{
/** The parameters of `prm_file` with `overrides`. */
RunParameters read(const std::string& prm_file, const std::vector<std::string>& overrides)
{
  return ParameterReader(source_path(prm_file), overrides).parameters();
}

/** The candidate contact pairs of a bar problem, built from its nodes as a run builds them. */
std::vector<ContactPair<1>> contact_pairs(const RunParameters& parameters)
{
  BarModel model(parameters.geometry);
  Triangulation<1> triangulation;
  model.create_triangulation(triangulation);
  DoFHandler<1> dof_handler(triangulation);
  dof_handler.distribute_dofs(FESystem<1>(FE_Q<1>(1), 1));
  const NodeIndex<1> nodes(dof_handler, MappingQ<1>(1));
  // The exact solution accepts the geometry too (it rejects overlaps with its own tolerance).
  model.exact_solution(parameters.time.end_time);
  const auto kinematics    = model.create_kinematics();
  const Contact<1> contact = create_contact(
      model.contact_description(nodes), dof_handler, *kinematics, nodes, parameters.contact);
  return contact.constraints->candidate_pairs();
}

/** The message of the InputError that reading `prm_file` with `overrides` throws, or "". */
std::string input_error(const std::string& prm_file, const std::vector<std::string>& overrides)
{
  try
  {
    read(prm_file, overrides);
  }
  catch (const InputError& error)
  {
    return error.what();
  }
  return "";
}

/** Bar 1 of 0.2 in 2 elements from `left_end`. */
std::vector<std::string> short_bar_1(const std::string& left_end)
{
  return {"Geometry/Bar 1/left end=" + left_end,
          "Geometry/Bar 1/length=0.2",
          "Geometry/Bar 1/number of elements=2"};
}
} // namespace

TEST(TouchingBodies, BarsTypedAsTouchingStartClosed)
{
  ASSERT_NE(0.1 + 0.2, 0.3); // the round-off this is about
  for (const auto& [left_end, touching_left_end] :
       {std::pair<std::string, std::string>{"0.1", "0.3"},
        {"1000000.1", "1000000.3"}, // far from the origin: round-off 1e-10, the element 0.1
        {"-0.3", "-0.1"}})
  {
    const RunParameters parameters =
        read("prm/bars_identical.prm",
             with(short_bar_1(left_end), {"Geometry/Bar 2/left end=" + touching_left_end}));
    const std::vector<ContactPair<1>> pairs = contact_pairs(parameters);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0].reference_gap(), 0.) << "bar 1 from " << left_end;
  }
}

TEST(TouchingBodies, WallTypedAsTouchingStartsClosed)
{
  const RunParameters parameters = read(
      "prm/bar_rigid_wall.prm", with(short_bar_1("0.1"), {"Geometry/Rigid wall/position=0.3"}));
  const std::vector<ContactPair<1>> pairs = contact_pairs(parameters);
  ASSERT_EQ(pairs.size(), 1u);
  ASSERT_TRUE(pairs[0].against_wall());
  EXPECT_EQ(pairs[0].reference_gap(), 0.);
}

TEST(TouchingBodies, SmallGapsBeyondTheToleranceStay)
{
  // A gap of 1e-9 (ten times the tolerance, 1e-9 of the 0.1 elements) is a gap.
  const RunParameters parameters = read(
      "prm/bars_identical.prm", with(short_bar_1("0.1"), {"Geometry/Bar 2/left end=0.300000001"}));
  EXPECT_NEAR(contact_pairs(parameters)[0].reference_gap(), 1e-9, 1e-15);
}

TEST(TouchingBodies, OverlapsBeyondTheToleranceAreRejectedWithTheirDigits)
{
  const std::string bars = input_error(
      "prm/bars_identical.prm", with(short_bar_1("0.1"), {"Geometry/Bar 2/left end=0.299999999"}));
  EXPECT_NE(bars.find("Bar 1 [0.1, 0.30000000000000004] and Bar 2 [0.299999999, "
                      "10.299999999] overlap at t = 0 by 1e-09"),
            std::string::npos)
      << bars;
  const std::string wall =
      input_error("prm/bar_rigid_wall.prm",
                  with(short_bar_1("0.1"), {"Geometry/Rigid wall/position=0.2999999"}));
  EXPECT_NE(wall.find("position = 0.2999999 is left of the right end 0.30000000000000004 of Bar 1"),
            std::string::npos)
      << wall;
}
} // namespace dyncontact::testing
