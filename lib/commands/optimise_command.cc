// `gearfem optimise study.prm`: Koronaios 2021 B-spline tooth-profile
// optimisation for minimum and constant equivalent curvature. Parse, call lib/optimise,
// write.
#include "commands/command.h"
#include "optimise/parameters.h"
#include "optimise/relief_parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>

namespace gearfem::commands
{
  namespace optimise_job
  {
    /// Problem = tip relief: the FE model in the loop (lib/optimise/relief.h).
    void run_relief(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out              = *ctx.out;
      const optimise::ReliefStudy st = optimise::parse_relief_study(prm);
      const auto &p                  = st.problem;
      out << "optimise: tip relief (" << (p.per_gear ? "per gear, 4" : "same on both gears, 2") << " variables), "
          << optimise::to_string(p.measure) << " STE, " << optimise::to_string(p.aggregate) << " over "
          << p.torques.size() << " torque(s), " << p.positions << " positions per cycle, method "
          << optimise::to_string(st.optimiser.method) << ", at most " << st.optimiser.max_evaluations << " evaluations"
          << (p.grid_points > 0 ? ", then a grid of " + std::to_string(p.grid_points) + " points per variable" : "")
          << (p.single_torque_optima ? ", then the single-load optimum at each torque" : "")
          << (p.check_torques.empty() ? "" : ", then a check at " + std::to_string(p.check_torques.size()) + " torques")
          << "\n";
      if (ctx.validate_only)
        return;
      const optimise::ReliefStudyResult r = optimise::run_relief_study(st, &out);
      out << "\n";
      optimise::print_relief_summary(st, r, out);
      optimise::write_relief_study(st, r, ctx.output_dir);
      run_plot_script("plot_relief.py", {ctx.output_dir.string()}, ctx.out);
      out << "wrote " << (ctx.output_dir / "optimise.csv").string() << ", ste.csv, summary.md, optimum.prm"
          << (r.check.empty() ? "" : ", robust.csv") << "\n";
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      if (optimise::is_relief_problem(prm))
        return run_relief(prm, ctx);
      std::ostream           &out   = *ctx.out;
      const optimise::Study   study = optimise::parse_study_parameters(prm);
      const bool multistart = std::any_of(study.runs.begin(), study.runs.end(),
                                          [](const optimise::OptimiserSettings &o) { return o.multistart > 0; });
      out << "optimise: Koronaios 2021 " << optimise::to_string(study.kind) << ", " << study.runs.size()
          << " method(s), "
          << (multistart ? "multistart from random points of the box (the start point need not be feasible)" :
                           "start point feasible")
          << "\n";
      if (ctx.validate_only)
        return;
      const optimise::StudyResult r = optimise::run_study(study, &out);
      optimise::print_summary(study, r, out);
      optimise::write_study(study, r, ctx.output_dir);
      run_plot_script("plot_optimise.py", {ctx.output_dir.string()}, ctx.out);
      out << "wrote " << (ctx.output_dir / "optimise.csv").string()
          << ", summary.md, curvature.csv, profiles.csv, optimum.prm\n";
    }
  } // namespace optimise_job

  Command optimise_command()
  {
    Command c;
    c.name    = "optimise";
    c.summary = "Profile optimisation: Koronaios 2021 B-spline tooth (min. curvature) or tip relief for min. STE (FE in the loop)";
    c.description =
      "Koronaios 2021: the pinion rack (case 1) or pinion flank (case 2) as a\n"
      "degree-4 B-spline, equivalent curvature 1/R along the path of contact, objectives\n"
      "max + mean + std of |1/R| (case 1) or 2.5 int (1/R)^2 dx + std + 0.1/eps (case 2), under\n"
      "named constraints (flank decreasing in position 2, no flank overlap, eps >= minimum,\n"
      "1/R > 0, path meets the mate's tip, gearfem's design checks). Runs each listed method\n"
      "(steepest descent with golden section, NLopt SLSQP/MMA/COBYLA/BOBYQA/ISRES/CRS2/ESCH)\n"
      "from one start and writes optimise.csv (history), summary.md (table), curvature.csv,\n"
      "profiles.csv, optimum.prm (case 2: runs with `gearfem solve`) and, with\n"
      "/usr/bin/python3 and matplotlib, curvature.png, profiles.png, convergence.png.\n\n"
      "With `Optimise/Problem = tip relief`: amount and length of linear or parabolic tip\n"
      "relief (both gears alike: 2 variables, or per gear: 4) for minimum peak-to-peak STE or\n"
      "first mesh harmonic at the torques of Solve/Torques (maximum or weighted mean), with the\n"
      "FE model of the gearfem solve sections in the loop: built once, each evaluation applies\n"
      "the relief as a gap modification and sweeps one mesh cycle. Optional grid over the same\n"
      "box (Tip relief/Grid points). Writes optimise.csv, ste.csv, summary.md, optimum.prm\n"
      "(runs with `gearfem solve`) and relief.png (STE before and after at each torque).\n"
      "Tip relief/Single-torque optima also optimises at each torque alone; Tip relief/Check\n"
      "torques evaluates the designs at other torques (robust.csv, relief_robust.png).\n\n"
      "Sample runs:\n"
      "  gearfem optimise inputs/seed003_opt_case2.prm\n"
      "  gearfem optimise inputs/seed003_opt_case1.prm --output-dir results/case1\n"
      "  gearfem optimise --validate inputs/seed003_opt_case2.prm\n"
      "  gearfem optimise inputs/tip_relief_opt.prm";
    c.declare = optimise::declare_study_parameters;
    c.run     = optimise_job::run;
    return c;
  }
} // namespace gearfem::commands
