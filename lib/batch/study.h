#pragma once
// A batch study: a normal `solve` case file plus `subsection Batch` (the designs), and the
// case of each design (the study with the design's parameter paths overridden). The chain
// never sees the study: each job gets a ParameterHandler that reads exactly like a `solve`
// case file. Errors of the study itself (unknown path, malformed table, a value that does
// not match the pattern of its entry) are InputErrors naming the column and the row, found
// before any job runs (exit 2); a design whose values are legal but whose pair is not
// (interference, undercut, range checks of the parsers) is an invalid design: its job is
// recorded as failed and the batch goes on.
#include "batch/design.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::batch
{
  /// The `Batch` section.
  struct BatchParameters
  {
    enum class Source
    {
      table,          ///< `Design table`: a CSV file
      factorial,      ///< `Factorial`: lists per path
      latin_hypercube ///< `Latin hypercube`: ranges per path, `Samples`, `Seed`
    };
    Source source = Source::table;
    std::string table;        ///< as written; relative to the study file
    std::string factorial;    ///< "path: v1, v2; path: ..."
    std::string hypercube;    ///< "path: lo, hi; path: ..."
    int samples        = 10;
    unsigned long seed = 1;
    bool write_vtu     = false; ///< per-job VTU as in `Solve/VTU`; false: none
    /// `Condensed cycle = auto`: designs that share one FE model (same model key, reliefs on
    /// the gap route) and together ask for at least 3 torque sweeps are re-solved on one
    /// condensed cycle per rank (condensed/cycle.h) instead of a full solve each.
    bool condensed = true;
    /// `Job isolation = process`: each rank runs its jobs in a supervised worker process
    /// (batch/isolation.h), so that a crash or time-out is one failed job; `none`: in the
    /// rank's own process (a crash ends the batch).
    bool isolation = true;
    /// `Job time limit` [s]: a job running longer is killed and recorded as failed; 0: none.
    double job_time_limit = 0;
  };

  void declare_batch_parameters(dealii::ParameterHandler &prm);
  BatchParameters parse_batch_parameters(dealii::ParameterHandler &prm);

  struct Study
  {
    std::filesystem::path file; ///< the study file
    std::string text;           ///< its content
    BatchParameters batch;
    DesignSet designs;
    std::string source_name; ///< "design table d.csv", "Batch/Factorial", ... for messages
  };

  /// Read the study's designs (table, factorial or hypercube) and check every design's paths
  /// and values against the case parameters (design_handler), all before any job runs.
  /// Throws the first InputError, naming column and row.
  Study load_study(dealii::ParameterHandler &prm, const std::filesystem::path &file);

  /// The parameters of design `i`: the study text read by a handler that declares what
  /// `solve` reads, the design's values set by path, per-job VTU and plots switched off
  /// unless `Batch/Write VTU`. Throws InputError naming the column (path) and the design's
  /// row for an unknown path or a value its entry's pattern refuses.
  std::unique_ptr<dealii::ParameterHandler> design_handler(const Study &study, std::size_t i);

  /// Everything the job's results depend on, as text (the handler's parameters, PRM
  /// format), and its hash: the restart key of the job.
  std::string design_parameters(dealii::ParameterHandler &prm);

  /// The unit of the entry at `path` from its documentation ("... Units: um."), "-" for
  /// "none", "" when the documentation states none.
  std::string parameter_unit(const dealii::ParameterHandler &prm, const std::string &path);

  /// The message of every design that fails the checks of `solve` (parse of the case,
  /// geometry and outline checks, Post section), by design index; empty when all pass.
  std::vector<std::pair<std::size_t, std::string>> check_designs(const Study &study);
} // namespace gearfem::batch
