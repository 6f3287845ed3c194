// Integrator tests: convergence order, energy conservation, damped free decay, forced
// steady state and event location, each against a closed form.
#include "common.h"
#include "base/units.h"

#include "base/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gearfem::dynamics;

namespace
{
  /// x'' + x = 0: exact x = cos t, v = -sin t (smooth, no switches).
  class Oscillator : public HybridSystem
  {
  public:
    int dimension() const override { return 2; }
    void operator()(const State &x, State &dx, double) const override
    {
      dx.resize(2);
      dx << x[1], -x[0];
    }
  };

  double error_at(Method m, double h, double t_end)
  {
    IntegratorOptions o;
    o.method = m;
    o.adaptive = false;
    o.step = h;
    Integrator integ(o);
    Oscillator s;
    State x(2);
    x << 1.0, 0.0;
    double t = 0;
    integ.advance(s, x, t, t_end);
    return std::hypot(x[0] - std::cos(t_end), x[1] + std::sin(t_end));
  }
} // namespace

// Closed form: the global error of an order-p method scales as h^p.
TEST(Integrators, ConvergenceOrder)
{
  struct Case
  {
    Method m;
    double h;
  };
  for (const Case c : {Case{Method::rk4, 0.1}, Case{Method::dopri5, 0.2}, Case{Method::sdirk3, 0.05}})
    {
      const double e1 = error_at(c.m, c.h, 4.0), e2 = error_at(c.m, c.h / 2, 4.0);
      const double p = std::log2(e1 / e2);
      EXPECT_NEAR(p, order(c.m), 0.25) << to_string(c.m) << " e(h)=" << e1 << " e(h/2)=" << e2;
      std::cout << to_string(c.m) << ": observed order " << p << "\n";
    }
}

// Conservation law: undamped constant stiffness keeps E = m v^2/2 + k (d - d_s)^2/2.
// Requirement: relative drift <= 1e-6 over 1e4 periods for DOPRI5 at tight tolerance.
TEST(Integrators, EnergyConservationDopri5)
{
  const double m = 1.0, k = 1.0, F0 = 1.0;
  DteModel model = test::linear_oscillator(m, k, 0.0, F0);
  IntegratorOptions o;
  o.method = Method::dopri5;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  o.step = 0.01;
  Integrator integ(o);
  State x(2);
  x << F0 / k + 0.5, 0.0; // amplitude 0.5 < static deflection 1: stays in contact
  auto energy = [&](const State &s) {
    return 0.5 * m * s[1] * s[1] + 0.5 * k * (s[0] - F0 / k) * (s[0] - F0 / k);
  };
  const double E0 = energy(x);
  double t = 0;
  const double T = 2 * gearfem::units::pi * std::sqrt(m / k);
  integ.advance(model, x, t, 1e4 * T);
  const double drift = std::abs(energy(x) - E0) / E0;
  EXPECT_LE(drift, 1e-6);
  RecordProperty("energy_drift", std::to_string(drift));
  std::cout << "energy drift over 1e4 periods (DOPRI5, rtol 1e-12): " << drift << " with "
            << integ.stats().accepted << " steps\n";
}

