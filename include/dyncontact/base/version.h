#pragma once

namespace dyncontact
{
/** The code's version, the CMake project version (e.g. "0.14.0"). */
const char* version();

/**
 * The git commit the build was made from (git describe: an abbreviated hash, "-dirty" with
 * uncommitted changes), or "unknown" outside a git checkout. Refreshed at every build
 * (cmake/write_version.cmake).
 */
const char* commit();
} // namespace dyncontact
