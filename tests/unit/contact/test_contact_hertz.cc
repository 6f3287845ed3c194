// Contact solver against the 2-D Hertz closed form (Johnson 1985, sec. 4.3): two discs,
// both methods, plane stress and plane strain, equal and dissimilar radii, materials and
// thicknesses (face widths).
#include "base/units.h"
#include "contact/hertz.h"

#include <gtest/gtest.h>

#include <iostream>

using namespace gearfem;
using namespace gearfem::contact;

namespace
{
  void print(const char *name, const HertzResult &r)
  {
    std::cout << name << ": DoFs " << r.n_dofs << ", h " << r.h_contact * 1e3 << " mm, active "
              << r.n_active << ", p0 fit/exact " << r.p0_fit / r.p0_exact << ", p0 nodal/exact "
              << r.p0_nodal / r.p0_exact << ", a fit/exact " << r.a_fit / r.a_exact
              << ", profile RMS " << r.profile_error << ", geometry it "
              << r.solution.geometry_iterations << ", " << r.seconds << " s\n";
  }
} // namespace

TEST(Hertz, LagrangePlaneStressEqualDiscs)
{
  HertzCase c;
  c.h_contact = 0; // a/8
  const auto r = solve_hertz(c);
  print("lagrange plane stress", r);
  EXPECT_LT(r.force_balance, 1e-9);               // equilibrium: sum of nodal forces = F
  EXPECT_NEAR(r.p0_fit / r.p0_exact, 1.0, 0.015);  // closed form p0
  EXPECT_NEAR(r.a_fit / r.a_exact, 1.0, 0.03);     // closed form a
  EXPECT_LT(r.profile_error, 0.05);                // elliptical profile
}

TEST(Hertz, PenaltyPlaneStrainDissimilar)
{
  HertzCase c;
  c.R2 = 35e-3, c.E2 = 110e9, c.nu2 = 0.34;
  c.model  = fem::PlaneModel::plane_strain;
  c.method = Method::penalty;
  const auto r = solve_hertz(c);
  print("penalty plane strain dissimilar", r);
  EXPECT_LT(r.force_balance, 1e-9);
  EXPECT_NEAR(r.p0_fit / r.p0_exact, 1.0, 0.015);
  EXPECT_NEAR(r.a_fit / r.a_exact, 1.0, 0.03);
  EXPECT_LT(r.profile_error, 0.05);
}

TEST(Hertz, UnequalThicknessesPressureOverTheCommonWidth)
{
  // A 10 mm disc against a 7 mm one (a 75 mm pinion against a 70 mm gear, scaled): each body
  // deforms with its own thickness, and the line load acts over the common 7 mm. Closed form
  // of the 2-D model (hertz.h): a^2 = 4 F R (1/(E t1) + 1/(E t2)) / pi, p0 = 2 F / (pi a t_min).
  // The pressure is recovered on the wider body's slave surface and must still carry the load
  // over the common width (equilibrium: pi a p0 t_min / 2 = F).
  HertzCase c;
  c.thickness = 10e-3, c.thickness2 = 7e-3;
  c.slave     = 1;
  const auto r = solve_hertz(c);
  print("lagrange plane stress, 10 mm against 7 mm", r);
  EXPECT_LT(r.force_balance, 1e-9);
  EXPECT_NEAR(r.p0_fit / r.p0_exact, 1.0, 0.015);
  EXPECT_NEAR(r.a_fit / r.a_exact, 1.0, 0.03);
  EXPECT_NEAR(units::pi * r.a_fit * r.p0_fit * 7e-3 / 2 / c.force, 1.0, 0.03);
  // Equal thicknesses reduce to the classical form.
  HertzCase e;
  const auto [a0, p0] = hertz_closed_form(e);
  e.thickness2        = e.thickness;
  EXPECT_DOUBLE_EQ(hertz_closed_form(e).first, a0);
  EXPECT_DOUBLE_EQ(hertz_closed_form(e).second, p0);
}
