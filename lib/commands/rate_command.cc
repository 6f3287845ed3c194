// `gearfem rate case.prm`: ISO 6336-1/-2/-3 (method B) and AGMA 2101-D04 / 908-B89
// ratings of a generated pair, with every factor, its clause, value and unit, plus the
// analytical mesh stiffness, loaded STE and load sharing over one pitch per torque.
// The models live in lib/analytical.
#include "analytical/from_geometry.h"
#include "analytical/cycle_table.h"
#include "analytical/parameters.h"
#include "rating/parameters.h"
#include "rating/rating.h"
#include "base/errors.h"
#include "base/table.h"
#include "commands/command.h"
#include "geometry/parameters.h"
#include "geometry/internal_pair.h"
#include "rating/internal.h"
#include "solve/ring_input.h"

#include <deal.II/base/parameter_handler.h>

#include <chrono>
#include <cmath>
#include <iomanip>

namespace gearfem::commands
{
  namespace rate_job
  {
    namespace an = gearfem::analytical;

    void declare(dealii::ParameterHandler &prm)
    {
      geometry::declare_geometry_parameters(prm);
      geometry::declare_material_parameters(prm);
      rating::declare_rating_parameters(prm);
      an::declare_analytical_parameters(prm);
      solve::declare_ring_parameters(prm);
    }

    /// The stresses of each torque on stdout.
    void print_stresses(std::ostream &out, const rating::RatingReport &rep, const std::vector<double> &torques)
    {
      out << std::fixed << std::setprecision(1);
      for (std::size_t i = 0; i < torques.size(); ++i)
        out << "T = " << torques[i] << " N m: AGMA sigma_H " << rep.row("AGMA", "sigma_H").values[i]
            << ", sigma_F1 " << rep.row("AGMA", "sigma_F1").values[i] << ", sigma_F2 "
            << rep.row("AGMA", "sigma_F2").values[i] << " MPa; ISO sigma_H "
            << rep.row("ISO 6336", "sigma_H1").values[i] << ", sigma_F1 "
            << rep.row("ISO 6336", "sigma_F1").values[i] << ", sigma_F2 "
            << rep.row("ISO 6336", "sigma_F2").values[i] << " MPa\n";
      out.unsetf(std::ios::floatfield);
    }

    /// `Pair/Type = internal`: the pinion and its shaper-cut ring (docs/internal-gears.md),
    /// rated by rating::rate_internal with the ring's rim from `Ring/Backup ratio`.
    void run_internal(dealii::ParameterHandler &prm, const RunContext &ctx, const geometry::GeometryInput &gi,
                      const rating::RatingInput &ri)
    {
      std::ostream &out = *ctx.out;
      mesh::GearMeshParameters m2; // the ring's mesh sizes are not read here
      const solve::RingInput ring = solve::parse_ring_parameters(prm, gi.gear2, m2);
      const geometry::InternalGearPair pair(geometry::ToothProfile::generate(gi.gear1),
                                            geometry::InternalToothProfile::generate(ring.gear),
                                            gi.pair.center_distance, ring.face_width);
      rating::InternalRatingInput in;
      in.rating          = ri;
      in.ring_face_width = ring.face_width;
      const auto &k      = pair.ring().radii();
      if (ring.mesh.backup_ratio > 0)
        in.ring_rim_thickness = ring.mesh.backup_ratio * (k.root - k.tip);
      if (ctx.validate_only)
        {
          out << "rate: " << gi.gear1.teeth << "/" << gi.gear2.teeth << " internal pair, " << ri.torques.size()
              << " torques\n";
          return;
        }
      const rating::RatingReport rep = rating::rate_internal(pair.pinion(), pair.ring(), pair.mesh(), in);
      rep.write_markdown(ctx.output_dir / "rating.md", "Rating of the " + std::to_string(gi.gear1.teeth) + "/" +
                                                           std::to_string(gi.gear2.teeth) + " internal pair (" +
                                                           ctx.input_file.filename().string() + ")");
      rep.write_csv(ctx.output_dir / "rating.csv");
      print_stresses(out, rep, ri.torques);
      out << "wrote " << (ctx.output_dir / "rating.md").string()
          << ", rating.csv (the analytical mesh cycle covers external pairs only)\n";
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const geometry::GeometryInput gi = geometry::parse_geometry_parameters(prm);
      const geometry::PairMaterial pm = geometry::parse_material_parameters(prm);
      rating::RatingInput ri = rating::parse_rating_parameters(prm);
      const an::AnalyticalInput ai = an::parse_analytical_parameters(prm);
      ri.E1 = pm.gear1.youngs_modulus, ri.nu1 = pm.gear1.poisson_ratio;
      ri.E2 = pm.gear2.youngs_modulus, ri.nu2 = pm.gear2.poisson_ratio;
      if (solve::internal_pair_requested(prm))
        return run_internal(prm, ctx, gi, ri);
      const geometry::GearPair pair = geometry::build_pair(gi);
      if (ctx.validate_only)
        {
          out << "rate: " << gi.gear1.teeth << "/" << gi.gear2.teeth << " pair, "
              << ri.torques.size() << " torques, model " << an::to_string(ai.options.model) << "\n";
          return;
        }

      const auto t_rate            = std::chrono::steady_clock::now();
      const rating::RatingReport rep   = rating::rate(pair, ri);
      const double rating_seconds  = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_rate).count();
      rep.write_markdown(ctx.output_dir / "rating.md",
                         "Rating of the " + std::to_string(gi.gear1.teeth) + "/" +
                           std::to_string(gi.gear2.teeth) + " pair (" + ctx.input_file.filename().string() + ")");
      rep.write_csv(ctx.output_dir / "rating.csv");

