#pragma once
// The report of a gear pair's geometry that `gearfem profile` writes: the sampled outlines
// of both gears (profile_gear1.csv, profile_gear2.csv, body frames), the pair kinematics
// and design quantities (pair.csv), the path of contact (contact_path.csv), and a console
// summary with the design warnings. Light layer (base tables, no deal.II).
#include "base/table.h"
#include "geometry/material.h"
#include "geometry/pair.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace gearfem::geometry
{
  /// One row of pair.csv.
  struct PairQuantity
  {
    std::string name;
    double value = 0;
    std::string unit;
  };

  /// The whole gear outline sampled every m_n/40 (mm, with normals, curvature, segment codes).
  Table profile_table(const ToothProfile &gear);
  /// Kinematics, radii, line of action, backlash, clearances and checks of the pair.
  std::vector<PairQuantity> pair_quantities(const GearPair &pair);
  /// The path of contact from A to E (201 points) with its equivalent curvature.
  Table contact_path_table(const GearPair &pair);
  /// Radii, line of action, contact ratio, backlash, then every design warning.
  void print_pair_summary(const GearPair &pair, const PairMaterial &material, std::ostream &out);
  /// profile_gear1.csv, profile_gear2.csv, pair.csv and contact_path.csv in `dir` (atomic).
  void write_profile_report(const GearPair &pair, const std::filesystem::path &dir);
} // namespace gearfem::geometry
