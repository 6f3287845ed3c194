#pragma once
// The `solve` chain as one library call: the loading sweep over the mesh cycle
// (loading/sweep.h), each finished position turned into rows of the solve-results tables
// (io/solve_results.h), VTU files of the selected positions, a checkpoint journal after
// every position, progress with i/N and ETA, and the results written at the end (also
// after a solver failure, with every finished position). A run that was killed resumes
// from its journal (`resume`), and the result equals that of an uninterrupted run.
// Used by `gearfem solve`; callable by a batch driver or an optimiser without CLI code.
#include "solve/input.h"
#include "io/solve_results.h"
#include "loading/sweep.h"
#include "post/observers.h"
#include "post/position.h"

#include <filesystem>
#include <functional>
#include <map>
#include <ostream>
#include <string>

namespace gearfem::solve
{
  /// Name of the checkpoint journal in the output folder; removed when a run completes.
  inline constexpr const char *journal_file = "solve.journal";

  struct SolveRunOptions
  {
    std::filesystem::path output_dir; ///< must exist
    /// Hash of everything the results depend on (the input file): a journal with another
    /// key is not resumed.
    std::string input_hash;
    std::string input_name; ///< file name, for the results' `input` attribute
    /// Continue from output_dir/solve.journal if it exists and matches input_hash (else
    /// InputError); without a journal the run starts from the beginning.
    bool resume = false;
    std::ostream *out = nullptr; ///< progress lines; null: silent
    post::PostOptions post;            ///< thresholds of the evaluation (`Post` section)
    /// Called when the last position of torque `torque_index` (in the order of Solve/Torques)
    /// is evaluated, with the sweep table so far and the wall time of the solves so far [s];
    /// false ends the sweep there (SolveRunResult::stopped): a caller that can already tell
    /// it will discard the run (Solve/Target's p-p check) saves the other torques.
    std::function<bool(std::size_t torque_index, const Table &sweep, double contact_seconds)> torque_done;
  };

  struct SolveRunResult
  {
    io::SolveResults results;         ///< also written to output_dir
    std::size_t resumed = 0;          ///< positions taken from the journal
    std::size_t solved  = 0;          ///< positions solved in this call
    std::string failure;              ///< the SolverError message, empty on success
    /// SolveRunOptions::torque_done ended the sweep: the tables hold the torques before it
    /// (written, the journal removed); not a failure.
    bool stopped = false;
    /// Per torque: unresolved loaded Hertzian pairs (below PostOptions::min_patch_nodes,
    /// share above PostOptions::unresolved_share).
    std::map<double, int> unresolved;
    /// Wall time [s] of the phases of this call: "contact" (the solves), "post" (the
    /// evaluation), "output" (tables, VTU, journal, results files).
    std::map<std::string, double> seconds;
    double pinion_speed = 0;          ///< of the power loss [rad/s] (Contact/Pinion speed)
    std::vector<double> friction;     ///< the friction coefficient per torque (empty: frictionless)
  };

  /// The rows of one evaluated position (index = position index in the plan, name = its
  /// point name or "") in the sweep, pairs and pressure tables.
  void append_position(io::SolveResults &tables, const contact::ContactState &s, const post::PositionResult &r,
                       const std::string &name, int index, double z_ratio, double face_width);

  /// Empty solve-results tables for `in`: the root attributes (program, geometry hash,
  /// method, input) and the line of action.
  io::SolveResults start_results(const solve::GearContactInput &in, const std::string &input_name,
                                 const std::string &program = "gearfem solve");
  /// Unresolved loaded Hertzian pairs (fewer than Post/Min patch nodes across the patch,
  /// load share above `min_share`, not edge contact), per torque.
  std::map<double, int> count_unresolved(const io::SolveResults &t, double min_share);

  /// How run_points runs a plan, beside SolveRunOptions.
  struct PointsSettings
  {
    std::string program = "gearfem solve"; ///< the results' `program` attribute
    /// A checkpoint journal after every point (SolveRunOptions::resume); off where a point
    /// takes a millisecond.
    bool journal = true;
    /// A progress line every `progress_every` points (0: every tenth of the run).
    std::size_t progress_every = 1;
    /// false: no tables, no journal, nothing written (the observers below see every point).
    bool tables = true;
    std::vector<post::PositionObserver *> observers; ///< after the run's own
  };

  /// The plan of `in`: its positions, its torques and the friction coefficient of each torque.
  loading::SweepPlan solve_plan(const GearContactInput &in);

  /// The one sweep of a solve: `plan` on `solver` (loading::run_sweep), each point evaluated by
  /// the solver, its rows appended to the results tables, VTU files (where the solver keeps
  /// fields), the checkpoint journal, progress with i/N and ETA, SolveRunOptions::torque_done;
  /// the results written at the end, also after a failure (docs/output-format.md). run_solve,
  /// condensed::run_condensed and deviations::run_hunting are this call on their backends.
  SolveRunResult run_points(post::PointSolver &solver, const GearContactInput &in, const loading::SweepPlan &plan,
                            const SolveRunOptions &options, const PointsSettings &settings = {});

  /// Run the sweep of `in` on `model` (post::FeSolver) and write the results.
  SolveRunResult run_solve(contact::GearContactModel &model, const solve::GearContactInput &in,
                           const SolveRunOptions &options);

  /// Markdown summary per torque: mean STE, its peak-to-peak, mean k_secant against ISO
  /// 6336-1 c_gamma_alpha, peak pressure and root stresses, unresolved pair-positions.
  std::string summary_table(const SolveRunResult &run, const geometry::MeshingPair &pair,
                            const std::vector<double> &torques);
  /// With friction: per torque, the mean friction force and mesh power loss over the
  /// positions, the mesh efficiency from the loss (1 - P_loss/P_in) and from the torques
  /// (T2 w2 / T1 w1), and the coefficient mu* with P_loss = P_in mu* H_V (Ohlendorf's H_V:
  /// mu* equals mu where the idealised load sharing holds). Empty when frictionless.
  std::string friction_table(const SolveRunResult &run, const geometry::MeshingPair &pair,
                             const std::vector<double> &torques);
} // namespace gearfem::solve
