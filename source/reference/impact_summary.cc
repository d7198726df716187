#include <dyncontact/reference/impact_measures.h>
#include <dyncontact/reference/impact_summary.h>

#include <fstream>
#include <iomanip>
#include <limits>

namespace dyncontact
{
void write_impact_references(const std::string& directory,
                             const std::vector<double>& times,
                             const HertzImpact& hertz,
                             const std::optional<FiniteSphereImpact>& law,
                             const double law_approach_scale)
{
  // Plain CSV files (a header row, then numbers); the constants that produced them beside them in
  // *_parameters.csv, one "quantity,value" row each.
  std::ofstream parameters(directory + "/hertz_parameters.csv");
  parameters << "quantity,value\n"
             << std::setprecision(15) << "effective_radius," << hertz.effective_radius()
             << "\neffective_modulus," << hertz.effective_modulus() << "\neffective_mass,"
             << hertz.effective_mass() << "\nrelative_approach_speed,"
             << hertz.relative_approach_speed() << "\nfirst_touch_time," << hertz.first_touch_time()
             << "\npeak_force," << hertz.maximum_force() << "\nduration,"
             << hertz.contact_duration() << "\nimpulse," << hertz.impulse() << "\n";
  std::ofstream file(directory + "/hertz.csv");
  file << "time,contact_force,approach\n" << std::setprecision(15);
  for (const double time : times)
    file << time << "," << hertz.contact_force(time) << "," << hertz.approach(time) << "\n";

  if (!law)
    return;
  std::ofstream law_parameters(directory + "/finite_sphere_parameters.csv");
  law_parameters << "quantity,value\n"
                 << std::setprecision(15) << "c0," << FiniteSphereImpact::c0_for_nu_0_3
                 << "\npeak_force," << law->maximum_force() << "\nduration,"
                 << law->contact_duration() << "\nimpulse," << law->impulse() << "\n";
  std::ofstream law_file(directory + "/finite_sphere.csv");
  law_file << "time,contact_force,approach\n" << std::setprecision(15);
  for (const double time : times)
    law_file << time << "," << law->contact_force(time) << ","
             << law_approach_scale * law->approach(time) << "\n";
}

void write_impact_summary(const std::string& directory,
                          const History& history,
                          const double whole_body_factor,
                          const double impulse,
                          const HertzImpact& hertz,
                          const std::optional<FiniteSphereImpact>& law,
                          const std::string& status,
                          std::ostream& log)
{
  if (history.n_rows() < 3)
  {
    log << "  no comparison with Hertz (impact_summary.csv): it needs at least 2 time steps.\n";
    return;
  }
  std::vector<double> force = history.column("contact_force");
  for (double& value : force)
    value *= whole_body_factor;
  const ImpactMeasures fe = measure_impact(history.column("time"), force);
  struct Row
  {
    std::string quantity;
    double computed, hertz, law;
  };
  // Both references start at the same first touch t0 and are symmetric about their peak.
  const double t0             = hertz.first_touch_time();
  const double law_duration   = law ? law->contact_duration() : 0.;
  const double nan            = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Row> rows = {
      {"peak_force", fe.peak_force, hertz.maximum_force(), law ? law->maximum_force() : nan},
      {"peak_time",
       fe.peak_time,
       t0 + 0.5 * hertz.contact_duration(),
       law ? t0 + 0.5 * law_duration : nan},
      {"contact_start", fe.contact_start, t0, law ? t0 : nan},
      {"contact_end", fe.contact_end, t0 + hertz.contact_duration(), law ? t0 + law_duration : nan},
      {"duration", fe.duration, hertz.contact_duration(), law ? law_duration : nan},
      {"impulse", impulse, hertz.impulse(), law ? law->impulse() : nan},
      {"ringing", fe.ringing, 0., law ? 0. : nan}};
  const auto relative = [](const double computed, const double reference)
  { return reference != 0. ? (computed - reference) / reference : 0.; };
  std::ofstream file(directory + "/impact_summary.csv");
  file << "quantity,computed,hertz,relative_difference"
       << (law ? ",finite_sphere,finite_sphere_difference" : "") << ",status\n"
       << std::setprecision(12);
  log << "  impact against Hertz (computed / Hertz / relative difference"
      << (law ? " / finite-sphere law / relative difference" : "") << "), " << status << ":\n";
  for (const Row& row : rows)
  {
    file << row.quantity << "," << row.computed << "," << row.hertz << ","
         << relative(row.computed, row.hertz);
    log << "    " << std::left << std::setw(14) << row.quantity << std::right << std::setw(14)
        << row.computed << std::setw(14) << row.hertz << std::setw(14)
        << relative(row.computed, row.hertz);
    if (law)
    {
      file << "," << row.law << "," << relative(row.computed, row.law);
      log << std::setw(14) << row.law << std::setw(14) << relative(row.computed, row.law);
    }
    file << "," << status << "\n";
    log << "\n";
  }
}
} // namespace dyncontact
