// `gearfem profile`: rack-generated tooth profiles, pair kinematics and design checks (the
// report itself is geometry/profile_report.h).
#include "commands/command.h"
#include "geometry/parameters.h"
#include "geometry/profile_report.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::commands
{
  Command profile_command()
  {
    Command c;
    c.name        = "profile";
    c.summary     = "tooth profiles by rack generation, pair kinematics, design checks";
    c.description =
      "Generates both tooth outlines from their racks (involute, trochoidal fillet, profile\n"
      "shift, tip rounding, tip relief, B-spline racks and flanks), computes the pair\n"
      "kinematics (working pressure angle, line of action T1 A B C D E T2, contact ratio,\n"
      "backlash, clearances, equivalent curvature) and runs the design checks.\n"
      "Writes profile_gear1.csv, profile_gear2.csv (whole gears, body frames), pair.csv,\n"
      "contact_path.csv and profile.png.\n\n"
      "Sample runs:\n"
      "  gearfem profile inputs/demo.prm\n"
      "  gearfem profile inputs/seed001_23_69.prm --output-dir results/seed001\n"
      "  gearfem profile --validate inputs/fzg_c.prm";
    c.declare = [](dealii::ParameterHandler &prm) {
      geometry::declare_geometry_parameters(prm);
      geometry::declare_material_parameters(prm);
    };
    c.run = [](dealii::ParameterHandler &prm, const RunContext &ctx) {
      const geometry::GeometryInput in   = geometry::parse_geometry_parameters(prm);
      const geometry::PairMaterial  mat  = geometry::parse_material_parameters(prm);
      const geometry::GearPair      pair = geometry::build_pair(in);
      geometry::print_pair_summary(pair, mat, *ctx.out);
      if (ctx.validate_only)
        return;
      geometry::write_profile_report(pair, ctx.output_dir);
      run_plot_script("plot_profile.py", {ctx.output_dir.string()}, ctx.out);
    };
    return c;
  }
} // namespace gearfem::commands
