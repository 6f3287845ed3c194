// `gearfem gearbox study.prm`: gearbox-level rating (seed 001, Siasos 2010, ch. 7-9) of a
// train of parallel and planetary stages under a load spectrum: AGMA stresses of every
// mesh, AGMA 925 scuffing, Miner damage per member and mode, life in spectra and years.
// Parse, call lib/analytical (gearbox*.h, fatigue.h, scuffing.h), write.
#include "analytical/gearbox_parameters.h"
#include "analytical/gearbox_report.h"
#include "base/errors.h"
#include "commands/command.h"
#include "gearbox_fe/parameters.h"
#include "io/solve_results.h"

#include <deal.II/base/parameter_handler.h>

#include <iomanip>

namespace gearfem::commands
{
  namespace
  {
    namespace gb = gearfem::analytical::gearbox;

    void declare(dealii::ParameterHandler &prm)
    {
      gb::declare_gearbox_parameters(prm);
      gearbox_fe::declare_fe_stress_parameters(prm);
    }

    const char *source_name(gb::StressSource s)
    {
      return s == gb::StressSource::table ? "table" :
             s == gb::StressSource::fe    ? "FE" :
             s == gb::StressSource::iso   ? "ISO" :
                                            "AGMA";
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const gb::GearboxStudy study = gb::parse_gearbox_parameters(prm);
      const gb::GearboxInput &in = study.input;
      gearbox_fe::FeStressOptions fe = gearbox_fe::parse_fe_stress_parameters(prm, in.stages.size());
      if (ctx.validate_only)
        {
          out << "gearbox: " << in.stages.size() << " stages, " << in.spectrum.torques.size()
              << " spectrum bins, stress source " << source_name(study.source) << "\n";
          return;
        }
      gb::GearboxResult r = gb::analyse(in);
      std::string source = "AGMA 2101-D04 / 908-B89 from the geometry";
      if (study.source == gb::StressSource::table)
        {
          gb::use_reference_stresses(r, in, study.reference, study.reference_torque);
          source = "table (given at " + to_string_g(study.reference_torque) +
                   " N m, sigma_H scaled with sqrt(M), sigma_F with M)";
        }
      if (study.source == gb::StressSource::iso)
        {
          gb::use_stress_table(r, in, gb::iso_stresses(r.stress));
          source = "ISO 6336-2 (sigma_H = max(sigma_H1, sigma_H2) of the mesh; K_A, K_v, K_Hbeta of the Rating "
                   "section, K_Halpha = 1) and ISO 6336-3 method B (sigma_F) from the geometry";
        }
      std::string fe_text, fe_failure;
      if (study.source == gb::StressSource::fe)
        {
          fe.output_dir = ctx.output_dir / "fe";
          fe.out = &out;
          const gearbox_fe::FeStressResult f = gearbox_fe::fe_stress_table(in, r.train, r.stress, fe);
          gb::use_stress_table(r, in, f.stress);
          gearbox_fe::write_fe_stresses(f, ctx.output_dir / "fe_stresses.csv");
          fe_text = gearbox_fe::fe_markdown(f, fe);
          fe_failure = f.failure;
          source = "FE (external meshes: gearfem solve sector models, Hertz from the FE load share and "
                   "fillet sigma_1, maxima over the mesh cycle; internal meshes: AGMA 2101-D04 / 908-B89)";
        }
      gb::write_markdown(in, r, source, ctx.output_dir / "gearbox.md",
                         "Gearbox rating (" + ctx.input_file.filename().string() + ")", fe_text);
      gb::write_csv(in, r, ctx.output_dir);
      gb::write_sn_csv(in, r, ctx.output_dir / "gearbox_sn.csv");
      const gb::GearboxTables t = gb::gearbox_tables(in, r);
      io::write_table_file({{"meshes", &t.meshes}, {"lives", &t.lives}}, ctx.output_dir / "gearbox.h5",
                           {{"format", "gearfem-gearbox"}, {"format_version", "1"},
                            {"input", ctx.input_file.filename().string()}, {"stress source", source}},
                           {{"meshes", "stage [text]", t.mesh_stage}, {"meshes", "mesh [text]", t.mesh_name},
                            {"lives", "stage [text]", t.life_stage}, {"lives", "member [text]", t.life_member},
                            {"lives", "mode [text]", t.life_mode}, {"lives", "load [text]", t.life_load}});

      const auto n = r.train.speeds();
      out << "output speed " << n.back() << " rpm\n";
      out << std::setprecision(5);
      for (const gb::MemberLife &m : r.lives)
        if (m.damage.D > 0.0)
          out << m.stage << " " << m.member << " " << m.mode << " (" << m.detail << "): D = " << m.damage.D
              << ", life " << m.damage.life_spectra << " spectra = " << m.life_years << " years\n";
      if (r.first_failure >= 0)
        out << "first failure: " << r.lives[r.first_failure].stage << " " << r.lives[r.first_failure].member
            << " (" << r.lives[r.first_failure].mode << ")\n";
      else
        out << "no member is damaged by this spectrum\n";
      if (!fe_failure.empty())
        throw SolverError("FE stresses: " + fe_failure + "\n  the finished meshes' results are kept in " +
                          (ctx.output_dir / "fe").string() + " and fe_stresses.csv; gearbox.md and the tables use "
                          "the standard stresses for the meshes not solved");
      run_plot_script("plot_gearbox.py", {ctx.output_dir.string()}, ctx.out);
      out << "wrote " << (ctx.output_dir / "gearbox.md").string()
          << ", gearbox.csv, gearbox_life.csv, gearbox_sn.csv, gearbox.h5, scuffing_path.csv"
          << (study.source == gb::StressSource::fe ? ", fe_stresses.csv, fe/" : "") << "\n";
    }
  } // namespace

