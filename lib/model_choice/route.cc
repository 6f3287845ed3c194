#include "model_choice/route.h"

#include "base/errors.h"
#include "condensed/cycle.h"
#include "condensed/resolve.h"
#include "solve/error_estimate.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>
#include <sstream>
#include <vector>

namespace gearfem::model_choice
{
  /// The candidate band of Solve/Target's cycle (condensed::CycleOptions::band_factor): it is
  /// re-solved at its own torques only, so a scene keeps the candidates within 4 times the
  /// approach at the top of its load range, not every node within Contact/Search distance.
  constexpr double target_band = 4.0;

  RoutePlan plan_route(const solve::GearContactInput &in, bool resume, double scene_ratio)
  {
    RoutePlan r;
    const auto &T = in.solve.torques;
    if (T.empty())
      return r;
    const condensed::CycleRange range = condensed::cycle_range(T, condensed::CycleUse::given_torques);
    r.lo = range.lo, r.hi = range.hi, r.build_torque = range.build;
    const double parts =
      r.hi > r.lo * (1 + 1e-12) ? std::max(1.0, std::ceil(std::log(r.hi / r.lo) / std::log(scene_ratio))) : 1.0;
    r.predicted_build_sweeps = build_sweeps_per_scene * (1 + parts);
    std::ostringstream why;
    why.precision(3);
    if (!in.solve.target_route_auto)
      {
        r.why = "Solve/Target route = full FE";
        return r;
      }
    const double needed = std::ceil(1.2 * r.predicted_build_sweeps);
    if (double(T.size()) < needed)
      {
        why << T.size() << " torque sweep(s): a condensed cycle would cost about " << r.predicted_build_sweeps
            << " sweeps to build (" << 1 + parts << " scenes per position), so it pays from " << needed
            << " torques";
        r.why = why.str();
        return r;
      }
    if (in.solve.vtu != solve::SolveParameters::Vtu::none)
      {
        r.why = "Solve/VTU asks for fields, which a condensed cycle does not keep";
        return r;
      }
    if (resume)
      {
        r.why = "--resume continues the full FE sweep's journal";
        return r;
      }
    try
      {
        condensed::check_condensable(in);
      }
    catch (const InputError &e)
      {
        r.why = std::string("the input cannot be condensed (") + e.what() + ")";
        return r;
      }
    r.condensed = true;
    why << T.size() << " torque sweeps on one condensed cycle of the delivered model, built at " << r.build_torque
        << " N m for " << r.lo << "-" << r.hi << " N m: about " << r.predicted_build_sweeps
        << " sweeps to build, then about 2 % of a sweep per torque (the full FE from " << needed
        << " torques costs more); the condensation's error is measured on the run at the range ends";
    r.why = why.str();
    return r;
  }

  bool probe_before_cycle(const TargetOutcome &o, const FixedSettings &fixed)
  {
    return o.target[Quantity::pp_ste] > 0 && !fixed.h_contact;
  }

  CycleSweep sweep_on_cycle(TargetOutcome &o, solve::GearContactInput &in, const FixedSettings &fixed,
                            const TargetOptions &options, const solve::SolveRunOptions &run, bool resume)
  {
    CycleSweep c;
    const RoutePlan plan = plan_route(in, resume);
    o.route              = "full FE";
    o.route_why          = plan.why;
    o.condensation.fill(std::numeric_limits<double>::quiet_NaN());
    if (!plan.condensed)
      return c;
    if (run.out)
      *run.out << "model choice: " << plan.why << std::endl;
    if (probe_before_cycle(o, fixed))
      {
        const std::vector<double> torques = in.solve.torques;
        in.solve.torques                  = {torques.front()};
        c.result                          = solve::run_solve(*o.model, in, run);
        in.solve.torques                  = torques;
        if (!c.result.failure.empty())
          throw SolverError(c.result.failure + "\n  (the full FE sweep of the first torque, before the condensed cycle)");
        if (abandon_sweep(o, in, fixed, options, swept_pp(c.result.results.sweep, torques), 1,
                          c.result.seconds.at("contact")))
          {
            o.route_why += "; the first torque, swept in full first, already asks for a finer level";
            if (run.out)
              *run.out << "model choice: the first torque's p-p STE, swept in full, already asks for a finer "
                          "level: no cycle for this one"
                       << std::endl;
            c.result.stopped = true;
            c.how            = Swept::probe_stopped;
            return c;
          }
      }
    std::string failure;
    try
      {
        const auto t0 = std::chrono::steady_clock::now();
        const condensed::CondensedCycle cycle =
          condensed::cycle_for(*o.model, in, {plan.build_torque, plan.lo, plan.hi}, {4.0, run.out, target_band});
        c.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        c.dofs          = cycle.dofs;
        c.result        = condensed::run_condensed(cycle, in, run);
        failure         = c.result.failure;
      }
    catch (const SolverError &e)
      {
        failure = e.what();
      }
    catch (const InputError &e)
      {
        failure = e.what();
      }
    if (failure.empty())
      {
        o.route = "condensed cycle";
        c.how   = Swept::on_cycle;
        return c;
      }
    o.route_why = "the condensed route failed (" + failure + "); the full FE sweep instead";
    if (run.out)
      *run.out << "model choice: " << o.route_why << std::endl;
    c.result = solve::SolveRunResult();
    return c;
  }