// Closed form: damped free decay d - d_s = A e^{-zeta w t}(cos w_d t + zeta/sqrt(1-zeta^2) sin w_d t).
TEST(Integrators, DampedFreeDecay)
{
  const double m = 2.0, k = 8.0e3, zeta = 0.05, F0 = 100.0, A = 0.004;
  const double w = std::sqrt(k / m), wd = w * std::sqrt(1 - zeta * zeta);
  for (Method meth : {Method::rk4, Method::dopri5, Method::sdirk3})
    {
      DteModel model = test::linear_oscillator(m, k, zeta, F0);
      IntegratorOptions o;
      o.method = meth;
      o.step = (2 * gearfem::units::pi / w) / (meth == Method::sdirk3 ? 2000 : 200);
      o.rtol = 1e-11;
      Integrator integ(o);
      State x(2);
      x << F0 / k + A, 0.0;
      double t = 0;
      double max_err = 0;
      for (int i = 1; i <= 100; ++i)
        {
          integ.advance(model, x, t, i * 0.01);
          const double exact =
            F0 / k + A * std::exp(-zeta * w * t) *
                       (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
          max_err = std::max(max_err, std::abs(x[0] - exact));
        }
      EXPECT_LE(max_err / A, meth == Method::sdirk3 ? 1e-5 : 1e-7) << to_string(meth);
    }
}

// Closed form: steady amplitude X = F_a / sqrt((k - m W^2)^2 + (c W)^2); RMS = X / sqrt 2.
TEST(Integrators, ForcedSteadyState)
{
  const double m = 1.5, k = 6.0e4, zeta = 0.08, F0 = 50.0, Fa = 5.0;
  const double W = 0.8 * std::sqrt(k / m);
  DteModel::Parameters p;
  p.mass = m, p.static_force = F0, p.zeta = zeta, p.speed = W;
  p.external_force = [&](double t) { return Fa * std::cos(W * t); };
  ContactLogic c;
  c.backlash = std::numeric_limits<double>::infinity();
  DteModel model(std::make_unique<FourierStiffnessLaw>(k, 1, std::vector<double>{}), c, p);
  const double cd = 2 * zeta * std::sqrt(k * m);
  const double X = Fa / std::hypot(k - m * W * W, cd * W);
  IntegratorOptions o;
  o.method = Method::dopri5;
  o.rtol = 1e-10;
  ResponseOptions ro;
  ro.max_periods = 400;
  ro.steady_tolerance = 1e-7;
  State x = model.initial_state();
  double t = 0;
  const Response r = run_response(model, o, ro, x, t);
  EXPECT_TRUE(r.settled);
  EXPECT_EQ(r.period_multiplicity, 1);
  EXPECT_NEAR(r.rms, X / std::sqrt(2.0), 1e-5 * X);
  EXPECT_NEAR(r.mean, F0 / k, 1e-6 * F0 / k);
}

// Closed form: with F0 = 0 and d(0) = A, the contact is lost at t1 = pi / (2 w); the free
// flight at d' = -A w reaches the back flank (d = -b) at t2 = t1 + b / (A w).
// Requirement: event times to <= 1e-10 s.
TEST(Integrators, EventLocation)
{
  const double m = 1.0, k = 1e6, A = 1e-5, b = 2e-5;
  const double w = std::sqrt(k / m);
  const double t1 = gearfem::units::pi / (2 * w), t2 = t1 + b / (A * w);
  for (Method meth : {Method::rk4, Method::dopri5})
    {
      DteModel::Parameters p;
      p.mass = m, p.static_force = 0, p.zeta = 0, p.speed = 1.0;
      ContactLogic c;
      c.backlash = b;
      DteModel model(std::make_unique<FourierStiffnessLaw>(k, 1, std::vector<double>{}), c, p);
      IntegratorOptions o;
      o.method = meth;
      o.step = 2 * gearfem::units::pi / w / 2000; // RK4 global error ~1e-13 relative
      o.rtol = 1e-12;
      o.atol = 1e-20;
      Integrator integ(o);
      State x(2);
      x << A, 0.0;
      model.update_mode(0, x);
      std::vector<double> times;
      double t = 0;
      integ.advance(model, x, t, 1.2 * t2,
                    [&](const Event &e, const State &) { times.push_back(e.t); });
      ASSERT_GE(times.size(), 2u) << to_string(meth);
      std::cout << to_string(meth) << ": event time errors " << times[0] - t1 << ", "
                << times[1] - t2 << " s\n";
      EXPECT_NEAR(times[0], t1, 1e-10) << to_string(meth);
      EXPECT_NEAR(times[1], t2, 1e-10) << to_string(meth);
      EXPECT_EQ(model.mode().s, -1);
    }
}

// Bad input: step or tolerance <= 0 is an InputError naming the parameter.
TEST(Integrators, BadInput)
{
  IntegratorOptions o;
  o.step = 0;
  EXPECT_THROW(Integrator{o}, gearfem::InputError);
  o.step = 1e-3;
  o.rtol = -1;
  try
    {
      Integrator integ(o);
      FAIL();
    }
  catch (const gearfem::InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("Relative tolerance"), std::string::npos);
    }
  EXPECT_THROW(method_from_string("Euler"), gearfem::InputError);
}

