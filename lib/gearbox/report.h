#pragma once
// Writers of `gearfem gearbox`: gearbox.md (every factor with its clause, stresses,
// scuffing and lives), gearbox.csv (one row per stage, mesh and bin), gearbox_life.csv
// (one row per member and mode) and scuffing_path.csv (the path of contact of the worst
// bin). Engineering units in the files; all written atomically; never NaN (an infinite
// life is written as "inf"). gearbox_tables gives the numbers of gearbox.csv and
// gearbox_life.csv as tables, for gearbox.h5 (written by the command through lib/io).
#include "gearbox/life.h"
#include "base/table.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gearfem::gearbox
{
  /// `appendix`: markdown inserted before the fatigue-life section (e.g. the FE stresses).
  void write_markdown(const GearboxInput &in, const GearboxResult &r, const std::string &stress_source,
                      const std::filesystem::path &file, const std::string &title,
                      const std::string &appendix = "");
  void write_csv(const GearboxInput &in, const GearboxResult &r, const std::filesystem::path &dir);
  /// gearbox_sn.csv: one row per member, mode, load and bin (stress, load cycles per
  /// spectrum, cycles to failure, damage n/N) with the member's S-N curve (kind, sigma_n,
  /// N_ref, B, N_static, Y_static), for the S-N plot of scripts/plot_gearbox.py. Atomic.
  void write_sn_csv(const GearboxInput &in, const GearboxResult &r, const std::filesystem::path &file);

  /// The numbers of gearbox.csv (`meshes`: one row per stage, mesh and bin) and of
  /// gearbox_life.csv (`lives`: one row per member and mode), in the same engineering units,
  /// with their text columns. A life without damage is 0 with `damaged [-]` = 0 (HDF5 holds
  /// no inf or NaN).
  struct GearboxTables
  {
    Table meshes, lives;
    std::vector<std::string> mesh_stage, mesh_name, life_stage, life_member, life_mode, life_load;
  };
  GearboxTables gearbox_tables(const GearboxInput &in, const GearboxResult &r);
} // namespace gearfem::gearbox
