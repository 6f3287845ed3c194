// `gearfem export case.prm`: mesh-stiffness and transmission-error tables for the tools
// engineers already use (ROSS arrays, Simpack/Adams spline tables, COMSOL/NX TE tables, the
// two-sided force table), from a solve result or a mesh table (lib/export, docs/export.md).
#include "analytical/from_geometry.h"
#include "base/errors.h"
#include "base/units.h"
#include "calibration/model.h"
#include "commands/command.h"
#include "export/force_table.h"
#include "export/formats.h"
#include "export/grid.h"
#include "export/parameters.h"
#include "geometry/parameters.h"
#include "io/mesh_table_io.h"
#include "io/solve_results.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace gearfem::commands
{
  namespace export_job
  {
    void declare(dealii::ParameterHandler &prm)
    {
      geometry::declare_geometry_parameters(prm);
      exports::declare_export_parameters(prm);
    }

    bool wants(const exports::ExportInput &in, const std::string &f)
    {
      return std::count(in.formats.begin(), in.formats.end(), f) || std::count(in.formats.begin(), in.formats.end(), "all");
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const auto pair = geometry::build_pair(geometry::parse_geometry_parameters(prm));
      const exports::ExportInput in = exports::parse_export_parameters(prm);
      exports::PairInfo pi;
      pi.z1 = pair.gear(1).teeth(), pi.z2 = pair.gear(2).teeth();
      pi.base_radius   = pair.base_radius(1);
      pi.theta_A       = pair.point("A").roll_angle;
      pi.geometry_hash = geometry::geometry_fingerprint(pair);
      const std::filesystem::path src =
        std::filesystem::path(in.source).is_relative() ? ctx.input_file.parent_path() / in.source : std::filesystem::path(in.source);
      const bool from_table = in.source_kind == "mesh table";
      const bool explicit_force = std::count(in.formats.begin(), in.formats.end(), "force") > 0;

      std::optional<io::MeshTable> table;
      std::optional<io::SolveResults> results;
      std::string source;
      if (from_table)
        {
          table = io::read_mesh_table(src, pi.geometry_hash);
          if (std::abs(table->period - pi.mesh_period()) > 1e-9 * pi.mesh_period() ||
              std::abs(table->base_radius - pi.base_radius) > 1e-9 * pi.base_radius)
            throw InputError("Export/Source", src.string(), "a mesh table of this pair (period 2 pi/" + std::to_string(pi.z1) +
                                                              ", r_b1 " + to_string_g(pi.base_radius * 1e3) + " mm)",
                             "the table has period " + to_string_g(table->period) + " rad and r_b1 " +
                               to_string_g(table->base_radius * 1e3) + " mm");
          source = src.filename().string() + " (mesh table, " + io::value_quantity(table->kind) + ")";
        }
      else
        {
          results = io::read_solve_results(src);
          const auto h = results->attributes.find("geometry_hash");
          if (h == results->attributes.end() || h->second != pi.geometry_hash)
            throw InputError("Export/Source", src.string(), "a solve result of this pair (geometry hash " + pi.geometry_hash + ")",
                             "its geometry hash is " + (h == results->attributes.end() ? std::string("missing") : h->second));
          source = src.filename().string() + " (gearfem solve results)";
        }
      const bool torque_table = table && table->kind == io::MeshTable::Kind::torque_vs_compression;
      if (explicit_force && !torque_table)
        throw InputError("Export/Formats", "force", "ross, spline, te for this source",
                         "the force table is made from a torque table T(theta, delta) (Source kind = mesh table)");
      // "all" takes the force table only when the clearance is known (a two-sided table or Backlash).
      const bool do_force =
        torque_table && (explicit_force || (wants(in, "force") && (table->two_sided() || in.backlash >= 0)));
      if (torque_table && !do_force && wants(in, "force"))
        out << "note: no force table (one-sided torque table and no Export/Backlash)\n";
      const bool do_grid  = wants(in, "ross") || wants(in, "spline") || wants(in, "te");

      std::optional<exports::CycleGrid> grid;
      if (do_grid)
        grid = table ? exports::grid_from_table(*table, pi, in.torques, "Export/Torques") :
                       exports::grid_from_solve(*results, pi, in.torques, "Export/Torques");
      std::optional<exports::ForceTable> force;
      if (do_force)
        {
          const double b = table->two_sided() ? table->backlash : in.backlash;
          const double psi = b >= 0 ? calibration::reverse_offset(analytical::involute_tooth(pair.gear(1)),
                                                                  analytical::pair_line(pair), b) :
                                      0.0;
          force = exports::force_table(*table, in.backlash, psi, "Export/Backlash");
        }
      out << "export: " << source << ", pair " << pi.z1 << "/" << pi.z2 << ", geometry " << pi.geometry_hash << "\n";
      if (grid)
        out << "  grid: " << grid->theta.size() << " roll angles over " << grid->pitches << " mesh period(s) x "
            << grid->torque.size() << " torque(s)\n";
      if (ctx.validate_only)
        return;

      const std::string prov = source + ", gearfem export " + ctx.input_file.filename().string();
      std::vector<std::string> written;
      if (grid && wants(in, "ross"))
        exports::write_ross_json(ctx.output_dir / "ross_mesh.json", exports::ross_arrays(*grid, pi), pi, prov),
          written.push_back("ross_mesh.json");
      if (grid && wants(in, "spline"))
        {
          exports::write_spline_csv(ctx.output_dir / "spline_ste.csv", *grid, "ste");
          exports::write_spline_csv(ctx.output_dir / "spline_stiffness.csv", *grid, "stiffness");
          written.push_back("spline_ste.csv"), written.push_back("spline_stiffness.csv");
        }
      if (grid && wants(in, "te"))
        {
          exports::write_te_table(ctx.output_dir / "te_mesh_cycle.txt", *grid, pi, false, prov);
          exports::write_te_table(ctx.output_dir / "te_revolution.txt", *grid, pi, true, prov);
          written.push_back("te_mesh_cycle.txt"), written.push_back("te_revolution.txt");
        }
      if (force)
        {
          exports::write_force_csv(ctx.output_dir / "force_table.csv", *force);
          written.push_back("force_table.csv");
          out << "  force table: " << force->theta.size() << " x " << force->delta.size() << ", backlash "
              << force->backlash * 1e6 << " um"
              << (force->mapped ? ", back contact mapped at psi = " + to_string_g(force->reverse_offset / units::deg) + " deg" :
                                  std::string(", two-sided table copied"))
              << "\n";
        }
      out << "wrote:";
      for (const auto &w : written)
        out << " " << w;
      out << "\n";
    }
  } // namespace export_job

  Command export_command()
  {
    Command c;
    c.name        = "export";
    c.summary     = "write STE and mesh-stiffness tables for ROSS, multibody codes (spline, TE) and force-law codes";
    c.description = "Reads a solve result (results.h5: one mesh cycle, or a hunting cycle with deviations) or a mesh\n"
                    "table (docs/mesh-tables.md) of the pair in the input (geometry hash checked) and writes, per\n"
                    "Export/Formats: ross_mesh.json (ROSS Mesh theta_range/stiffness_range), spline_ste.csv and\n"
                    "spline_stiffness.csv (angle x torque), te_mesh_cycle.txt and te_revolution.txt (COMSOL/NX TE\n"
                    "tables), force_table.csv (two-sided F(theta, delta), torque tables). Contract: docs/export.md.\n"
                    "Sample run: validation/multibody_exports/run.sh (condense, export, dynamics, and an\n"
                    "independent integration of the exported ROSS arrays); case files in that folder.\n";
    c.declare = export_job::declare;
    c.run     = export_job::run;
    return c;
  }
} // namespace gearfem::commands