// The tolerances are bounded where the numerics need it: a loose absolute tolerance lets
// the steps grow until contact events chatter (a run that never ends), so 1e20 is refused.
TEST(Integrators, ToleranceBounds)
{
  IntegratorOptions o;
  o.atol = 1e20;
  EXPECT_THROW(Integrator{o}, gearfem::InputError);
  o.atol = gearfem::dynamics::max_absolute_tolerance;
  EXPECT_NO_THROW(Integrator{o});
  o.rtol = 0.5;
  EXPECT_THROW(Integrator{o}, gearfem::InputError);
  o.rtol = 1e-8;
  o.event_tolerance = 1.0;
  EXPECT_THROW(Integrator{o}, gearfem::InputError);
}

namespace
{
  /// A mode that switches 1e-9 time units after each switch (a Zeno-like chatter, as contact
  /// events under a far too loose tolerance): every step ends at the next event, so reaching
  /// t = 1 would take 1e9 steps.
  class Chatter : public Oscillator
  {
  public:
    int n_switches() const override { return 1; }
    void switching_functions(double t, const State &, double *g) const override
    {
      g[0] = mode_ * (last_ + 1e-9 - t);
    }
    bool update_mode(double t, const State &) override
    {
      if (t < last_ + 0.5e-9)
        return false;
      last_ = t, mode_ = -mode_;
      return true;
    }

  private:
    double last_ = 0, mode_ = 1;
  };
} // namespace

// Wall-time safety: an advance that cannot finish (each step shorter than 1e-8 of the
// interval) ends with a named SolverError after max_stalled_steps steps, instead of running on.
TEST(Integrators, StepCapEndsAChatteringRun)
{
  IntegratorOptions o;
  o.method = Method::rk4;
  o.adaptive = false;
  o.step = 1e-3;
  o.event_tolerance = 1e-12;
  Integrator integ(o);
  Chatter s;
  State x(2);
  x << 1.0, 0.0;
  double t = 0;
  try
    {
      integ.advance(s, x, t, 1.0);
      FAIL() << "the chattering run finished";
    }
  catch (const gearfem::SolverError &e)
    {
      EXPECT_NE(std::string(e.what()).find("consecutive steps"), std::string::npos) << e.what();
    }
}

// The run's wall-time cap: an advance of 1e7 fixed steps (1e-7 over t = 1, about a second)
// ends, once the deadline has passed, with a SolverError naming the entry, after about the
// limit (0.02 s here).
TEST(Integrators, WallTimeCapEndsALongRun)
{
  IntegratorOptions o;
  o.method     = Method::rk4;
  o.adaptive   = false;
  o.step       = 1e-7;
  o.wall_limit = 0.02;
  Integrator integ(o.with_deadline());
  Oscillator s;
  State x(2);
  x << 1.0, 0.0;
  double t    = 0;
  const double start = gearfem::dynamics::monotonic_seconds();
  try
    {
      integ.advance(s, x, t, 1.0);
      FAIL() << "the capped run finished";
    }
  catch (const gearfem::SolverError &e)
    {
      EXPECT_NE(std::string(e.what()).find("Wall time limit"), std::string::npos) << e.what();
    }
  EXPECT_GT(t, 0.0);
  EXPECT_LT(t, 1.0);
  EXPECT_LT(gearfem::dynamics::monotonic_seconds() - start, 5.0); // ended near the cap, not at t = 1
  o.wall_limit = -1;
  EXPECT_THROW(Integrator{o}, gearfem::InputError);
}
