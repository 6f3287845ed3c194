// `gearfem system train.prm`: a parallel-axis gear train on its shafts (system_deflection/
// train.h): every stage's helical input read from the file the `Train` section names, all
// meshes coupled through the shafts at every position and input torque.
#include "base/errors.h"
#include "base/units.h"
#include "commands/command.h"
#include "commands/helical_input.h"
#include "helical/run.h"
#include "system_deflection/run.h"
#include "system_deflection/train.h"

#include <deal.II/base/parameter_handler.h>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace gearfem::commands
{
  helical::Request read_helical_input(const std::filesystem::path &file)
  {
    std::ifstream f(file);
    if (!f)
      throw InputError("helical input file", file.string(), "an existing readable file");
    std::stringstream text;
    text << f.rdbuf();
    dealii::ParameterHandler prm;
    helical::declare_request(prm);
    system_deflection::declare_system_parameters(prm);
    parse_input_text(text.str(), file.string(), prm);
    return helical::parse_request(prm);
  }

  namespace system_job
  {
    void declare(dealii::ParameterHandler &prm) { system_deflection::declare_train_parameters(prm); }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      auto train        = system_deflection::parse_train_parameters(prm, ctx.input_file);
      for (auto &s : train.stages)
        s.request = read_helical_input(s.input);
      out << "system: " << train.stages.size() << " stages on " << train.system.shafts.size() << " shafts\n";
      for (std::size_t k = 0; k < train.stages.size(); ++k)
        {
          const auto &p = *train.stages[k].request.section.pair;
          const auto &h = train.stages[k].request.slicing.helix;
          out << std::setprecision(5) << "  stage " << k + 1 << ": z " << p.gear(1).teeth() << "/" << p.gear(2).teeth()
              << ", a " << p.center_distance() / units::mm << " mm, beta " << h.beta / units::deg << " deg, b "
              << h.face_width / units::mm << " mm, " << train.stages[k].request.slicing.slices << " slices ("
              << train.stages[k].input.filename().string() << ")\n";
        }
      if (ctx.validate_only)
        return;
      const bool plots = train.stages.front().request.section.solve.plots;
      const auto run   = system_deflection::run_train(std::move(train), &out);
      system_deflection::write_train(run, ctx.output_dir, ctx.input_file.filename().string());
      out << std::setprecision(5);
      for (std::size_t k = 0; k < run.stages.size(); ++k)
        for (const auto &t : run.stages[k].summary)
          out << "stage " << k + 1 << ", T " << t.torque << " N m: STE mean " << t.ste_mean / units::um << " um, p-p "
              << t.ste_pp / units::um << " um; K_Hbeta " << t.k_h_beta << "; p_max " << t.p_max / 1e6
              << " MPa; root stress " << t.root_stress_pinion / 1e6 << " / " << t.root_stress_gear / 1e6 << " MPa\n";
      for (std::size_t k = 0; k < run.iso.size(); ++k)
        for (const auto &m : run.iso[k])
          out << "stage " << k + 1 << ", T " << m.torque << " N m: ISO 6336-1 method C with the shafts' mismatch "
              << "F_beta_y " << m.f_beta_y / units::um << " um: K_Hbeta " << m.k_h_beta << "\n";
      int it = 0;
      double res = 0;
      for (const auto &c : run.coupled.front())
        it = std::max(it, c.iterations), res = std::max(res, c.residual);
      out << "on the shafts: up to " << it << " iterations per position, residual <= " << res / units::um
          << " um; sweep " << run.sweep_seconds << " s (" << run.coupled.front().size()
          << " positions); wrote stage_<k>/, coupling.csv, misalignment.csv, shafts.csv, bearings.csv, system.json\n";
      if (plots)
        run_plot_script("plot_system.py", {ctx.output_dir.string()}, &out);
      if (!run.failure.empty())
        throw SolverError(run.failure + " (the " + std::to_string(run.coupled.front().size()) +
                          " positions before it are written)");
    }
  } // namespace system_job

  Command system_command()
  {
    Command c;
    c.name        = "system";
    c.summary     = "a parallel-axis gear train on its shafts: every stage's helical slicing coupled through them";
    c.description = "Reads the Train section: the stages (each a gearfem helical input file, stage k's\n"
                    "pinion on shaft k and its gear on shaft k + 1), the shafts with their bearings, and\n"
                    "the input torques. Builds every stage's condensed cycle, then solves all meshes on the\n"
                    "shafts together at every position of stage 1's cycle (the others following through\n"
                    "the ratios): the mismatch along every face from all meshes' loads, to a fixed point.\n"
                    "Writes stage_<k>/ (each stage's helical tables), coupling.csv, misalignment.csv,\n"
                    "shafts.csv, bearings.csv and system.json (docs/system-deflection.md).\n"
                    "Sample runs:\n"
                    "  gearfem system inputs/system_two_stage.prm --output-dir results/system_two_stage\n";
    c.declare = system_job::declare;
    c.run     = system_job::run;
    return c;
  }
} // namespace gearfem::commands
