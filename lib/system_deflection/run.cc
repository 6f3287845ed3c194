#include "system_deflection/run.h"
#include "system_deflection/solid_face.h"
#include "system_deflection/tables.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/progress.h"
#include "base/units.h"
#include "analytical/iso6336_stiffness.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <memory>

namespace gearfem::system_deflection
{
  void complete(SystemInput &sys, const solve::GearContactInput &section, const helical::SlicingOptions &o)
  {
    const auto &pair = *section.pair;
    if (sys.system.shafts.size() != 2)
      throw InputError("System shafts", std::to_string(sys.system.shafts.size()), "a pinion shaft and a gear shaft");
    sys.system.shafts[0].x = sys.system.shafts[0].y = 0;
    sys.system.shafts[1].x = pair.center_distance(), sys.system.shafts[1].y = 0;
    auto &m          = sys.mesh;
    m.pinion_shaft   = 0, m.gear_shaft = 1;
    m.face_width     = o.helix.face_width;
    m.alpha_wt       = o.alpha_wt;
    m.pitch_radius_1 = pair.working_pitch_radius(1);
    // The axial force's sign by the hand (roll_per_length carries it) and the drive sense.
    m.beta_b = (o.helix.roll_per_length >= 0 ? 1.0 : -1.0) * m.drive_sense * o.helix.beta_b;
    m.validate(sys.system);
  }

  CoupledRun run_coupled(const solve::GearContactInput &section, const helical::SlicingOptions &o,
                         helical::RunOptions ro, SystemInput sys)
  {
    complete(sys, section, o);
    CoupledRun run;
    run.system = sys.system, run.mesh = sys.mesh;
    std::unique_ptr<CoupledPair> pair;
    helical::LeadModification lead = o.lead;
    std::vector<double> warm; // the previous position's mismatch
    double last_torque = -1;
    ro.position = [&](const helical::SlicedPair &sliced, double phi1, double torque) {
      if (!pair)
        {
          pair = std::make_unique<CoupledPair>(sliced, sys.system, sys.mesh, sys.options);
          if (sys.correction_torque > 0)
            {
              const auto t0  = std::chrono::steady_clock::now();
              const auto all = o.grid.positions();
              std::vector<double> phis;
              const int n = std::max(1, std::min(sys.correction_positions, int(all.size())));
              for (int k = 0; k < n; ++k)
                phis.push_back(all[std::size_t(k * int(all.size()) / n)].second);
              if (ro.out)
                *ro.out << "lead correction at " << sys.correction_torque << " N m over " << n << " positions\n";
              run.design    = design_correction(*pair, phis, sys.correction_torque, o.lead);
              run.corrected = true;
              lead          = pair->corrected(o.lead, run.design.correction);
              run.design_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
              if (ro.out)
                *ro.out << std::setprecision(4) << "lead correction: slope " << run.design.correction.slope / units::um
                        << " um, crowning " << run.design.correction.crowning / units::um << " um ("
                        << run.design.iterations << " corrections, " << run.design_seconds << " s)\n";
            }
        }
      // The shafts are linear and the mismatch follows the load: a new torque starts from the
      // last one's mismatch scaled to it.
      if (torque != last_torque)
        {
          for (auto &g : warm)
            g *= torque / last_torque;
          last_torque = torque;
        }
      run.coupled.push_back(pair->solve(phi1, torque, lead, warm));
      warm = run.coupled.back().mismatch;
      return run.coupled.back().helical;
    };
    run.helical = helical::run_helical(section, o, ro);
    // Per torque: the shafts under the cycle's mean slice forces (the shafts are linear).
    if (pair)
      for (const double T : run.helical.torques)
        {
          int n = 0;
          const CoupledResult mean = mean_at(run.coupled, T, n);
          if (n > 0)
            run.shafts.push_back({T, pair->shafts_under(mean)});
        }
    run.iso = method_c(section, o, run.coupled, run.helical.summary, run.corrected ? &run.design.correction : nullptr);
    return run;
  }

  CoupledRun run_job(const solve::GearContactInput &section, const helical::SlicingOptions &o, helical::RunOptions ro,
                     const SystemInput &sys)
  {
    // The 3-D face, when asked, joins the slices on either route.
    const helical::SlicingOptions so = o.model == helical::FaceModel::solid && !o.face ? with_solid_face(section, o, ro.out) : o;
    if (sys.coupled)
      return run_coupled(section, so, std::move(ro), sys);
    CoupledRun run;
    run.helical = helical::run_helical(section, so, ro);
    return run;
  }

  void write_job(const CoupledRun &run, bool coupled, const std::filesystem::path &dir, const std::string &input_name)
  {
    if (coupled)
      write_coupled(run, dir, input_name);
    else
      helical::write_helical(run.helical, dir, input_name);
  }

