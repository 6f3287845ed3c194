// The Deviations routes (route/route.h): the hunting cycle with manufacturing deviations on a
// condensed cycle (deviations/hunting.h), the given one or one built in memory; with
// `Deviations/Model = geometry`, the full-FE sweep of `Solve` with the single pitch deviations
// built into the mesh (deviations/geometry.h).
#include "route/detail.h"

#include "base/errors.h"
#include "base/memory.h"
#include "condensed/resolve.h"
#include "deviations/geometry.h"
#include "deviations/hunting.h"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <memory>
#include <sstream>

namespace gearfem::route::detail
{
  void run_geometry(Request &r, Outcome &o)
  {
    const solve::GearContactInput &in = r.input;
    const deviations::DeviationParameters &dev = r.dev;
    const geometry::GearPair &meshed = in.unmodified_pair ? *in.unmodified_pair : *in.pair;
    const auto angles                = deviations::tooth_angles(dev, *in.pair, meshed);
    if (r.out)
      {
        std::ostream &out = *r.out;
        out << "deviations: single pitch deviations built into the geometry (teeth turned by F_p,k / r_ref";
        for (int b = 0; b < 2; ++b)
          if (!angles[b].empty())
            {
              const auto [lo, hi] = std::minmax_element(angles[b].begin(), angles[b].end());
              out << "; gear " << b + 1 << ": " << std::setprecision(4) << *lo * 1e6 << " .. " << *hi * 1e6
                  << " urad";
            }
        out << "); full FE over " << in.positions().size() << " positions\n";
      }
    if (r.validate_only)
      return;
    mesh::GearMeshParameters mp[2] = {in.mesh[0], in.mesh[1]};
    const auto t0                  = std::chrono::steady_clock::now();
    std::array<contact::GearBody, 2> bodies;
    for (int b = 0; b < 2; ++b)
      mp[b].tooth_angles = angles[b];
    bodies[0] = contact::build_gear_body(meshed, 1, mp[0], in.material[0], in.fe);
    // Only gears without offsets may share one body (identical_bodies compares the nominal mesh).
    if (angles[0].empty() && angles[1].empty() && contact::identical_bodies(meshed, mp, in.material))
      bodies[1] = bodies[0];
    else
      bodies[1] = contact::build_gear_body(meshed, 2, mp[1], in.material[1], in.fe);
    contact::GearContactModel model(*in.pair, std::move(bodies), in.contact);
    const double setup     = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu_setup = process_cpu_seconds();
    if (r.out)
      *r.out << "model: " << model.n_dofs() << " DoFs (" << model.body(1).n_dofs() << " + "
             << model.body(2).n_dofs() << "), set-up (mesh, assemble, factorise) " << std::setprecision(3) << setup
             << " s" << std::endl;
    o.run = full_fe_sweep(model, r, o, {setup, cpu_setup, model.mesh_seconds(), "full FE, pitch deviations in the geometry"},
                          {});
  }

  namespace
  {
    /// The cycle of the hunting route: the given one, or one built for the input's torques.
    std::unique_ptr<condensed::CondensedCycle> hunting_cycle(const Request &r)
    {
      const solve::GearContactInput &in = r.input;
      if (r.cycle)
        {
          const condensed::Resolver check(*r.cycle, in);
          return nullptr;
        }
      if (!r.cycle_file.empty())
        {
          auto c = std::make_unique<condensed::CondensedCycle>(condensed::read_cycle(r.cycle_file));
          const condensed::Resolver check(*c, in);
          return c;
        }
      condensed::check_condensable(in);
      if (r.validate_only)
        return nullptr;
      const condensed::CycleRange range = condensed::cycle_range(in.solve.torques, condensed::CycleUse::variants);
      auto model                        = in.model();
      if (r.out)
        *r.out << "condensed cycle: building it in memory (" << model->n_dofs() << " DoFs, set-up "
               << std::setprecision(3) << model->setup_seconds() << " s) for " << range.lo << " .. " << range.hi
               << " N m\n";
      condensed::CycleOptions co;
      co.out = r.out;
      return std::make_unique<condensed::CondensedCycle>(condensed::cycle_for(*model, in, range, co));
    }

