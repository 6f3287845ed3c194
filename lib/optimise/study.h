#pragma once
// A Koronaios 2021 optimisation study: the case, its evaluation settings, the optimisers to run
// from one start point, and the report (tables, CSV files, optimum.prm). No deal.II.
#include "optimise/optimisers.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace gearfem::optimise
{
  struct Study
  {
    DesignKind kind = DesignKind::case2_flank;
    PairData pair;
    FixedEnd fixed_end = FixedEnd::tip; ///< case 2: the fixed end control point
    double face_width = 20e-3;          ///< written to optimum.prm [m]
    EvaluationSettings eval;            ///< used inside the optimisation
    int report_samples = 2001;          ///< samples of the reported statistics and curves
    std::vector<double> start;          ///< [module units]; empty = Design::default_start()
    std::vector<OptimiserSettings> runs; ///< one per method, same start
  };

  /// One method's run and its optimum re-evaluated with the report sampling.
  struct StudyRun
  {
    OptimiseResult result;
    Evaluation optimum; ///< report sampling
  };

  struct StudyResult
  {
    std::vector<StudyRun> runs;
    Evaluation involute, sinusoid, start; ///< references, report sampling
    int best_run = 0;                     ///< index of the run with the lowest objective
  };

  /// Check the study (InputError naming the parameter), evaluate the start point (InputError
  /// naming Optimise/Start point with the reason when infeasible).
  void check_study(const Study &s);
  /// Run every optimiser; `out` receives progress lines (i/N, ETA) and may be null.
  StudyResult run_study(const Study &s, std::ostream *out);

  /// Files of a study (atomically): optimise.csv (history), summary.csv (one row per method
  /// and the references), curvature.csv (1/R along the path), profiles.csv (flanks and
  /// racks), optimum.prm (case 2: a `gearfem solve` case of the best design; case 1: the
  /// rack control points as a `gearfem profile` case, see docs/optimise.md).
  void write_study(const Study &s, const StudyResult &r, const std::filesystem::path &dir);
  /// The summary table as text (console and optimise.md).
  void print_summary(const Study &s, const StudyResult &r, std::ostream &out);
} // namespace gearfem::optimise
