// Kahraman & Singh (1990, JSV 142(1) 49-75) dimensionless SDOF model with backlash:
// x'' + 2 zeta x' + k(t) f(x) = F_m, zeta 0.05, F_m 0.1, k = 1 - 0.2 cos - 0.1 cos 2 - 0.05 cos 3.
// References used here: our harmonic-balance solution (no-impact regime), a tight-tolerance
// DOPRI5 integration (rtol 1e-12), and the qualitative features the paper reports
// (softening primary resonance with jumps, single-sided impacts, superharmonic near 0.5).
#include "common.h"

#include "base/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gearfem::dynamics;

namespace
{
  Response point(double Omega, const IntegratorOptions &io, int steps_per_period = 128)
  {
    DteModel m = test::kahraman_singh(Omega);
    ResponseOptions ro;
    ro.steps_per_period = steps_per_period;
    ro.steady_tolerance = 1e-8;
    ro.max_periods = 400;
    State x = m.initial_state();
    double t = 0;
    return run_response(m, io, ro, x, t);
  }

  IntegratorOptions dopri(double rtol)
  {
    IntegratorOptions io;
    io.method = Method::dopri5;
    io.rtol = rtol;
    io.atol = 1e-3 * rtol;
    io.step = 0.01;
    return io;
  }
} // namespace

// Reference: harmonic balance (40 harmonics) of the linear time-varying equation, valid
// because the solution never leaves contact (checked: its minimum is > 0).
TEST(KahramanSingh, HarmonicBalanceWithoutImpacts)
{
  for (double W : {0.3, 0.75, 1.5})
    {
      DteModel m = test::kahraman_singh(W);
      const auto &law = static_cast<const FourierStiffnessLaw &>(m.law());
      const HarmonicBalance hb = harmonic_balance(law, 1.0, m.damping_coefficient(), 0.1, W, 40);
      ASSERT_GT(hb.minimum(), 0.0) << "HB solution has impacts at W = " << W;
      const Response r = point(W, dopri(1e-11));
      EXPECT_EQ(r.impact_regime, 0);
      EXPECT_NEAR(r.rms, hb.rms(), 1e-6 * hb.rms()) << "W = " << W;
      std::cout << "W " << W << ": RMS HB " << hb.rms() << ", DOPRI5 " << r.rms << ", rel. diff "
                << std::abs(r.rms - hb.rms()) / hb.rms() << "\n";
      EXPECT_NEAR(r.mean, hb.D[hb.N].real(), 1e-7) << "W = " << W;
    }
}

// Reference: DOPRI5 at rtol 1e-12 on an impacting case (contact loss near resonance).
TEST(KahramanSingh, TightToleranceReferenceWithImpacts)
{
  const double W = 0.95;
  const Response ref = point(W, dopri(1e-12));
  ASSERT_EQ(ref.impact_regime, 1);
  ASSERT_GT(ref.contact_loss_fraction, 0.1);
  IntegratorOptions rk4;
  rk4.method = Method::rk4;
  IntegratorOptions sdirk;
  sdirk.method = Method::sdirk3;
  const Response a = point(W, rk4, 128), b = point(W, dopri(1e-8)), c = point(W, sdirk, 512);
  EXPECT_NEAR(a.rms, ref.rms, 1e-5 * ref.rms);
  EXPECT_NEAR(b.rms, ref.rms, 1e-5 * ref.rms);
  EXPECT_NEAR(c.rms, ref.rms, 1e-3 * ref.rms);
  EXPECT_NEAR(a.dynamic_factor, ref.dynamic_factor, 1e-3 * ref.dynamic_factor);
  std::cout << "W 0.95 rel. RMS differences to the rtol 1e-12 reference: RK4 "
            << std::abs(a.rms / ref.rms - 1) << ", DOPRI5(1e-8) " << std::abs(b.rms / ref.rms - 1)
            << ", SDIRK3(512/period) " << std::abs(c.rms / ref.rms - 1) << "\n";
}

// Requirement: halving the step (fixed) or the tolerance (adaptive) changes RMS DTE by
// less than 0.1 % on a case with contact loss.
TEST(KahramanSingh, StepHalvingConvergence)
{
  const double W = 0.95;
  IntegratorOptions rk4;
  rk4.method = Method::rk4;
  const Response a = point(W, rk4, 64), b = point(W, rk4, 128);
  ASSERT_GT(a.contact_loss_fraction, 0.1);
  EXPECT_LT(std::abs(a.rms - b.rms) / b.rms, 1e-3);
  const Response c = point(W, dopri(1e-6)), d = point(W, dopri(0.5e-6));
  EXPECT_LT(std::abs(c.rms - d.rms) / d.rms, 1e-3);
  std::cout << "step halving RK4 64->128 steps/period: " << std::abs(a.rms - b.rms) / b.rms
            << "; DOPRI5 rtol 1e-6 -> 5e-7: " << std::abs(c.rms - d.rms) / d.rms << "\n";
}