    void print_summary(const deviations::HuntingRun &h, const solve::GearContactInput &in, std::ostream &out)
    {
      const int z1 = in.pair->gear(1).teeth();
      out << "\n| T1 [N m] | p-p STE [um] | mesh order 1 / 2 / 3 [um] | largest other order [um] (order) | max "
             "root stress pinion / gear [MPa] | max p [MPa] |\n|---|---|---|---|---|---|\n";
      for (std::size_t ti = 0; ti < h.summary.size(); ++ti)
        {
          const auto &s       = h.summary[ti];
          const auto [lo, hi] = std::minmax_element(h.ste[ti].begin(), h.ste[ti].end());
          out << std::setprecision(4) << "| " << in.solve.torques[ti] << " | " << (*hi - *lo) * 1e6 << " | "
              << s.mesh[0] * 1e6 << " / " << s.mesh[1] * 1e6 << " / " << s.mesh[2] * 1e6 << " | "
              << s.largest_other * 1e6 << " (" << s.largest_other_order << ") | " << h.max_root_stress[0][ti] * 1e-6
              << " / " << h.max_root_stress[1][ti] * 1e-6 << " | " << h.max_pressure[ti] * 1e-6 << " |\n";
        }
      out << "time: contact " << h.run.seconds.at("contact") << " s, post-processing " << h.run.seconds.at("post")
          << " s, output " << h.run.seconds.at("output") << " s (" << h.run.results.sweep.n_rows()
          << " positions; orders are per pinion revolution, mesh order z1 = " << z1 << ")\n";
    }
  } // namespace

  void run_hunting(Request &r, Outcome &o)
  {
    const solve::GearContactInput &in          = r.input;
    const deviations::DeviationParameters &dev = r.dev;
    deviations::check_one_pitch_cycle(in);
    const geometry::PairDeviations d = deviations::resolve_deviations(dev, *in.pair);
    const int z1 = in.pair->gear(1).teeth(), z2 = in.pair->gear(2).teeth();
    const long pitches = dev.pitches > 0 ? dev.pitches : geometry::hunting_pitches(z1, z2);
    if (r.out)
      *r.out << "deviations: "
             << (dev.grade > 0 ? "drawn within ISO 1328-1 grade " + std::to_string(dev.grade) + " (" +
                                   geometry::to_string(dev.distribution) + ", seed " + std::to_string(dev.seed) + ")" :
                                 std::string("as given"))
             << "; cycle of " << pitches << " pitches (" << double(pitches) / z1 << " pinion revolutions) x "
             << in.positions().size() << " positions on the condensed route\n";
    const std::unique_ptr<condensed::CondensedCycle> built = hunting_cycle(r);
    if (r.validate_only)
      return;
    const condensed::CondensedCycle &cycle = r.cycle ? *r.cycle : *built;
    const double cpu_setup                 = process_cpu_seconds();
    deviations::HuntingOptions opt;
    opt.pitches    = dev.pitches;
    opt.post       = r.post;
    opt.out        = r.out;
    opt.output_dir = r.output_dir;
    opt.input_name = r.input_name;
    const deviations::HuntingRun h = deviations::run_hunting(cycle, in, d, opt);
    if (in.solve.plots && !h.spectrum.empty())
      o.plots = {"plot_hunting.py"};
    o.run = h.run;
    if (!h.run.failure.empty())
      {
        o.failure = h.run.failure + "\n  the " + std::to_string(h.run.results.sweep.n_rows()) +
                    " completed positions are saved in " + r.output_dir.string();
        return;
      }
    if (r.out)
      print_summary(h, in, *r.out);
    std::ostringstream cost;
    cost << std::setprecision(6) << "{\"hunting\": true, \"pitches\": " << h.pitches
         << ", \"contact_seconds\": " << h.run.seconds.at("contact") << ", \"post_seconds\": "
         << h.run.seconds.at("post") << ", \"positions\": " << h.run.results.sweep.n_rows()
         << ", \"peak_memory_mb\": " << peak_memory_mb() << ", \"cpu_setup_seconds\": " << cpu_setup
         << ", \"cpu_sweep_seconds\": " << process_cpu_seconds() - cpu_setup << "}";
    set_member(o.record, "cost", cost.str());
  }
} // namespace gearfem::route::detail
