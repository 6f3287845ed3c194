// The analyses of a dynamics case and their output tables.
#include "dynamics/report.h"
#include "base/units.h"

#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

namespace gearfem::dynamics
{
  namespace
  {
    using units::pi;

    /// A time response of a clone of `model` at its speed (or at `speed` if > 0), from the
    /// static state (the branch reached from rest; a sweep shows the others). Returns the
    /// clone as the run left it, and the response.
    std::pair<std::unique_ptr<MeshModel>, Response> response_at(const DynamicsCase &c, const MeshModel &model,
                                                                double speed)
    {
      ResponseOptions ro = c.response;
      ro.keep_history    = true;
      auto m             = model.clone();
      if (speed > 0)
        m->set_pinion_speed(speed);
      State x  = m->initial_state();
      double t = 0;
      Response r = run_response(*m, c.integrator, ro, x, t);
      return {std::move(m), std::move(r)};
    }

    void add(CaseReport &report, const std::string &prefix, std::vector<std::pair<std::string, Table>> tables)
    {
      for (auto &[name, table] : tables)
        report.tables.emplace_back(prefix + name, std::move(table));
    }
  } // namespace

  OutputUnits::OutputUnits(bool kahraman_singh)
    : ks(kahraman_singh)
  {
    if (ks)
      {
        d_scale = 1, d_offset = 1, v_scale = 1, speed_scale = 1;
        d_unit = v_unit = f_unit = t_unit = hz = speed_unit = "-";
      }
  }

  std::vector<std::pair<std::string, Table>> response_tables(const Response &r, const MeshModel &m,
                                                             const OutputUnits &u)
  {
    Table t;
    t.add_column("time", u.t_unit);
    t.add_column("mesh position", u.ks ? "rad" : "deg");
    t.add_column(u.ks ? "x" : "DTE", u.d_unit);
    t.add_column(u.ks ? "x rate" : "DTE rate", u.v_unit);
    t.add_column("mesh force", u.f_unit);
    t.add_column("contact state", "-");
    const bool angles = !u.ks && r.angle1.size() == r.t.size() && !r.t.empty();
    if (angles)
      {
        t.add_column("pinion vibration angle", "urad");
        t.add_column("gear vibration angle", "urad");
      }
    for (std::size_t i = 0; i < r.t.size(); ++i)
      {
        const double th = m.pinion_speed() * r.t[i];
        std::vector<double> row = {r.t[i], u.ks ? th : th / units::deg, r.delta[i] * u.d_scale + u.d_offset,
                                   r.rate[i] * u.v_scale, r.force[i], double(r.state[i])};
        if (angles)
          row.push_back(r.angle1[i] * 1e6), row.push_back(r.angle2[i] * 1e6);
        t.add_row(row);
      }
    Table p;
    p.add_column("mesh period", "-");
    p.add_column(u.ks ? "x" : "DTE", u.d_unit);
    p.add_column(u.ks ? "x rate" : "DTE rate", u.v_unit);
    for (std::size_t i = 0; i < r.poincare_delta.size(); ++i)
      p.add_row({double(i + 1), r.poincare_delta[i] * u.d_scale + u.d_offset, r.poincare_rate[i] * u.v_scale});
    const double dt     = r.t.size() > 1 ? r.t[1] - r.t[0] : 1.0;
    const Spectrum s    = amplitude_spectrum(r.delta, dt);
    Table f;
    f.add_column("frequency", u.hz);
    f.add_column("order", "-");
    f.add_column(u.ks ? "x amplitude" : "DTE amplitude", u.d_unit);
    for (std::size_t k = 0; k < s.frequency.size(); ++k)
      f.add_row({s.frequency[k], s.frequency[k] / r.mesh_frequency, s.amplitude[k] * u.d_scale});
    return {{"response", t}, {"poincare", p}, {"spectrum", f}};
  }

