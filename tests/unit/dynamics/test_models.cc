// 2-DOF torsional model (Gkimisis 2019, 4.1-4.2), tooth inertia and the case of the NTUA
// tooth-mass thesis.
#include "common.h"
#include "base/units.h"

#include "base/errors.h"
#include "dynamics/case.h"
#include "dynamics/pair_data.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gearfem::dynamics;

namespace
{
  constexpr double deg = gearfem::units::pi / 180;

  /// NTUA tooth-mass thesis: z 20/40, m 2.5, alpha 20, b 30 mm, J from solid cylinders of pitch diameter
  /// (rho 7850): J = pi rho b r^4 / 2.
  struct Seed004
  {
    PairData pair = standard_pair(20, 40, 2.5e-3, 20 * deg, 1.0, 0.5, 0.5, 0.0);
    double b = 0.03, rho = 7850;
    double J(double r) const { return 0.5 * gearfem::units::pi * rho * b * std::pow(r, 4); }
    double J1() const { return J(0.025); }
    double J2() const { return J(0.050); }
    /// ISO-like piecewise stiffness: k_single = c' b with c' = 14 N/(mm um) (ISO 6336-1
    /// rule of thumb) and k_double = 1.75 k_single, so that the mean is c'(0.75 eps + 0.25) b
    /// = c_gamma_alpha b.
    std::unique_ptr<MeshForceLaw> law() const
    {
      const double ks = 14e9 * b;
      return std::make_unique<PiecewiseConstantLaw>(ks, 1.75 * ks, 20, pair.contact_ratio,
                                                    pair.theta_A);
    }
    TorsionalModel model(std::unique_ptr<MeshForceLaw> l, double extra1 = 0,
                         double extra2 = 0) const
    {
      TorsionalModel::Parameters p;
      p.inertia1 = J1() + extra1, p.inertia2 = J2() + extra2;
      p.base_radius1 = pair.r_b1, p.base_radius2 = pair.r_b2;
      p.input_torque = 100, p.output_torque = 200;
      p.speed = 160;
      p.zeta = 0;
      p.start_at_rest_deflection = true; // zero initial conditions (the thesis)
      ContactLogic c;
      c.backlash = 1e-4;
      return TorsionalModel(std::move(l), c, p);
    }
  };

  /// Integrate the 2-DOF model and return samples of th1 - w0 t and of delta.
  void simulate(TorsionalModel &m, double t_end, int n, std::vector<double> &th1,
                std::vector<double> &delta, std::vector<int> *states = nullptr)
  {
    IntegratorOptions io;
    io.method = Method::dopri5;
    io.rtol = 1e-10;
    io.atol = 1e-14;
    io.step = 1e-6;
    Integrator integ(io);
    State x = m.initial_state();
    m.update_mode(0, x);
    double t = 0;
    const double w0 = x[1];
    for (int i = 1; i <= n; ++i)
      {
        integ.advance(m, x, t, t_end * i / n);
        th1.push_back(x[0] - w0 * t);
        delta.push_back(m.compression(t, x));
        if (states)
          states->push_back(m.contact_state(t, x));
      }
  }

  double peak_frequency(const std::vector<double> &v, double dt, double fmin)
  {
    const Spectrum s = amplitude_spectrum(v, dt);
    double best = 0, f = 0;
    for (std::size_t k = 1; k < s.frequency.size(); ++k)
      if (s.frequency[k] > fmin && s.amplitude[k] > best)
        best = s.amplitude[k], f = s.frequency[k];
    return f;
  }
} // namespace

