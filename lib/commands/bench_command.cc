// `gearfem bench <what> [file.prm]`: benchmarks that print figures (wall time, DoFs, error).
// Targets belong here, not in timed unit tests; the figures go to validation/RESULTS.md.
#include "base/errors.h"
#include "commands/command.h"

#include <deal.II/base/parameter_handler.h>

#if __has_include("analytical/benchmark.h")
#  include "analytical/benchmark.h"
#  define GEARFEM_BENCH_ANALYTICAL 1
#endif
#if __has_include("dynamics/benchmark.h")
#  include "dynamics/benchmark.h"
#  define GEARFEM_BENCH_DYNAMICS 1
#endif
#if __has_include("post/benchmark.h")
#  include "post/benchmark.h"
#  define GEARFEM_BENCH_SOLVE
#endif
#if __has_include("fem/benchmark.h")
#  include "fem/benchmark.h"
#  define GEARFEM_BENCH_FEM 1
#endif

namespace gearfem::commands
{
  Command bench_command()
  {
    Command c;
    c.name        = "bench";
    c.summary     = "benchmarks that print timings and errors (analytical | dynamics | fem | solve)";
    c.description = "Sample runs:\n"
                    "  gearfem bench analytical\n"
                    "  gearfem bench dynamics\n"
                    "  gearfem bench fem inputs/demo.prm\n"
                    "  gearfem bench solve inputs/demo.prm\n"
                    "Figures are printed; validation/RESULTS.md records them with the command.";
    c.needs_input = false;
    c.parse_input = false;
    c.declare     = [](dealii::ParameterHandler &) {};
    c.run         = [](dealii::ParameterHandler &, const RunContext &ctx) {
      const std::string what = ctx.arguments.empty() ? "" : ctx.arguments.front();
      std::string available;
#ifdef GEARFEM_BENCH_ANALYTICAL
      available += " analytical";
      if (what == "analytical")
        {
          if (!ctx.validate_only)
            analytical::benchmark(*ctx.out);
          return;
        }
#endif
#ifdef GEARFEM_BENCH_DYNAMICS
      available += " dynamics";
      if (what == "dynamics")
        {
          if (!ctx.validate_only)
            dynamics::benchmark(*ctx.out);
          return;
        }
#endif
#ifdef GEARFEM_BENCH_FEM
      available += " fem";
      if (what == "fem")
        {
          if (ctx.input_file.empty())
            throw InputError("bench fem input file", "(none)", "a .prm file",
                             "usage: gearfem bench fem inputs/demo.prm");
          if (!ctx.validate_only)
            fem::benchmark(ctx.input_file, *ctx.out);
          return;
        }
#endif
#ifdef GEARFEM_BENCH_SOLVE
      available += " solve";
      if (what == "solve")
        {
          if (ctx.input_file.empty())
            throw InputError("bench solve input file", "(none)", "a .prm file",
                             "usage: gearfem bench solve inputs/demo.prm");
          if (!ctx.validate_only)
            solve::benchmark(ctx.input_file, *ctx.out);
          return;
        }
#endif
      throw InputError("bench target", what.empty() ? "(none)" : what, "{" + available + " }");
    };
    return c;
  }
} // namespace gearfem::commands
