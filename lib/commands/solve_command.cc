// `gearfem solve case.prm`: loaded static contact of the pair over the mesh positions and
// torques of the `Solve` section. The route (full FE, a stored condensed cycle, Solve/Target,
// deviations on a cycle or in the geometry) is the library's (route::run); this command parses,
// calls it, plots and records. Writes sweep.csv, pairs.csv, pressure.csv, line_of_action.csv,
// results.h5 (docs/output-format.md), VTU/PVD files of the deformed pair and the PNG plots
// (scripts/plot_solve.py). `--resume` continues a killed run from its journal.
#include "base/errors.h"
#include "commands/command.h"
#include "io/journal.h"
#include "route/route.h"

#include <deal.II/base/parameter_handler.h>

#include <fstream>
#include <sstream>

namespace gearfem::commands
{
  namespace solve_job
  {
    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      route::Request r = route::parse_request(prm);
      r.cycle_file     = ctx.condensed;
      r.output_dir     = ctx.output_dir;
      r.input_name     = ctx.input_file.filename().string();
      std::ostringstream content;
      content << std::ifstream(ctx.input_file).rdbuf();
      r.input_hash    = io::content_hash(content.str());
      r.resume        = ctx.resume;
      r.validate_only = ctx.validate_only;
      r.out           = ctx.out;
      const route::Outcome o = route::run(r);
      for (const auto &script : o.plots)
        run_plot_script(script, {ctx.output_dir.string()}, ctx.out);
      if (ctx.outcome)
        for (const auto &member : o.record)
          ctx.outcome->record_members.push_back(member);
      if (!o.failure.empty())
        throw SolverError(o.failure);
    }
  } // namespace solve_job

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
    c.declare = route::declare_request;
    c.run     = solve_job::run;
    return c;
  }
} // namespace gearfem::commands
