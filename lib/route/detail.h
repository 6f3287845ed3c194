#pragma once
// The parts of route::run shared by its routes (route.cc, target.cc, deviations.cc).
#include "route/route.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::route::detail
{
  /// Sets run-record member `name` to `json`, in place where it exists already.
  void set_member(std::vector<std::pair<std::string, std::string>> &record, const std::string &name,
                  const std::string &json);
  std::string json_string(const std::string &s);

  /// The solve options of `r` (output folder, names, resume, progress, Post).
  solve::SolveRunOptions run_options(const Request &r);

  /// What the cost record of a full FE sweep states besides the sweep's own timings.
  struct FullFeCost
  {
    double setup_seconds = 0, cpu_setup = 0, mesh_seconds = 0;
    std::string label; ///< names the route in the timing line and marks the record; may be empty
  };

  /// The full FE sweep of r.input on `model` (solve::run_solve): the subdivision note, the
  /// plot, a failure with every finished position kept (Outcome::failure), the summary, the
  /// `cost` and `friction` members. `torque_done`: solve::SolveRunOptions::torque_done; a sweep
  /// it stopped returns with its partial tables written and nothing printed or recorded.
  solve::SolveRunResult full_fe_sweep(contact::GearContactModel &model, const Request &r, Outcome &o,
                                      const FullFeCost &cost,
                                      const std::function<bool(std::size_t, const Table &, double)> &torque_done);

  /// A sweep on a condensed cycle as a run reports it: the plot, a failure with the finished
  /// positions kept, the summary, the `cost` member (`build_seconds`: of a cycle built in this run).
  solve::SolveRunResult report_condensed(solve::SolveRunResult res, const Request &r, Outcome &o, double cpu_setup,
                                         unsigned int dofs, double build_seconds);

  void run_target(Request &r, Outcome &o);   ///< Route::target (target.cc)
  void run_hunting(Request &r, Outcome &o);  ///< Route::hunting_cycle (deviations.cc)
  void run_geometry(Request &r, Outcome &o); ///< Route::deviations_in_geometry (deviations.cc)
} // namespace gearfem::route::detail
