#pragma once

#include <dyncontact/base/global.h>

#include <string>
#include <vector>

namespace dyncontact
{
/**
 * The executable's command line: `dyncontact FILE.prm [--set "Section/entry=value"]...
 * [--output DIR]`, `--validate` with a FILE.prm anywhere, `--print-parameters [bars|mesh]`,
 * `--version`,
 * `--help`; options in any order. Parsing only; running is main's job.
 */
struct CommandLine
{
  enum class Action
  {
    run,
    validate,
    print_parameters,
    version,
    help
  };

  Action action = Action::help;
  std::string parameter_file;
  std::vector<std::string> overrides; ///< "Section/entry=value", in order; --output adds one
  std::string resume_directory;       ///< --resume DIR: continue from DIR/checkpoint.bin
  bool quiet                = false;  ///< --quiet: no progress lines
  std::string template_kind = "bars"; ///< --print-parameters KIND: "bars", "mesh" or "3d"

  /** Throws InputError naming the offending argument. */
  static CommandLine parse(const std::vector<std::string>& arguments);

  /** The --help text. */
  static std::string usage();
};
} // namespace dyncontact
