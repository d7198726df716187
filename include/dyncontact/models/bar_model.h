#pragma once

#include <dyncontact/models/bar_parameters.h>
#include <dyncontact/models/problem_model.h>
#include <dyncontact/reference/exact_bar_solution.h>

namespace dyncontact
{
/**
 * The paper's 1D problems (section 6.1-6.3): any number of straight linear elastic bars on the x
 * axis, each meshed with equal 2-node elements, plus an optional fixed rigid wall facing -x.
 * Bars are disconnected pieces of one triangulation (each has its own end vertices, even where
 * two bars touch). Candidate contacts: the facing ends of neighbouring bars (normal +x) and the
 * rightmost bar's right end against the wall. The tip of a body is its node in the first
 * candidate that involves it. Reference: the exact wave solution (ExactBarSolution) as exact.csv.
 */
class BarModel : public ProblemModel<1>
{
public:
  explicit BarModel(const GeometryParameters& geometry);

  unsigned int element_degree() const override { return 1; }
  unsigned int n_bodies() const override { return geometry.bars.size(); }
  void create_triangulation(Triangulation<1>& triangulation) override;
  std::vector<BodyMaterial> body_materials() const override;
  std::unique_ptr<Kinematics<1>> create_kinematics() const override;
  Tensor<1, 1> initial_velocity(types::material_id body, const Point<1>& X) const override;
  /**
   * A pair between the facing ends of neighbouring bars, normal +x, stiffness scale E A / h of
   * the stiffer end element; the rightmost bar's end against the wall if there is one.
   */
  ContactDescription<1> contact_description(const NodeIndex<1>& nodes) const override;
  std::vector<Node<1>> monitor_nodes(const NodeIndex<1>& nodes) const override;
  /** The leftmost bar's left end node, if Geometry/clamped left end. */
  std::vector<types::global_dof_index> fixed_dofs(const NodeIndex<1>& nodes) const override;
  Tensor<1, 1> impact_direction() const override;
  void write_reference(const std::string& directory,
                       const std::vector<double>& times,
                       const std::vector<Node<1>>& monitors) const override;
  void print_summary(std::ostream& out, double time_step) const override;

  /**
   * exact_summary.csv: the run against the exact solution sampled at the same steps, both measured
   * alike (measure_impact() on the total contact force: contact start, end, duration, peak,
   * ringing), the impulse of the total contact force (the run's: summed over the interfaces from
   * `contact_impulses`; the exact one: measure_impact()'s), and each bar's final momentum and the
   * final total energy. Columns quantity,
   * computed, exact, difference, relative_difference (0 where the exact value is 0); the same
   * table in `log`.
   */
  void summarize_run(const std::string& directory,
                     const History& history,
                     const std::vector<double>& contact_impulses,
                     const std::string& status,
                     std::ostream& log) const override;

  /** The exact wave solution of these bars, tracked up to `end_time`. */
  ExactBarSolution exact_solution(double end_time) const;

private:
  /** Bar indices sorted by position along x. */
  std::vector<unsigned int> bars_in_x_order() const;

  /**
   * The impulse of the total contact force (compression positive, summed over the interfaces
   * between neighbouring bars and the wall) from the bars' contact impulses along +x (one per
   * bar, prm order): the bars left of an interface receive, in sum, minus the impulse it
   * transmits, since the impulses of the interfaces among them cancel.
   */
  double total_contact_impulse(const std::vector<double>& contact_impulses) const;

  GeometryParameters geometry;
};
} // namespace dyncontact
