#pragma once

#include <dyncontact/base/global.h>

#include <string>

namespace dyncontact
{
/**
 * Creates `directory` (and parents) if needed and checks that a file can be written in it;
 * throws InputError naming Output/directory otherwise.
 */
void prepare_output_directory(const std::string& directory);

/**
 * Checks, without creating or writing anything, that prepare_output_directory() can succeed:
 * `directory` is a writable directory, or it does not exist and its nearest existing ancestor is
 * a writable directory. Throws InputError naming Output/directory otherwise. For --validate.
 */
void check_output_directory(const std::string& directory);

/**
 * Whether `file_name` (a name without directory) is one that a dyncontact run writes into its
 * output directory: history.csv, exact.csv, hertz.csv, impact_summary.csv, cells.csv,
 * profile_t<T>.csv, contact_pressure_t<T>.csv, solution_<row>.<rank>.vtu, solution_<row>.pvtu,
 * solution.pvd, the same three of contact_surface, original.prm, parameters.prm, run.json and
 * checkpoint.bin (an earlier run's checkpoint must not be resumed into a new run's results).
 */
bool is_result_file(const std::string& file_name);

/**
 * Removes the files of `directory` (not of its subdirectories) that is_result_file() recognizes,
 * so that a new run owns the directory: no result of an earlier run, e.g. a profile at a time the
 * new run does not write, can pass for one of the new run. Every other file stays. Returns the
 * number of files removed; throws InputError naming Output/directory if one cannot be removed.
 */
unsigned int remove_previous_results(const std::string& directory);
} // namespace dyncontact
