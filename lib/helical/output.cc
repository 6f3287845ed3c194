// The tables of a helical run (helical/run.h): helical.csv, slices.csv, lines.csv, helical.json.
#include "base/atomic_file.h"
#include "base/units.h"
#include "helical/run.h"

#include <iomanip>

namespace gearfem::helical
{
  namespace
  {
    constexpr double MPa = 1e6;
  } // namespace

  void write_helical(const HelicalRun &run, const std::filesystem::path &dir, const std::string &input_name)
  {
    const auto &o = run.options;
    const double b = o.helix.face_width;
    write_atomically(dir / "helical.csv", [&](std::ostream &s) {
      s << "position,phi1_deg,torque_Nm,ste_um,k_mesh_N_per_um,k_tangent_N_per_um,k_h_beta,p_max_MPa,"
           "root_stress_pinion_MPa,root_stress_gear_MPa,n_pairs,unknowns,iterations,seconds\n";
      for (std::size_t i = 0; i < run.results.size(); ++i)
        {
          const auto &r = run.results[i];
          s << i % std::size_t(o.grid.size) << ',' << r.phi1 / units::deg << ',' << r.torque << ','
            << r.ste / units::um << ',' << r.k_mesh * units::um << ',' << r.k_tangent * units::um << ','
            << r.k_h_beta << ',' << r.p_max / MPa << ',' << r.root_stress_pinion / MPa << ','
            << r.root_stress_gear / MPa << ',' << r.n_pairs << ',' << r.candidates << ',' << r.iterations << ','
            << r.seconds << '\n';
        }
    });
    write_atomically(dir / "slices.csv", [&](std::ostream &s) {
      s << "position,torque_Nm,slice,z_mm,phi1_deg,force_N,load_N_per_mm,p_max_MPa,root_stress_pinion_MPa,"
           "root_stress_gear_MPa,lead_gap_um\n";
      for (std::size_t i = 0; i < run.results.size(); ++i)
        for (std::size_t k = 0; k < run.results[i].slices.size(); ++k)
          {
            const auto &r  = run.results[i];
            const auto &sl = r.slices[k];
            s << i % std::size_t(o.grid.size) << ',' << r.torque << ',' << k << ',' << sl.z / units::mm << ','
              << sl.phi1 / units::deg << ',' << sl.force << ',' << sl.load_per_width * units::mm << ','
              << sl.p_max / MPa << ',' << sl.root_stress_pinion / MPa << ',' << sl.root_stress_gear / MPa << ','
              << sl.lead_gap / units::um << '\n';
          }
    });
    write_atomically(dir / "lines.csv", [&](std::ostream &s) {
      s << "position,torque_Nm,pinion_tooth,gear_tooth,slice,z_mm,load_N_per_mm\n";
      for (std::size_t i = 0; i < run.results.size(); ++i)
        for (const auto &l : run.results[i].lines)
          for (std::size_t k = 0; k < l.load_per_width.size(); ++k)
            if (l.load_per_width[k] != 0)
              s << i % std::size_t(o.grid.size) << ',' << run.results[i].torque << ',' << l.pinion_tooth << ','
                << l.gear_tooth << ',' << k << ',' << run.results[i].slices[k].z / units::mm << ','
                << l.load_per_width[k] * units::mm << '\n';
    });
    write_atomically(dir / "helical.json", [&](std::ostream &s) {
      const auto &h = o.helix;
      s << "{\n  \"format\": \"gearfem-helical\", \"version\": 1, \"input\": \"" << input_name << "\",\n"
        << "  \"helix_angle_deg\": " << h.beta / units::deg << ", \"base_helix_angle_deg\": " << h.beta_b / units::deg
        << ", \"normal_module_mm\": " << h.m_n / units::mm << ", \"transverse_module_mm\": " << h.m_t / units::mm
        << ",\n  \"transverse_pressure_angle_deg\": " << h.alpha_t / units::deg
        << ", \"face_width_mm\": " << b / units::mm << ", \"axial_pitch_mm\": "
        << (std::isfinite(h.axial_pitch) ? h.axial_pitch / units::mm : 0.0) << ",\n  \"eps_alpha\": " << run.eps_alpha
        << ", \"eps_beta\": " << h.overlap_ratio << ", \"eps_gamma\": " << run.eps_gamma << ", \"slices\": " << o.slices
         << ", \"model\": \"" << (o.model == FaceModel::solid ? "3-D FE" : "slices") << "\""
        << ", \"face_setup_seconds\": " << o.face_seconds << ", \"face_dofs\": " << o.face_dofs
        << ", \"coupling\": \"" << (o.coupling == Coupling::shear ? "shear" : "bending") << "\""
        << ", \"coupling_length_mm\": " << o.coupling_length / units::mm << ", \"grid_positions\": " << o.grid.size
        << ",\n  \"mesh_misalignment_um\": " << o.lead.mesh_misalignment(o.alpha_wt) / units::um
        << ", \"crowning_um\": " << o.lead.crowning / units::um << ", \"setup_seconds\": " << run.setup_seconds
        << ", \"build_seconds\": " << run.build_seconds
        << ", \"sweep_seconds\": " << run.sweep_seconds << ", \"solved\": " << run.results.size()
        << ", \"failure\": \"" << (run.failure.empty() ? "" : "see the console") << "\",\n  \"torques\": [";
      for (std::size_t i = 0; i < run.summary.size(); ++i)
        {
          const auto &t = run.summary[i];
          s << (i ? ",\n" : "\n") << "    {\"torque_Nm\": " << t.torque << ", \"ste_mean_um\": " << t.ste_mean / units::um
            << ", \"ste_pp_um\": " << t.ste_pp / units::um << ", \"k_mean_N_per_um\": " << t.k_mean * units::um
            << ", \"c_gamma_N_per_mm_um\": " << t.c_gamma_iso() << ", \"k_h_beta\": " << t.k_h_beta
            << ", \"p_max_MPa\": " << t.p_max / MPa << ", \"root_stress_pinion_MPa\": " << t.root_stress_pinion / MPa
            << ", \"root_stress_gear_MPa\": " << t.root_stress_gear / MPa << "}";
        }
      s << "\n  ]\n}\n";
    });
  }
} // namespace gearfem::helical
