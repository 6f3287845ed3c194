// `gearfem mesh case.prm`: gmsh meshes of both gears in their body frames (gear1.msh,
// gear2.msh, MSH 4.1 with the physical groups of meshes/README.md), a quality report
// (mesh_quality.csv) and mesh.png. Each mesh is also imported into deal.II with its
// exact-curve manifolds as a check.
#include "base/errors.h"
#include "base/table.h"
#include "commands/command.h"
#include "fem/parameters.h"
#include "geometry/parameters.h"
#include "mesh/parameters.h"
#include "mesh/triangulation.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <iomanip>
#include <unistd.h>

namespace gearfem::commands
{
  namespace
  {
    void declare(dealii::ParameterHandler &prm)
    {
      geometry::declare_geometry_parameters(prm);
      geometry::declare_material_parameters(prm);
      mesh::declare_mesh_parameters(prm);
      fem::declare_fe_parameters(prm);
    }

    /// Zoom box around tooth 0 in mm: xmin,xmax,ymin,ymax.
    std::string zoom_box(const geometry::ToothProfile &t)
    {
      const double p = t.angular_pitch() * t.radii().tip, m = t.parameters().rack.module;
      std::ostringstream s;
      s << 1e3 * -1.6 * p << "," << 1e3 * 1.6 * p << "," << 1e3 * (t.radii().root - 2.5 * m) << ","
        << 1e3 * (t.radii().tip + 0.5 * m);
      return s.str();
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const geometry::GeometryInput gi = geometry::parse_geometry_parameters(prm);
      (void)geometry::parse_material_parameters(prm);
      (void)fem::parse_fe_parameters(prm);
      const geometry::GearPair pair = geometry::build_pair(gi);
      mesh::GearMeshParameters mp[2] = {mesh::parse_mesh_parameters(prm, 1),
                                        mesh::parse_mesh_parameters(prm, 2)};
      for (int i = 0; i < 2; ++i)
        {
          const auto d = mesh::gear_domain(pair.gear(i + 1), mp[i]); // all checks, no gmsh
          out << "gear " << i + 1 << ": z " << pair.gear(i + 1).teeth() << ", "
              << (mp[i].model == mesh::GearMeshParameters::Model::sector ?
                    std::to_string(mp[i].sector_teeth) + "-tooth sector" : std::string("full gear"))
              << ", inner radius " << mesh::inner_radius(mp[i], pair.gear(i + 1)) * 1e3
              << " mm, " << d.loops[0].pieces.size() << " outline pieces\n";
        }
      if (ctx.validate_only)
        return;

      // Mesh both gears into a private folder first: no output files unless both succeed.
      const auto tmp = ctx.output_dir / (".mesh_tmp_" + std::to_string(::getpid()));
      std::filesystem::create_directories(tmp);
      struct Cleanup
      {
        std::filesystem::path p;
        ~Cleanup()
        {
          std::error_code ec;
          std::filesystem::remove_all(p, ec);
        }
      } cleanup{tmp};

      Table q;
      for (const auto &[n, u] : std::vector<std::pair<std::string, std::string>>{
             {"gear", "-"}, {"cells", "-"}, {"vertices", "-"}, {"min angle", "deg"},
             {"max angle", "deg"}, {"max aspect ratio", "-"}, {"min edge", "mm"},
             {"max edge", "mm"}, {"inverted cells", "-"}, {"mesh time", "s"}})
        q.add_column(n, u);
      for (int i = 0; i < 2; ++i)
        {
          const auto file = tmp / ("gear" + std::to_string(i + 1) + ".msh");
          const mesh::MeshData m = mesh::mesh_gear(pair.gear(i + 1), mp[i], file);
          dealii::Triangulation<2> tria;
          mesh::create_triangulation(m, tria);
          const auto r = mesh::quality(m);
          q.add_row({double(i + 1), double(r.n_cells), double(r.n_vertices), r.min_angle, r.max_angle,
                     r.max_aspect_ratio, r.min_edge * 1e3, r.max_edge * 1e3, double(r.n_inverted),
                     m.mesh_seconds});
          out << "gear " << i + 1 << ": " << r.n_cells << " quadrilaterals, angles " << std::fixed
              << std::setprecision(1) << r.min_angle << "-" << r.max_angle << " deg, max aspect "
              << std::setprecision(2) << r.max_aspect_ratio << ", edges " << std::setprecision(3)
              << r.min_edge * 1e3 << "-" << r.max_edge * 1e3 << " mm, meshed in "
              << std::setprecision(2) << m.mesh_seconds << " s" << std::defaultfloat
              << (m.subdivided ? " (all-quad subdivision fallback)" : "") << "\n";
        }
      for (int i = 1; i <= 2; ++i)
        std::filesystem::rename(tmp / ("gear" + std::to_string(i) + ".msh"),
                                ctx.output_dir / ("gear" + std::to_string(i) + ".msh"));
      q.write_csv(ctx.output_dir / "mesh_quality.csv", 6);
      run_plot_script("plot_mesh.py",
                      {(ctx.output_dir / "mesh.png").string(), (ctx.output_dir / "gear1.msh").string(),
                       zoom_box(pair.gear(1)), (ctx.output_dir / "gear2.msh").string(),
                       zoom_box(pair.gear(2))},
                      &out);
    }
  } // namespace

  Command mesh_command()
  {
    Command c;
    c.name        = "mesh";
    c.summary     = "gmsh meshes of both gears (gear1.msh, gear2.msh), quality report, mesh.png";
    c.description = "Builds the all-quadrilateral gmsh mesh of each gear in its body frame (full\n"
                    "gear or N-tooth sector; sizes from the Mesh section), writes gear1.msh and\n"
                    "gear2.msh (MSH 4.1, physical groups per tooth: see meshes/README.md),\n"
                    "mesh_quality.csv (cells, angles, aspect ratio, edge lengths) and mesh.png.\n\n"
                    "Sample runs:\n"
                    "  gearfem mesh inputs/mesh_demo.prm\n"
                    "  gearfem mesh inputs/mesh_demo.prm --validate";
    c.declare = declare;
    c.run     = run;
    return c;
  }
} // namespace gearfem::commands
