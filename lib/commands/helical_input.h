#pragma once
// A `gearfem helical` input file read and checked as the CLI reads one: the stages of
// `gearfem system` and of gearfem.system from Python (defined in system_command.cc).
#include "helical/run.h"

#include <filesystem>

namespace gearfem::commands
{
  /// InputError naming the file and the entry for a bad one.
  helical::Request read_helical_input(const std::filesystem::path &file);
} // namespace gearfem::commands