  Table sweep_table(const std::vector<SweepPoint> &pts, const OutputUnits &u)
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
                   u.ks ? r.mesh_frequency * 2 * pi : r.mesh_frequency, r.rms * u.d_scale, r.peak_to_peak * u.d_scale,
                   r.mean * u.d_scale + u.d_offset, r.dynamic_factor, r.contact_loss_fraction,
                   r.back_contact_fraction, double(r.period_multiplicity), double(r.settled),
                   double(r.out_of_range)});
      }
    return t;
  }

  CaseReport run_case(const DynamicsCase &c, const MeshModel &model, std::ostream *out)
  {
    const OutputUnits u(c.model == ModelKind::kahraman_singh);
    CaseReport report;
    std::ostringstream summary;
    summary << std::setprecision(8);
    if (c.run_response)
      {
        const auto [m, r] = response_at(c, model, 0.0);
        add(report, "", response_tables(r, *m, u));
        report.clamps += r.out_of_range;
        const double w = u.ks ? 2 * pi : 1.0; // KS: circular frequencies (Omega, 1)
        summary << (u.ks ? "Omega" : "mesh frequency") << " [" << u.hz << "] = " << r.mesh_frequency * w << "\n"
                << "linear natural frequency [" << u.hz << "] = " << m->linear_natural_frequency() * w << "\n"
                << "RMS DTE [" << u.d_unit << "] = " << r.rms * u.d_scale << "\n"
                << "peak-to-peak DTE [" << u.d_unit << "] = " << r.peak_to_peak * u.d_scale << "\n"
                << "dynamic factor K_v [-] = " << r.dynamic_factor << "\n"
                << "contact loss fraction [-] = " << r.contact_loss_fraction << "\n"
                << "back contact fraction [-] = " << r.back_contact_fraction << "\n"
                << "period [mesh periods] = " << r.period_multiplicity
                << (r.period_multiplicity == 0 ? " (not periodic within the run)" : "") << "\n"
                << "settled [-] = " << (r.settled ? "yes" : "no") << " after " << r.transient_periods
                << " periods\n";
        if (std::isfinite(r.angle_amplitude1))
          summary << "pinion angle amplitude [rad] = " << r.angle_amplitude1 << "\n"
                  << "gear angle amplitude [rad] = " << r.angle_amplitude2 << "\n";
        if (std::isfinite(r.energy_balance))
          summary << "energy balance (change of kinetic + elastic energy - torque work) / initial kinetic "
                     "energy [-] = "
                  << r.energy_balance << "\n";
        if (out)
          *out << summary.str();
      }
    for (std::size_t k = 0; k < c.portrait_speeds.size(); ++k)
      {
        // Phase portrait, Poincare section and spectrum at a chosen speed.
        const auto [m, r]      = response_at(c, model, c.portrait_speeds[k]);
        const std::string name = "portrait_" + std::to_string(k + 1);
        add(report, name + "_", response_tables(r, *m, u));
        report.clamps += r.out_of_range;
        summary << name << ": " << (u.ks ? "Omega" : "pinion speed") << " [" << u.speed_unit
                << "] = " << r.pinion_speed * u.speed_scale << ", RMS DTE [" << u.d_unit << "] = " << r.rms * u.d_scale
                << ", K_v [-] = " << r.dynamic_factor << ", contact loss fraction [-] = " << r.contact_loss_fraction
                << ", back contact fraction [-] = " << r.back_contact_fraction
                << ", period [mesh periods] = " << r.period_multiplicity << "\n";
        if (out)
          *out << name << " at " << r.pinion_speed * u.speed_scale << " " << u.speed_unit << ": RMS DTE "
               << r.rms * u.d_scale << " " << u.d_unit << ", contact loss fraction " << r.contact_loss_fraction
               << ", period " << r.period_multiplicity << "\n";
      }
    if (c.run_sweep)
      {
        const auto pts = sweep_up_down(model, c.integrator, c.response, c.sweep_min, c.sweep_max, c.sweep_points,
                                       out, c.threads);
        report.tables.emplace_back("sweep", sweep_table(pts, u));
        for (const auto &p : pts)
          report.clamps += p.response.out_of_range;
      }
    summary << "table clamps (evaluations outside the table) [-] = " << report.clamps << "\n";
    report.summary = summary.str();
    return report;
  }
} // namespace gearfem::dynamics
