#pragma once
// FE-exact torque tables from a condensed cycle: T(theta, delta) of the mesh-table contract
// (docs/mesh-tables.md, format version 2 when two-sided) from contact solves under rotation
// control at every (position, compression) of the grid, instead of a calibrated analytical
// model. The positions of the cycle are the theta axis (a whole pitch, equally spaced); the
// compressions run from 0 to the largest one every position reaches within the cycle's
// torque range. The reverse flank of a two-sided table is the drive flank of the symmetric
// teeth mapped as the calibrated tables map it (Gkimisis 2019, 4.11).
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
} // namespace gearfem::condensed