      // Mesh cycle: stiffness, loaded STE and load per pair over one pitch (cycle_table.h).
      an::CycleInput ci{an::involute_tooth(pair.gear(1), ai.bore_radius1),
                        an::involute_tooth(pair.gear(2), ai.bore_radius2),
                        {pm.gear1.youngs_modulus, pm.gear1.poisson_ratio},
                        {pm.gear2.youngs_modulus, pm.gear2.poisson_ratio},
                        std::min(gi.gear1.face_width, gi.gear2.face_width),
                        an::pair_line(pair),
                        ai.options,
                        ai.corner_contact};
      ci.options.plane = pm.plane_strain ? an::PlaneCondition::plane_strain : an::PlaneCondition::plane_stress;
      const an::CycleTable ct = an::mesh_cycle_table(ci, ai.law, ri.torques, ai.positions);
      for (std::size_t i = 0; i < ct.torques.size(); ++i)
        out << "T = " << ct.torques[i] << " N m: mesh stiffness " << std::setprecision(4) << ct.k_min[i] * 1e-6
            << " .. " << ct.k_max[i] * 1e-6 << " N/um (mean " << ct.k_mean[i] * 1e-6 << ")\n";
      out << "mesh cycle (" << (ai.law == an::CycleLaw::ricker ? "seed000 ricker" : "load sharing")
          << "): " << ai.positions << " positions x " << ct.torques.size() << " torques in "
          << std::setprecision(3) << ct.seconds * 1e3 << " ms\n";
      ct.table.write_csv(ctx.output_dir / "mesh_cycle.csv");
      out << "ratings (ISO 6336 and AGMA, " << ri.torques.size() << " torques) in " << rating_seconds * 1e3 << " ms\n";

      print_stresses(out, rep, ri.torques);
      out << "wrote " << (ctx.output_dir / "rating.md").string() << ", rating.csv, mesh_cycle.csv\n";
    }
  } // namespace rate_job

  Command rate_command()
  {
    Command c;
    c.name = "rate";
    c.summary = "ISO 6336 and AGMA 2101/908 ratings with every factor, plus analytical mesh stiffness";
    c.description =
      "Rates a generated spur pair at one or more pinion torques: ISO 6336-1 stiffness,\n"
      "ISO 6336-2 contact stress, ISO 6336-3 root stress (30-degree tangent on the generated\n"
      "fillet), AGMA 2101-D04 contact and bending stress with AGMA 908-B89 Z_I and Y_J\n"
      "(Lewis parabola, Newton from alpha_n = pi/4). Writes rating.md and rating.csv (every\n"
      "factor with clause, value, unit) and mesh_cycle.csv (analytical mesh stiffness,\n"
      "loaded STE and load per pair over one pitch for each torque).\n"
      "With Pair/Type = internal (gear 2 a shaper-cut ring: docs/internal-gears.md) the ISO and AGMA\n"
      "ratings of the internal pair, the ring included, with the rim factors Y_B and K_B from\n"
      "Ring/Backup ratio (rating.md, rating.csv).\n\n"
      "Sample runs:\n"
      "  gearfem rate inputs/seed001_23_69_rate.prm\n"
      "  gearfem rate inputs/internal_rate.prm";
    c.declare = rate_job::declare;
    c.run = rate_job::run;
    return c;
  }
} // namespace gearfem::commands
