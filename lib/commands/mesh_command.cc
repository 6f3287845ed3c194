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
#include "geometry/internal_pair.h"
#include "solve/ring_input.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <iomanip>
#include <memory>
#include <unistd.h>

namespace gearfem::commands
{
  namespace mesh_job
  {
    void declare(dealii::ParameterHandler &prm)
    {
      geometry::declare_geometry_parameters(prm);
      geometry::declare_material_parameters(prm);
      mesh::declare_mesh_parameters(prm);
      fem::declare_fe_parameters(prm);
      solve::declare_ring_parameters(prm);
    }

    /// Zoom box around tooth 0 in mm: xmin,xmax,ymin,ymax (half width p, radii lo..hi [m]).
    std::string zoom_box(double p, double lo, double hi)
    {
      return to_string_g(-1.6e3 * p) + "," + to_string_g(1.6e3 * p) + "," + to_string_g(1e3 * lo) + "," + to_string_g(1e3 * hi);
    }
    std::string zoom_box(const geometry::ToothProfile &t)
    {
      const double m = t.parameters().rack.module;
      return zoom_box(t.angular_pitch() * t.radii().tip, t.radii().root - 2.5 * m, t.radii().tip + 0.5 * m);
    }
    std::string zoom_box(const geometry::InternalToothProfile &t)
    {
      const double m = t.parameters().module;
      return zoom_box(t.angular_pitch() * t.radii().tip, t.radii().tip - 0.5 * m, t.radii().root + 2.5 * m);
    }

    /// The gear bodies to mesh: gmsh meshing of gear i (writing `file`), a one-line
    /// description and the zoom box of its plot.
    struct Bodies
    {
      std::function<mesh::MeshData(int, const std::filesystem::path &)> mesh;
      std::string text[2], zoom[2];
    };

    Bodies external_bodies(const geometry::GearPair &pair, const mesh::GearMeshParameters mp[2])
    {
      Bodies b;
      for (int i = 0; i < 2; ++i)
        {
          const auto d = mesh::gear_domain(pair.gear(i + 1), mp[i]); // all checks, no gmsh
          std::ostringstream t;
          t << "gear " << i + 1 << ": z " << pair.gear(i + 1).teeth() << ", "
            << (mp[i].model == mesh::GearMeshParameters::Model::sector ?
                  std::to_string(mp[i].sector_teeth) + "-tooth sector" : std::string("full gear"))
            << ", inner radius " << mesh::inner_radius(mp[i], pair.gear(i + 1)) * 1e3 << " mm, "
            << d.loops[0].pieces.size() << " outline pieces\n";
          b.text[i] = t.str();
          b.zoom[i] = zoom_box(pair.gear(i + 1));
        }
      b.mesh = [&pair, mp0 = mp[0], mp1 = mp[1]](int i, const std::filesystem::path &f) {
        return mesh::mesh_gear(pair.gear(i + 1), i == 0 ? mp0 : mp1, f);
      };
      return b;
    }

    Bodies internal_bodies(const geometry::InternalGearPair &pair, const mesh::GearMeshParameters &pinion,
                           const mesh::RingMeshParameters &ring)
    {
      Bodies b;
      const auto d = mesh::gear_domain(pair.pinion(), pinion);
      std::ostringstream t;
      t << "gear 1: z " << pair.teeth(1) << ", "
        << (pinion.model == mesh::GearMeshParameters::Model::sector ?
              std::to_string(pinion.sector_teeth) + "-tooth sector" : std::string("full gear"))
        << ", inner radius " << mesh::inner_radius(pinion, pair.pinion()) * 1e3 << " mm, "
        << d.loops[0].pieces.size() << " outline pieces\n";
      b.text[0] = t.str();
      const auto r = mesh::ring_domain(pair.ring(), ring);
      std::ostringstream u;
      u << "gear 2 (ring): z " << pair.teeth(2) << ", "
        << (ring.model == mesh::RingMeshParameters::Model::sector ? std::to_string(ring.sector_teeth) + "-tooth sector" :
                                                                    std::string("full ring"))
        << ", outer radius " << mesh::ring_outer_radius(pair.ring(), ring) * 1e3 << " mm, "
        << (ring.bolts > 0 ? std::to_string(ring.bolts) + " bolts" : std::string("clamped")) << "\n";
      b.text[1] = u.str();
      b.zoom[0] = zoom_box(pair.pinion()), b.zoom[1] = zoom_box(pair.ring());
      b.mesh = [&pair, pinion, ring](int i, const std::filesystem::path &f) {
        return i == 0 ? mesh::mesh_gear(pair.pinion(), pinion, f) : mesh::mesh_ring(pair.ring(), ring, f);
      };
      return b;
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const geometry::GeometryInput gi = geometry::parse_geometry_parameters(prm);
      (void)geometry::parse_material_parameters(prm);
      (void)fem::parse_fe_parameters(prm);
      mesh::GearMeshParameters mp[2] = {mesh::parse_mesh_parameters(prm, 1),
                                        mesh::parse_mesh_parameters(prm, 2)};
      // An internal pair (Pair/Type = internal): gear 2 is the ring, meshed with its rim.
      std::unique_ptr<geometry::GearPair> external;
      std::unique_ptr<geometry::InternalGearPair> internal;
      Bodies bodies;
      if (solve::internal_pair_requested(prm))
        {
          const solve::RingInput ring = solve::parse_ring_parameters(prm, gi.gear2, mp[1]);
          internal = std::make_unique<geometry::InternalGearPair>(
            geometry::ToothProfile::generate(gi.gear1), geometry::InternalToothProfile::generate(ring.gear),
            gi.pair.center_distance, ring.face_width);
          bodies = internal_bodies(*internal, mp[0], ring.mesh);
        }
      else
        {
          external = std::make_unique<geometry::GearPair>(geometry::build_pair(gi));
          bodies   = external_bodies(*external, mp);
        }
      out << bodies.text[0] << bodies.text[1];
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
          const mesh::MeshData m = bodies.mesh(i, file);
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
                       bodies.zoom[0], (ctx.output_dir / "gear2.msh").string(), bodies.zoom[1]},
                      &out);
    }
  } // namespace mesh_job

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
    c.declare = mesh_job::declare;
    c.run     = mesh_job::run;
    return c;
  }
} // namespace gearfem::commands
