// `gearfem dynamics case.prm`: nonlinear gear-pair dynamics (time response, up/down speed
// sweeps, spectra, phase portraits). The model and analyses live in lib/dynamics.
#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/table.h"
#include "commands/command.h"
#include "io/solve_results.h"
#include "dynamics/analysis.h"
#include "dynamics/case.h"
#include "dynamics/law_factory.h"
#include "dynamics/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace gearfem::commands
{
  namespace
  {
    namespace dyn = gearfem::dynamics;

    /// Output scaling: SI -> engineering units, or the dimensionless Kahraman-Singh x.
    struct Units
    {
      bool ks = false;
      double d_scale = 1e6, d_offset = 0; ///< DTE [um] (KS: x = delta + 1 [-])
      std::string d_unit = "um", v_unit = "mm/s", f_unit = "N", t_unit = "s", hz = "Hz",
                  speed_unit = "rpm";
      double v_scale = 1e3, speed_scale = 60 / (2 * M_PI);
      explicit Units(bool kahraman_singh)
        : ks(kahraman_singh)
      {
        if (ks)
          {
            d_scale = 1, d_offset = 1, v_scale = 1, speed_scale = 1;
            d_unit = v_unit = f_unit = t_unit = hz = speed_unit = "-";
          }
      }
    };

    /// Response, Poincare and spectrum tables of a time response.
    std::vector<std::pair<std::string, Table>> response_tables(const dyn::Response &r,
                                                               const dyn::MeshModel &m,
                                                               const Units &u)
    {
      Table t;
      t.add_column("time", u.t_unit);
      t.add_column("mesh position", u.ks ? "rad" : "deg");
      t.add_column(u.ks ? "x" : "DTE", u.d_unit);
      t.add_column(u.ks ? "x rate" : "DTE rate", u.v_unit);
      t.add_column("mesh force", u.f_unit);
      t.add_column("contact state", "-");
      for (std::size_t i = 0; i < r.t.size(); ++i)
        {
          const double th = m.pinion_speed() * r.t[i];
          t.add_row({r.t[i], u.ks ? th : th * 180 / M_PI, r.delta[i] * u.d_scale + u.d_offset,
                     r.rate[i] * u.v_scale, r.force[i], double(r.state[i])});
        }
      Table p;
      p.add_column("mesh period", "-");
      p.add_column(u.ks ? "x" : "DTE", u.d_unit);
      p.add_column(u.ks ? "x rate" : "DTE rate", u.v_unit);
      for (std::size_t i = 0; i < r.poincare_delta.size(); ++i)
        p.add_row({double(i + 1), r.poincare_delta[i] * u.d_scale + u.d_offset,
                   r.poincare_rate[i] * u.v_scale});
      const double dt = r.t.size() > 1 ? r.t[1] - r.t[0] : 1.0;
      const dyn::Spectrum s = dyn::amplitude_spectrum(r.delta, dt);
      Table f;
      f.add_column("frequency", u.hz);
      f.add_column("order", "-");
      f.add_column(u.ks ? "x amplitude" : "DTE amplitude", u.d_unit);
      for (std::size_t k = 0; k < s.frequency.size(); ++k)
        f.add_row({s.frequency[k], s.frequency[k] / r.mesh_frequency, s.amplitude[k] * u.d_scale});
      return {{"response", t}, {"poincare", p}, {"spectrum", f}};
    }

    Table sweep_table(const std::vector<dyn::SweepPoint> &pts, const Units &u)
    {
      Table t;
      t.add_column("direction", "-");
      t.add_column(u.ks ? "Omega" : "pinion speed", u.speed_unit);
      t.add_column("mesh frequency", u.hz);
      t.add_column(u.ks ? "RMS x" : "RMS DTE", u.d_unit);
      t.add_column(u.ks ? "peak-to-peak x" : "peak-to-peak DTE", u.d_unit);
      t.add_column(u.ks ? "mean x" : "mean DTE", u.d_unit);
      t.add_column("dynamic factor", "-");
      t.add_column("contact loss fraction", "-");
      t.add_column("back contact fraction", "-");
      t.add_column("period", "mesh periods");
      t.add_column("settled", "-");
      t.add_column("table clamps", "-");
      for (const auto &p : pts)
        {
          const auto &r = p.response;
          t.add_row({double(p.direction), r.pinion_speed * u.speed_scale,
                     u.ks ? r.mesh_frequency * 2 * M_PI : r.mesh_frequency, r.rms * u.d_scale,
                     r.peak_to_peak * u.d_scale, r.mean * u.d_scale + u.d_offset, r.dynamic_factor,
                     r.contact_loss_fraction, r.back_contact_fraction, double(r.period_multiplicity),
                     double(r.settled), double(r.out_of_range)});
        }
      return t;
    }


    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      dyn::DynamicsCase c = dyn::parse_parameters(prm, ctx.input_file.parent_path().string());
      std::vector<std::string> table_notes;
      if (c.law == dyn::LawKind::external)
        c.external_law = dyn::external_law(c, c.backlash, table_notes);
      std::vector<std::string> notes = table_notes;
      auto model = dyn::build_model(c, &notes);
      const Units u(c.model == dyn::ModelKind::kahraman_singh);
      out << "dynamics: " << (u.ks ? "Kahraman-Singh (dimensionless)" :
                              c.model == dyn::ModelKind::dte ? "1-DOF DTE" : "2-DOF torsional")
          << ", law " << model->law().name() << ", " << dyn::to_string(c.integrator.method)
          << "\n";
      for (const auto &n : notes)
        out << "  " << n << "\n";
      if (!u.ks)
        out << "  mesh frequency at the pinion speed = " << 1.0 / model->mesh_period_time()
            << " Hz\n";
      if (ctx.validate_only)
        return;

      std::ostringstream summary;
      summary << std::setprecision(8);
      std::vector<std::pair<std::string, Table>> h5_tables;
      long clamps = 0;
      if (c.run_response)
        {
          dyn::ResponseOptions ro = c.response;
          ro.keep_history = true;
          auto m = model->clone();
          dyn::State x = m->initial_state();
          double t = 0;
          const dyn::Response r = dyn::run_response(*m, c.integrator, ro, x, t);
          for (const auto &nt : response_tables(r, *m, u))
            {
              nt.second.write_csv(ctx.output_dir / (nt.first + ".csv"));
              h5_tables.push_back(nt);
            }
          clamps += r.out_of_range;
          const double w = u.ks ? 2 * M_PI : 1.0; // KS: circular frequencies (Omega, 1)
          summary << (u.ks ? "Omega" : "mesh frequency") << " [" << u.hz
                  << "] = " << r.mesh_frequency * w << "\n"
                  << "linear natural frequency [" << u.hz << "] = "
                  << m->linear_natural_frequency() * w << "\n"
                  << "RMS DTE [" << u.d_unit << "] = " << r.rms * u.d_scale << "\n"
                  << "peak-to-peak DTE [" << u.d_unit << "] = " << r.peak_to_peak * u.d_scale << "\n"
                  << "dynamic factor K_v [-] = " << r.dynamic_factor << "\n"
                  << "contact loss fraction [-] = " << r.contact_loss_fraction << "\n"
                  << "back contact fraction [-] = " << r.back_contact_fraction << "\n"
                  << "period [mesh periods] = " << r.period_multiplicity
                  << (r.period_multiplicity == 0 ? " (not periodic within the run)" : "") << "\n"
                  << "settled [-] = " << (r.settled ? "yes" : "no") << " after "
                  << r.transient_periods << " periods\n";
          out << summary.str();
        }
      for (std::size_t k = 0; k < c.portrait_speeds.size(); ++k)
        {
          // Phase portrait, Poincare section and spectrum at a chosen speed, from the static
          // state (the branch reached from rest; a sweep shows the others).
          dyn::ResponseOptions ro = c.response;
          ro.keep_history = true;
          auto m = model->clone();
          m->set_pinion_speed(c.portrait_speeds[k]);
          dyn::State x = m->initial_state();
          double t = 0;
          const dyn::Response r = dyn::run_response(*m, c.integrator, ro, x, t);
          const std::string name = "portrait_" + std::to_string(k + 1);
          for (const auto &nt : response_tables(r, *m, u))
            {
              nt.second.write_csv(ctx.output_dir / (name + "_" + nt.first + ".csv"));
              h5_tables.emplace_back(name + "_" + nt.first, nt.second);
            }
          clamps += r.out_of_range;
          summary << name << ": " << (u.ks ? "Omega" : "pinion speed") << " [" << u.speed_unit
                  << "] = " << r.pinion_speed * u.speed_scale << ", RMS DTE [" << u.d_unit
                  << "] = " << r.rms * u.d_scale << ", K_v [-] = " << r.dynamic_factor
                  << ", contact loss fraction [-] = " << r.contact_loss_fraction
                  << ", back contact fraction [-] = " << r.back_contact_fraction
                  << ", period [mesh periods] = " << r.period_multiplicity << "\n";
          out << name << " at " << r.pinion_speed * u.speed_scale << " " << u.speed_unit
              << ": RMS DTE " << r.rms * u.d_scale << " " << u.d_unit << ", contact loss fraction "
              << r.contact_loss_fraction << ", period " << r.period_multiplicity << "\n";
        }
      if (c.run_sweep)
        {
          const auto pts = dyn::sweep_up_down(*model, c.integrator, c.response, c.sweep_min,
                                              c.sweep_max, c.sweep_points, ctx.out, c.threads);
          const Table st = sweep_table(pts, u);
          st.write_csv(ctx.output_dir / "sweep.csv");
          h5_tables.emplace_back("sweep", st);
          for (const auto &p : pts)
            clamps += p.response.out_of_range;
          out << "sweep: " << pts.size() << " points written to sweep.csv\n";
        }
      summary << "table clamps (evaluations outside the table) [-] = " << clamps << "\n";
      if (clamps > 0)
        out << "warning: the mesh-force table was evaluated outside its range " << clamps
            << " times (stiffness clamped); see summary.txt\n";
      write_file_atomically(ctx.output_dir / "summary.txt", summary.str());
      std::vector<std::pair<std::string, const Table *>> h5;
      for (const auto &[name, table] : h5_tables)
        h5.emplace_back(name, &table);
      io::write_table_file(h5, ctx.output_dir / "response.h5", {{"program", "gearfem dynamics"}});
      run_plot_script("plot_dynamics.py", {ctx.output_dir.string()}, ctx.out);
    }
  } // namespace

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
    c.run = run;
    return c;
  }
} // namespace gearfem::commands
