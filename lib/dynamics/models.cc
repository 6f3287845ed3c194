#include "dynamics/models.h"
#include "base/units.h"

#include "base/errors.h"

#include <cmath>
#include <limits>

namespace gearfem::dynamics
{
  // ---------------------------------------------------------------- MeshModel
  MeshModel::MeshModel(std::unique_ptr<MeshForceLaw> law, const ContactLogic &contact,
                       double zeta, bool damping_only_in_contact)
    : law_(std::move(law))
    , contact_(contact)
    , breaks_(law_->breaks())
    , zeta_(zeta)
    , damp_only_contact_(damping_only_in_contact)
  {
    if (!(zeta >= 0))
      throw InputError("Dynamics/Damping ratio", to_string_g(zeta), ">= 0");
    if (!(contact.backlash >= 0))
      throw InputError("Dynamics/Backlash", to_string_g(contact.backlash), ">= 0");
  }

  MeshModel::MeshModel(const MeshModel &o)
    : HybridSystem(o)
    , law_(o.law_->clone())
    , contact_(o.contact_)
    , breaks_(o.breaks_)
    , zeta_(o.zeta_)
    , c_(o.c_)
    , damp_only_contact_(o.damp_only_contact_)
    , mode_(o.mode_)
  {}

  void MeshModel::update_damping()
  {
    c_ = 2.0 * zeta_ * std::sqrt(law_->mean_stiffness() * equivalent_mass());
  }

  double MeshModel::linear_natural_frequency() const
  {
    return std::sqrt(law_->mean_stiffness() / equivalent_mass()) / (2.0 * units::pi);
  }

  MeshMode MeshModel::classify(double theta, double delta) const
  {
    MeshMode m;
    m.s = contact_.state(delta);
    if (m.s != 0 && !breaks_.empty())
      m.zone = locate_zone(breaks_, law_->period(),
                           m.s == 1 ? theta : contact_.coast_theta(theta));
    return m;
  }

  double MeshModel::elastic_force(double theta, double delta, const MeshMode &m) const
  {
    if (m.s == 1)
      return law_->force(theta, delta, m.zone.zone);
    if (m.s == -1)
      return law_->has_reverse_branch() ?
               -law_->reverse_force(theta, -delta - contact_.backlash) :
               -law_->force(contact_.coast_theta(theta), -delta - contact_.backlash, m.zone.zone);
    return 0.0;
  }

  double MeshModel::frozen_force(double theta, double delta, double rate) const
  {
    double f = elastic_force(theta, delta, mode_);
    if (mode_.s != 0 || !damp_only_contact_)
      f += c_ * rate;
    return f;
  }

  double MeshModel::mesh_force(double t, const State &x) const
  {
    const double th = mesh_position(t, x), d = compression(t, x);
    const MeshMode m = classify(th, d);
    double f = elastic_force(th, d, m);
    if (m.s != 0 || !damp_only_contact_)
      f += c_ * compression_rate(t, x);
    return f;
  }

  double MeshModel::elastic_energy(double t, const State &x) const
  {
    const double th = mesh_position(t, x), d = compression(t, x);
    const MeshMode m = classify(th, d);
    if (m.s == 0)
      return 0.0;
    // Compression of the active flank c and the force along it, F(c); V = int_0^c F dc'.
    const double c = m.s == 1 ? d : -d - contact_.backlash;
    static const double xg[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                 0.9602898564975363};
    static const double wg[4] = {0.3626837833783620, 0.3137066053877759, 0.2223810344533745,
                                 0.1012285362903763};
    double V = 0;
    for (int k = 0; k < 4; ++k)
      for (const double sgn : {-1.0, 1.0})
        {
          const double ck = 0.5 * c * (1 + sgn * xg[k]);
          const double dk = m.s == 1 ? ck : -ck - contact_.backlash;
          V += wg[k] * std::abs(elastic_force(th, dk, m));
        }
    return 0.5 * c * V;
  }

  int MeshModel::contact_state(double t, const State &x) const
  {
    return contact_.state(compression(t, x));
  }

  void MeshModel::switching_functions(double t, const State &x, double *g) const
  {
    const double d = compression(t, x);
    g[0] = d;
    g[1] = std::isfinite(contact_.backlash) ? d + contact_.backlash : 1.0;
    if (mode_.s == 0 || breaks_.empty())
      {
        g[2] = g[3] = 1.0;
        return;
      }
    const double th = mesh_position(t, x);
    const double te = mode_.s == 1 ? th : contact_.coast_theta(th);
    g[2] = te - mode_.zone.next;
    g[3] = te - mode_.zone.prev;
  }

