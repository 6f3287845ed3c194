#pragma once
// `gearfem condense` as one library call: the condensed cycle of a `solve` input with the
// `Condense` section's build torque, torque range and scene ratio (condensed/cycle.h).
#include "condensed/cycle.h"
#include "condensed/parameters.h"

#include <ostream>

namespace gearfem::condensed
{
  /// The range of `gearfem condense`: cycle_range of Solve/Torques for CycleUse::variants,
  /// with `Condense/Build torque` and `Condense/Torque range` where the input sets them.
  CycleRange condense_range(const solve::GearContactInput &in, const CondenseParameters &cp);

  /// Builds the model of `in` and its cycle over condense_range (checked: check_condensable).
  /// The model's size and set-up time and the build's progress go to `out` (may be null).
  CondensedCycle condense(const solve::GearContactInput &in, const CondenseParameters &cp, std::ostream *out);
} // namespace gearfem::condensed
