// `gearfem helical case.prm`: a helical pair by face-width slicing (helical/run.h): the
// condensed cycle of its transverse section, the slices coupled across the face at every
// position and torque, the lead modifications and misalignment of the `Helical` section.
#include "base/errors.h"
#include "base/units.h"
#include "commands/command.h"
#include "helical/run.h"
#include "system_deflection/run.h"

#include <deal.II/base/parameter_handler.h>

#include <iomanip>

namespace gearfem::commands
{
  namespace helical_job
  {
    void declare(dealii::ParameterHandler &prm)
    {
      helical::declare_request(prm);
      system_deflection::declare_system_parameters(prm);
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out                 = *ctx.out;
      helical::Request req              = helical::parse_request(prm);
      const system_deflection::SystemInput sys = system_deflection::parse_system_parameters(prm);
      const solve::GearContactInput &in = req.section;
      const helical::SlicingOptions &o  = req.slicing;
      helical::RunOptions &ro           = req.run;
      ro.out                            = &out;
      ro.cycle_file                     = ctx.condensed;
      {
        const auto &h = o.helix;
        out << std::setprecision(5) << "helical: z " << in.pair->gear(1).teeth() << "/" << in.pair->gear(2).teeth()
            << ", beta " << h.beta / units::deg << " deg (beta_b " << h.beta_b / units::deg << " deg), m_n "
            << h.m_n / units::mm << " mm, m_t " << h.m_t / units::mm << " mm, alpha_t " << h.alpha_t / units::deg
            << " deg, b " << h.face_width / units::mm << " mm\n"
            << "  eps_alpha " << in.pair->contact_ratio() << ", eps_beta " << h.overlap_ratio << ", eps_gamma "
            << in.pair->contact_ratio() + h.overlap_ratio << "; " << o.slices << " slices, "
            << (o.coupling == helical::Coupling::shear ? "shear" : "bending") << " coupling, length "
            << o.coupling_length / units::mm << " mm, mesh misalignment "
            << o.lead.mesh_misalignment(o.alpha_wt) / units::um << " um, crowning " << o.lead.crowning / units::um
            << " um; " << o.grid.size << " sections per pitch\n";
      }
      if (ctx.validate_only)
        return;
      if (ctx.condensed.empty())
        ro.write_cycle = ctx.output_dir / condensed::file_name;
      const system_deflection::CoupledRun coupled = system_deflection::run_job(in, o, ro, sys);
      system_deflection::write_job(coupled, sys.coupled, ctx.output_dir, ctx.input_file.filename().string());
      const helical::HelicalRun &r = coupled.helical;
      out << std::setprecision(5);
      for (const auto &t : r.summary)
        out << "T " << t.torque << " N m: STE mean " << t.ste_mean / units::um << " um, p-p " << t.ste_pp / units::um
            << " um; mesh stiffness " << t.k_mean * units::um << " N/um (c_gamma " << t.c_gamma_iso()
            << " N/(mm um)); K_Hbeta " << t.k_h_beta << "; p_max " << t.p_max / 1e6 << " MPa; root stress "
            << t.root_stress_pinion / 1e6 << " / " << t.root_stress_gear / 1e6 << " MPa\n";
      if (sys.coupled)
        {
          int it = 0;
          double res = 0;
          for (const auto &c : coupled.coupled)
            it = std::max(it, c.iterations), res = std::max(res, c.residual);
          out << "on the shafts: up to " << it << " iterations per position, residual <= " << res / units::um
              << " um; wrote coupling.csv, misalignment.csv, shafts.csv, bearings.csv, system.json\n";
          for (const auto &m : coupled.iso)
            out << "T " << m.torque << " N m on the shafts: K_Hbeta " << m.k_h_beta_coupled
                << "; ISO 6336-1 method C with the shafts' mismatch" << (coupled.corrected ? " and the correction" : "")
                << " F_beta_y " << m.f_beta_y / units::um << " um: "
                << m.k_h_beta << "\n";
        }
      out << "build " << r.build_seconds << " s, sweep " << r.sweep_seconds << " s (" << r.results.size()
          << " positions, " << r.sweep_seconds / std::max<std::size_t>(1, r.results.size()) * 1e3
          << " ms each); wrote helical.csv, slices.csv, lines.csv, helical.json\n";
      if (in.solve.plots)
        {
          run_plot_script("plot_helical.py", {ctx.output_dir.string()}, &out);
          if (sys.coupled)
            run_plot_script("plot_system.py", {ctx.output_dir.string()}, &out);
        }
      if (!r.failure.empty())
        throw SolverError(r.failure + " (the " + std::to_string(r.results.size()) + " positions before it are written)");
    }
  } // namespace helical_job

  Command helical_command()
  {
    Command c;
    c.name        = "helical";
    c.summary     = "a helical pair by face-width slicing on the condensed cycle of its transverse section";
    c.description = "Meshes the transverse section of the pair (the Rack and Gear sections in the normal\n"
                    "section by default, ISO 21771), condenses it over one pitch (the Solve cycle), and\n"
                    "solves the face as Helical/Slices transverse sections staggered by z tan(beta_b)/r_b1,\n"
                    "coupled across the face (Pasternak shear layer) and loaded together, with the lead\n"
                    "crowning, end relief, helix slope deviation and misalignment as gap offsets.\n"
                    "Writes helical.csv (STE, mesh stiffness, K_Hbeta per position and torque), slices.csv\n"
                    "(load per unit width, p_max and root stress per slice), lines.csv (load along each\n"
                    "contact line), helical.json (helix, contact ratios, summary) and condensed.h5, which\n"
                    "--condensed reuses for another helix angle, slice count or lead modification of the\n"
                    "same transverse section (docs/helical.md).\n"
                    "Sample runs:\n"
                    "  gearfem helical inputs/helical_demo.prm --output-dir results/helical_demo\n";
    c.declare = helical_job::declare;
    c.run     = helical_job::run;
    return c;
  }
} // namespace gearfem::commands