  bool MeshModel::update_mode(double t, const State &x)
  {
    const MeshMode m = classify(mesh_position(t, x), compression(t, x));
    const bool changed = m.s != mode_.s || m.zone.zone != mode_.zone.zone ||
                         m.zone.next != mode_.zone.next;
    mode_ = m;
    return changed;
  }

  // ---------------------------------------------------------------- DteModel
  DteModel::DteModel(std::unique_ptr<MeshForceLaw> law, const ContactLogic &contact,
                     const Parameters &p)
    : MeshModel(std::move(law), contact, p.zeta, p.damping_only_in_contact)
    , p_(p)
  {
    require_greater("Dynamics/Equivalent mass", p.mass, 0.0, "kg");
    require_greater("Dynamics/Pinion speed", p.speed, 0.0, "rad/s");
    update_damping();
    update_mode(0.0, initial_state());
  }

  void DteModel::operator()(const State &x, State &dxdt, double t) const
  {
    const double th = p_.speed * t + p_.theta0;
    double f = p_.static_force - frozen_force(th, x[0], x[1]);
    if (p_.external_force)
      f += p_.external_force(t);
    dxdt.resize(2);
    dxdt[0] = x[1];
    dxdt[1] = f / p_.mass;
  }

  void DteModel::set_pinion_speed(double w)
  {
    require_greater("Dynamics/Pinion speed", w, 0.0, "rad/s");
    p_.speed = w;
  }

  State DteModel::initial_state() const
  {
    State x(2);
    x << p_.static_force / law_->mean_stiffness(), 0.0;
    return x;
  }

  State DteModel::continue_at_speed(double, const State &x, double speed)
  {
    set_pinion_speed(speed);
    update_mode(0.0, x);
    return x;
  }

  // ---------------------------------------------------------------- TorsionalModel
  TorsionalModel::TorsionalModel(std::unique_ptr<MeshForceLaw> law, const ContactLogic &contact,
                                 const Parameters &p)
    : MeshModel(std::move(law), contact, p.zeta, p.damping_only_in_contact)
    , p_(p)
  {
    require_greater("Dynamics/Inertia 1", p.inertia1, 0.0, "kg m^2");
    require_greater("Dynamics/Inertia 2", p.inertia2, 0.0, "kg m^2");
    require_greater("Dynamics/Base radius 1", p.base_radius1, 0.0, "m");
    require_greater("Dynamics/Base radius 2", p.base_radius2, 0.0, "m");
    require_greater("Dynamics/Pinion speed", p.speed, 0.0, "rad/s");
    if (p.ramp_time < 0)
      throw InputError("Dynamics/Torque ramp time", to_string_g(p.ramp_time), ">= 0 s");
    update_damping();
    update_mode(0.0, initial_state());
  }

  double TorsionalModel::output_torque() const
  {
    return p_.output_torque < 0 ? p_.input_torque * p_.base_radius2 / p_.base_radius1 :
                                  p_.output_torque;
  }

  double TorsionalModel::ramp(double t) const
  {
    return p_.ramp_time > 0 ? std::min(1.0, t / p_.ramp_time) : 1.0;
  }

  double TorsionalModel::mean_inertia(int i) const
  {
    const auto &Jt = i == 1 ? p_.tooth_inertia1 : p_.tooth_inertia2;
    return (i == 1 ? p_.inertia1 : p_.inertia2) + (Jt ? Jt->mean() : 0.0);
  }

  double TorsionalModel::inertia(int i, const State &x, double *derivative) const
  {
    const auto &Jt = i == 1 ? p_.tooth_inertia1 : p_.tooth_inertia2;
    const double J0 = i == 1 ? p_.inertia1 : p_.inertia2;
    if (derivative)
      *derivative = 0.0;
    if (!Jt || (i == 1 && p_.speed_source))
      return J0;
    // Each gear's own angle as a mesh position: theta_1 = th1, theta_2 = (r_b2/r_b1) th2.
    const double q = i == 1 ? 1.0 : p_.base_radius2 / p_.base_radius1;
    const double th = q * x[i == 1 || p_.speed_source ? 0 : 2];
    if (derivative)
      *derivative = q * Jt->derivative(th);
    return J0 + Jt->value(th);
  }

  std::vector<double> TorsionalModel::angle_deviations(double t, const State &x) const
  {
    const double w2 = p_.speed * p_.base_radius1 / p_.base_radius2;
    if (p_.speed_source)
      return {0.0, x[0] - w2 * t};
    return {x[0] - p_.speed * t, x[2] - w2 * t};
  }