  std::vector<MethodC> method_c(const solve::GearContactInput &section, const helical::SlicingOptions &o,
                                const std::vector<CoupledResult> &coupled,
                                const std::vector<helical::TorqueSummary> &summary, const LeadCorrection *correction)
  {
    const auto &pair = *section.pair;
    const auto &h    = o.helix;
    const double b   = h.face_width;
    // Method B in the normal section: the section's transverse shift and dedendum scaled back.
    analytical::iso6336::StiffnessInput si;
    si.z1 = pair.gear(1).teeth(), si.z2 = pair.gear(2).teeth();
    const double to_n = h.m_t / h.m_n;
    si.x1 = pair.gear(1).parameters().profile_shift * to_n, si.x2 = pair.gear(2).parameters().profile_shift * to_n;
    si.h_fP1 = pair.gear(1).parameters().rack.dedendum * to_n, si.h_fP2 = pair.gear(2).parameters().rack.dedendum * to_n;
    si.beta = h.beta, si.alpha_n = h.alpha_n, si.module = h.m_n;
    si.eps_alpha = pair.contact_ratio(), si.eps_beta = h.overlap_ratio;
    std::vector<MethodC> out;
    for (const auto &t : summary)
      {
        MethodC m;
        m.torque           = t.torque;
        m.k_h_beta_coupled = t.k_h_beta;
        for (const auto &c : coupled)
          if (c.helical.torque == t.torque)
            {
              double lo = 1e300, hi = -1e300;
              for (std::size_t k = 0; k < c.mismatch.size(); ++k)
                {
                  const double g = c.mismatch[k] + (correction ? correction->at(c.z[k], b) : 0.0);
                  lo = std::min(lo, g), hi = std::max(hi, g);
                }
              m.f_beta_y = std::max(m.f_beta_y, hi - lo);
            }
        const double Ft = t.torque / (0.5 * pair.gear(1).teeth() * h.m_t);
        m.line_load     = Ft / b * 1e-3;
        si.load_per_width = Ft / b;
        try
          {
            m.c_gamma_beta = analytical::iso6336::mesh_stiffness(si).c_gamma_beta;
            m.k_h_beta     = analytical::iso6336::face_load_factor_method_c(m.f_beta_y / units::um, m.c_gamma_beta,
                                                                            m.line_load);
          }
        catch (const InputError &)
          {
            m.c_gamma_beta = m.k_h_beta = 0;
          }
        out.push_back(m);
      }
    return out;
  }

  CoupledResult mean_at(const std::vector<CoupledResult> &results, double torque, int &n)
  {
    CoupledResult mean;
    n = 0;
    for (const auto &c : results)
      if (c.helical.torque == torque)
        {
          if (n++ == 0)
            mean = c;
          else
            for (std::size_t k = 0; k < c.helical.slices.size(); ++k)
              mean.helical.slices[k].force += c.helical.slices[k].force;
        }
    for (auto &s : mean.helical.slices)
      s.force /= std::max(n, 1);
    return mean;
  }

