#pragma once
// The aggregate of a batch: batch.csv and batch.h5, one row per design x torque
// (docs/batch.md), built from the job records and the jobs' results.h5 files only, so that
// a finished batch, a restarted one and `gearfem batch --merge` of job-array slices give
// the same table.
#include "batch/job.h"
#include "io/solve_results.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gearfem::batch
{
  inline constexpr const char *batch_format         = "gearfem-batch";
  inline constexpr const char *batch_format_version = "1";

  /// The numbers of one torque of one job's sweep.
  struct TorqueSummary
  {
    double torque        = 0; ///< [N m]
    std::size_t positions = 0;
    double ste_mean = 0, ste_peak_to_peak = 0; ///< [um]
    double k_mean = 0, k_min = 0, k_max = 0;   ///< secant mesh stiffness per width [N/(mm um)]
    double p_max           = 0;                ///< max Hertzian (flank-to-flank) pressure [MPa]
    double root_pinion     = 0, root_gear = 0; ///< max root stress [MPa]
  };

  /// Per torque, in the order the torques first appear in the sweep table: mean and
  /// peak-to-peak of `STE`, mean/min/max of `k_secant per width`, max of `p_max`, `root
  /// stress pinion` and `root stress gear` (columns of docs/output-format.md).
  std::vector<TorqueSummary> summarise(const io::SolveResults &results);

  /// What each design's row says: its record (nullopt: not run) and, for a finished job,
  /// its summaries.
  struct DesignOutcome
  {
    std::optional<JobRecord> record;
    std::vector<TorqueSummary> summaries;
    std::string status; ///< "ok", "failed: <message>" or "not run"
    std::vector<double> torques; ///< the design's torques [N m]: one row each without results
  };

  /// Read jobs_root/<id>/job.txt and results.h5 of every design of the study.
  std::vector<DesignOutcome> collect_outcomes(const Study &study, const std::filesystem::path &jobs_root);

  /// Write `dir`/batch.csv and `dir`/batch.h5 (atomically). `units[k]` is the unit of
  /// design path k ("" if unknown). Returns the number of rows.
  std::size_t write_aggregate(const Study &study, const std::vector<std::string> &units,
                              const std::vector<DesignOutcome> &outcomes, const std::filesystem::path &dir);
} // namespace gearfem::batch
