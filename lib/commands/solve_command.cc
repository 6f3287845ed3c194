// `gearfem solve case.prm`: loaded static contact of the pair over the mesh positions and
// torques of the `Solve` section (the library call solve::run_solve). Writes sweep.csv,
// pairs.csv, pressure.csv, line_of_action.csv, results.h5 (docs/output-format.md), VTU/PVD
// files of the deformed pair and the PNG plots (scripts/plot_solve.py). `--resume`
// continues a killed run from its journal.
#include "base/errors.h"
#include "base/memory.h"
#include "base/units.h"
#include "commands/command.h"
#include "solve/input.h"
#include "io/journal.h"
#include "solve/error_estimate.h"
#include "post/parameters.h"
#include "solve/run.h"
#include "condensed/resolve.h"
#include "commands/solve_hunting.h"
#include "tolerance/parameters.h"
#include "choice/parameters.h"
#include "choice/route.h"
#include "choice/to_target.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace gearfem::commands
{
  solve::SolveRunResult run_full_fe(contact::GearContactModel &model, const solve::GearContactInput &in,
                                    const post::PostOptions &post, const RunContext &ctx, double setup_seconds,
                                    double cpu_setup, double mesh_seconds, const std::string &label,
                                    const std::function<bool(std::size_t, const Table &, double)> &torque_done)
  {
    std::ostream &out = *ctx.out;
    for (int i = 1; i <= 2; ++i)
      if (model.body(i).mesh().subdivided)
        out << "note: gear " << i << "'s all-quad mesh comes from gmsh's subdivision fallback (Blossom "
            << "recombination failed): smaller, less regular cells; `gearfem mesh` reports its quality" << std::endl;
    solve::SolveRunOptions opt;
    opt.output_dir = ctx.output_dir;
    opt.input_name = ctx.input_file.filename().string();
    std::ostringstream content;
    content << std::ifstream(ctx.input_file).rdbuf();
    opt.input_hash = io::content_hash(content.str());
    opt.resume     = ctx.resume;
    opt.out        = &out;
    opt.post       = post;
    opt.torque_done = torque_done;
    const solve::SolveRunResult r = solve::run_solve(model, in, opt);
    if (r.stopped)
      {
        out << "sweep stopped after " << r.solved << " positions: its p-p STE already asks for a finer level\n";
        return r;
      }
    if (in.solve.plots && r.results.sweep.n_rows() > 0)
      run_plot_script("plot_solve.py", {ctx.output_dir.string()}, &out);
    if (!r.failure.empty())
      throw SolverError(r.failure + "\n  the " + std::to_string(r.results.sweep.n_rows()) +
                        " completed positions are saved in " + ctx.output_dir.string() +
                        " (their journal stays: with the input unchanged, --resume retries from the failed position)");
    out << "\n" << solve::summary_table(r, in.meshing(), in.solve.torques) << "time: contact " << r.seconds.at("contact")
        << " s, post-processing " << r.seconds.at("post") << " s, output " << r.seconds.at("output") << " s"
        << (label.empty() ? "" : " (" + label + ")") << "\n";
    if (!ctx.outcome)
      return r;
    // The cost of the run, for the speed-against-error study (validation/speed_vs_error).
    std::ostringstream cost;
    cost << std::setprecision(6) << "{" << (label.empty() ? "" : "\"deviations_in_geometry\": true, ")
         << "\"dofs\": " << model.n_dofs() << ", \"mesh_seconds\": " << mesh_seconds
         << ", \"setup_seconds\": " << setup_seconds << ", \"contact_seconds\": " << r.seconds.at("contact")
         << ", \"post_seconds\": " << r.seconds.at("post") << ", \"output_seconds\": " << r.seconds.at("output")
         << ", \"positions\": " << r.results.sweep.n_rows() << ", \"peak_memory_mb\": " << peak_memory_mb()
         << ", \"cpu_setup_seconds\": " << cpu_setup << ", \"cpu_sweep_seconds\": " << process_cpu_seconds() - cpu_setup
         << "}";
    ctx.outcome->record_members.emplace_back("cost", cost.str());
    if (!r.friction.empty())
      {
        // The coefficient applied at each torque, at full precision (docs/friction.md).
        std::ostringstream f;
        f << std::setprecision(17) << "{\"law\": \"" << analytical::friction::to_string(in.friction.law)
          << "\", \"pinion_speed_rpm\": " << in.friction.pinion_speed * 30 / units::pi << ", \"torques\": [";
        for (std::size_t i = 0; i < in.solve.torques.size(); ++i)
          f << (i ? ", " : "") << in.solve.torques[i];
        f << "], \"coefficients\": [";
        for (std::size_t i = 0; i < r.friction.size(); ++i)
          f << (i ? ", " : "") << r.friction[i];
        f << "]}";
        ctx.outcome->record_members.emplace_back("friction", f.str());
      }
    return r;
  }

  namespace
  {
    void declare(dealii::ParameterHandler &prm)
    {
      solve::declare_gear_contact_input(prm);
      post::declare_post_parameters(prm);
      tolerance::declare_deviation_parameters(prm);
    }

    /// A run on a condensed cycle as `gearfem solve` reports it: plots, a failure with the
    /// finished positions kept, the summary, the run record's `cost` (`build_seconds`: of a
    /// cycle built in this run).
    solve::SolveRunResult report_condensed(solve::SolveRunResult r, const solve::GearContactInput &in,
                                           const RunContext &ctx, double cpu_setup, unsigned int dofs,
                                           double build_seconds = 0)
    {
      std::ostream &out = *ctx.out;
      if (in.solve.plots && r.results.sweep.n_rows() > 0)
        run_plot_script("plot_solve.py", {ctx.output_dir.string()}, &out);
      if (!r.failure.empty())
        throw SolverError(r.failure + "\n  the " + std::to_string(r.results.sweep.n_rows()) +
                          " completed positions are saved in " + ctx.output_dir.string());
      out << "\n" << solve::summary_table(r, in.meshing(), in.solve.torques) << "time: contact "
          << r.seconds.at("contact") << " s, post-processing " << r.seconds.at("post") << " s, output "
          << r.seconds.at("output") << " s (" << r.results.sweep.n_rows() << " positions on the condensed cycle)\n";
      if (ctx.outcome)
        {
          std::ostringstream cost;
          cost << std::setprecision(6) << "{\"condensed\": true, \"build_seconds\": " << build_seconds
               << ", \"contact_seconds\": " << r.seconds.at("contact") << ", \"post_seconds\": " << r.seconds.at("post")
               << ", \"output_seconds\": " << r.seconds.at("output") << ", \"positions\": " << r.results.sweep.n_rows()
               << ", \"dofs\": " << dofs << ", \"peak_memory_mb\": " << peak_memory_mb()
               << ", \"cpu_setup_seconds\": " << cpu_setup << ", \"cpu_sweep_seconds\": " << process_cpu_seconds() - cpu_setup
               << "}";
          ctx.outcome->record_members.emplace_back("cost", cost.str());
        }
      return r;
    }

    /// `--condensed FILE`: the same run on a stored condensed cycle.
    void run_on_cycle(const solve::GearContactInput &in, const post::PostOptions &post_options, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const condensed::CondensedCycle cycle = condensed::read_cycle(ctx.condensed);
      const condensed::Resolver check(cycle, in); // refuses a different model or position
      out << "condensed cycle: " << ctx.condensed.string() << ", " << cycle.positions.size()
          << " positions built at " << cycle.build_torque << " N m (" << cycle.dofs << " DoFs)\n";
      if (ctx.validate_only)
        return;
      const double cpu_setup = process_cpu_seconds(); // parsing and reading the cycle
      solve::SolveRunOptions opt;
      opt.output_dir = ctx.output_dir;
      opt.input_name = ctx.input_file.filename().string();
      opt.out        = &out;
      opt.post       = post_options;
      report_condensed(condensed::run_condensed(cycle, in, opt), in, ctx, cpu_setup, cycle.dofs);
    }

    /// `Solve/Target`: choose the model, prove it at sample positions, refine, then sweep the
    /// accepted level (choice/to_target.h).
    void run_to_target(solve::GearContactInput &in, const choice::AccuracyTarget &target,
                       const dealii::ParameterHandler &prm, const post::PostOptions &post_options,
                       const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      choice::TargetOptions options;
      options.cost_cap = in.solve.cost_cap;
      options.post     = post_options;
      options.out      = &out;
      out << "model choice: target " << choice::to_string(target) << ", cost cap " << in.solve.cost_cap << " s"
          << std::endl;
      const choice::FixedSettings fixed = choice::fixed_settings(prm);
      choice::TargetOutcome o           = choice::run_to_target(in, target, fixed, options);
      for (;;)
        {
          if (ctx.outcome) // a second sweep records its own cost
            {
              auto &m = ctx.outcome->record_members;
              m.erase(std::remove_if(m.begin(), m.end(), [](const auto &e) { return e.first == "cost" || e.first == "friction"; }),
                      m.end());
            }
          const double cpu_setup = process_cpu_seconds();
          const auto t0          = std::chrono::steady_clock::now();
          solve::SolveRunOptions opt;
          opt.output_dir = ctx.output_dir;
          opt.input_name = ctx.input_file.filename().string();
          opt.out        = &out;
          opt.post       = post_options;
          choice::CycleSweep cs = choice::sweep_on_cycle(o, in, fixed, options, opt, ctx.resume);
          const choice::Swept how = cs.how;
          const bool on_cycle     = how == choice::Swept::on_cycle;
          solve::SolveRunResult r = std::move(cs.result);
          if (on_cycle)
            r = report_condensed(std::move(r), in, ctx, cpu_setup, cs.dofs, cs.build_seconds);
          if (how == choice::Swept::full_fe)
            {
              // The p-p check after each torque: a sweep the torques done already condemn stops.
              const auto check = [&](std::size_t t, const Table &sweep, double seconds) {
                return !choice::abandon_sweep(o, in, fixed, options, choice::swept_pp(sweep, in.solve.torques), t + 1,
                                              seconds);
              };
              r = run_full_fe(*o.model, in, post_options, ctx, o.model->setup_seconds(), cpu_setup,
                              o.model->mesh_seconds(), "", check);
            }
          const choice::SweptPp swept = choice::swept_pp(r.results.sweep, in.solve.torques);
          choice::rescale_pp(o, swept);
          if (on_cycle)
            choice::add_condensation_error(o, choice::condensation_error(*o.model, in, r.results.sweep, post_options));
          const double seconds =
            how != choice::Swept::full_fe ? std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() :
                                    r.seconds.at("contact") + r.seconds.at("post");
          if (!choice::refine_after_sweep(o, in, fixed, options, seconds, r.stopped ? swept.pp.size() : 0))
            break;
        }
      out << "\n" << choice::model_choice_summary(o);
      if (ctx.outcome)
        ctx.outcome->record_members.emplace_back("model_choice", choice::model_choice_json(o));
      if (!o.met)
        out << "warning: Solve/Target not met (" << o.stop_reason
            << "); the results are those of the finest level, with the estimates above\n";
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      solve::GearContactInput in = solve::parse_gear_contact_input(prm);
      const choice::AccuracyTarget target = choice::parse_target(in.solve.target);
      const post::PostOptions post_options = post::parse_post_parameters(prm);
      const auto &pair = in.meshing();
      out << "solve: z " << pair.teeth(1) << "/" << pair.teeth(2) << (pair.is_internal() ? " (internal)" : "") << ", a "
          << pair.center_distance() * 1e3 << " mm, contact ratio " << pair.contact_ratio() << ", "
          << in.positions().size() << " positions x " << in.solve.torques.size() << " torques, method "
          << contact::to_string(in.contact.method) << ", slave body " << in.contact.slave << ", "
          << (in.material[0].model == fem::PlaneModel::plane_stress ? "plane stress" : "plane strain")
          << "\n";
      for (const auto &w : solve::input_warnings(in))
        out << "warning: " << w << "\n";
      const tolerance::DeviationParameters deviations = tolerance::parse_deviation_parameters(prm);
      if (deviations.active())
        {
          if (target.active())
            throw InputError("Solve/Target", in.solve.target, "none with a Deviations section (its cycle has its own mesh)");
          in.require_external("Deviations");
          run_hunting_cycle(in, post_options, deviations, ctx);
          return;
        }
      if (target.active())
        {
          in.require_external("Solve/Target");
          if (!ctx.condensed.empty())
            throw InputError("Solve/Target", in.solve.target, "none with --condensed (a stored cycle has its own mesh)");
          if (ctx.validate_only)
            return;
          run_to_target(in, target, prm, post_options, ctx);
          return;
        }
      if (!ctx.condensed.empty())
        {
          in.require_external("--condensed");
          run_on_cycle(in, post_options, ctx);
          return;
        }
      if (in.solve.error_estimate)
        in.require_external("Solve/Error estimate");
      if (ctx.validate_only)
        return;

      auto model             = in.model();
      const double cpu_setup = process_cpu_seconds(); // parsing, meshing, assembly, factorisation
      out << "model: " << model->n_dofs() << " DoFs (" << model->body(1).n_dofs() << " + "
          << model->body(2).n_dofs() << "), " << model->body(1).triangulation().n_active_cells() << " + "
          << model->body(2).triangulation().n_active_cells() << " cells, mesh " << std::setprecision(3)
          << model->mesh_seconds() << " s, set-up (mesh, assemble, factorise) " << model->setup_seconds()
          << " s" << std::endl;
      const solve::SolveRunResult r =
        run_full_fe(*model, in, post_options, ctx, model->setup_seconds(), cpu_setup, model->mesh_seconds(), "");
      if (in.solve.error_estimate)
        {
          solve::ErrorEstimateOptions eo;
          eo.post = post_options;
          eo.out  = &out;
          out << "\nerror estimate: " << solve::error_sample_positions(*in.pair).size() << " sample positions x "
              << in.solve.torques.size() << " torques on two mesh levels (Solve/Error estimate)" << std::endl;
          const solve::ErrorEstimate e = solve::estimate_error(*model, in, eo);
          const double sweep = r.seconds.at("contact") + r.seconds.at("post") + r.seconds.at("output");
          out << "\n" << solve::error_estimate_table(e) << "cost of the estimate " << e.seconds()
              << " s against the run's set-up " << model->setup_seconds() << " s + sweep " << sweep << " s\n";
          if (ctx.outcome)
            ctx.outcome->record_members.emplace_back(
              "error_estimate", solve::error_estimate_json(e, {{"run_setup_seconds", model->setup_seconds()},
                                                              {"run_sweep_seconds", sweep}}));
        }
      int n_unresolved = 0;
      for (const auto &[T, n] : r.unresolved)
        n_unresolved += n;
      if (n_unresolved > 0)
        out << "warning: " << n_unresolved
            << " loaded tooth-pair positions (each loaded pair at each position, all torques) have fewer "
               "than "
            << post_options.min_patch_nodes
            << " contact nodes across the patch (Post/Min patch nodes): their peak pressure is unresolved (refine "
               "Mesh/h_contact; column \"resolved\" of pairs.csv); STE, stiffness and root "
               "stress are not affected\n";
    }
  } // namespace

  Command solve_command()
  {
    Command c;
    c.name        = "solve";
    c.summary     = "loaded static contact over the mesh cycle: STE, mesh stiffness, load sharing, pressure, root stress";
    c.description = "Meshes both gears, factorises them once, and solves the contact (Lagrange\n"
                    "multipliers or penalty; frictionless, or Coulomb friction with `Contact/Friction\n"
                    "coefficient` or `Friction law`, docs/friction.md) at each position of the `Solve`\n"
                    "section for each torque, with the pinion rotation found by torque targeting.\n"
                    "Writes sweep.csv, pairs.csv, pressure.csv, line_of_action.csv, results.h5\n"
                    "(docs/output-format.md), pair_T<T>_<i>.vtu + pair_T<T>.pvd, and ste.png,\n"
                    "stiffness.png, load_sharing.png, pressure.png, root_stress.png (with friction,\n"
                    "friction.png).\n"
                    "A killed run continues with --resume (the input must be unchanged: its hash\n"
                    "is checked against the journal solve.journal in the output folder).\n"
                    "With `Solve/Error estimate = true` it also estimates the discretisation error\n"
                    "of STE, root stress and p_max at three sample positions on a finer mesh\n"
                    "(summary and run.json, member error_estimate).\n"
                    "With `Solve/Target` (e.g. 'mean STE 1, p-p STE 1, root stress 3', percent, or a\n"
                    "preset) it chooses the mesh itself, estimates the error of its choice at four\n"
                    "sample positions against a coarser companion, refines where the estimate exceeds\n"
                    "the target within `Solve/Cost cap`, and reports the achieved estimate (summary and\n"
                    "run.json, member model_choice; docs/model-choice.md).\n"
                    "With a `Deviations` section (pitch, profile and runout deviations, given or drawn\n"
                    "within an ISO 1328-1 grade) it solves the hunting cycle on a condensed cycle (the\n"
                    "one of --condensed, else one built in memory) and adds spectrum.csv (the order\n"
                    "spectrum of the STE) and hunting.png (docs/deviations.md). With\n"
                    "`Deviations/Model = geometry` the pitch deviations are meshed instead (each tooth\n"
                    "turned by its deviation) and the ordinary full-FE sweep runs.\n"
                    "Sample runs:\n"
                    "  gearfem solve inputs/demo.prm\n"
                    "  gearfem solve inputs/demo.prm --resume\n"
                    "  gearfem solve inputs/demo_fixed_mesh.prm --condensed results/demo_condensed/condensed.h5 "
                    "--output-dir results/demo_on_cycle\n"
                    "  gearfem solve validation/parker_ste/parker_ste.prm --output-dir results/parker\n"
                    "  gearfem solve inputs/deviations_demo.prm\n";
    c.declare = declare;
    c.run     = run;
    return c;
  }
} // namespace gearfem::commands
