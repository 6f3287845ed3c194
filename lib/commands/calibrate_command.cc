// `gearfem calibrate case.prm`: fit the analytical mesh model (lib/analytical/calibration.h)
// to FE STE from one or more `gearfem solve` results.h5 files, report the errors before
// and after, cross-validate on held-out torques, and write the stiffness and torque tables
// (lib/io, docs/mesh-tables.md) that the dynamics module reads.
#include "calibration/calibrate.h"
#include "calibration/parameters.h"
#include "condensed/cycle.h"
#include "condensed/table.h"
#include "base/units.h"
#include "analytical/from_geometry.h"
#include "base/errors.h"
#include "params/checked.h"
#include "base/atomic_file.h"
#include "base/table.h"
#include "commands/command.h"
#include "geometry/parameters.h"
#include "io/mesh_table_io.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <ctime>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace gearfem::commands
{
  namespace calibrate_job
  {
    namespace an = analytical;
    using units::pi;

    void declare(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      geometry::declare_geometry_parameters(prm);
      geometry::declare_material_parameters(prm);
      calibration::declare_calibration_parameters(prm);
    }

    std::string now_utc()
    {
      const std::time_t t = std::time(nullptr);
      char buf[32];
      std::strftime(buf, sizeof(buf), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
      return buf;
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const auto gi     = geometry::parse_geometry_parameters(prm);
      const auto pm     = geometry::parse_material_parameters(prm);
      const auto pair   = geometry::build_pair(gi);
      const calibration::Input in = calibration::parse_calibration_parameters(prm);
      const std::string hash = geometry::geometry_fingerprint(pair);
      std::vector<std::filesystem::path> paths;
      for (const auto &f : in.files)
        paths.push_back(std::filesystem::path(f).is_relative() ? ctx.input_file.parent_path() / f :
                                                                 std::filesystem::path(f));
      auto samples = calibration::read_fe_samples(paths, hash, "Calibration/Results files");
      std::optional<condensed::CondensedCycle> cycle;
      if (!in.cycle.empty())
        {
          const std::filesystem::path f = std::filesystem::path(in.cycle).is_relative() ?
                                            ctx.input_file.parent_path() / in.cycle :
                                            std::filesystem::path(in.cycle);
          cycle = condensed::read_cycle(f);
          if (cycle->geometry_hash != hash)
            throw InputError("Calibration/Condensed cycle", f.string(), "a cycle of this pair (geometry hash " + hash + ")",
                             "the cycle was condensed for geometry " + cycle->geometry_hash +
                               ": refusing to calibrate against another pair");
          out << "condensed cycle: " << f.string() << ", " << cycle->positions.size() << " positions, torques "
              << cycle->torque_lo << " to " << cycle->torque_hi << " N m\n";
        }
      if (cycle)
        condensed::check_cycle_torques(*cycle, in.cycle_torques, "Calibration/Cycle torques");
      if (ctx.validate_only)
        return;
      if (cycle)
        {
          const auto t0 = std::chrono::steady_clock::now();
          const auto s  = condensed::ste_samples(*cycle, pair.base_radius(1), in.cycle_torques, "Calibration/Cycle torques");
          samples.insert(samples.end(), s.begin(), s.end());
          out << "condensed cycle: " << s.size() << " FE positions re-solved in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
        }
      std::set<double> torques;
      for (const auto &s : samples)
        torques.insert(s.torque);
      out << "calibrate: " << samples.size() << " FE positions at " << torques.size() << " torques from "
          << in.files.size() << " file(s)" << (cycle ? " and the condensed cycle" : "") << ", model " << in.model
          << ", geometry " << hash << "\n";

      an::PairModelOptions opt;
      opt.model = in.model == "weber-cornell" ? an::StiffnessModel::weber_cornell : an::StiffnessModel::potential_energy;
      opt.plane = pm.plane_strain ? an::PlaneCondition::plane_strain : an::PlaneCondition::plane_stress;
      // The rim of the Sainsot foundation is the FE default bore (geometry::rim_inner_radius).
      const an::PairCompliance pc = an::pair_compliance(pair, {pm.gear1.youngs_modulus, pm.gear1.poisson_ratio},
                                                        {pm.gear2.youngs_modulus, pm.gear2.poisson_ratio}, opt);
      const calibration::Result r = calibration::calibrate(pc, pair, samples, in.options);

      const std::string rep = calibration::report(r, in.model, hash, samples.size(), in.files);
      write_file_atomically(ctx.output_dir / "calibration.md", rep);
      out << rep;
      for (const auto &w : r.fit.warnings)
        std::cerr << "warning: " << w << std::endl;
      calibration::comparison_table(r, pc, samples).write_csv(ctx.output_dir / "calibration.csv");
      {
        // Cost of the calibrated model per cycle (the speed-against-error study reads it).
        const auto c = calibration::time_cycle(calibration::CalibratedMesh(pc, r.fit.factors), pc, *torques.rbegin());
        out << "calibrated model: 40-position cycle in " << c.seconds * 1e3 << " ms (mean STE " << c.mean_ste * 1e6
            << " um at " << *torques.rbegin() << " N m)\n";
      }

      const io::TableProvenance prov{"gearfem calibrate " + ctx.input_file.filename().string() + " (" + in.model + ")",
                                     now_utc()};
      io::write_mesh_table(ctx.output_dir / "mesh_stiffness.h5", r.stiffness, prov);
      io::write_mesh_table(ctx.output_dir / "mesh_torque.h5", r.torque, prov);
      io::write_mesh_table(ctx.output_dir / "mesh_ste.h5", r.ste, prov);
      calibration::ste_table(r, pc).write_csv(ctx.output_dir / "ste_table.csv");
      const auto &g = in.options.grid;
      out << "\ntables: k(theta, F), T(theta, delta) and STE(theta, T) " << g.n_theta << " x " << g.n_load
          << " (F up to " << r.F_max << " N, delta up to " << r.delta_max * 1e6 << " um"
          << (g.backlash >= 0 ? ", two-sided T with backlash " + to_string_g(g.backlash * 1e6) +
                                  " um and reverse-flank offset " + to_string_g(r.reverse_offset / units::deg) + " deg" :
                                std::string())
          << ") in " << r.table_seconds << " s: mesh_stiffness.h5, mesh_torque.h5, mesh_ste.h5, ste_table.csv\n";
      run_plot_script("plot_calibration.py", {ctx.output_dir.string()}, &out);
    }
  } // namespace calibrate_job

  Command calibrate_command()
  {
    Command c;
    c.name        = "calibrate";
    c.summary     = "fit the analytical mesh model to FE STE (gearfem solve results) and write stiffness tables";
    c.description = "Reads one or more results.h5 of `gearfem solve` for the same pair (geometry hash\n"
                    "checked) and/or samples a condensed cycle of the pair (gearfem condense) at any\n"
                    "torques of its range (Calibration/Condensed cycle, Cycle torques), fits multipliers on the beam, foundation and Hertz compliances, a body\n"
                    "compliance and the Hertz radius of the tip corners in corner contact, reports the\n"
                    "STE error before/after and\n"
                    "with each torque held out, and writes mesh_stiffness.h5 (k(theta, F)),\n"
                    "mesh_torque.h5 (T(theta, delta), two-sided with Backlash >= 0), mesh_ste.h5\n"
                    "(STE(theta, T)) (docs/mesh-tables.md), ste_table.csv,\n"
                    "calibration.md, calibration.csv and calibration.png.\n"
                    "Sample run:\n"
                    "  gearfem calibrate validation/analytical_vs_fe/calibrate.prm   (after the Parker\n"
                    "  sweeps: validation/parker_ste/sweeps.sh)\n";
    c.declare = calibrate_job::declare;
    c.run     = calibrate_job::run;
    return c;
  }
} // namespace gearfem::commands