// Closed forms for a step load on two free inertias with constant stiffness k:
// w^2 = k / m_eq, m_eq = I1 I2 / (I2 r1^2 + I1 r2^2) (Gkimisis 2019), and
// th1 - w0 t = r1 F (1 - cos w t) / (I1 w^2), i.e. peak 2 r1 F m_eq / (I1 k).
TEST(Models, TorsionalStepLoadClosedForm)
{
  Seed004 s;
  const double k = 5e8;
  TorsionalModel m = s.model(std::make_unique<FourierStiffnessLaw>(k, 20, std::vector<double>{}));
  const double F = 100 / s.pair.r_b1;
  const double meq = m.equivalent_mass();
  EXPECT_NEAR(meq, s.J1() * s.J2() / (s.J2() * std::pow(s.pair.r_b1, 2) + s.J1() * std::pow(s.pair.r_b2, 2)),
              1e-12 * meq);
  std::vector<double> th1, delta;
  const int n = 8192;
  const double t_end = 0.02;
  simulate(m, t_end, n, th1, delta);
  const double peak = *std::max_element(th1.begin(), th1.end());
  const double expected = 2 * s.pair.r_b1 * F * meq / (s.J1() * k);
  EXPECT_NEAR(peak, expected, 2e-3 * expected);
  const double fn = std::sqrt(k / meq) / (2 * gearfem::units::pi);
  EXPECT_NEAR(m.linear_natural_frequency(), fn, 1e-12 * fn);
  EXPECT_NEAR(peak_frequency(delta, t_end / n, 10.0), fn, 1.0 / t_end + 1e-3 * fn);
}

namespace
{
  /// The stiffness the thesis' model_solve actually ran: its loop `K = feval(Kth1, c)`
  /// overwrites the whole vector on every pass, so the last pass decides; with the 50 ms run
  /// at 160 rad/s the last c = rem(8, pi/10) = 0.146 <= a = 0.228 and K = Kth1(c) for every
  /// step, c = rem(theta1, pi/10): Kth1 = 1.269e9 sin(3.174 c + 1.195) N/m (the double-pair
  /// fit) over the whole mesh period. The thesis applies it at the pitch radii; at the base
  /// radii the same equations need K/cos^2(alpha) (the mesh force changes, the angles not).
  class ThesisOverwrittenK : public MeshForceLaw
  {
  public:
    explicit ThesisOverwrittenK(double cos_alpha) : s_(1 / (cos_alpha * cos_alpha)) {}
    static double K(double c) { return 1.269e9 * std::sin(3.174 * c + 1.195); }
    std::string name() const override { return "thesis K (overwritten)"; }
    double period() const override { return gearfem::units::pi / 10; }
    double force(double theta, double delta, int) const override
    {
      const double p = period();
      return s_ * K(theta - p * std::floor(theta / p)) * delta;
    }
    /// Mean of Kth1 over c in [0, pi/10) (closed form of the sine's integral), scaled.
    double mean_stiffness() const override
    {
      const double p = period();
      return s_ * 1.269e9 * (std::cos(1.195) - std::cos(3.174 * p + 1.195)) / (3.174 * p);
    }
    std::unique_ptr<MeshForceLaw> clone() const override { return std::make_unique<ThesisOverwrittenK>(*this); }

  private:
    double s_;
  };
} // namespace