  bool TorsionalModel::conservative() const
  {
    return zeta_ == 0.0 && p_.ramp_time == 0.0 && !p_.speed_source && law_->position_independent() &&
           p_.inertia_velocity_terms;
  }

  double TorsionalModel::kinetic_energy(double, const State &x) const
  {
    if (p_.speed_source)
      return 0.5 * inertia(2, x) * x[1] * x[1];
    return 0.5 * inertia(1, x) * x[1] * x[1] + 0.5 * inertia(2, x) * x[3] * x[3];
  }

  double TorsionalModel::torque_work(const State &x0, const State &x) const
  {
    if (p_.speed_source)
      return 0.0;
    return p_.input_torque * (x[0] - x0[0]) - output_torque() * (x[2] - x0[2]);
  }

  double TorsionalModel::equivalent_mass() const
  {
    const double r1 = p_.base_radius1, r2 = p_.base_radius2, I1 = mean_inertia(1), I2 = mean_inertia(2);
    if (p_.speed_source)
      return I2 / (r2 * r2);
    return I1 * I2 / (I2 * r1 * r1 + I1 * r2 * r2);
  }

  double TorsionalModel::mesh_position(double t, const State &x) const
  {
    return p_.speed_source ? p_.speed * t : x[0];
  }

  double TorsionalModel::compression(double t, const State &x) const
  {
    return p_.speed_source ? p_.base_radius1 * p_.speed * t - p_.base_radius2 * x[0] :
                             p_.base_radius1 * x[0] - p_.base_radius2 * x[2];
  }

  double TorsionalModel::compression_rate(double, const State &x) const
  {
    return p_.speed_source ? p_.base_radius1 * p_.speed - p_.base_radius2 * x[1] :
                             p_.base_radius1 * x[1] - p_.base_radius2 * x[3];
  }

  void TorsionalModel::operator()(const State &x, State &dxdt, double t) const
  {
    const double r = ramp(t);
    const double F =
      frozen_force(mesh_position(t, x), compression(t, x), compression_rate(t, x));
    dxdt.resize(x.size());
    // J_i th_i'' + 1/2 J_i'(th_i) th_i'^2 = torque_i (Lagrange, T = 1/2 sum J_i th_i'^2).
    const double v = p_.inertia_velocity_terms ? 0.5 : 0.0;
    double dJ2;
    const double J2 = inertia(2, x, &dJ2);
    if (p_.speed_source)
      {
        dxdt[0] = x[1];
        dxdt[1] = (p_.base_radius2 * F - output_torque() * r - v * dJ2 * x[1] * x[1]) / J2;
        return;
      }
    double dJ1;
    const double J1 = inertia(1, x, &dJ1);
    dxdt[0] = x[1];
    dxdt[1] = (p_.input_torque * r - p_.base_radius1 * F - v * dJ1 * x[1] * x[1]) / J1;
    dxdt[2] = x[3];
    dxdt[3] = (p_.base_radius2 * F - output_torque() * r - v * dJ2 * x[3] * x[3]) / J2;
  }

  void TorsionalModel::set_pinion_speed(double w)
  {
    require_greater("Dynamics/Pinion speed", w, 0.0, "rad/s");
    p_.speed = w;
  }

  State TorsionalModel::continue_at_speed(double t, const State &x, double speed)
  {
    const double d = compression(t, x), dr = compression_rate(t, x);
    const double th = mesh_position(t, x);
    const double th0 = th - law_->period() * std::round(th / law_->period());
    set_pinion_speed(speed);
    State y(x.size());
    if (p_.speed_source)
      y << -d / p_.base_radius2, (p_.base_radius1 * speed - dr) / p_.base_radius2;
    else
      y << th0, speed, (p_.base_radius1 * th0 - d) / p_.base_radius2,
        (p_.base_radius1 * speed - dr) / p_.base_radius2;
    update_mode(0.0, y);
    return y;
  }

  State TorsionalModel::initial_state() const
  {
    const double d0 =
      p_.start_at_rest_deflection ? 0.0 : ramp(0.0) * static_force() / law_->mean_stiffness();
    const double w2 = p_.speed * p_.base_radius1 / p_.base_radius2;
    State x(dimension());
    if (p_.speed_source)
      x << d0 / -p_.base_radius2 * 1.0, w2;
    else
      x << 0.0, p_.speed, -d0 / p_.base_radius2, w2;
    return x;
  }
} // namespace gearfem::dynamics
