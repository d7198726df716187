#pragma once

#include <dyncontact/base/parameters.h>

namespace dyncontact
{
/**
 * Does what a run does before its first step, without writing anything, so that --validate
 * rejects every input a run would reject there: Simulation::prepare() (mesh, DoFs, contact
 * candidates, monitor nodes, penalty sizing, the stability limit of the time step, the initial
 * conditions at every node) and, for bars with Output/write exact solution, the exact solution;
 * and checks that Output/directory can be created and written. Throws the InputError the run
 * would throw.
 */
void check_run_setup(const RunParameters& parameters);
} // namespace dyncontact