// Case of the NTUA tooth-mass thesis (20/40, m 2.5, b 30, 160 rad/s, M_in 100, M_out 200 N m,
// no damping, zero initial conditions, J1/J2 = cylinders of the pitch diameter plus the
// thesis' Jeq1/Jeq2) with the stiffness its model_solve really used (ThesisOverwrittenK).
// Closed forms (constant K = mean of that vector): theta1 swings as A (1 - cos w t) with
// A = M_in m_eq/(J1 K), m_eq = J1 J2/(J2 r1^2 + J1 r2^2) at the thesis' pitch radii; and
// r2 J1 th1 + r1 J2 th2 = const (balanced torques), so the gear swings -(r2 J1/(r1 J2)) A.
// The thesis reports "of the order of 1e-4 rad" and "1e-5 rad"; the closed form of its own K
// gives 1.05e-4 and 1.35e-5 (the first swing of the step response and the mean angle; later
// the amplitude grows: f_n = 12.7 kHz is close to 25 f_mesh and K jumps once per period).
// The mesh line z1 W/(2 pi) = 509.3 Hz is in the DTE spectrum.
TEST(Models, Seed004Case)
{
  Seed004 s;
  const double Jeq1 = 4.5631e-6, Jeq2 = 1.8743e-5; // listing model_solve
  auto law = std::make_unique<ThesisOverwrittenK>(std::cos(20 * deg));
  const double Kbar = law->mean_stiffness() * std::pow(std::cos(20 * deg), 2);
  EXPECT_NEAR(Kbar, 1.2079e9, 0.0005e9); // the mean of 1.269e9 sin(3.174 c + 1.195)
  TorsionalModel m = s.model(std::move(law), Jeq1, Jeq2);
  const double f_mesh = 20 * 160 / (2 * gearfem::units::pi);
  EXPECT_NEAR(1.0 / m.mesh_period_time(), f_mesh, 1e-9 * f_mesh);
  EXPECT_NEAR(f_mesh, 509.3, 0.05); // the thesis value (independent: 20 x 160 / 2 pi)
  std::vector<double> th1, delta;
  const int periods = 64, per = 128;
  const double t_end = periods * m.mesh_period_time();
  simulate(m, t_end, periods * per, th1, delta);
  const Spectrum sp = amplitude_spectrum(delta, t_end / (periods * per));
  const std::size_t k_mesh = periods; // the bin of f_mesh over an integer number of periods
  EXPECT_NEAR(sp.frequency[k_mesh], f_mesh, 1e-6 * f_mesh);
  EXPECT_GT(sp.amplitude[k_mesh], 3 * sp.amplitude[k_mesh - 3]);
  EXPECT_GT(sp.amplitude[k_mesh], 3 * sp.amplitude[k_mesh + 3]);
  const double J1 = s.J1() + Jeq1, J2 = s.J2() + Jeq2, r1 = 0.025, r2 = 0.05; // the thesis' radii
  const double meq = J1 * J2 / (J2 * r1 * r1 + J1 * r2 * r2);
  const double A = 100 * meq / (J1 * Kbar);
  EXPECT_NEAR(A, 1.0548e-4, 0.0001e-4);
  // theta1 oscillates about the static angle A: its mean over the first 10 periods (later
  // the growing swing opens the contact, which the thesis' linear spring never does).
  double mean = 0;
  for (int i = 0; i < 10 * per; ++i)
    mean += th1[i] / (10 * per);
  EXPECT_NEAR(mean, A, 0.03 * A);
  // The first swing (0.1 ms, about one natural period): half its peak-to-peak is A for a
  // constant K; the thesis' K changes by < 2 % in that time. Against the closed form and the
  // thesis' "order 1e-4 rad" as 1.07e-4 within 10 %.
  TorsionalModel m1 = s.model(std::make_unique<ThesisOverwrittenK>(std::cos(20 * deg)), Jeq1, Jeq2);
  std::vector<double> a1, d1;
  simulate(m1, 1e-4, 400, a1, d1);
  const auto [lo, hi] = std::minmax_element(a1.begin(), a1.end());
  const double amplitude = 0.5 * (*hi - std::min(0.0, *lo));
  std::cout << "tooth-mass thesis case, overwritten K: first-swing theta1 amplitude " << amplitude
            << " rad (closed form " << A << "), mean over 10 periods " << mean << ", f_n "
            << m.linear_natural_frequency() << " Hz\n";
  EXPECT_NEAR(amplitude, A, 0.03 * A);
  EXPECT_NEAR(amplitude, 1.07e-4, 0.10 * 1.07e-4);
  // The gear: th2 = -(r2 J1/(r1 J2)) th1 at every instant (momentum of the balanced pair).
  State x = m.initial_state();
  IntegratorOptions io;
  io.rtol = 1e-10, io.atol = 1e-14, io.step = 1e-6;
  Integrator integ(io);
  double t = 0;
  const double w1 = x[1], w2 = x[3];
  integ.advance(m, x, t, 0.0123);
  const double ratio = (x[2] - w2 * t) / (x[0] - w1 * t);
  EXPECT_NEAR(ratio, -(r2 * J1) / (r1 * J2), 1e-6);
  EXPECT_NEAR(-ratio * amplitude, 1.3e-5, 0.10 * 1.3e-5);
}

