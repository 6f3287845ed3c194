#pragma once
// Optimisers for the Koronaios 2021 designs: the thesis' steepest descent with a golden-section
// line search (Koronaios 2021, ch. 4-6), and NLopt's SLSQP, MMA (gradient-based, forward
// finite differences), COBYLA, BOBYQA (derivative-free), ISRES, CRS2, ESCH (global).
// Every evaluation is recorded; the result is the best feasible design seen. No deal.II.
#include "optimise/design.h"

#include <functional>
#include <string>
#include <vector>

namespace gearfem::optimise
{
  enum class Method
  {
    steepest_descent, ///< thesis: -grad f / |grad f|, golden section on [0, alpha_max]
    slsqp,            ///< NLopt LD_SLSQP, constraints as inequalities
    mma,              ///< NLopt LD_MMA, constraints as inequalities
    cobyla,           ///< NLopt LN_COBYLA, constraints as inequalities
    bobyqa,           ///< NLopt LN_BOBYQA, constraints by penalty
    isres,            ///< NLopt GN_ISRES (evolution strategy), constraints as inequalities
    crs2,             ///< NLopt GN_CRS2_LM, constraints by penalty
    esch              ///< NLopt GN_ESCH (evolutionary), constraints by penalty
  };
  const char *to_string(Method m);
  /// "steepest descent" -> Method; throws InputError naming `parameter` otherwise.
  Method method_from_string(const std::string &name, const std::string &parameter);
  /// The names accepted by method_from_string, separated by '|'.
  std::string method_names();

  struct OptimiserSettings
  {
    Method method = Method::steepest_descent;
    int max_evaluations = 3000;       ///< hard cap on design evaluations (all methods)
    double bound = 0.3;               ///< box half-width about the start [module units]
    double fd_step = 1e-6;            ///< forward-difference step [module units]
    double xtol_rel = 1e-8;           ///< NLopt relative step tolerance
    double ftol_rel = 1e-10;          ///< relative objective tolerance (NLopt and steepest descent)
    int iterations = 100;             ///< steepest descent iterations (thesis: 100)
    double golden_tolerance = 1e-8;   ///< golden-section interval [module units] (thesis: 1e-8)
    int line_search_steps = 100;      ///< golden-section steps per line search (thesis: 100)
    unsigned int seed = 3;            ///< random seed of the global methods
    int population = 0;               ///< global methods: population (0 = NLopt's default)
    /// Multistart (0 = off): 20 n points drawn uniformly in the box (seeded by `seed`) are
    /// evaluated; the method runs from the start point (when feasible) and from the n best
    /// feasible of them, each run with `max_evaluations`; the result is the best. The box
    /// stays centred on the start point, which may then be infeasible.
    int multistart = 0;
    /// Throws InputError naming "Optimiser/<entry>" for a value out of range.
    void check() const;
  };

  /// One evaluation of the history.
  struct HistoryRow
  {
    int evaluation;      ///< 1-based
    double objective;    ///< objective of this design [1/mm] (NaN-free: 0 when not computable)
    bool feasible;
    double best;         ///< best feasible objective so far [1/mm] (start value before any)
    double seconds;      ///< wall time since the start of the run
  };

  struct OptimiseResult
  {
    Method method;
    std::vector<double> x_start, x_best; ///< [module units]
    Evaluation start, best;
    std::vector<HistoryRow> history;
    int evaluations = 0;
    double seconds = 0;
    std::string stop_reason;
  };

  /// Called every so often with (evaluations done, limit, best feasible objective).
  using ProgressCallback = std::function<void(int, int, double)>;

  /// Minimise the design's objective from x0 under its constraints. Throws InputError
  /// naming "Optimise/Start point" with the reason when x0 is infeasible, and for bad
  /// settings (OptimiserSettings::check). Never returns an infeasible design: when no better
  /// feasible point is found, the start is returned.
  /// Any problem: an evaluation of a design vector (objective, feasibility, the named
  /// constraints; a problem without constraints reports them all met, c = -1).
  using EvaluateFunction = std::function<Evaluation(const std::vector<double> &)>;
  /// Minimise f from x0 in the box [lb, ub] (OptimiserSettings::bound is not used). COBYLA
  /// and BOBYQA take first steps of `initial_step` times the box width. Throws InputError
  /// naming "Optimise/Start point" when f(x0) is infeasible, and for bad settings. The
  /// evaluation of x0 is not counted in the history (it is OptimiseResult::start).
  OptimiseResult optimise(const EvaluateFunction &f, const std::vector<double> &x0, const std::vector<double> &lb,
                          const std::vector<double> &ub, const OptimiserSettings &settings,
                          const ProgressCallback &progress = nullptr, double initial_step = 0.05);

  /// Multistart of `settings.method` in the box [lb, ub] (OptimiserSettings::multistart > 0):
  /// the start point may be infeasible; InputError naming Optimiser/Multistart when neither
  /// it nor any random point is feasible.
  OptimiseResult multistart(const EvaluateFunction &f, const std::vector<double> &x0, const std::vector<double> &lb,
                            const std::vector<double> &ub, const OptimiserSettings &settings,
                            const ProgressCallback &progress = nullptr);

  /// The design's box is x0 +- settings.bound; with settings.multistart > 0, multistart().
  OptimiseResult optimise(const Design &design, const std::vector<double> &x0,
                          const EvaluationSettings &eval, const OptimiserSettings &settings,
                          const ProgressCallback &progress = nullptr);
} // namespace gearfem::optimise
