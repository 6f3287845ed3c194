#include "dynamics/case.h"
#include "dynamics/law_factory.h"
#include "dynamics/tooth_mass.h"
#include "geometry/limits.h"
#include "base/units.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gearfem::dynamics
{
  namespace limits = geometry::limits;

  namespace
  {
    std::string fmt(const std::string &name, double v, const std::string &unit)
    {
      std::ostringstream s;
      s.precision(6);
      s << name << " = " << v << (unit.empty() ? "" : " " + unit);
      return s.str();
    }
  } // namespace

  void DynamicsCase::check() const
  {
    integrator.check();
    response.check();
    // A speed sweep starts each speed from the previous one's state and records a steady
    // state: without damping the free vibration is carried from speed to speed and never
    // decays (near the parametric resonance it grows without bound), so a sweep needs
    // zeta > 0; a single time response may be undamped.
    const bool ks            = model == ModelKind::kahraman_singh;
    const double z           = ks ? ks_zeta : zeta;
    const std::string z_name = ks ? "Dynamics/Kahraman-Singh/Damping ratio" : "Dynamics/Operating/Damping ratio";
    if (!(z >= 0 && z <= 1))
      throw InputError(z_name, to_string_g(z), "[0, 1]");
    if (run_sweep && !(z > 0))
      throw InputError(z_name, to_string_g(z), "> 0 with a speed sweep (Dynamics/Analysis = sweep or both)",
                       "an undamped sweep carries free vibration from speed to speed and never settles");
    if (run_sweep && !(sweep_min < sweep_max))
      {
        // Report in the units of the input: rpm, or Omega [-] in the Kahraman-Singh mode.
        const bool ks = model == ModelKind::kahraman_singh;
        const double f = ks ? 1.0 : 30.0 / units::pi;
        const std::string u = ks ? "" : " rpm";
        throw InputError("Dynamics/Analysis/Sweep minimum speed",
                         to_string_g(sweep_min * f) + u + " (maximum " + to_string_g(sweep_max * f) + u + ")",
                         "< Sweep maximum speed");
      }
    if (run_sweep)
      require_range("Dynamics/Analysis/Number of speeds", sweep_points, 2, 100000);
    require_range("Dynamics/Analysis/Threads", threads, 1, 1024);
    if (model != ModelKind::kahraman_singh)
      {
        require_greater("Dynamics/Operating/Pinion speed", speed, 0.0, "rad/s");
        limits::check_teeth("Dynamics/Pair/Pinion teeth", z1);
        limits::check_teeth("Dynamics/Pair/Gear teeth", z2);
        limits::check_module("Dynamics/Pair/Module", module);
        limits::check_pressure_angle("Dynamics/Pair/Pressure angle", alpha);
        limits::check_addendum("Dynamics/Pair/Addendum coefficient", addendum);
        limits::check_face_width("Dynamics/Pair/Face width", face_width);
        require_greater("Dynamics/Mesh force/Single-pair stiffness", single_pair_stiffness, 0.0);
        require_greater("Dynamics/Mesh force/Double-pair factor", double_pair_factor, 0.0);
        // Every law but a mesh table's (whose torque range bounds it, checked with the table):
        // the small-strain bound of the contact models at the pitch point of the standard pair
        // (plane strain, one material). A torque beyond it is no longer a gear mesh of this pair
        // (and 2^31 N m took the integrator into an unbounded run).
        if (!(law == LawKind::external && external_source == ExternalSource::table_file))
        {
          limits::check_youngs_modulus("Dynamics/Pair/Young modulus", youngs_modulus);
          const double r1 = 0.5 * module * z1, r2 = 0.5 * module * z2;
          const double Es = youngs_modulus / (2 * (1 - poisson_ratio * poisson_ratio));
          limits::check_small_strain("Dynamics/Operating/Input torque", input_torque, r1 * std::cos(alpha),
                                     face_width, Es, (1 / r1 + 1 / r2) / std::sin(alpha));
        }
        if (law == LawKind::ste && ste_theta.size() < 2)
          throw InputError("Dynamics/Mesh force/STE file", "(empty)",
                           "a CSV with >= 2 rows: position [deg], STE [um]");
      }
    else
      require_greater("Dynamics/Kahraman-Singh/Frequency", ks_frequency, 0.0);
  }

  PairData DynamicsCase::pair() const
  {
    return standard_pair(z1, z2, module, alpha, addendum, thickness1, thickness2, delta_a);
  }

  std::unique_ptr<MeshModel> build_model(const DynamicsCase &c, std::vector<std::string> *notes)
  {
    c.check();
    auto note = [&](const std::string &s) {
      if (notes)
        notes->push_back(s);
    };
    if (c.model == ModelKind::kahraman_singh)
      {
        ContactLogic contact;
        contact.backlash = 2.0; // dead zone of half-width 1
        DteModel::Parameters p;
        p.mass = 1.0, p.static_force = c.ks_force, p.speed = c.ks_frequency, p.zeta = c.ks_zeta;
        p.damping_only_in_contact = c.damping_only_in_contact;
        note("Kahraman-Singh dimensionless model: kbar = 1, m = 1, backlash 2 (x = delta + 1)");
        return std::make_unique<DteModel>(
          std::make_unique<FourierStiffnessLaw>(1.0, 1, c.ks_cos), contact, p);
      }

    const PairData pair = c.pair();
    const double eps = pair.contact_ratio;
    const double ks = c.single_pair_stiffness * c.face_width;
    std::unique_ptr<MeshForceLaw> law;
    const double kmean_iso = ks * (0.75 * eps + 0.25); // ISO 6336-1 c_gamma_alpha b
    switch (c.law)
      {
        case LawKind::piecewise_constant:
          law = std::make_unique<PiecewiseConstantLaw>(ks, c.double_pair_factor * ks, c.z1, eps,
                                                       pair.theta_A);
          break;
        case LawKind::fourier:
          law = std::make_unique<FourierStiffnessLaw>(kmean_iso, c.z1, c.fourier_cos, c.fourier_sin);
          break;
        case LawKind::ste:
          law = std::make_unique<SteExcitationLaw>(c.ste_stiffness > 0 ? c.ste_stiffness : kmean_iso,
                                                   c.ste_theta, c.ste_values,
                                                   2 * units::pi / c.z1);
          break;
        case LawKind::external:
          if (!c.external_law)
            throw InputError("Dynamics/Mesh force/Law", "external", "a law provided by the caller");
          law = c.external_law->clone();
          break;
      }
    ContactLogic contact;
    contact.backlash = c.backlash >= 0 ? c.backlash : pair.backlash;
    contact.reverse_mapping = c.reverse_mapping;
    contact.reverse_offset = pair.thickness_angle1;
    if (law->has_reverse_branch())
      {
        // A two-sided table carries its own clearance and reverse flank.
        if (c.backlash >= 0 && std::abs(c.backlash - law->backlash()) > 1e-9)
          throw InputError("Dynamics/Pair/Backlash", to_string_g(c.backlash * 1e6) + " um",
                           "< 0 (from the table) or the table's " + to_string_g(law->backlash() * 1e6) + " um",
                           "the mesh table is two-sided: its backlash and reverse flank are part of it");
        contact.backlash = law->backlash();
        note("backlash and reverse flank from the two-sided mesh table");
      }

    const double r1 = c.module * c.z1 / 2, r2 = c.module * c.z2 / 2;
    auto cylinder = [&](double r) { return 0.5 * units::pi * c.density * c.face_width * std::pow(r, 4); };
    double J1 = c.inertia1 > 0 ? c.inertia1 : cylinder(r1);
    double J2 = c.inertia2 > 0 ? c.inertia2 : cylinder(r2);
    note(fmt("contact ratio", eps, ""));
    note(fmt("backlash", contact.backlash * 1e6, "um"));
    note(fmt("base radii r_b1", pair.r_b1 * 1e3, "mm") + ", " + fmt("r_b2", pair.r_b2 * 1e3, "mm"));
    note(fmt("start of contact theta_A", pair.theta_A / units::deg, "deg"));
    note(fmt("inertias J1", J1, "kg m^2") + ", " + fmt("J2", J2, "kg m^2"));
    std::shared_ptr<const PeriodicInertia> Jt1_theta, Jt2_theta;
    if (c.tooth_mass)
      {
        // The NTUA tooth-mass thesis (eqs. 3.1-3.6) on the generated pair: m_eq along the
        // path with the Weber/Cornell foundation share, J_t(theta) = sum m_eq r^2.
        const ToothInertiaCurves tc =
          tooth_inertia_curves(generated_pair(c), analytical::Material{c.youngs_modulus, c.poisson_ratio},
                               c.density,
                               c.tooth_mass_energy_weighting ? ToothMassWeighting::kinetic_energy :
                                                               ToothMassWeighting::thesis_linear);
        note(fmt("tooth inertia J_tooth1", tc.mean1, "kg m^2") + ", " + fmt("J_tooth2", tc.mean2, "kg m^2") +
             " (mean over a mesh period; " + to_string_g(100 * tc.mean1 / J1) + " % of J1, " +
             to_string_g(100 * tc.mean2 / J2) + " % of J2; " +
             (c.tooth_mass_energy_weighting ? "(delta/delta0)^2" : "(delta/delta0), the thesis") +
             " weighting)");
        if (c.tooth_inertia_position_dependent)
          {
            if (c.model != ModelKind::torsional)
              throw InputError("Dynamics/Operating/Tooth inertia", "position dependent",
                               "constant with Dynamics/Model = DTE (the 1-DOF model has no gear angles)");
            Jt1_theta = std::make_shared<PeriodicInertia>(tc.theta_A, tc.period, tc.J1);
            Jt2_theta = std::make_shared<PeriodicInertia>(tc.theta_A, tc.period, tc.J2);
            const auto [lo1, hi1] = std::minmax_element(tc.J1.begin(), tc.J1.end());
            const auto [lo2, hi2] = std::minmax_element(tc.J2.begin(), tc.J2.end());
            note("tooth inertia J_t(theta) in the equations of motion: J_tooth1 " + to_string_g(*lo1) + " .. " +
                 to_string_g(*hi1) + " kg m^2, J_tooth2 " + to_string_g(*lo2) + " .. " + to_string_g(*hi2) +
                 " kg m^2");
          }
        else
          J1 += tc.mean1, J2 += tc.mean2;
      }
    note(fmt("mean mesh stiffness per face width", law->mean_stiffness() / c.face_width / 1e9,
             "N/(mm um)"));

    if (c.model == ModelKind::dte)
      {
        DteModel::Parameters p;
        p.mass = J1 * J2 / (J2 * pair.r_b1 * pair.r_b1 + J1 * pair.r_b2 * pair.r_b2);
        p.static_force = c.input_torque / pair.r_b1;
        p.speed = c.speed;
        p.zeta = c.zeta;
        p.damping_only_in_contact = c.damping_only_in_contact;
        auto m = std::make_unique<DteModel>(std::move(law), contact, p);
        note(fmt("equivalent mass", m->equivalent_mass(), "kg"));
        note(fmt("linear natural frequency", m->linear_natural_frequency(), "Hz"));
        return m;
      }
    TorsionalModel::Parameters p;
    p.inertia1 = J1, p.inertia2 = J2;
    p.base_radius1 = pair.r_b1, p.base_radius2 = pair.r_b2;
    p.input_torque = c.input_torque, p.output_torque = c.output_torque;
    p.ramp_time = c.ramp_time, p.speed = c.speed, p.speed_source = c.speed_source;
    p.zeta = c.zeta, p.damping_only_in_contact = c.damping_only_in_contact;
    p.start_at_rest_deflection = c.start_at_rest_deflection;
    p.tooth_inertia1 = Jt1_theta, p.tooth_inertia2 = Jt2_theta;
    auto m = std::make_unique<TorsionalModel>(std::move(law), contact, p);
    note(fmt("equivalent mass", m->equivalent_mass(), "kg"));
    note(fmt("linear natural frequency", m->linear_natural_frequency(), "Hz"));
    return m;
  }
} // namespace gearfem::dynamics