// Energy balance with the position-dependent tooth inertia J_t(theta) of the 20/40 pair (the
// thesis definition on the generated pair, 512 nodes per period) in the equations of motion:
// constant stiffness, no damping, no ramp, the thesis' torques (a conservative system). Over
// 100 mesh periods the change of kinetic + elastic energy equals the work of the torques to
// 1e-6 of the initial kinetic energy; without the 1/2 J'(theta) theta'^2 terms it does not.
TEST(Models, PositionDependentInertiaEnergyBalance)
{
  DynamicsCase c;
  c.law = LawKind::fourier;
  c.fourier_cos.clear(); // constant stiffness c_gamma_alpha b
  c.input_torque = 100, c.output_torque = 200, c.speed = 160, c.zeta = 0;
  c.youngs_modulus = 210e9;
  c.backlash = 1e-4;
  c.tooth_mass = true;
  c.tooth_inertia_position_dependent = true;
  auto run = [&](bool velocity_terms, double *variation) {
    auto base = build_model(c, nullptr);
    auto *tm = dynamic_cast<TorsionalModel *>(base.get());
    EXPECT_NE(tm, nullptr);
    TorsionalModel::Parameters p = tm->parameters();
    p.inertia_velocity_terms = velocity_terms;
    TorsionalModel m(tm->law().clone(), tm->contact(), p);
    EXPECT_EQ(m.conservative(), velocity_terms);
    IntegratorOptions io;
    io.rtol = 1e-11, io.atol = 1e-15, io.step = 1e-7;
    Integrator integ(io);
    State x = m.initial_state();
    m.update_mode(0, x);
    const State x0 = x;
    double t = 0;
    const double E0 = m.kinetic_energy(0, x) + m.elastic_energy(0, x), K0 = m.kinetic_energy(0, x);
    (void)K0;
    // Sampled 16 times per mesh period: J(theta) exchanges energy within each period (its
    // integral of J' over a whole period vanishes).
    double worst = 0, wmin = 1e300, wmax = -1e300;
    for (int k = 1; k <= 100 * 16; ++k)
      {
        integ.advance(m, x, t, k * m.mesh_period_time() / 16);
        EXPECT_EQ(m.contact_state(t, x), 1);
        wmin = std::min(wmin, x[1]), wmax = std::max(wmax, x[1]);
        const double err = (m.kinetic_energy(t, x) + m.elastic_energy(t, x) - E0 - m.torque_work(x0, x)) / K0;
        worst = std::max(worst, std::abs(err));
        if (velocity_terms && k % 400 == 0)
          std::cout << "  period " << k / 16 << ": energy balance " << err << "\n";
      }
    if (variation)
      *variation = (wmax - wmin) / x0[1];
    return worst;
  };
  double variation = 0;
  const double with = run(true, &variation), without = run(false, nullptr);
  std::cout << "J(theta) energy balance over 100 mesh periods: " << with << " (without the J' terms " << without
            << "); pinion speed variation " << variation << "\n";
  EXPECT_LT(with, 1e-6);
  EXPECT_GT(without, 1e-4);
  EXPECT_GT(variation, 1e-3); // J(theta) really modulates the rotation
}

// Bad input: position-dependent tooth inertia with the 1-DOF model.
TEST(Models, PositionDependentInertiaNeedsTorsionalModel)
{
  DynamicsCase c;
  c.model = ModelKind::dte;
  c.tooth_mass = true;
  c.tooth_inertia_position_dependent = true;
  EXPECT_THROW(build_model(c, nullptr), gearfem::InputError);
}

// Tooth inertia: adding J_tooth lowers the natural frequency; the simulated frequency
// follows sqrt(k / m_eq) / (2 pi) with the increased inertias.
TEST(Models, ToothMassLowersNaturalFrequency)
{
  Seed004 s;
  const double k = 5e8;
  // The thesis' mean tooth inertias (listing model_solve: Jeq1, Jeq2).
  const double Jt1 = 4.5631e-6, Jt2 = 1.8743e-5;
  TorsionalModel a = s.model(std::make_unique<FourierStiffnessLaw>(k, 20, std::vector<double>{}));
  TorsionalModel b =
    s.model(std::make_unique<FourierStiffnessLaw>(k, 20, std::vector<double>{}), Jt1, Jt2);
  std::cout << "tooth inertia: " << Jt1 / s.J1() * 100 << " % of J1, " << Jt2 / s.J2() * 100
            << " % of J2; f_n " << a.linear_natural_frequency() << " -> "
            << b.linear_natural_frequency() << " Hz\n";
  EXPECT_LT(b.linear_natural_frequency(), a.linear_natural_frequency());
  std::vector<double> th1, delta;
  const int n = 16384;
  const double t_end = 0.04;
  simulate(b, t_end, n, th1, delta);
  EXPECT_NEAR(peak_frequency(delta, t_end / n, 10.0), b.linear_natural_frequency(), 1.0 / t_end);
}

