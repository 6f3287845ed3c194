// `gearfem dynamics case.prm`: nonlinear gear-pair dynamics (time response, up/down speed
// sweeps, spectra, phase portraits). The model and analyses live in lib/dynamics.
#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/table.h"
#include "commands/command.h"
#include "io/solve_results.h"
#include "dynamics/case.h"
#include "dynamics/law_factory.h"
#include "dynamics/parameters.h"
#include "dynamics/report.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::commands
{
  namespace dynamics_job
  {
    namespace dyn = gearfem::dynamics;

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      dyn::DynamicsCase c = dyn::parse_parameters(prm, ctx.input_file.parent_path().string());
      std::vector<std::string> table_notes;
      if (c.law == dyn::LawKind::external)
        c.external_law = dyn::external_law(c, c.backlash, table_notes);
      std::vector<std::string> notes = table_notes;
      auto model = dyn::build_model(c, &notes);
      const bool ks = c.model == dyn::ModelKind::kahraman_singh;
      out << "dynamics: "
          << (ks ? "Kahraman-Singh (dimensionless)" : c.model == dyn::ModelKind::dte ? "1-DOF DTE" : "2-DOF torsional")
          << ", law " << model->law().name() << ", " << dyn::to_string(c.integrator.method) << "\n";
      for (const auto &n : notes)
        out << "  " << n << "\n";
      if (!ks)
        out << "  mesh frequency at the pinion speed = " << 1.0 / model->mesh_period_time() << " Hz\n";
      if (ctx.validate_only)
        return;

      const dyn::CaseReport report = dyn::run_case(c, *model, ctx.out);
      std::vector<std::pair<std::string, const Table *>> h5;
      for (const auto &[name, table] : report.tables)
        {
          table.write_csv(ctx.output_dir / (name + ".csv"));
          h5.emplace_back(name, &table);
          if (name == "sweep")
            out << "sweep: " << table.n_rows() << " points written to sweep.csv\n";
        }
      if (report.clamps > 0)
        out << "warning: the mesh-force table was evaluated outside its range " << report.clamps
            << " times (stiffness clamped); see summary.txt\n";
      write_file_atomically(ctx.output_dir / "summary.txt", report.summary);
      io::write_table_file(h5, ctx.output_dir / "response.h5", {{"program", "gearfem dynamics"}});
      run_plot_script("plot_dynamics.py", {ctx.output_dir.string()}, ctx.out);
    }
  } // namespace dynamics_job

  Command dynamics_command()
  {
    Command c;
    c.name = "dynamics";
    c.summary = "nonlinear gear-pair dynamics: time response, speed sweeps, spectra";
    c.description =
      "1-DOF DTE, 2-DOF torsional or dimensionless Kahraman-Singh model with backlash,\n"
      "contact loss and back contact; RK4 / DOPRI5 / SDIRK3 with event location.\n"
      "Writes response.h5 (groups response, poincare, spectrum, sweep), the same tables as\n"
      "response.csv, poincare.csv, spectrum.csv, sweep.csv, summary.txt and sweep.png,\n"
      "spectrum.png, phase.png; with Analysis/Portrait speeds also portrait_<k>_{response,\n"
      "poincare,spectrum}.csv and portraits.png (phase portraits and Poincare sections).\n\n"
      "Sample runs:\n"
      "  gearfem dynamics inputs/dynamics_kahraman_singh.prm\n"
      "  gearfem dynamics inputs/dynamics_seed004.prm";
    c.declare = [](dealii::ParameterHandler &prm) { dynamics::declare_parameters(prm); };
    c.run = dynamics_job::run;
    return c;
  }
} // namespace gearfem::commands
