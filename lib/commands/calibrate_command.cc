// `gearfem calibrate case.prm`: fit the analytical mesh model (lib/analytical/calibration.h)
// to FE STE from one or more `gearfem solve` results.h5 files, report the errors before
// and after, cross-validate on held-out torques, and write the stiffness and torque tables
// (lib/io, docs/mesh-tables.md) that the dynamics module reads.
#include "analytical/calibration.h"
#include "analytical/from_geometry.h"
#include "base/errors.h"
#include "params/checked.h"
#include "base/atomic_file.h"
#include "base/table.h"
#include "commands/command.h"
#include "geometry/parameters.h"
#include "io/mesh_table_io.h"

#include <deal.II/base/hdf5.h>

#include <hdf5.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <chrono>
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

    struct FeFile
    {
      std::string hash;
      std::vector<an::SteSample> samples;
    };

    FeFile read_results(const std::filesystem::path &file)
    {
      const std::string entry = "Calibration/Results files";
      if (!std::filesystem::is_regular_file(file))
        throw InputError(entry, file.string(), "an existing results.h5 of `gearfem solve`", "file not found");
      // Check the structure with the HDF5 C API first: deal.II's wrappers abort (rather than
      // throw) on some failures, and a corrupt or foreign file must give a named error.
      {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // no HDF5 error stack on stderr
        const std::string name = file.string();
        if (H5Fis_hdf5(name.c_str()) <= 0)
          throw InputError(entry, name, "an HDF5 results file of `gearfem solve`", "not an HDF5 file (corrupt or wrong file)");
        const hid_t h = H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        if (h < 0)
          throw InputError(entry, name, "a readable HDF5 file", "H5Fopen failed");
        std::string missing;
        for (const char *a : {"format", "geometry_hash"})
          if (H5Aexists(h, a) <= 0)
            missing += std::string(" attribute '") + a + "'";
        if (H5Lexists(h, "sweep", H5P_DEFAULT) <= 0)
          missing += " group '/sweep'";
        else
          for (const char *d : {"sweep/torque [N m]", "sweep/roll angle [deg]", "sweep/STE [um]"})
            if (H5Lexists(h, d, H5P_DEFAULT) <= 0)
              missing += std::string(" dataset '/") + d + "'";
        H5Fclose(h);
        if (!missing.empty())
          throw InputError(entry, name, "a results.h5 of `gearfem solve` (docs/output-format.md)", "missing:" + missing);
      }
      FeFile r;
      try
        {
          dealii::HDF5::File f(file.string(), dealii::HDF5::File::FileAccessMode::open);
          const auto format = f.get_attribute<std::string>("format");
          if (format != "gearfem-solve-results")
            throw InputError(entry, file.string(), "a file with format = gearfem-solve-results", "format is '" + format + "'");
          r.hash  = f.get_attribute<std::string>("geometry_hash");
          auto g  = f.open_group("sweep");
          const auto T   = g.open_dataset("torque [N m]").read<std::vector<double>>();
          const auto phi = g.open_dataset("roll angle [deg]").read<std::vector<double>>();
          const auto ste = g.open_dataset("STE [um]").read<std::vector<double>>();
          if (T.size() != phi.size() || T.size() != ste.size() || T.empty())
            throw InputError(entry, file.string(), "equal, non-empty sweep columns");
          for (std::size_t i = 0; i < T.size(); ++i)
            r.samples.push_back({T[i], phi[i] * pi / 180, ste[i] * 1e-6});
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (const std::exception &e)
        {
          throw InputError(entry, file.string(), "a readable results.h5 of `gearfem solve`",
                           std::string("HDF5: ") + e.what());
        }
      return r;
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
      const auto gi   = geometry::parse_geometry_parameters(prm);
      const auto pm   = geometry::parse_material_parameters(prm);
      const auto pair = geometry::build_pair(gi);
      prm.enter_subsection("Calibration");
      const auto files = dealii::Utilities::split_string_list(prm.get("Results files"), ',');
      const std::string model = prm.get("Model");
      const auto fit_set = dealii::Utilities::split_string_list(prm.get("Fit factors"), ',');
      const bool corner  = params::get_bool(prm, "Corner contact");
      const double rho0  = params::get_double(prm, "Corner radius") * 1e-3;
      const int n_theta  = params::get_integer(prm, "Table positions");
      const int n_load   = params::get_integer(prm, "Table loads");
      const double lf    = params::get_double(prm, "Table load factor");
      const double b_um  = params::get_double(prm, "Backlash");
      prm.leave_subsection();
      if (files.empty())
        throw InputError("Calibration/Results files", "(empty)", "at least one results.h5 of `gearfem solve`");
      if (!(rho0 >= 0))
        throw InputError("Calibration/Corner radius", to_string_g(rho0 * 1e3) + " mm", ">= 0");
      if (n_theta < 8)
        throw InputError("Calibration/Table positions", std::to_string(n_theta), ">= 8");
      if (n_load < 4)
        throw InputError("Calibration/Table loads", std::to_string(n_load), ">= 4");
      if (!(lf >= 1))
        throw InputError("Calibration/Table load factor", to_string_g(lf), ">= 1");
      std::set<std::string> fs(fit_set.begin(), fit_set.end());
      an::FitMask mask;
      mask.beam = fs.count("beam"), mask.foundation = fs.count("foundation"), mask.hertz = fs.count("hertz");
      mask.body = fs.count("body"), mask.corner_radius = fs.count("corner") || fs.count("extended");
      if (mask.corner_radius && !corner)
        throw InputError("Calibration/Fit factors", "corner", "no `corner` without corner contact",
                         "Calibration/Corner contact is false");
      if (mask.corner_radius && !(rho0 > 0))
        throw InputError("Calibration/Corner radius", "0 mm", "> 0 when `corner` is fitted (the start value)");

      const std::string hash = geometry::geometry_fingerprint(pair);
      std::vector<an::SteSample> samples;
      for (const auto &f : files)
        {
          std::filesystem::path p(f);
          if (p.is_relative())
            p = ctx.input_file.parent_path() / p;
          const FeFile r = read_results(p);
          if (r.hash != hash)
            throw InputError("Calibration/Results files", p.string(),
                             "results of this pair (geometry hash " + hash + ")",
                             "the file was computed for geometry " + r.hash + ": refusing to calibrate against another pair");
          samples.insert(samples.end(), r.samples.begin(), r.samples.end());
        }
      std::set<double> torques;
      for (const auto &s : samples)
        torques.insert(s.torque);
      out << "calibrate: " << samples.size() << " FE positions at " << torques.size() << " torques from "
          << files.size() << " file(s), model " << model << ", geometry " << hash << "\n";
      if (ctx.validate_only)
        return;

      an::PairModelOptions opt;
      opt.model = model == "weber-cornell" ? an::StiffnessModel::weber_cornell : an::StiffnessModel::potential_energy;
      opt.plane = pm.plane_strain ? an::PlaneCondition::plane_strain : an::PlaneCondition::plane_stress;
      // Rim inner radius for the Sainsot foundation: the FE default bore, half the root radius.
      const an::PairCompliance pc(an::involute_tooth(pair.gear(1), 0.5 * pair.gear(1).radii().root),
                                  an::involute_tooth(pair.gear(2), 0.5 * pair.gear(2).radii().root),
                                  {pm.gear1.youngs_modulus, pm.gear1.poisson_ratio},
                                  {pm.gear2.youngs_modulus, pm.gear2.poisson_ratio},
                                  std::min(pair.gear(1).parameters().face_width, pair.gear(2).parameters().face_width),
                                  an::pair_line(pair), opt);
      an::CalibrationFactors start;
      start.corner        = corner;
      start.corner_radius = rho0;
      an::CalibrationFactors plain; // uncalibrated: multipliers 1, no body; the same corner model
      plain.corner        = corner;
      plain.corner_radius = rho0;
      const auto before = an::ste_errors(pc, plain, samples);
      const auto fit    = an::fit_factors(pc, samples, start, mask);
      const auto after  = an::ste_errors(pc, fit.factors, samples);

      // Cross-validation: fit without one torque, test on it.
      std::vector<std::pair<double, an::SteErrors>> cv;
      std::map<double, an::CalibrationFactors> cv_factors;
      if (torques.size() >= 2)
        for (const double T : torques)
          {
            std::vector<an::SteSample> train, test;
            for (const auto &s : samples)
              (s.torque == T ? test : train).push_back(s);
            const auto f = an::fit_factors(pc, train, start, mask);
            cv.emplace_back(T, an::ste_errors(pc, f.factors, test).front());
            cv_factors.emplace(T, f.factors);
          }

      // Report.
      std::ostringstream rep;
      rep << std::setprecision(4);
      rep << "# Calibration of the " << model << " mesh model against FE STE\n\n"
          << "Geometry " << hash << ", " << samples.size() << " FE positions, files: ";
      for (const auto &f : files)
        rep << f << " ";
      rep << "\n\n## Fitted factors\n\n| factor | value | standard error |\n|---|---|---|\n";
      for (std::size_t i = 0; i < fit.names.size(); ++i)
        {
          const bool body = fit.names[i] == "body compliance", re = fit.names[i] == "corner radius";
          const double s  = body ? 1e9 : re ? 1e3 : 1.0;
          rep << "| " << fit.names[i] << (body ? " [m/N x 1e-9]" : re ? " [mm]" : " [-]") << " | "
              << fit.values[i] * s << " | " << fit.std_error[i] * s << " |\n";
        }
      rep << "\nRMS relative STE error at the optimum " << fit.rms << ", " << fit.iterations
          << " Levenberg-Marquardt iterations, condition number " << fit.condition << ".\n";
      for (const auto &w : fit.warnings)
        rep << "\nwarning: " << w << "\n";
      rep << "\n## STE error against FE (relative)\n\n| T1 [N m] | before: mean | before: max | after: mean | after: max | "
             "held out: mean | held out: max |\n|---|---|---|---|---|---|---|\n";
      for (std::size_t i = 0; i < before.size(); ++i)
        {
          rep << "| " << before[i].torque << " | " << 100 * before[i].mean_abs << " % | " << 100 * before[i].max_abs
              << " % | " << 100 * after[i].mean_abs << " % | " << 100 * after[i].max_abs << " % | ";
          bool found = false;
          for (const auto &[T, e] : cv)
            if (T == before[i].torque)
              rep << 100 * e.mean_abs << " % | " << 100 * e.max_abs << " % |\n", found = true;
          if (!found)
            rep << "- | - |\n";
        }
      rep << "\n`held out`: factors fitted on the other torques only, tested on this one";
      if (!cv_factors.empty())
        {
          rep << " (beam / foundation / Hertz multipliers, body compliance [m/N x 1e-9], corner radius [mm]):\n\n";
          for (const auto &[T, f] : cv_factors)
            rep << "- without " << T << " N m: " << f.beam << " / " << f.foundation << " / " << f.hertz << ", "
                << f.body * 1e9 << ", " << f.corner_radius * 1e3 << "\n";
        }
      else
        rep << ".\n";
      write_file_atomically(ctx.output_dir / "calibration.md", rep.str());
      out << rep.str();
      for (const auto &w : fit.warnings)
        std::cerr << "warning: " << w << std::endl;

      // FE against the model before and after (and held out), per position.
      Table cmp;
      for (const auto &[n, u] : std::vector<std::pair<std::string, std::string>>{{"torque", "N m"},
                                                                                 {"roll angle", "deg"},
                                                                                 {"STE FE", "um"},
                                                                                 {"STE before", "um"},
                                                                                 {"STE after", "um"},
                                                                                 {"STE held out", "um"}})
        cmp.add_column(n, u);
      const an::CalibratedMesh m0(pc, plain), m1(pc, fit.factors);
      std::map<double, an::CalibratedMesh> mcv;
      for (const auto &[T, f] : cv_factors)
        mcv.emplace(T, an::CalibratedMesh(pc, f));
      const double rb1 = m1.base_radius();
      for (const auto &s : samples)
        {
          const auto it     = mcv.find(s.torque);
          const double held = it == mcv.end() ? std::nan("") : it->second.ste(s.roll_angle, s.torque / rb1) * 1e6;
          cmp.add_row({s.torque, s.roll_angle * 180 / pi, s.ste * 1e6, m0.ste(s.roll_angle, s.torque / rb1) * 1e6,
                       m1.ste(s.roll_angle, s.torque / rb1) * 1e6, held});
        }
      cmp.write_csv(ctx.output_dir / "calibration.csv");

      // Tables for the dynamics module.
      const auto t0      = std::chrono::steady_clock::now();
      const double period = 2 * pi / pair.gear(1).teeth();
      const double phiA  = pair.point("A").roll_angle;
      const double Fmax  = lf * *torques.rbegin() / rb1;
      dynamics::MeshTable kt, tt, et;
      kt.kind = dynamics::MeshTable::Kind::stiffness_vs_load;
      tt.kind = dynamics::MeshTable::Kind::torque_vs_compression;
      et.kind = dynamics::MeshTable::Kind::ste_vs_torque;
      for (auto *t : {&kt, &tt, &et})
        {
          t->period = period, t->base_radius = rb1, t->geometry_hash = hash;
          for (int i = 0; i < n_theta; ++i)
            t->theta.push_back(phiA + period * i / n_theta);
        }
      kt.second_unit = "N", kt.value_unit = "N/m";
      for (int j = 0; j < n_load; ++j)
        kt.second.push_back(Fmax * (j + 1) / n_load);
      double dmax = 0;
      for (const double th : kt.theta)
        for (const double F : kt.second)
          {
            const double s = m1.ste(th, F);
            kt.values.push_back(F / s);
            dmax = std::max(dmax, s);
          }
      tt.second_unit = "m", tt.value_unit = "N*m";
      std::vector<double> drive;
      for (int j = 0; j < n_load; ++j)
        drive.push_back(dmax * j / (n_load - 1));
      double psi = 0;
      if (b_um >= 0)
        {
          // Two-sided: reverse flank below -b, the gap [-b, 0], the drive flank above 0.
          tt.backlash = b_um * 1e-6;
          psi = an::reverse_offset(an::involute_tooth(pair.gear(1)), pc.line(), tt.backlash);
          for (int j = n_load - 1; j >= 0; --j)
            tt.second.push_back(-tt.backlash - drive[j]);
          if (tt.backlash > 0)
            tt.second.push_back(0.0);
          tt.second.insert(tt.second.end(), drive.begin() + 1, drive.end());
        }
      else
        tt.second = drive;
      for (const double th : tt.theta)
        for (const double d : tt.second)
          tt.values.push_back(b_um >= 0 ? m1.torque(th, d, tt.backlash, psi) : rb1 * m1.load_at(th, d));
      et.second_unit = "N*m", et.value_unit = "m";
      for (const double F : kt.second)
        et.second.push_back(F * rb1);
      for (std::size_t i = 0; i < kt.theta.size(); ++i)
        for (std::size_t j = 0; j < kt.second.size(); ++j)
          et.values.push_back(kt.second[j] / kt.value(i, j)); // STE = F / k
      Table st;
      st.add_column("roll angle", "deg");
      st.add_column("torque", "N m");
      st.add_column("STE", "um");
      for (const double th : kt.theta)
        for (const double T : torques)
          st.add_row({th * 180 / pi, T, m1.ste(th, T / rb1) * 1e6});
      const double t_tables = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const io::TableProvenance prov{"gearfem calibrate " + ctx.input_file.filename().string() + " (" + model + ")",
                                     now_utc()};
      io::write_mesh_table(ctx.output_dir / "mesh_stiffness.h5", kt, prov);
      io::write_mesh_table(ctx.output_dir / "mesh_torque.h5", tt, prov);
      io::write_mesh_table(ctx.output_dir / "mesh_ste.h5", et, prov);
      st.write_csv(ctx.output_dir / "ste_table.csv");
      out << "\ntables: k(theta, F), T(theta, delta) and STE(theta, T) " << n_theta << " x " << n_load
          << " (F up to " << Fmax << " N, delta up to " << dmax * 1e6 << " um"
          << (b_um >= 0 ? ", two-sided T with backlash " + to_string_g(b_um) + " um and reverse-flank offset " +
                            to_string_g(psi * 180 / pi) + " deg" :
                          std::string())
          << ") in " << t_tables << " s: mesh_stiffness.h5, mesh_torque.h5, mesh_ste.h5, ste_table.csv\n";
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
