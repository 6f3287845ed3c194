#include "helical/run.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/progress.h"
#include "base/units.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace gearfem::helical
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
  } // namespace

  SlicingOptions slicing_options(solve::GearContactInput &in, const HelixInput &hx, const post::PostOptions &post)
  {
    in.require_external("gearfem helical");
    condensed::check_condensable(in);
    const auto &pair = *in.pair;
    const double b   = std::min(pair.face_width(1), pair.face_width(2));
    check(hx, b);
    auto &s = in.solve;
    if (s.positions != solve::SolveParameters::Positions::cycle || std::abs(s.pitches - 1.0) > 1e-12)
      throw InputError("Solve/Positions", s.positions == solve::SolveParameters::Positions::cycle ? "cycle over " +
                                                                                                      to_string_g(s.pitches) +
                                                                                                      " pitches" :
                                                                                                    "not a cycle",
                       "cycle with Solve/Pitches = 1",
                       "the slices sit on one pitch of equally spaced sections (their grid)");
    SlicingOptions o;
    const auto &r = pair.gear(1).parameters().rack;
    o.helix       = helix(hx, r.module, r.pressure_angle, pair.base_radius(1), b);
    o.slices      = hx.slices;
    o.coupling        = hx.coupling;
    o.coupling_length = hx.coupling_length < 0 ? o.helix.m_n : hx.coupling_length;
    o.model       = hx.model;
    o.solid       = hx.solid;
    o.lead        = hx.lead;
    o.alpha_wt    = pair.working_pressure_angle();
    o.post        = post;
    const auto positions = in.positions();
    o.grid.size = int(positions.size());
    o.grid.phi0 = positions.front().second;
    o.grid.step = 2 * M_PI / pair.gear(1).teeth() / o.grid.size;
    s.positions   = solve::SolveParameters::Positions::list;
    s.roll_angles.clear();
    for (const auto &[name, phi] : o.grid.positions())
      s.roll_angles.push_back(phi);
    return o;
  }

  std::vector<TorqueSummary> summarise(const std::vector<HelicalResult> &results)
  {
    std::vector<TorqueSummary> out;
    for (const auto &r : results)
      {
        auto it = std::find_if(out.begin(), out.end(), [&](const TorqueSummary &s) { return s.torque == r.torque; });
        if (it == out.end())
          {
            TorqueSummary s;
            s.torque   = r.torque;
            s.ste_mean = 0;
            out.push_back(s);
            it = out.end() - 1;
          }
      }
    for (auto &s : out)
      {
        double lo = 1e300, hi = -1e300, sum = 0, ksum = 0;
        int n = 0;
        for (const auto &r : results)
          if (r.torque == s.torque)
            {
              lo = std::min(lo, r.ste), hi = std::max(hi, r.ste), sum += r.ste, ksum += r.k_mesh, ++n;
              s.k_h_beta           = std::max(s.k_h_beta, r.k_h_beta);
              s.root_stress_pinion = std::max(s.root_stress_pinion, r.root_stress_pinion);
              s.root_stress_gear   = std::max(s.root_stress_gear, r.root_stress_gear);
              s.p_max              = std::max(s.p_max, r.p_max);
            }
        s.ste_mean = sum / n;
        s.ste_pp   = hi - lo;
        s.k_mean   = ksum / n;
      }
    return out;
  }

  namespace
  {
    void per_width(std::vector<TorqueSummary> &out, double b)
    {
      for (auto &s : out)
        s.c_gamma = s.k_mean / b;
    }
  } // namespace

  condensed::CondensedCycle section_cycle(const solve::GearContactInput &in, const std::vector<double> &torques,
                                          const RunOptions &ro, HelicalRun &run)
  {
    condensed::CondensedCycle cycle;
    if (!ro.cycle_file.empty())
      {
        cycle = condensed::read_cycle(ro.cycle_file);
        for (const double T : torques)
          if (T < cycle.torque_lo * (1 - 1e-12) || T > cycle.torque_hi * (1 + 1e-12))
            throw InputError("Solve/Torques", to_string_g(T) + " N m",
                             to_string_g(cycle.torque_lo) + " to " + to_string_g(cycle.torque_hi) +
                               " N m (the torque range of the condensed cycle " + ro.cycle_file.string() + ")",
                             "build a cycle for this torque (without --condensed, or with Condense/Torque range)");
        return cycle;
      }
    const auto t0   = Clock::now();
    condensed::CycleRange range = condensed::cycle_range(torques, condensed::CycleUse::slices, ro.build_torque);
    if (ro.torque_lo > 0)
      range.lo = ro.torque_lo;
    if (ro.torque_hi > 0)
      range.hi = ro.torque_hi;
    auto model = in.model();
    if (ro.out)
      *ro.out << "transverse section: " << model->n_dofs() << " DoFs, set-up " << std::setprecision(3)
              << model->setup_seconds() << " s; condensing " << in.positions().size() << " sections for torques "
              << range.lo << " to " << range.hi << " N m\n";
    cycle = condensed::cycle_for(*model, in, range,
                                 {condensed::scene_ratio(condensed::CycleUse::slices, ro.scene_ratio), ro.out});
    run.setup_seconds = model->setup_seconds();
    run.build_seconds = since(t0);
    if (!ro.write_cycle.empty())
      condensed::write_cycle(cycle, ro.write_cycle);
    return cycle;
  }

  HelicalRun run_helical(const solve::GearContactInput &in, const SlicingOptions &o, const RunOptions &ro)
  {
    HelicalRun run;
    run.options = o;
    run.helix   = run.options.helix;
    run.torques = in.solve.torques;
    const auto &pair = *in.pair;
    run.eps_alpha    = pair.contact_ratio();
    run.eps_gamma    = run.eps_alpha + run.helix.overlap_ratio;
    const condensed::CondensedCycle cycle = section_cycle(in, run.torques, ro, run);
    const SlicedPair sliced(cycle, in, run.options);
    const auto grid      = run.options.grid.positions();
    const std::size_t total = grid.size() * run.torques.size();
    Progress progress(ro.out, total, "helical position");
    const auto t0 = Clock::now();
    for (std::size_t i = 0; i < total && run.failure.empty(); ++i)
      {
        const double T   = run.torques[i / grid.size()];
        const double phi = grid[i % grid.size()].second;
        try
          {
            run.results.push_back(ro.position ? ro.position(sliced, phi, T) : sliced.solve(phi, T));
            const auto &r = run.results.back();
            std::ostringstream d;
            d << "T " << T << " N m, STE " << std::setprecision(4) << r.ste / units::um << " um, K_Hbeta "
              << r.k_h_beta << ", " << r.candidates << " unknowns";
            if (ro.out && ((i + 1) % std::max<std::size_t>(1, total / 10) == 0 || i + 1 == total))
              progress.step(i + 1, d.str());
          }
        catch (const SolverError &e)
          {
            run.failure = e.what();
          }
      }
    run.sweep_seconds = since(t0);
    run.summary       = summarise(run.results);
    per_width(run.summary, run.helix.face_width);
    return run;
  }
} // namespace gearfem::helical