// Contact-state logic in the 2-DOF torque-driven model (Gkimisis 2019 Table 1 pair 32/60 m 3
// b 30, piecewise stiffness until the analytical torque table exists): far below resonance
// no contact loss; at the primary resonance the contact opens; the state sequence only
// moves between neighbours (1 <-> 0 <-> -1) and never skips the gap.
TEST(Models, Seed000ContactStates)
{
  const PairData pair = standard_pair(32, 60, 3e-3, 20 * deg, 1.0, 0.49, 0.49, 0.0);
  EXPECT_NEAR(pair.r_b1, 45.105e-3, 1e-6);          // Gkimisis 2019: R_g1 = 45.105 mm
  EXPECT_NEAR(pair.contact_ratio, 1.725, 0.01);     // Gkimisis 2019: 1.72-1.73
  const double b = 0.03, rho = 7860;
  auto J = [&](double r) { return 0.5 * gearfem::units::pi * rho * b * std::pow(r, 4); };
  auto run = [&](double torque, double rpm, std::vector<int> &states) {
    TorsionalModel::Parameters p;
    p.inertia1 = J(0.048), p.inertia2 = J(0.090);
    p.base_radius1 = pair.r_b1, p.base_radius2 = pair.r_b2;
    p.input_torque = torque;
    p.speed = rpm * 2 * gearfem::units::pi / 60;
    p.zeta = 0.02;
    p.ramp_time = 0.0;
    ContactLogic c;
    c.backlash = pair.backlash;
    c.reverse_mapping = true;
    c.reverse_offset = pair.thickness_angle1;
    const double ks = 14e9 * b;
    TorsionalModel m(std::make_unique<PiecewiseConstantLaw>(ks, 1.75 * ks, 32, pair.contact_ratio,
                                                            pair.theta_A),
                     c, p);
    std::vector<double> th1, delta;
    simulate(m, 120 * m.mesh_period_time(), 120 * 64, th1, delta, &states);
    return m.linear_natural_frequency();
  };
  std::vector<int> s1, s2;
  run(5, 600, s1);
  EXPECT_TRUE(std::all_of(s1.begin(), s1.end(), [](int s) { return s == 1; }));
  const double fn = run(5, 600, s2);
  std::vector<int> s3;
  run(5, fn / 32 * 60, s3); // mesh frequency = linear natural frequency
  const long loss = std::count_if(s3.begin() + s3.size() / 2, s3.end(), [](int s) { return s != 1; });
  std::cout << "Gkimisis 2019 pair: f_n " << fn << " Hz, backlash " << pair.backlash * 1e3
            << " mm; contact-loss samples at resonance " << loss << "/" << s3.size() / 2 << "\n";
  EXPECT_GT(loss, 0);
  for (std::size_t i = 1; i < s3.size(); ++i)
    EXPECT_LE(std::abs(s3[i] - s3[i - 1]), 1) << "at sample " << i;
}

// Bad input: ramp < 0, inertia <= 0, impossible pair.
TEST(Models, BadInput)
{
  Seed004 s;
  TorsionalModel::Parameters p;
  p.ramp_time = -1;
  EXPECT_THROW(TorsionalModel(s.law(), ContactLogic{}, p), gearfem::InputError);
  p.ramp_time = 0;
  p.inertia1 = 0;
  EXPECT_THROW(TorsionalModel(s.law(), ContactLogic{}, p), gearfem::InputError);
  EXPECT_THROW(standard_pair(20, 40, 2.5e-3, 20 * deg, 1.0, 0.5, 0.5, -5e-3), gearfem::InputError);
}
