#pragma once
// `gearfem solve` with a `Deviations` section: the hunting cycle with manufacturing deviations on
// a condensed cycle (tolerance/hunting.h), the stored one of --condensed or one built in memory;
// with `Deviations/Model = geometry`, the full-FE sweep of `Solve` with the single pitch
// deviations built into the mesh (tolerance/geometry.h).
#include "commands/command.h"
#include "contact/gear_contact.h"
#include "solve/run.h"
#include "post/position.h"
#include "solve/input.h"
#include "tolerance/parameters.h"

namespace gearfem::commands
{
  /// The full-FE sweep of `in` on `model` (solve::run_solve) as `gearfem solve` runs it: the
  /// subdivision note, plots, a failure with every finished position kept, the summary, and
  /// the run record's `cost` and `friction` members. `label` (may be empty) names the route in
  /// the timing line and marks the cost record (the deviations built into the geometry).
  /// `torque_done`: solve::SolveRunOptions::torque_done; a sweep it stopped returns with its
  /// partial tables written and nothing printed or recorded.
  solve::SolveRunResult run_full_fe(contact::GearContactModel &model, const solve::GearContactInput &in,
                                    const post::PostOptions &post, const RunContext &ctx, double setup_seconds,
                                    double cpu_setup, double mesh_seconds, const std::string &label,
                                    const std::function<bool(std::size_t, const Table &, double)> &torque_done = {});

  void run_hunting_cycle(const solve::GearContactInput &in, const post::PostOptions &post,
                         const tolerance::DeviationParameters &dev, const RunContext &ctx);
} // namespace gearfem::commands
