#include <dyncontact/models/bar_model.h>
#include <dyncontact/postprocess/history.h>
#include <dyncontact/reference/impact_measures.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <numeric>

namespace dyncontact
{
namespace
{
/** Penalty stiffness eps = factor * E A / h of a bar (its axial stiffness per element). */
double element_stiffness(const BarParameters& bar)
{
  return bar.youngs_modulus * bar.area / bar.element_length();
}
} // namespace

BarModel::BarModel(const GeometryParameters& geometry) : geometry(geometry) {}

std::vector<unsigned int> BarModel::bars_in_x_order() const
{
  std::vector<unsigned int> order(geometry.bars.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(),
            order.end(),
            [this](const unsigned int a, const unsigned int b)
            { return geometry.bars[a].left_end < geometry.bars[b].left_end; });
  return order;
}

void BarModel::create_triangulation(Triangulation<1>& triangulation)
{
  std::vector<Point<1>> vertices;
  std::vector<CellData<1>> cells;
  for (unsigned int b = 0; b < geometry.bars.size(); ++b)
  {
    const BarParameters& bar        = geometry.bars[b];
    const unsigned int first_vertex = vertices.size();
    // The ends exactly at left_end and right_end(), where the parameters put touching bodies.
    for (unsigned int i = 0; i < bar.n_elements; ++i)
      vertices.emplace_back(bar.left_end + bar.length * i / bar.n_elements);
    vertices.emplace_back(bar.right_end());
    for (unsigned int e = 0; e < bar.n_elements; ++e)
    {
      CellData<1> cell;
      cell.vertices    = {first_vertex + e, first_vertex + e + 1};
      cell.material_id = b;
      cells.push_back(cell);
    }
  }
  triangulation.create_triangulation(vertices, cells, SubCellData());
}

std::vector<BodyMaterial> BarModel::body_materials() const
{
  std::vector<BodyMaterial> materials;
  for (const auto& bar : geometry.bars)
    materials.push_back(
        {std::make_shared<LinearElasticMaterial>(bar.youngs_modulus, 0.), bar.density});
  return materials;
}

std::unique_ptr<Kinematics<1>> BarModel::create_kinematics() const
{
  std::vector<double> areas;
  for (const auto& bar : geometry.bars)
    areas.push_back(bar.area);
  return std::make_unique<BarKinematics>(areas);
}

Tensor<1, 1> BarModel::initial_velocity(const types::material_id body, const Point<1>&) const
{
  Tensor<1, 1> velocity;
  velocity[0] = geometry.bars[body].initial_velocity;
  return velocity;
}

ContactDescription<1> BarModel::contact_description(const NodeIndex<1>& nodes) const
{
  Tensor<1, 1> plus_x;
  plus_x[0]                             = 1.;
  const std::vector<unsigned int> order = bars_in_x_order();
  ContactDescription<1> description;
  for (unsigned int i = 0; i + 1 < order.size(); ++i)
  {
    const BarParameters& left  = geometry.bars[order[i]];
    const BarParameters& right = geometry.bars[order[i + 1]];
    description.fixed_pairs.push_back(
        {nodes.closest_node(order[i], Point<1>(left.right_end())),
         nodes.closest_node(order[i + 1], Point<1>(right.left_end)),
         Point<1>(),
         plus_x,
         std::max(element_stiffness(left), element_stiffness(right))});
  }
  if (geometry.wall_enabled)
  {
    const BarParameters& rightmost = geometry.bars[order.back()];
    description.fixed_pairs.push_back(
        {nodes.closest_node(order.back(), Point<1>(rightmost.right_end())),
         std::nullopt,
         Point<1>(geometry.wall_position),
         plus_x,
         element_stiffness(rightmost)});
  }
  return description;
}

std::vector<Node<1>> BarModel::monitor_nodes(const NodeIndex<1>& nodes) const
{
  const auto pairs = contact_description(nodes).fixed_pairs;
  std::vector<Node<1>> monitors;
  for (unsigned int b = 0; b < geometry.bars.size(); ++b)
  {
    // Its node in the first candidate that involves it; a bar without candidates: its right end.
    std::optional<Node<1>> tip;
    for (const auto& pair : pairs)
    {
      if (!tip && pair.node_a.body == b)
        tip = pair.node_a;
      if (!tip && pair.node_b && pair.node_b->body == b)
        tip = *pair.node_b;
    }
    monitors.push_back(tip ? *tip : nodes.closest_node(b, Point<1>(geometry.bars[b].right_end())));
  }
  return monitors;
}

std::vector<types::global_dof_index> BarModel::fixed_dofs(const NodeIndex<1>& nodes) const
{
  if (!geometry.clamped_left_end)
    return {};
  unsigned int leftmost = 0;
  for (unsigned int b = 1; b < geometry.bars.size(); ++b)
    if (geometry.bars[b].left_end < geometry.bars[leftmost].left_end)
      leftmost = b;
  return {nodes.closest_node(leftmost, Point<1>(geometry.bars[leftmost].left_end)).dofs[0]};
}

Tensor<1, 1> BarModel::impact_direction() const
{
  Tensor<1, 1> plus_x;
  plus_x[0] = 1.;
  return plus_x;
}

void BarModel::write_reference(const std::string& directory,
                               const std::vector<double>& times,
                               const std::vector<Node<1>>& monitors) const
{
  const ExactBarSolution exact = exact_solution(times.back());
  const unsigned int n_bars    = geometry.bars.size();

  std::vector<std::string> columns = {"time",
                                      "contact_force",
                                      "active_constraints",
                                      "kinetic_energy",
                                      "strain_energy",
                                      "total_energy"};
  for (unsigned int b = 1; b <= n_bars; ++b)
    for (const std::string quantity : {"momentum_", "u_tip_", "v_tip_", "a_tip_"})
      columns.push_back(quantity + std::to_string(b));
  History table(columns);
  table.attach_file(directory + "/exact.csv");
  for (const double t : times)
  {
    double force = 0., contacts = 0., kinetic = 0., strain = 0.;
    for (unsigned int i = 0; i < exact.n_interfaces(); ++i)
    {
      force += exact.contact_force(i, t);
      contacts += exact.in_contact(i, t) ? 1. : 0.;
    }
    for (unsigned int b = 0; b < n_bars; ++b)
    {
      kinetic += exact.kinetic_energy(b, t);
      strain += exact.strain_energy(b, t);
    }
    std::vector<double> row = {t, force, contacts, kinetic, strain, kinetic + strain};
    for (unsigned int b = 0; b < n_bars; ++b)
    {
      const double X = monitors[b].position[0];
      // The exact acceleration is zero between wave arrivals (impulses are not represented).
      row.insert(row.end(),
                 {exact.momentum(b, t), exact.displacement(b, X, t), exact.velocity(b, X, t), 0.});
    }
    table.add_row(row);
  }
}

double BarModel::total_contact_impulse(const std::vector<double>& contact_impulses) const
{
  AssertDimension(contact_impulses.size(), geometry.bars.size());
  const std::vector<unsigned int> order = bars_in_x_order();
  double left_of_interface = 0., total = 0.;
  for (unsigned int k = 0; k < order.size(); ++k)
  {
    left_of_interface += contact_impulses[order[k]];
    if (k + 1 < order.size() || geometry.wall_enabled)
      total -= left_of_interface;
  }
  return total;
}

ExactBarSolution BarModel::exact_solution(const double end_time) const
{
  std::vector<ExactBar> bars;
  for (const auto& bar : geometry.bars)
    bars.push_back({bar.left_end,
                    bar.length,
                    bar.youngs_modulus,
                    bar.density,
                    bar.area,
                    bar.initial_velocity});
  return ExactBarSolution(bars,
                          geometry.wall_enabled ? std::optional<double>(geometry.wall_position)
                                                : std::nullopt,
                          end_time,
                          geometry.clamped_left_end);
}

void BarModel::print_summary(std::ostream& out, const double time_step) const
{
  for (unsigned int b = 0; b < geometry.bars.size(); ++b)
  {
    const BarParameters& bar = geometry.bars[b];
    out << "  body " << b + 1 << ": bar [" << bar.left_end << ", " << bar.right_end() << "], "
        << bar.n_elements << " elements, c = " << bar.wave_speed()
        << ", Courant number c dt / h = " << bar.wave_speed() * time_step / bar.element_length()
        << ", v0 = " << bar.initial_velocity << "\n";
  }
  if (geometry.wall_enabled)
    out << "  rigid wall at x = " << geometry.wall_position << "\n";
}
void BarModel::summarize_run(const std::string& directory,
                             const History& history,
                             const std::vector<double>& contact_impulses,
                             const std::string& status,
                             std::ostream& log) const
{
  if (history.n_rows() < 3)
  {
    log << "  no comparison with the exact solution (exact_summary.csv): it needs at least 2 time "
           "steps.\n";
    return;
  }
  const std::vector<double> times = history.column("time");
  const ExactBarSolution exact    = exact_solution(times.back());
  std::vector<double> exact_force(times.size(), 0.);
  for (unsigned int k = 0; k < times.size(); ++k)
    for (unsigned int i = 0; i < exact.n_interfaces(); ++i)
      exact_force[k] += exact.contact_force(i, times[k]);
  const ImpactMeasures fe = measure_impact(times, history.column("contact_force"));
  const ImpactMeasures ex = measure_impact(times, exact_force);
  struct Row
  {
    std::string quantity;
    double computed, exact;
  };
  std::vector<Row> rows = {{"contact_start", fe.contact_start, ex.contact_start},
                           {"contact_end", fe.contact_end, ex.contact_end},
                           {"duration", fe.duration, ex.duration},
                           {"impulse", total_contact_impulse(contact_impulses), ex.impulse},
                           {"peak_force", fe.peak_force, ex.peak_force},
                           {"ringing", fe.ringing, ex.ringing}};
  const double t_end    = times.back();
  for (unsigned int b = 0; b < geometry.bars.size(); ++b)
    rows.push_back({"final_momentum_" + std::to_string(b + 1),
                    history.value(history.n_rows() - 1, "momentum_" + std::to_string(b + 1)),
                    exact.momentum(b, t_end)});
  double exact_energy = 0.;
  for (unsigned int b = 0; b < geometry.bars.size(); ++b)
    exact_energy += exact.kinetic_energy(b, t_end) + exact.strain_energy(b, t_end);
  rows.push_back(
      {"final_total_energy", history.value(history.n_rows() - 1, "total_energy"), exact_energy});

  std::ofstream file(directory + "/exact_summary.csv");
  file << "quantity,computed,exact,difference,relative_difference,status\n"
       << std::setprecision(12);
  log << "  run against the exact solution (computed / exact / difference), " << status << ":\n";
  for (const Row& row : rows)
  {
    const double difference = row.computed - row.exact;
    file << row.quantity << "," << row.computed << "," << row.exact << "," << difference << ","
         << (row.exact != 0. ? difference / row.exact : 0.) << "," << status << "\n";
    log << "    " << std::left << std::setw(20) << row.quantity << std::right << std::setw(14)
        << row.computed << std::setw(14) << row.exact << std::setw(14) << difference << "\n";
  }
}
} // namespace dyncontact
