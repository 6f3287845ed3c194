// `gearfem solve` with manufacturing deviations: parse, build or read the condensed cycle, run the
// hunting cycle (tolerance::run_hunting), print the summary and plot; or, with
// `Deviations/Model = geometry`, mesh the gears with their teeth turned by the pitch deviations
// and run the ordinary full-FE sweep (solve::run_solve).
#include "commands/solve_hunting.h"

#include "base/errors.h"
#include "base/memory.h"
#include "condensed/cycle.h"
#include "condensed/resolve.h"
#include "io/journal.h"
#include "solve/run.h"
#include "tolerance/geometry.h"
#include "tolerance/hunting.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace gearfem::commands
{
  namespace
  {
    /// `Deviations/Model = geometry`: the full FE with the teeth turned by their cumulative pitch
    /// deviations in the mesh, over the positions of `Solve`, with the ordinary outputs.
    void run_geometry_sweep(const solve::GearContactInput &in, const post::PostOptions &post,
                            const tolerance::DeviationParameters &dev, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      if (!ctx.condensed.empty())
        throw InputError("--condensed", ctx.condensed.string(), "none with Deviations/Model = geometry",
                         "the deviations are built into the mesh: the full FE is solved, no condensed cycle");
      const geometry::GearPair &meshed = in.unmodified_pair ? *in.unmodified_pair : *in.pair;
      const auto angles                = tolerance::tooth_angles(dev, *in.pair, meshed);
      out << "deviations: single pitch deviations built into the geometry (teeth turned by F_p,k / r_ref";
      for (int b = 0; b < 2; ++b)
        if (!angles[b].empty())
          {
            const auto [lo, hi] = std::minmax_element(angles[b].begin(), angles[b].end());
            out << "; gear " << b + 1 << ": " << std::setprecision(4) << *lo * 1e6 << " .. " << *hi * 1e6 << " urad";
          }
      out << "); full FE over " << in.positions().size() << " positions\n";
      if (ctx.validate_only)
        return;
      mesh::GearMeshParameters mp[2] = {in.mesh[0], in.mesh[1]};
      const auto t0 = std::chrono::steady_clock::now();
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
      const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double cpu_setup = process_cpu_seconds();
      out << "model: " << model.n_dofs() << " DoFs (" << model.body(1).n_dofs() << " + " << model.body(2).n_dofs()
          << "), set-up (mesh, assemble, factorise) " << std::setprecision(3) << setup << " s" << std::endl;
      (void)run_full_fe(model, in, post, ctx, setup, cpu_setup, model.mesh_seconds(),
                        "full FE, pitch deviations in the geometry");
    }
  } // namespace

  void run_hunting_cycle(const solve::GearContactInput &in, const post::PostOptions &post,
                         const tolerance::DeviationParameters &dev, const RunContext &ctx)
  {
    if (dev.model == tolerance::DeviationParameters::Model::geometry)
      {
        run_geometry_sweep(in, post, dev, ctx);
        return;
      }
    std::ostream &out = *ctx.out;
    tolerance::check_one_pitch_cycle(in);
    const geometry::PairDeviations d = tolerance::resolve_deviations(dev, *in.pair);
    const int z1 = in.pair->gear(1).teeth(), z2 = in.pair->gear(2).teeth();
    const long pitches = dev.pitches > 0 ? dev.pitches : geometry::hunting_pitches(z1, z2);
    out << "deviations: " << (dev.grade > 0 ? "drawn within ISO 1328-1 grade " + std::to_string(dev.grade) + " (" +
                                                geometry::to_string(dev.distribution) + ", seed " +
                                                std::to_string(dev.seed) + ")" :
                                              std::string("as given"))
        << "; cycle of " << pitches << " pitches (" << double(pitches) / z1 << " pinion revolutions) x "
        << in.positions().size() << " positions on the condensed route\n";
    std::unique_ptr<condensed::CondensedCycle> cycle;
    if (!ctx.condensed.empty())
      {
        cycle = std::make_unique<condensed::CondensedCycle>(condensed::read_cycle(ctx.condensed));
        const condensed::Resolver check(*cycle, in);
      }
    else
      condensed::check_condensable(in);
    if (ctx.validate_only)
      return;
    if (!cycle)
      {
        const auto &T = in.solve.torques;
        const double lo = 0.25 * *std::min_element(T.begin(), T.end()), hi = 2 * *std::max_element(T.begin(), T.end());
        auto model = in.model();
        out << "condensed cycle: building it in memory (" << model->n_dofs() << " DoFs, set-up "
            << std::setprecision(3) << model->setup_seconds() << " s) for " << lo << " .. " << hi << " N m\n";
        cycle = std::make_unique<condensed::CondensedCycle>(
          condensed::build_cycle(*model, in, *std::max_element(T.begin(), T.end()), lo, hi, &out));
      }
    const double cpu_setup = process_cpu_seconds();
    tolerance::HuntingOptions opt;
    opt.pitches    = dev.pitches;
    opt.post       = post;
    opt.out        = &out;
    opt.output_dir = ctx.output_dir;
    opt.input_name = ctx.input_file.filename().string();
    const tolerance::HuntingRun h = tolerance::run_hunting(*cycle, in, d, opt);
    if (in.solve.plots && !h.spectrum.empty())
      run_plot_script("plot_hunting.py", {ctx.output_dir.string()}, &out);
    if (!h.run.failure.empty())
      throw SolverError(h.run.failure + "\n  the " + std::to_string(h.run.results.sweep.n_rows()) +
                        " completed positions are saved in " + ctx.output_dir.string());
    out << "\n| T1 [N m] | p-p STE [um] | mesh order 1 / 2 / 3 [um] | largest other order [um] (order) | max root "
           "stress pinion / gear [MPa] | max p [MPa] |\n|---|---|---|---|---|---|\n";
    for (std::size_t ti = 0; ti < h.summary.size(); ++ti)
      {
        const auto &s = h.summary[ti];
        const auto [lo, hi] = std::minmax_element(h.ste[ti].begin(), h.ste[ti].end());
        out << std::setprecision(4) << "| " << in.solve.torques[ti] << " | " << (*hi - *lo) * 1e6 << " | "
            << s.mesh[0] * 1e6 << " / " << s.mesh[1] * 1e6 << " / " << s.mesh[2] * 1e6 << " | "
            << s.largest_other * 1e6 << " (" << s.largest_other_order << ") | " << h.max_root_stress[0][ti] * 1e-6
            << " / " << h.max_root_stress[1][ti] * 1e-6 << " | " << h.max_pressure[ti] * 1e-6 << " |\n";
      }
    out << "time: contact " << h.run.seconds.at("contact") << " s, post-processing " << h.run.seconds.at("post")
        << " s, output " << h.run.seconds.at("output") << " s (" << h.run.results.sweep.n_rows()
        << " positions; orders are per pinion revolution, mesh order z1 = " << z1 << ")\n";
    if (ctx.outcome)
      {
        std::ostringstream cost;
        cost << std::setprecision(6) << "{\"hunting\": true, \"pitches\": " << h.pitches
             << ", \"contact_seconds\": " << h.run.seconds.at("contact") << ", \"post_seconds\": "
             << h.run.seconds.at("post") << ", \"positions\": " << h.run.results.sweep.n_rows()
             << ", \"peak_memory_mb\": " << peak_memory_mb() << ", \"cpu_setup_seconds\": " << cpu_setup
             << ", \"cpu_sweep_seconds\": " << process_cpu_seconds() - cpu_setup << "}";
        ctx.outcome->record_members.emplace_back("cost", cost.str());
      }
  }
} // namespace gearfem::commands
