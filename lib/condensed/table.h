#pragma once
// FE-exact torque tables from a condensed cycle: T(theta, delta) of the mesh-table contract
// (docs/mesh-tables.md, format version 2 when two-sided) from contact solves under rotation
// control at every (position, compression) of the grid, instead of a calibrated analytical
// model. The positions of the cycle are the theta axis (a whole pitch, equally spaced); the
// compressions run from 0 to the largest one every position reaches within the cycle's
// torque range. The reverse flank of a two-sided table is the drive flank of the symmetric
// teeth mapped as the calibrated tables map it (Gkimisis 2019, 4.11).
#include "calibration/model.h"
#include "condensed/cycle.h"
#include "io/mesh_table.h"

#include <ostream>

namespace gearfem::condensed
{
  struct TableOptions
  {
    int n_delta = 60;       ///< compressions on the drive side, 0 included (>= 4)
    double backlash = -1;   ///< clearance b [m] of a two-sided table; < 0: one-sided
  };

  /// The table of `cycle` for the gears of `pair` (the cycle's design). InputError when the
  /// cycle's positions are not one pitch of equally spaced roll angles; SolverError when a
  /// solve fails. Progress on `out` (may be null).
  io::MeshTable torque_table(const CondensedCycle &cycle, const geometry::GearPair &pair, const TableOptions &o,
                             std::ostream *out = nullptr);

  /// FE STE samples of the unmodified design of `cycle` at each pinion torque of `torques`
  /// [N m] at every stored position (torque control; STE = q r_b1): the training data of
  /// `gearfem calibrate` at any torque of the cycle's range, milliseconds per position.
  /// `torques` empty: 6 torques spread geometrically over [torque_lo, torque_hi]. InputError
  /// (naming `entry`) for a torque outside that range; SolverError when a solve fails.
  /// InputError naming `entry` for a torque [N m] outside the range the cycle was built for.
  void check_cycle_torques(const CondensedCycle &cycle, const std::vector<double> &torques, const std::string &entry);

  std::vector<calibration::SteSample> ste_samples(const CondensedCycle &cycle, double base_radius1,
                                                  std::vector<double> torques, const std::string &entry);
} // namespace gearfem::condensed
