// `gearfem optimise study.prm`: seed 003 (Koronaios 2021) B-spline tooth-profile
// optimisation for minimum and constant equivalent curvature. Parse, call lib/optimise,
// write.
#include "commands/command.h"
#include "optimise/parameters.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::commands
{
  namespace
  {
    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream           &out   = *ctx.out;
      const optimise::Study   study = optimise::parse_study_parameters(prm);
      out << "optimise: seed 003 " << optimise::to_string(study.kind) << ", " << study.runs.size()
          << " method(s), start point feasible\n";
      if (ctx.validate_only)
        return;
      const optimise::StudyResult r = optimise::run_study(study, &out);
      optimise::print_summary(study, r, out);
      optimise::write_study(study, r, ctx.output_dir);
      run_plot_script("plot_optimise.py", {ctx.output_dir.string()}, ctx.out);
      out << "wrote " << (ctx.output_dir / "optimise.csv").string()
          << ", summary.md, curvature.csv, profiles.csv, optimum.prm\n";
    }
  } // namespace

  Command optimise_command()
  {
    Command c;
    c.name    = "optimise";
    c.summary = "B-spline tooth-profile optimisation for minimum, constant equivalent curvature (seed 003)";
    c.description =
      "Seed 003 (Koronaios 2021): the pinion rack (case 1) or pinion flank (case 2) as a\n"
      "degree-4 B-spline, equivalent curvature 1/R along the path of contact, objectives\n"
      "max + mean + std of |1/R| (case 1) or 2.5 int (1/R)^2 dx + std + 0.1/eps (case 2), under\n"
      "named constraints (flank decreasing in position 2, no flank overlap, eps >= minimum,\n"
      "1/R > 0, path meets the mate's tip, gearfem's design checks). Runs each listed method\n"
      "(steepest descent with golden section, NLopt SLSQP/MMA/COBYLA/BOBYQA/ISRES/CRS2/ESCH)\n"
      "from one start and writes optimise.csv (history), summary.md (table), curvature.csv,\n"
      "profiles.csv, optimum.prm (case 2: runs with `gearfem solve`) and, with\n"
      "/usr/bin/python3 and matplotlib, curvature.png, profiles.png, convergence.png.\n\n"
      "Sample runs:\n"
      "  gearfem optimise inputs/seed003_opt_case2.prm\n"
      "  gearfem optimise inputs/seed003_opt_case1.prm --output-dir results/case1\n"
      "  gearfem optimise --validate inputs/seed003_opt_case2.prm";
    c.declare = optimise::declare_study_parameters;
    c.run     = run;
    return c;
  }
} // namespace gearfem::commands
