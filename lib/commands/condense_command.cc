// `gearfem condense case.prm`: the condensed mesh cycle of the case (condensed/cycle.h):
// the FE solved once over the positions of its `Solve` section at the build torque, each
// position condensed to its contact unknowns, written to condensed.h5. `gearfem solve
// variant.prm --condensed condensed.h5` then re-solves any torque or gap-route relief on it.
#include "base/errors.h"
#include "commands/command.h"
#include "condensed/condense.h"
#include "condensed/parameters.h"
#include "condensed/table.h"
#include "io/mesh_table_io.h"
#include "post/parameters.h"
#include "solve/input.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace gearfem::commands
{
  namespace condense_job
  {
    void declare(dealii::ParameterHandler &prm)
    {
      solve::declare_gear_contact_input(prm);
      post::declare_post_parameters(prm);
      condensed::declare_condense_parameters(prm);
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const solve::GearContactInput in = solve::parse_gear_contact_input(prm);
      (void)post::parse_post_parameters(prm);
      const auto cp = condensed::parse_condense_parameters(prm);
      condensed::check_condensable(in);
      const condensed::CycleRange range = condensed::condense_range(in, cp);
      out << "condense: z " << in.pair->gear(1).teeth() << "/" << in.pair->gear(2).teeth() << ", "
          << in.positions().size() << " positions at the build torque " << range.build << " N m for torques "
          << range.lo << " to " << range.hi << " N m, method " << contact::to_string(in.contact.method) << "\n";
      if (ctx.validate_only)
        return;
      condensed::CondensedCycle c = condensed::condense(in, cp, &out);
      c.input_name = ctx.input_file.filename().string();
      std::ostringstream text;
      text << std::ifstream(ctx.input_file).rdbuf();
      c.input_text = text.str();
      const auto file = ctx.output_dir / condensed::file_name;
      condensed::write_cycle(c, file);
      std::size_t m = 0, scenes = 0;
      for (const auto &ps : c.cycle)
        for (const auto &p : ps)
          m = std::max(m, p.size()), ++scenes;
      if (!cp.table_file.empty())
        {
          condensed::TableOptions to;
          to.n_delta  = cp.table_compressions;
          to.backlash = cp.backlash;
          const io::MeshTable t = condensed::torque_table(c, *in.pair, to, &out);
          io::TableProvenance prov;
          prov.source = "gearfem condense (FE-exact contact solves on the condensed cycle of " + c.input_name + ")";
          io::write_mesh_table(ctx.output_dir / cp.table_file, t, prov);
          out << "wrote " << (ctx.output_dir / cp.table_file).string() << ": T(theta, delta) " << t.theta.size()
              << " x " << t.second.size() << ", delta up to " << t.second.back() * 1e6 << " um"
              << (t.two_sided() ? ", two-sided" : "") << ", geometry hash " << t.geometry_hash << "\n";
        }
      out << "wrote " << file.string() << ": " << c.cycle.size() << " positions (" << scenes
          << " scenes), up to " << m << " candidates each; set-up " << c.setup_seconds << " s, build "
          << c.build_seconds << " s\n";
    }
  } // namespace condense_job

  Command condense_command()
  {
    Command c;
    c.name        = "condense";
    c.summary     = "the condensed mesh cycle: FE once over the cycle, re-solved later in milliseconds per position";
    c.description = "Meshes and factorises the pair of a `solve` input, solves each position of its `Solve`\n"
                    "section at the build torque (`Condense/Build torque`, default the largest of\n"
                    "Solve/Torques), and condenses each position to its contact unknowns: the candidate\n"
                    "points, the exact Delassus operator W, the arm a, the gap of the unmodified geometry\n"
                    "and its curvature in the rotation, where a flank modification enters each gap, the\n"
                    "pressure recovery, and the fillet-stress influence coefficients of both gears.\n"
                    "Writes condensed.h5 (docs/output-format.md). Then\n"
                    "  gearfem solve variant.prm --condensed condensed.h5\n"
                    "re-solves any torque list and any gap-route tip relief of the same design without\n"
                    "meshing or factorising, and writes what `gearfem solve` writes (no VTU).\n"
                    "Sample runs:\n"
                    "  gearfem condense inputs/demo_fixed_mesh.prm --output-dir results/demo_condensed\n"
                    "  gearfem solve inputs/demo_fixed_mesh.prm --condensed results/demo_condensed/condensed.h5 "
                    "--output-dir results/demo_on_cycle\n";
    c.declare = condense_job::declare;
    c.run     = condense_job::run;
    return c;
  }
} // namespace gearfem::commands
