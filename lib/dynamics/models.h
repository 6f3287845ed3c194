#pragma once
// Gear-pair dynamic models as HybridSystems (see ode.h). Both share MeshModel, which owns
// the mesh-force law, the contact logic with backlash, the damping and the discrete mode
// (contact state s and stiffness zone frozen during a step).
//
// 1-DOF DTE model (speed source):  m_eq d'' + c d' + F_mesh(theta(t), d) = F0 + F_e(t),
//   theta = W t + theta0; Kahraman & Singh (1990) JSV 142(1) eq. (3) is the dimensionless
//   case m_eq = 1, kbar = 1, c = 2 zeta, b = 2, period 2 pi.
// 2-DOF torsional model (Gkimisis 2019, eqs. 4.1-4.2):
//   I1 th1'' = T_in r(t) - r_b1 (F_mesh + F_damp),  I2 th2'' = r_b2 (F_mesh + F_damp) - T_out r(t),
//   delta = r_b1 th1 - r_b2 th2 (compression along the line of action), theta = th1,
//   r(t) = min(1, t / t_ramp) the start-up torque ramp; or a speed source on gear 1.
// Damping c = 2 zeta sqrt(kbar m_eq), optionally acting only in contact (s != 0).
#include "dynamics/mesh_force.h"
#include "dynamics/ode.h"
#include "dynamics/tooth_mass.h"

#include <functional>
#include <memory>

namespace gearfem::dynamics
{
  /// The discrete mode of a meshing pair.
  struct MeshMode
  {
    int s = 1;           ///< contact state 1 / 0 / -1
    ZoneInfo zone;       ///< stiffness zone of the active flank (in that flank's theta)
  };

  /// Base of the gear-pair models: contact logic, damping, mode and switching functions.
  class MeshModel : public HybridSystem
  {
  public:
    MeshModel(std::unique_ptr<MeshForceLaw> law, const ContactLogic &contact, double zeta,
              bool damping_only_in_contact);
    MeshModel(const MeshModel &other);

    /// Mesh position theta [rad] (pinion roll angle).
    virtual double mesh_position(double t, const State &x) const = 0;
    /// Compression delta along the line of action [m] and its rate [m/s].
    virtual double compression(double t, const State &x) const = 0;
    virtual double compression_rate(double t, const State &x) const = 0;
    /// Equivalent mass along the line of action [kg].
    virtual double equivalent_mass() const = 0;
    /// Nominal mesh period in time [s]: period / pinion speed.
    virtual double mesh_period_time() const = 0;
    /// Static mesh force F_static [N] (K_v = F_max / F_static).
    virtual double static_force() const = 0;
    /// Pinion speed [rad/s] (nominal).
    virtual double pinion_speed() const = 0;
    /// Change the pinion speed (speed sweeps).
    virtual void set_pinion_speed(double w) = 0;
    /// A state near static equilibrium at t = 0 (compression F_static / kbar).
    virtual State initial_state() const = 0;
    /// Continuation: the state at t = 0 with the same delta, delta' and mesh position modulo
    /// the period as state x at time t (t a multiple of the mesh period), after setting
    /// the pinion speed to `speed`. Re-classifies the mode.
    virtual State continue_at_speed(double t, const State &x, double speed) = 0;
    virtual std::unique_ptr<MeshModel> clone() const = 0;

    int n_switches() const override { return 4; }
    void switching_functions(double t, const State &x, double *g) const override;
    bool update_mode(double t, const State &x) override;

    /// Elastic mesh force for the given mode [N].
    double elastic_force(double theta, double delta, const MeshMode &m) const;
    /// Total mesh force (elastic + damping) with the mode classified from the state [N].
    double mesh_force(double t, const State &x) const;
    /// Contact state classified from the state.
    int contact_state(double t, const State &x) const;
    const MeshMode &mode() const { return mode_; }
    double damping_coefficient() const { return c_; } ///< [N s/m]
    const MeshForceLaw &law() const { return *law_; }
    const ContactLogic &contact() const { return contact_; }
    /// Linear natural frequency sqrt(kbar / m_eq) / (2 pi) [Hz].
    double linear_natural_frequency() const;

    /// Vibratory angles of the gears (angle minus the nominal rotation at the pinion speed)
    /// [rad]; empty for models without rotational coordinates.
    virtual std::vector<double> angle_deviations(double /*t*/, const State & /*x*/) const { return {}; }
    /// True when the model conserves energy up to the work of its input torques: no damping,
    /// no torque ramp, and a mesh force that does not depend on the mesh position (otherwise
    /// the stiffness variation does work on the pair).
    virtual bool conservative() const { return false; }
    /// Kinetic energy [J] (0 for models without one).
    virtual double kinetic_energy(double /*t*/, const State & /*x*/) const { return 0.0; }
    /// Work of the input and output torques from (t0, x0) to (t, x) [J] (constant torques).
    virtual double torque_work(const State & /*x0*/, const State & /*x*/) const { return 0.0; }
    /// Elastic energy of the mesh [J]: the integral of the elastic force over the compression
    /// of the active flank (drive: delta; back: -delta - b; none in the gap), 8-point Gauss.
    double elastic_energy(double t, const State &x) const;

  protected:
    /// Force along the line of action (elastic + damping) with the frozen mode [N].
    double frozen_force(double theta, double delta, double delta_rate) const;
    void update_damping();
    MeshMode classify(double theta, double delta) const;

