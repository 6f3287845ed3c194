// `gearfem bench <what> [file.prm]`: benchmarks that print figures (wall time, DoFs, error).
// Targets belong here, not in timed unit tests; the figures go to validation/RESULTS.md.
#include "base/errors.h"
#include "commands/command.h"

#include <deal.II/base/parameter_handler.h>

#include "analytical/benchmark.h"
#include "dynamics/benchmark.h"
#include "fem/benchmark.h"
#include "solve/benchmark.h"
#include "condensed/benchmark.h"

#include <filesystem>
#include <ostream>
#include <string>

namespace gearfem::commands
{
  Command bench_command()
  {
    Command c;
    c.name        = "bench";
    c.summary     = "benchmarks that print timings and errors (analytical | dynamics | fem | solve | condensed)";
    c.description = "Sample runs:\n"
                    "  gearfem bench analytical\n"
                    "  gearfem bench dynamics\n"
                    "  gearfem bench fem inputs/demo_fixed_mesh.prm\n"
                    "  gearfem bench solve inputs/demo_fixed_mesh.prm\n"
                    "  gearfem bench condensed inputs/demo_fixed_mesh.prm\n"
                    "Figures are printed; validation/RESULTS.md records them with the command.";
    c.needs_input = false;
    c.parse_input = false;
    c.declare     = [](dealii::ParameterHandler &) {};
    c.run         = [](dealii::ParameterHandler &, const RunContext &ctx) {
      const std::string what = ctx.arguments.empty() ? "" : ctx.arguments.front();
      auto input_file = [&] {
        if (ctx.input_file.empty())
          throw InputError("bench " + what + " input file", "(none)", "a .prm file",
                           "usage: gearfem bench " + what + " inputs/demo_fixed_mesh.prm");
        return ctx.input_file;
      };
      if (what == "analytical")
        {
          if (!ctx.validate_only)
            analytical::benchmark(*ctx.out);
        }
      else if (what == "dynamics")
        {
          if (!ctx.validate_only)
            dynamics::benchmark(*ctx.out);
        }
      else if (what == "fem")
        {
          const auto file = input_file();
          if (!ctx.validate_only)
            fem::benchmark(file, *ctx.out);
        }
      else if (what == "solve")
        {
          const auto file = input_file();
          if (!ctx.validate_only)
            solve::benchmark(file, *ctx.out);
        }
      else if (what == "condensed")
        {
          const auto file = input_file();
          if (!ctx.validate_only)
            condensed::benchmark(file, *ctx.out);
        }
      else
        throw InputError("bench target", what.empty() ? "(none)" : what,
                         "{ analytical dynamics fem solve condensed }");
    };
    return c;
  }
} // namespace gearfem::commands
