#pragma once

#include <dyncontact/simulation/run_parameters.h>

#include <ostream>

namespace dyncontact
{
/**
 * Does what a run does before its first step, without writing anything, so that --validate
 * rejects every input a run would reject there: Simulation::prepare() (mesh, DoFs, contact
 * candidates, monitor nodes, penalty sizing, the stability limit of the time step, the initial
 * conditions at every node) and, for bars with Output/write exact solution, the exact solution;
 * and checks that Output/directory can be created and written. Throws the InputError the run
 * would throw. Writes to `log` the set-up summary a run prints (DoFs, pairs, steps, scheme, the
 * bodies, the highest mode, the reference solution the run will write).
 */
void check_run_setup(const RunParameters& parameters, std::ostream& log);
} // namespace dyncontact