    std::unique_ptr<MeshForceLaw> law_;
    ContactLogic contact_;
    std::vector<double> breaks_;
    double zeta_, c_ = 0;
    bool damp_only_contact_;
    MeshMode mode_;
  };

  /// 1-DOF dynamic-transmission-error model with a speed source.
  class DteModel : public MeshModel
  {
  public:
    struct Parameters
    {
      double mass = 1.0;          ///< m_eq [kg]
      double static_force = 0.1;  ///< F0 [N]
      double speed = 1.0;         ///< pinion speed W [rad/s] (theta = W t + theta0)
      double theta0 = 0.0;        ///< [rad]
      double zeta = 0.05;         ///< damping ratio [-]
      bool damping_only_in_contact = false;
      /// Optional external force F_e(t) [N].
      std::function<double(double)> external_force;
    };
    DteModel(std::unique_ptr<MeshForceLaw> law, const ContactLogic &contact,
             const Parameters &p);
    int dimension() const override { return 2; }
    void operator()(const State &x, State &dxdt, double t) const override;
    double mesh_position(double t, const State &) const override { return p_.speed * t + p_.theta0; }
    double compression(double, const State &x) const override { return x[0]; }
    double compression_rate(double, const State &x) const override { return x[1]; }
    double equivalent_mass() const override { return p_.mass; }
    double mesh_period_time() const override { return law_->period() / p_.speed; }
    double static_force() const override { return p_.static_force; }
    double pinion_speed() const override { return p_.speed; }
    void set_pinion_speed(double w) override;
    State initial_state() const override;
    State continue_at_speed(double t, const State &x, double speed) override;
    std::unique_ptr<MeshModel> clone() const override { return std::make_unique<DteModel>(*this); }

  private:
    Parameters p_;
  };

  /// 2-DOF torsional model (Gkimisis 2019, 4.1-4.2), torque-driven or with a speed source on gear 1.
  /// Optional position-dependent tooth inertias J_t,i(theta) (tooth_mass.h): gear i has
  /// J_i = I_i + J_t,i(theta_i) with theta_1 = th1 and theta_2 = (r_b2/r_b1) th2 (each gear's
  /// own angle expressed as a mesh position), and Lagrange's equations of
  /// T = 1/2 sum J_i(theta_i) th_i'^2 give J_i th_i'' + 1/2 J_i'(th_i) th_i'^2 = torque_i
  /// (docs/dynamics.md, "Position-dependent tooth inertia").
  class TorsionalModel : public MeshModel
  {
  public:
    struct Parameters
    {
      double inertia1 = 1e-4, inertia2 = 1e-3;  ///< I1, I2 [kg m^2] (incl. tooth inertia)
      double base_radius1 = 0.02, base_radius2 = 0.04; ///< r_b1, r_b2 [m]
      double input_torque = 10.0;  ///< T_in [N m]
      double output_torque = -1.0; ///< T_out [N m]; < 0: T_in r_b2 / r_b1 (balanced)
      double ramp_time = 0.0;      ///< linear torque ramp duration [s] (0: step)
      double speed = 100.0;        ///< initial / imposed pinion speed [rad/s]
      bool speed_source = false;   ///< true: th1 = speed t (1 DOF: gear 2)
      double zeta = 0.02;
      bool damping_only_in_contact = false;
      bool start_at_rest_deflection = false; ///< false: delta(0) = F/kbar; true: delta(0) = 0
      /// Position-dependent tooth inertias added to inertia1/2 [kg m^2] as functions of the
      /// mesh position [rad]; null: none.
      std::shared_ptr<const PeriodicInertia> tooth_inertia1, tooth_inertia2;
      /// Keep the 1/2 J'(theta) th'^2 terms (false only to show their effect in tests).
      bool inertia_velocity_terms = true;
    };
    TorsionalModel(std::unique_ptr<MeshForceLaw> law, const ContactLogic &contact,
                   const Parameters &p);
    int dimension() const override { return p_.speed_source ? 2 : 4; }
    void operator()(const State &x, State &dxdt, double t) const override;
    double mesh_position(double t, const State &x) const override;
    double compression(double t, const State &x) const override;
    double compression_rate(double t, const State &x) const override;
    double equivalent_mass() const override;
    double mesh_period_time() const override { return law_->period() / p_.speed; }
    double static_force() const override { return p_.input_torque / p_.base_radius1; }
    double pinion_speed() const override { return p_.speed; }
    void set_pinion_speed(double w) override;
    State initial_state() const override;
    State continue_at_speed(double t, const State &x, double speed) override;
    std::unique_ptr<MeshModel> clone() const override
    {
      return std::make_unique<TorsionalModel>(*this);
    }
    double output_torque() const;
    const Parameters &parameters() const { return p_; }
    /// Total inertia of gear i (1 or 2) at the state x and its derivative with respect to
    /// that gear's angle [kg m^2], [kg m^2/rad].
    double inertia(int i, const State &x, double *derivative = nullptr) const;
    /// Mean total inertia of gear i over a mesh period [kg m^2].
    double mean_inertia(int i) const;
    std::vector<double> angle_deviations(double t, const State &x) const override;
    bool conservative() const override;
    double kinetic_energy(double t, const State &x) const override;
    double torque_work(const State &x0, const State &x) const override;

  private:
    double ramp(double t) const;
    Parameters p_;
  };
} // namespace gearfem::dynamics
