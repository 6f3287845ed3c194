// `gearfem gearbox study.prm`: gearbox-level rating (Siasos 2010, ch. 7-9) of a
// train of parallel and planetary stages under a load spectrum: AGMA stresses of every
// mesh, AGMA 925 scuffing, Miner damage per member and mode, life in spectra and years.
// Parse, call lib/gearbox (study.h; gearbox/fe/source.h for the FE stresses), print.
#include "gearbox/study.h"
#include "base/errors.h"
#include "commands/command.h"
#include "gearbox/fe/parameters.h"
#include "gearbox/fe/source.h"

#include <deal.II/base/parameter_handler.h>

#include <iomanip>

namespace gearfem::commands
{
  namespace gearbox_job
  {
    namespace gb = gearfem::gearbox;

    void declare(dealii::ParameterHandler &prm)
    {
      gb::declare_gearbox_parameters(prm);
      gearbox::fe::declare_fe_stress_parameters(prm);
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const gb::GearboxStudy study = gb::parse_gearbox_parameters(prm);
      const gb::GearboxInput &in = study.input;
      gearbox::fe::FeStressOptions fe = gearbox::fe::parse_fe_stress_parameters(prm, in.stages.size());
      if (ctx.validate_only)
        {
          out << "gearbox: " << in.stages.size() << " stages, " << in.spectrum.torques.size()
              << " spectrum bins, stress source " << gb::source_name(study.source) << "\n";
          return;
        }
      gb::GearboxResult r = gb::analyse(in);
      std::string source = gb::apply_standard_source(r, study);
      gearbox::fe::FeSourceOutcome fe_out;
      if (study.source == gb::StressSource::fe)
        {
          fe.output_dir = ctx.output_dir / "fe";
          fe.out        = &out;
          fe_out        = gearbox::fe::apply_fe_source(r, in, fe, ctx.output_dir / "fe_stresses.csv");
          source        = fe_out.source;
        }
      gb::write_gearbox_outputs(in, r, source, ctx.output_dir, ctx.input_file.filename().string(), fe_out.text);

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
      if (!fe_out.failure.empty())
        throw SolverError("FE stresses: " + fe_out.failure + "\n  the finished meshes' results are kept in " +
                          (ctx.output_dir / "fe").string() + " and fe_stresses.csv; gearbox.md and the tables use "
                          "the standard stresses for the meshes not solved");
      run_plot_script("plot_gearbox.py", {ctx.output_dir.string()}, ctx.out);
      out << "wrote " << (ctx.output_dir / "gearbox.md").string()
          << ", gearbox.csv, gearbox_life.csv, gearbox_sn.csv, gearbox.h5, scuffing_path.csv"
          << (study.source == gb::StressSource::fe ? ", fe_stresses.csv, fe/" : "") << "\n";
    }
  } // namespace gearbox_job

  Command gearbox_command()
  {
    Command c;
    c.name = "gearbox";
    c.summary = "Gearbox rating: planetary/parallel stages, load spectrum, Miner life, AGMA 925 scuffing";
    c.description =
      "Rates a train of planetary (ring or carrier fixed, sun out) and parallel stages under a\n"
      "torque spectrum at the input (Siasos 2010, ch. 7-9): kinematics and torques,\n"
      "internal-gear geometry and design checks (equal spacing, Z_R >= Z_P + 10, involute\n"
      "interference, coaxiality, neighbour clearance), AGMA 2101-D04 / 908-B89 contact and\n"
      "bending stresses of every mesh (internal meshes with the lower signs), load cycles per\n"
      "member, Miner damage with the semi-log S-N line or the ISO 6336 life factors, life in\n"
      "spectra and years, and AGMA 925 scuffing along the path of contact. Writes gearbox.md\n"
      "(every factor with its clause), gearbox.csv, gearbox_life.csv, gearbox.h5 (the same\n"
      "numbers), gearbox_sn.csv, scuffing_path.csv and, with /usr/bin/python3 and matplotlib,\n"
      "gearbox_damage.png, scuffing_path.png and gearbox_sn.png (S-N lines and spectrum bins).\n"
      "Gearbox/Stress source: AGMA (default), ISO (ISO 6336-2/-3), table, or FE (section\n"
      "`FE stresses`: every mesh (planet-ring as a pinion in a ring) solved by `gearfem solve` sector models; exit 3 on a\n"
      "solver failure, with the finished meshes kept).\n\n"
      "Sample runs:\n"
      "  gearfem gearbox inputs/seed001_gearbox.prm\n"
      "  gearfem gearbox inputs/seed001_gearbox_thesis_stresses.prm\n"
      "  gearfem gearbox inputs/seed001_gearbox_fe.prm   (Stress source = FE: every mesh by\n"
      "  `gearfem solve` sector models, section `FE stresses`; a few minutes)";
    c.declare = gearbox_job::declare;
    c.run = gearbox_job::run;
    return c;
  }
} // namespace gearfem::commands
