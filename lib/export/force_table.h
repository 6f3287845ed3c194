#pragma once
// The two-sided mesh-force table F(theta, delta) with backlash and back contact, for any code
// that takes a force law (docs/export.md), from a torque mesh table T(theta, delta)
// (docs/mesh-tables.md).
#include "io/mesh_table.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gearfem::exports
{
  /// F [N] on (theta [rad] from C, delta [m]) theta-major; delta = DTE along the line of
  /// action (r_b1 theta1 - r_b2 theta2 beyond the rigid conjugate position, > 0: drive
  /// flanks compressed); F > 0 drive contact, 0 in the clearance -b <= delta <= 0, < 0 back
  /// contact on the coast flanks (delta < -b).
  struct ForceTable
  {
    std::vector<double> theta, delta, force;
    double backlash = 0;        ///< b [m]
    double period = 0;          ///< 2 pi / z1 [rad]
    double reverse_offset = 0;  ///< psi of theta_r = psi - theta [rad] (one-sided sources), else 0
    bool mapped = false;        ///< true: the back-contact branch was mapped here from a one-sided table
    double at(std::size_t i, std::size_t j) const { return force[i * delta.size() + j]; }
  };

  /// F = T / r_b1. A two-sided table is copied (its own backlash; `backlash` >= 0 must equal
  /// it). A one-sided table needs `backlash` >= 0 [m]: the delta axis becomes
  /// io::torque_table_axis(drive, b) and the back branch F(theta, -b - d) = -F(psi - theta, d)
  /// (Gkimisis 2019 eq. 4.11; psi = `reverse_offset` for that b, periodic linear in theta).
  /// Throws InputError naming `parameter` (the backlash entry) or the table.
  ForceTable force_table(const io::MeshTable &t, double backlash, double reverse_offset, const std::string &parameter);

  /// CSV, one row per (theta, delta), theta slowest: roll angle [deg], compression [um],
  /// force [N], contact (1 drive, 0 clearance, -1 back) [-]; 17 significant digits.
  void write_force_csv(const std::filesystem::path &file, const ForceTable &f);
} // namespace gearfem::exports
