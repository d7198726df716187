#pragma once

#include <dyncontact/parameters.h>

namespace dyncontact
{
/**
 * Does what a run does before its first step, without writing anything, so that --validate
 * rejects every input a run would reject there: builds the problem's mesh (reading or meshing a
 * gmsh file), its DoFs and nodes, the contact candidates (matching and non-overlapping surfaces,
 * at most two bodies in contact), the monitor nodes and the initial velocity at every node, and,
 * for bars with Output/write exact solution, the exact solution; and checks that
 * Output/directory can be created and written. Throws the InputError the run would throw.
 */
void check_run_setup(const RunParameters& parameters);
} // namespace dyncontact
