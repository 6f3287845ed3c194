// `gearfem calibrate case.prm`: fit the analytical mesh model (lib/analytical/calibration.h)
// to FE STE from one or more `gearfem solve` results.h5 files, report the errors before
// and after, cross-validate on held-out torques, and write the stiffness and torque tables
// (lib/io, docs/mesh-tables.md) that the dynamics module reads.
#include "calibration/calibrate.h"
#include "analytical/from_geometry.h"
#include "base/errors.h"
#include "params/checked.h"
#include "base/atomic_file.h"
#include "base/table.h"
#include "commands/command.h"
#include "geometry/parameters.h"
#include "io/mesh_table_io.h"

#include <chrono>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <ctime>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace gearfem::commands
{
  namespace
  {
    namespace an = analytical;
    const double pi = 3.14159265358979323846;

    void declare(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      geometry::declare_geometry_parameters(prm);
      geometry::declare_material_parameters(prm);
      prm.enter_subsection("Calibration");
      prm.declare_entry("Results files", "", Anything(),
                        "Comma-separated results.h5 files of `gearfem solve` for this pair (relative "
                        "to the input file). Units: none.");
      prm.declare_entry("Model", "weber-cornell", Selection("weber-cornell|potential-energy"),
                        "Analytical pair compliance that is calibrated. Units: none.");
      prm.declare_entry("Fit factors", "beam, hertz, body, corner",
                        MultipleSelection("beam|foundation|hertz|body|corner|extended"),
                        "Factors the fit may change: multipliers on the beam, foundation and Hertz "
                        "compliances, a series body compliance, and the effective radius of the tip "
                        "corners in the Hertz term of the corner contact (`corner`; `extended` is its "
                        "former name, kept for old inputs). Units: none.");
      prm.declare_entry("Corner contact", "true", Bool(),
                        "Corner contact OA/BΓ outside the path A..E with the exact rigid gap of the "
                        "tip corners (lib/analytical/corner.h). Units: none.");
      prm.declare_entry("Corner radius", "0.1", Double(),
                        "Radius of curvature of the tip corners in the Hertz term of a corner contact "
                        "(the start value when `corner` is fitted); 0: the tip rounding of the geometry, "
                        "or the involute radii at the path end for sharp teeth. Units: mm. Allowed: >= 0.");
      prm.declare_entry("Table positions", "200", Integer(), "Roll angles over one pitch in the tables. Units: none. Allowed: >= 8.");
      prm.declare_entry("Table loads", "50", Integer(), "Load (or compression) points in the tables. Units: none. Allowed: >= 4.");
      prm.declare_entry("Table load factor", "2", Double(),
                        "Largest table load over the largest FE load. Units: none. Allowed: >= 1.");
      prm.declare_entry("Backlash", "-1", Double(),
                        "Total clearance b along the line of action for a two-sided T(theta, delta) "
                        "table (format version 2): T = 0 on [-b, 0] and the reverse-flank branch "
                        "below -b (coast flanks mapped onto the drive flanks, b shared equally by "
                        "the two gears); < 0: a one-sided table (delta >= 0). Units: um.");
      prm.leave_subsection();
    }

    std::string now_utc()
    {
      const std::time_t t = std::time(nullptr);
      char buf[32];
      std::strftime(buf, sizeof(buf), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
      return buf;
    }

    /// The `Calibration` section, checked.
    struct Input
    {
      std::vector<std::string> files;
      std::string model;
      calibration::Options options;
    };

    Input parse(dealii::ParameterHandler &prm)
    {
      Input in;
      prm.enter_subsection("Calibration");
      in.files = dealii::Utilities::split_string_list(prm.get("Results files"), ',');
      in.model = prm.get("Model");
      const auto fit_set = dealii::Utilities::split_string_list(prm.get("Fit factors"), ',');
      const bool corner  = params::get_bool(prm, "Corner contact");
      const double rho0  = params::get_double(prm, "Corner radius") * 1e-3;
      auto &g            = in.options.grid;
      g.n_theta          = params::get_integer(prm, "Table positions");
      g.n_load           = params::get_integer(prm, "Table loads");
      g.load_factor      = params::get_double(prm, "Table load factor");
      const double b_um  = params::get_double(prm, "Backlash");
      g.backlash         = b_um >= 0 ? b_um * 1e-6 : -1.0;
      prm.leave_subsection();
      if (in.files.empty())
        throw InputError("Calibration/Results files", "(empty)", "at least one results.h5 of `gearfem solve`");
      if (!(rho0 >= 0))
        throw InputError("Calibration/Corner radius", to_string_g(rho0 * 1e3) + " mm", ">= 0");
      if (g.n_theta < 8)
        throw InputError("Calibration/Table positions", std::to_string(g.n_theta), ">= 8");
      if (g.n_load < 4)
        throw InputError("Calibration/Table loads", std::to_string(g.n_load), ">= 4");
      if (!(g.load_factor >= 1))
        throw InputError("Calibration/Table load factor", to_string_g(g.load_factor), ">= 1");
      std::set<std::string> fs(fit_set.begin(), fit_set.end());
      auto &mask = in.options.mask;
      mask.beam = fs.count("beam"), mask.foundation = fs.count("foundation"), mask.hertz = fs.count("hertz");
      mask.body = fs.count("body"), mask.corner_radius = fs.count("corner") || fs.count("extended");
      if (mask.corner_radius && !corner)
        throw InputError("Calibration/Fit factors", "corner", "no `corner` without corner contact",
                         "Calibration/Corner contact is false");
      if (mask.corner_radius && !(rho0 > 0))
        throw InputError("Calibration/Corner radius", "0 mm", "> 0 when `corner` is fitted (the start value)");
      in.options.start.corner        = corner;
      in.options.start.corner_radius = rho0;
      return in;
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const auto gi     = geometry::parse_geometry_parameters(prm);
      const auto pm     = geometry::parse_material_parameters(prm);
      const auto pair   = geometry::build_pair(gi);
      const Input in    = parse(prm);
      const std::string hash = geometry::geometry_fingerprint(pair);
      std::vector<std::filesystem::path> paths;
      for (const auto &f : in.files)
        paths.push_back(std::filesystem::path(f).is_relative() ? ctx.input_file.parent_path() / f :
                                                                 std::filesystem::path(f));
      const auto samples = calibration::read_fe_samples(paths, hash, "Calibration/Results files");
      std::set<double> torques;
      for (const auto &s : samples)
        torques.insert(s.torque);
      out << "calibrate: " << samples.size() << " FE positions at " << torques.size() << " torques from "
          << in.files.size() << " file(s), model " << in.model << ", geometry " << hash << "\n";
      if (ctx.validate_only)
        return;

      an::PairModelOptions opt;
      opt.model = in.model == "weber-cornell" ? an::StiffnessModel::weber_cornell : an::StiffnessModel::potential_energy;
      opt.plane = pm.plane_strain ? an::PlaneCondition::plane_strain : an::PlaneCondition::plane_stress;
      // Rim inner radius for the Sainsot foundation: the FE default bore, half the root radius.
      const an::PairCompliance pc(an::involute_tooth(pair.gear(1), 0.5 * pair.gear(1).radii().root),
                                  an::involute_tooth(pair.gear(2), 0.5 * pair.gear(2).radii().root),
                                  {pm.gear1.youngs_modulus, pm.gear1.poisson_ratio},
                                  {pm.gear2.youngs_modulus, pm.gear2.poisson_ratio},
                                  std::min(pair.gear(1).parameters().face_width, pair.gear(2).parameters().face_width),
                                  an::pair_line(pair), opt);
      const calibration::Result r = calibration::calibrate(pc, pair, samples, in.options);

      const std::string rep = calibration::report(r, in.model, hash, samples.size(), in.files);
      write_file_atomically(ctx.output_dir / "calibration.md", rep);
      out << rep;
      for (const auto &w : r.fit.warnings)
        std::cerr << "warning: " << w << std::endl;
      calibration::comparison_table(r, pc, samples).write_csv(ctx.output_dir / "calibration.csv");
      {
        // Cost of the calibrated model: one 40-position cycle from A at the largest FE load
        // (what a dynamics step or a design loop pays; the speed-against-error study reads it).
        const an::CalibratedMesh cm(pc, r.fit.factors);
        const auto &L  = pc.line();
        const double F = *torques.rbegin() / L.rb1;
        double sum     = 0;
        const auto t0  = std::chrono::steady_clock::now();
        for (int i = 0; i < 40; ++i)
          sum += cm.ste((L.g_A - L.g_C + i * L.base_pitch / 40) / L.rb1, F);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        out << "calibrated model: 40-position cycle in " << s * 1e3 << " ms (mean STE " << sum / 40 * 1e6
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
                                  " um and reverse-flank offset " + to_string_g(r.reverse_offset * 180 / pi) + " deg" :
                                std::string())
          << ") in " << r.table_seconds << " s: mesh_stiffness.h5, mesh_torque.h5, mesh_ste.h5, ste_table.csv\n";
      run_plot_script("plot_calibration.py", {ctx.output_dir.string()}, &out);
    }
  } // namespace

  Command calibrate_command()
  {
    Command c;
    c.name        = "calibrate";
    c.summary     = "fit the analytical mesh model to FE STE (gearfem solve results) and write stiffness tables";
    c.description = "Reads one or more results.h5 of `gearfem solve` for the same pair (geometry hash\n"
                    "checked), fits multipliers on the beam, foundation and Hertz compliances, a body\n"
                    "compliance and the Hertz radius of the tip corners in corner contact, reports the\n"
                    "STE error before/after and\n"
                    "with each torque held out, and writes mesh_stiffness.h5 (k(theta, F)),\n"
                    "mesh_torque.h5 (T(theta, delta), two-sided with Backlash >= 0), mesh_ste.h5\n"
                    "(STE(theta, T)) (docs/mesh-tables.md), ste_table.csv,\n"
                    "calibration.md, calibration.csv and calibration.png.\n"
                    "Sample run:\n"
                    "  gearfem calibrate validation/analytical_vs_fe/calibrate.prm\n";
    c.declare = declare;
    c.run     = run;
    return c;
  }
} // namespace gearfem::commands