  Command gearbox_command()
  {
    Command c;
    c.name = "gearbox";
    c.summary = "Gearbox rating: planetary/parallel stages, load spectrum, Miner life, AGMA 925 scuffing";
    c.description =
      "Rates a train of planetary (ring or carrier fixed, sun out) and parallel stages under a\n"
      "torque spectrum at the input (seed 001, Siasos 2010, ch. 7-9): kinematics and torques,\n"
      "internal-gear geometry and design checks (equal spacing, Z_R >= Z_P + 10, involute\n"
      "interference, coaxiality, neighbour clearance), AGMA 2101-D04 / 908-B89 contact and\n"
      "bending stresses of every mesh (internal meshes with the lower signs), load cycles per\n"
      "member, Miner damage with the semi-log S-N line or the ISO 6336 life factors, life in\n"
      "spectra and years, and AGMA 925 scuffing along the path of contact. Writes gearbox.md\n"
      "(every factor with its clause), gearbox.csv, gearbox_life.csv, gearbox.h5 (the same\n"
      "numbers), gearbox_sn.csv, scuffing_path.csv and, with /usr/bin/python3 and matplotlib,\n"
      "gearbox_damage.png, scuffing_path.png and gearbox_sn.png (S-N lines and spectrum bins).\n"
      "Gearbox/Stress source: AGMA (default), ISO (ISO 6336-2/-3), table, or FE (section\n"
      "`FE stresses`: the external meshes solved by `gearfem solve` sector models; exit 3 on a\n"
      "solver failure, with the finished meshes kept).\n\n"
      "Sample runs:\n"
      "  gearfem gearbox inputs/seed001_gearbox.prm\n"
      "  gearfem gearbox inputs/seed001_gearbox_thesis_stresses.prm\n"
      "  gearfem gearbox inputs/seed001_gearbox_fe.prm   (Stress source = FE: the external meshes by\n"
      "  `gearfem solve` sector models, section `FE stresses`; a few minutes)";
    c.declare = declare;
    c.run = run;
    return c;
  }
} // namespace gearfem::commands