  void write_shaft_tables(const std::vector<MeshTables> &meshes, const std::vector<TorqueShafts> &shafts,
                          const shafts::System &system, const std::filesystem::path &dir)
  {
    const bool staged = !meshes.empty() && meshes.front().stage > 0;
    const std::string col = staged ? "stage," : "";
    const auto stage = [&](const MeshTables &m) { return staged ? std::to_string(m.stage) + "," : std::string(); };
    write_atomically(dir / "coupling.csv", [&](std::ostream &s) {
      s << col << "position,torque_Nm,k_h_beta,iterations,residual_um,mean_approach_um,mismatch_max_um,"
                  "centre_distance_change_um,f_sigma_delta_um,f_sigma_beta_um\n";
      for (const auto &m : meshes)
        for (std::size_t i = 0; i < m.coupled->size(); ++i)
          {
            const auto &c = (*m.coupled)[i];
            double g = 0;
            for (const double v : c.mismatch)
              g = std::max(g, v);
            const auto span = [](const std::vector<double> &v) {
              return v.empty() ? 0.0 : v.back() - v.front(); // over the slice centres, signed
            };
            double a = 0;
            for (const double v : c.axes_e)
              a += v / double(c.axes_e.size());
            s << stage(m) << i % m.grid << ',' << c.helical.torque << ',' << c.helical.k_h_beta << ',' << c.iterations
              << ',' << c.residual / units::um << ',' << c.mean_approach / units::um << ',' << g / units::um << ','
              << a / units::um << ',' << span(c.axes_e) / units::um << ',' << span(c.axes_t) / units::um << '\n';
          }
    });
    write_atomically(dir / "misalignment.csv", [&](std::ostream &s) {
      s << col << "position,torque_Nm,slice,z_mm,force_N,approach_um,mismatch_um,axes_e_um,axes_t_um\n";
      for (const auto &m : meshes)
        for (std::size_t i = 0; i < m.coupled->size(); ++i)
          {
            const auto &c = (*m.coupled)[i];
            for (std::size_t k = 0; k < c.z.size(); ++k)
              s << stage(m) << i % m.grid << ',' << c.helical.torque << ',' << k << ',' << c.z[k] / units::mm << ','
                << c.helical.slices[k].force << ',' << c.approach[k] / units::um << ',' << c.mismatch[k] / units::um
                << ',' << c.axes_e[k] / units::um << ',' << c.axes_t[k] / units::um << '\n';
          }
    });
    write_atomically(dir / "shafts.csv", [&](std::ostream &s) {
      s << "torque_Nm,shaft,z_mm,u_x_um,u_y_um,u_z_um,theta_x_mrad,theta_y_mrad,theta_z_mrad\n";
      for (const auto &t : shafts)
        for (const auto &n : t.solution.nodes)
          s << t.torque << ',' << n.shaft << ',' << n.z / units::mm << ',' << n.u[0] / units::um << ','
            << n.u[1] / units::um << ',' << n.u[2] / units::um << ',' << n.u[3] * 1e3 << ',' << n.u[4] * 1e3 << ','
            << n.u[5] * 1e3 << '\n';
    });
    write_atomically(dir / "bearings.csv", [&](std::ostream &s) {
      s << "torque_Nm,bearing,shaft,z_mm,F_x_N,F_y_N,F_z_N,M_x_Nm,M_y_Nm,M_z_Nm\n";
      for (const auto &t : shafts)
        for (std::size_t i = 0; i < t.solution.reactions.size(); ++i)
          {
            const auto &r = t.solution.reactions[i];
            const auto &b = system.bearings[i];
            s << t.torque << ',' << r.name << ',' << b.shaft << ',' << b.z / units::mm << ',' << r.force.x() << ','
              << r.force.y() << ',' << r.force.z() << ',' << r.moment.x() << ',' << r.moment.y() << ','
              << r.moment.z() << '\n';
          }
    });
  }

  void write_method_c(std::ostream &s, const std::vector<MethodC> &iso)
  {
    for (std::size_t i = 0; i < iso.size(); ++i)
      {
        const auto &m = iso[i];
        s << (i ? ", " : "") << "{\"torque_Nm\": " << m.torque << ", \"k_h_beta\": " << m.k_h_beta_coupled
          << ", \"f_beta_y_um\": " << m.f_beta_y / units::um << ", \"line_load_N_per_mm\": " << m.line_load
          << ", \"c_gamma_beta_iso\": " << m.c_gamma_beta << ", \"k_h_beta_iso_method_c\": " << m.k_h_beta << "}";
      }
  }

  void write_coupled(const CoupledRun &run, const std::filesystem::path &dir, const std::string &input_name)
  {
    helical::write_helical(run.helical, dir, input_name);
    write_shaft_tables({MeshTables{0, std::size_t(run.helical.options.grid.size), &run.coupled}}, run.shafts, run.system,
                       dir);
    write_atomically(dir / "system.json", [&](std::ostream &s) {
      const auto &m = run.mesh;
      s << "{\n  \"input\": \"" << input_name << "\",\n  \"centre_distance_mm\": " << run.system.shafts[1].x / units::mm
        << ",\n  \"pinion_face_start_mm\": " << m.pinion_face_start / units::mm
        << ", \"gear_face_start_mm\": " << m.gear_face_start / units::mm
        << ", \"pitch_radius_1_mm\": " << m.pitch_radius_1 / units::mm << ", \"drive_sense\": " << m.drive_sense
        << ",\n  \"face_width_mm\": " << m.face_width / units::mm << ", \"alpha_wt_deg\": " << m.alpha_wt / units::deg
        << ", \"beta_b_deg\": " << m.beta_b / units::deg
        << ",\n  \"corrected\": " << (run.corrected ? "true" : "false");
      if (run.corrected)
        s << ", \"correction_slope_um\": " << run.design.correction.slope / units::um
          << ", \"correction_crowning_um\": " << run.design.correction.crowning / units::um
          << ", \"correction_iterations\": " << run.design.iterations
          << ", \"correction_seconds\": " << run.design_seconds;
      s << ",\n  \"sweep_seconds\": " << run.helical.sweep_seconds << ",\n  \"torques\": [";
      write_method_c(s, run.iso);
      s << "]\n}\n";
    });
  }
} // namespace gearfem::system_deflection
