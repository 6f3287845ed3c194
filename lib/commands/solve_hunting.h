#pragma once
// `gearfem solve` with a `Deviations` section: the hunting cycle with manufacturing deviations on
// a condensed cycle (tolerance/hunting.h), the stored one of --condensed or one built in memory;
// with `Deviations/Model = geometry`, the full-FE sweep of `Solve` with the single pitch
// deviations built into the mesh (tolerance/geometry.h).
#include "commands/command.h"
#include "post/position.h"
#include "solve/input.h"
#include "tolerance/parameters.h"

namespace gearfem::commands
{
  void run_hunting_cycle(const solve::GearContactInput &in, const post::PostOptions &post,
                         const tolerance::DeviationParameters &dev, const RunContext &ctx);
} // namespace gearfem::commands
