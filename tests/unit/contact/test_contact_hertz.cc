// Contact solver against the 2-D Hertz closed form (Johnson 1985, sec. 4.3): two discs,
// both methods, plane stress and plane strain, equal and dissimilar radii and materials.
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