  std::array<double, n_quantities> condensation_error(contact::GearContactModel &model,
                                                      const solve::GearContactInput &in, const Table &sweep,
                                                      const post::PostOptions &post)
  {
    std::array<double, n_quantities> e{};
    const auto T_col = sweep.column("torque"), pos = sweep.column("position"), ste = sweep.column("STE"),
               rp = sweep.column("root stress pinion"), rg = sweep.column("root stress gear"),
               pm = sweep.column("p_max");
    const auto positions = in.positions();
    const auto &T        = in.solve.torques;
    if (T.empty())
      return e;
    const double lo = *std::min_element(T.begin(), T.end()), hi = *std::max_element(T.begin(), T.end());
    for (const double torque : {lo, hi})
      {
        std::vector<std::size_t> rows;
        for (std::size_t i = 0; i < T_col.size(); ++i)
          if (T_col[i] == torque)
            rows.push_back(i);
        if (rows.empty())
          continue;
        // The rows of the largest and smallest STE, root stresses and p_max (sweep.csv: um, MPa).
        const auto arg = [&](const std::vector<double> &v, bool largest) {
          return *std::max_element(rows.begin(), rows.end(),
                                   [&](std::size_t x, std::size_t y) { return largest ? v[x] < v[y] : v[x] > v[y]; });
        };
        const std::size_t i_hi = arg(ste, true), i_lo = arg(ste, false), i_rp = arg(rp, true), i_rg = arg(rg, true),
                          i_pm = arg(pm, true);
        const std::size_t check[5] = {i_hi, i_lo, i_rp, i_rg, i_pm};
        std::vector<double> roll;
        for (const std::size_t i : check)
          {
            const std::size_t k = std::size_t(pos[i]);
            if (k >= positions.size())
              throw SolverError("condensation check: a sweep row names a position outside Solve/Positions");
            roll.push_back(positions[k].second);
          }
        const auto fe = solve::solve_samples(model, roll, {torque}, post); // m and Pa
        double mean = 0;
        for (const std::size_t i : rows)
          mean += ste[i];
        mean *= 1e-6 / double(rows.size());
        const double d_hi = ste[i_hi] * 1e-6 - fe[0].ste, d_lo = ste[i_lo] * 1e-6 - fe[1].ste;
        const double pp   = (ste[i_hi] - ste[i_lo]) * 1e-6;
        if (mean > 0)
          e[0] = std::max(e[0], std::max(std::abs(d_hi), std::abs(d_lo)) / mean);
        if (pp > 0)
          e[1] = std::max(e[1], std::abs(d_hi - d_lo) / pp);
        if (rp[i_rp] > 0)
          e[2] = std::max(e[2], std::abs(rp[i_rp] * 1e6 - fe[2].root_stress_pinion) / (rp[i_rp] * 1e6));
        if (rg[i_rg] > 0)
          e[2] = std::max(e[2], std::abs(rg[i_rg] * 1e6 - fe[3].root_stress_gear) / (rg[i_rg] * 1e6));
        if (pm[i_pm] > 0)
          e[3] = std::max(e[3], std::abs(pm[i_pm] * 1e6 - fe[4].p_max) / (pm[i_pm] * 1e6));
      }
    return e;
  }

  void add_condensation_error(TargetOutcome &o, const std::array<double, n_quantities> &error)
  {
    o.condensation = error;
    Level &l       = o.levels[o.delivered];
    for (int q = 0; q < n_quantities; ++q)
      if (std::isfinite(l.estimate[q]))
        l.estimate[q] += error[q];
    update_met(o);
  }
} // namespace gearfem::model_choice
