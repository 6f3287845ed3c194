#pragma once
// Writers of `gearfem gearbox`: gearbox.md (every factor with its clause, stresses,
// scuffing and lives), gearbox.csv (one row per stage, mesh and bin), gearbox_life.csv
// (one row per member and mode) and scuffing_path.csv (the path of contact of the worst
// bin). Engineering units in the files; all written atomically; never NaN (an infinite
// life is written as "inf").
#include "analytical/gearbox_life.h"

#include <filesystem>
#include <string>

namespace gearfem::analytical::gearbox
{
  void write_markdown(const GearboxInput &in, const GearboxResult &r, const std::string &stress_source,
                      const std::filesystem::path &file, const std::string &title);
  void write_csv(const GearboxInput &in, const GearboxResult &r, const std::filesystem::path &dir);
} // namespace gearfem::analytical::gearbox