// Published behaviour (Kahraman & Singh 1990, figs. 5-6): softening primary resonance, the
// up sweep jumps up at a higher frequency than the down sweep jumps down; single-sided
// impacts on the resonant branch; hysteresis between the branches.
TEST(KahramanSingh, SofteningResonanceWithJumps)
{
  DteModel m = test::kahraman_singh(0.6);
  IntegratorOptions rk4;
  rk4.method = Method::rk4;
  ResponseOptions ro;
  const auto pts = sweep_up_down(m, rk4, ro, 0.6, 1.2, 31, nullptr, 2);
  ASSERT_EQ(pts.size(), 62u);
  double jump_up = 0, w_up = 0, jump_down = 0, w_down = 0, max_split = 0;
  for (int i = 1; i < 31; ++i)
    {
      const auto &a = pts[i - 1].response, &b = pts[i].response;
      if (b.rms - a.rms > jump_up)
        jump_up = b.rms - a.rms, w_up = b.pinion_speed;
      const auto &c = pts[31 + i - 1].response, &d = pts[31 + i].response;
      if (c.rms - d.rms > jump_down)
        jump_down = c.rms - d.rms, w_down = d.pinion_speed;
      EXPECT_EQ(b.back_contact_fraction, 0.0); // single-sided at most
    }
  for (int i = 0; i < 31; ++i)
    max_split = std::max(max_split, std::abs(pts[i].response.rms - pts[61 - i].response.rms));
  std::cout << "jump up at W = " << w_up << " (+" << jump_up << "), jump down at W = " << w_down
            << " (-" << jump_down << ")\n";
  EXPECT_GT(w_up, w_down + 0.1);   // softening: hysteresis loop on the low-frequency side
  EXPECT_GT(jump_up, 0.04);        // a jump, not a smooth rise (rms ~0.06 -> 0.13)
  EXPECT_GT(jump_down, 0.1);
  EXPECT_GT(max_split, 0.1);
  EXPECT_LT(w_up, 1.0);            // below the linear natural frequency W = 1
  // On the resonant branch the impacts are single-sided: contact loss, no back contact.
  bool single_sided = false;
  for (const auto &p : pts)
    single_sided |= p.response.impact_regime == 1 && p.response.back_contact_fraction == 0;
  EXPECT_TRUE(single_sided);
}

// Published behaviour: a superharmonic resonance near W = 0.5 (half the natural frequency).
TEST(KahramanSingh, SuperharmonicNearHalf)
{
  DteModel m = test::kahraman_singh(0.35);
  IntegratorOptions rk4;
  rk4.method = Method::rk4;
  ResponseOptions ro;
  std::vector<double> w;
  for (int i = 0; i <= 15; ++i)
    w.push_back(0.36 + 0.02 * i);
  const auto pts = sweep(m, rk4, ro, w, 1, nullptr);
  std::size_t imax = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (pts[i].response.rms > pts[imax].response.rms)
      imax = i;
  const double w_peak = pts[imax].response.pinion_speed;
  std::cout << "superharmonic peak at W = " << w_peak << " rms " << pts[imax].response.rms << "\n";
  EXPECT_GT(w_peak, 0.44);
  EXPECT_LT(w_peak, 0.56);
  EXPECT_GT(pts[imax].response.rms, 1.5 * pts.front().response.rms);
  EXPECT_GT(pts[imax].response.rms, 1.5 * pts.back().response.rms);
}

// Bad input: speed range min >= max, zeta < 0.
TEST(KahramanSingh, BadInput)
{
  DteModel m = test::kahraman_singh(0.6);
  IntegratorOptions io;
  ResponseOptions ro;
  EXPECT_THROW(sweep_up_down(m, io, ro, 1.2, 0.6, 10, nullptr), gearfem::InputError);
  EXPECT_THROW(sweep_up_down(m, io, ro, 1.0, 1.0, 10, nullptr), gearfem::InputError);
  EXPECT_THROW(test::kahraman_singh(1.0, -0.01), gearfem::InputError);
  ro.samples_per_period = 0;
  EXPECT_THROW(ro.check(), gearfem::InputError);
}
