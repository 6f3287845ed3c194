#pragma once
// The route of the delivered sweep under `Solve/Target`: the full FE sweep of the delivered
// model, or, when the run repeats the cycle at enough torques for the build to pay, the
// condensed cycle of that same model (condensed/cycle.h), built once over the torque range and
// re-solved at every torque. The condensation's own error is then measured on the run, not
// assumed: full FE solves on the delivered model where the swept quantities peak (largest and
// smallest STE, largest root stresses and p_max) at the lowest and the highest torque (the
// range ends, where the condensation is farthest from the loads it was solved at), compared
// with the cycle's values there, and added to the delivered level's estimate.
#include "base/table.h"
#include "model_choice/to_target.h"
#include "post/position.h"
#include "solve/input.h"
#include "solve/run.h"

#include <array>
#include <string>

namespace gearfem::model_choice
{
  /// Measured on the Parker pair at m/45 (157 000 DoFs, 40 positions): the build of a cycle
  /// costs about 3.3 full torque sweeps per scene of a position (a solve and its condensation
  /// to some 380 candidates), and each position holds about one scene more than the parts its
  /// torque range is split into (100-340 N m: 82 scenes, 3.34 s, 6.8 sweeps of 0.49 s; 50-500
  /// N m: 123 scenes, 4.41 s, 9.3 sweeps); a re-solve costs about 2 % of a sweep.
  inline constexpr double build_sweeps_per_scene = 3.3;

  struct RoutePlan
  {
    bool condensed = false;
    double lo = 0, hi = 0, build_torque = 0; ///< torque range and build torque [N m]
    double predicted_build_sweeps = 0;       ///< the build's predicted cost in full torque sweeps
    std::string why;                         ///< the reason, in words
  };

  /// The full FE sweep where `Solve/Target route = full FE`; else the condensed route where
  /// the torques of `in` number at least 1.2 times the predicted cost of the build in torque
  /// sweeps (scenes per position: 1 + the parts of [lo, hi] at `scene_ratio`), the input is
  /// condensable (condensed::check_condensable: no tip relief meshed as geometry, no friction,
  /// an external pair), asks for no VTU (the cycle keeps no fields) and is not resumed.
  RoutePlan plan_route(const solve::GearContactInput &in, bool resume, double scene_ratio = 4.0);

  /// With a p-p STE tolerance that a finer h_contact may still meet (h_contact not set in the
  /// input): sweep the first torque in full before building a cycle, so that abandon_sweep
  /// can stop a level whose p-p already fails there, before its build (Siasos 2010 23/69 at
  /// ten torques: the m/45 level's cycle, about 2 s, was built and then discarded). Costs one
  /// full torque sweep where the level passes.
  bool probe_before_cycle(const TargetOutcome &o, const FixedSettings &fixed);

  /// How Solve/Target's sweep of one level went (sweep_on_cycle).
  enum class Swept
  {
    full_fe,      ///< not on a cycle: the full FE sweep is still the caller's to run
    on_cycle,     ///< on the condensed cycle (CycleSweep::result)
    probe_stopped ///< the first torque swept in full already asks for a finer level (result: it)
  };

  struct CycleSweep
  {
    Swept how = Swept::full_fe;
    solve::SolveRunResult result;     ///< written to run.output_dir like solve::run_solve
    double build_seconds = 0;         ///< wall time of the cycle's build
    unsigned int dofs    = 0;         ///< of the cycle's model
  };

  /// The condensed route of the delivered level (plan_route): with a p-p tolerance the first
  /// torque swept in full first (probe_before_cycle; Swept::probe_stopped where abandon_sweep
  /// stops it, result.stopped set), then the cycle of o.model built once and re-solved at
  /// every torque. Swept::full_fe, with the reason in o.route_why, where the full FE sweep must
  /// run instead: not planned, or the build or a re-solve failed (the full FE then decides).
  /// Sets o.route and o.route_why, clears o.condensation. Throws SolverError when the probe's
  /// full sweep fails.
  CycleSweep sweep_on_cycle(TargetOutcome &o, solve::GearContactInput &in, const FixedSettings &fixed,
                            const TargetOptions &options, const solve::SolveRunOptions &run, bool resume);

  /// The condensation's error on the run: full FE solves on `model` (the delivered model the
  /// cycle was built from) at the lowest and the highest torque of `sweep` (the condensed run's
  /// sweep table), at the rows of its largest and smallest STE, its largest root stress of each
  /// gear and its largest p_max, against the sweep's values there: per quantity (Quantity
  /// order), the mean STE max |d| / mean STE of the two STE rows, the p-p STE |d(max) - d(min)|
  /// / p-p, the root stress |d| / the largest root stress of each gear, p_max |d| / the largest
  /// p_max; the largest over the two torques. Throws SolverError when a solve fails.
  std::array<double, n_quantities> condensation_error(contact::GearContactModel &model,
                                                      const solve::GearContactInput &in, const Table &sweep,
                                                      const post::PostOptions &post);

  /// Adds `error` (condensation_error) to the delivered level's estimate, records it in
  /// `o.condensation`, and updates `met`.
  void add_condensation_error(TargetOutcome &o, const std::array<double, n_quantities> &error);
} // namespace gearfem::model_choice
