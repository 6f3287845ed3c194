// The per-run discretisation-error estimate (post/error_estimate.h) on a small case: 3-tooth
// sectors of the Parker pair (50/50, m 3, b 20) at 200 N m, at the three sample positions of
// the estimate. Three mesh levels h, h/2, h/4 (refined_mesh applied twice). Independent
// references:
// - the third, finer level: the estimate of the level-h error from levels h and h/2 must be
//   within a factor of 2 of Q_{h/4} - Q_h (asymptotically it is 1/(1 - 4^-p) = 1.07 times
//   it for p = 2), wherever that difference is above the noise floor of the solver and of
//   the sampling of the maxima;
// - the definition of the levels: the level-h/2 values of both estimates (h -> h/2 and
//   h/2 -> h/4) are solves of the same model at the same position, so they agree to the
//   solver tolerance whatever the warm start;
// - the algebra of Richardson extrapolation: error = (Q_{h/2} - Q_h) 4/3 for r = 2, p = 2.
#include "contact/gear_contact.h"
#include "common/fixtures.h"
#include "base/units.h"
#include "solve/input.h"
#include "solve/error_estimate.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>

using namespace gearfem;

namespace
{
  solve::GearContactInput parse_case()
  {
    const std::string text = gearfem::test::parker_pair(R"(
subsection Mesh
  set Model = sector
  set Sector teeth = 3
  set h_contact = 0.2
  set h_fillet = 0.4
  set h_body = 3
end
subsection Solve
  set Torques = 200
  set Error estimate = true
end
)");
    dealii::ParameterHandler prm;
    solve::declare_gear_contact_input(prm);
    prm.parse_input_from_string(text);
    return solve::parse_gear_contact_input(prm);
  }

  std::unique_ptr<contact::GearContactModel> model_at(const solve::GearContactInput &in, int level)
  {
    mesh::GearMeshParameters m[2] = {in.mesh[0], in.mesh[1]};
    for (int l = 0; l < level; ++l)
      for (int i = 0; i < 2; ++i)
        m[i] = solve::refined_mesh(m[i], 3e-3, 2.0);
    return std::make_unique<contact::GearContactModel>(*in.pair, m, in.material, in.fe, in.contact);
  }
} // namespace

TEST(ErrorEstimate, SampleMeshAndParameter)
{
  const auto in = parse_case();
  EXPECT_TRUE(in.solve.error_estimate);
  // The samples from the points of the line of action: (B+D)/2, (A+B)/2, D.
  const auto phi = solve::error_sample_positions(*in.pair);
  ASSERT_EQ(phi.size(), 3u);
  const double A = in.pair->point("A").roll_angle, B = in.pair->point("B").roll_angle,
               D = in.pair->point("D").roll_angle;
  EXPECT_TRUE(B < phi[0] && phi[0] < D);
  EXPECT_TRUE(A < phi[1] && phi[1] < B);
  EXPECT_DOUBLE_EQ(phi[2], D);
  // The fine sizes halve; the body sizes do not; the defaults follow (0 stays 0); an unset
  // h_contact (0: m/30) is resolved before halving.
  mesh::GearMeshParameters p = in.mesh[0];
  p.h_corner                 = 0.05e-3;
  const auto f               = solve::refined_mesh(p, 3e-3, 2.0);
  EXPECT_DOUBLE_EQ(f.h_contact, 0.1e-3);
  EXPECT_DOUBLE_EQ(f.h_fillet, 0.2e-3);
  EXPECT_DOUBLE_EQ(f.h_corner, 0.025e-3);
  EXPECT_EQ(f.h_coast, 0.0);
  EXPECT_EQ(f.h_body, p.h_body);
  p.h_contact = 0;
  EXPECT_DOUBLE_EQ(solve::refined_mesh(p, 3e-3, 2.0).h_contact, 0.05e-3);
  EXPECT_THROW(solve::refined_mesh(p, 3e-3, 1.0), InputError);
}

TEST(ErrorEstimate, AgainstAThirdLevel)
{
  const auto in  = parse_case();
  auto m0        = model_at(in, 0);
  auto m1        = model_at(in, 1);
  auto m2        = model_at(in, 2);
  const auto phi = solve::error_sample_positions(*in.pair);
  solve::ErrorEstimateOptions o;
  const auto e0 = solve::estimate_error(*m0, *m1, phi, in.solve.torques, o);
  const auto e1 = solve::estimate_error(*m1, *m2, phi, in.solve.torques, o);
  ASSERT_EQ(e0.samples.size(), 3u);
  ASSERT_EQ(e1.samples.size(), 3u);
  ASSERT_EQ(e0.max_relative.size(), 1u);
  EXPECT_EQ(e0.fine_dofs, m1->n_dofs());
  const auto &names = solve::EstimatedQuantities::names();
  int compared = 0, compared_ste = 0;
  for (std::size_t k = 0; k < 3; ++k)
    {
      const auto &s0 = e0.samples[k], &s1 = e1.samples[k];
      for (int i = 0; i < solve::EstimatedQuantities::size; ++i)
        {
          const double q0 = s0.coarse[i], q1 = s0.fine[i], q2 = s1.fine[i];
          ASSERT_TRUE(std::isfinite(s0.error[i]) && std::isfinite(s0.relative[i]));
          ASSERT_GT(std::abs(q0), 0.0) << names[i];
          // Richardson algebra, r = 2, p = 2.
          EXPECT_NEAR(s0.error[i], (q1 - q0) * 4.0 / 3.0, 1e-12 * std::abs(q0));
          EXPECT_NEAR(s0.relative[i], std::abs(s0.error[i] / q0), 1e-14);
          // Level h/2 of both estimates: the same model and position.
          EXPECT_NEAR(s1.coarse[i], q1, 1e-6 * std::abs(q1)) << names[i] << ", sample " << k;
          EXPECT_LE(s0.relative[i], e0.max_relative[0].second[i]);
          // Against the third level, above the noise floor: 0.05 % of the value; 0.2 % for the
          // root stresses, whose fitted fillet peak (fem/stress_peak.h) scatters by about
          // +-0.15 % from one mesh to the next once converged (the Siasos 2010 23/69 pinion
          // at h_fillet 0.2 / 0.15 / 0.1 / 0.05 mm: +0.04 / +0.02 / -0.12 / -0.13 % against
          // its reference), while its error at level h here is 0.25-1.7 %.
          const bool root    = std::string(names[i]).rfind("root_stress", 0) == 0;
          const double floor = root ? 2e-3 : 5e-4;
          const double truth = q2 - q0, ratio = s0.error[i] / truth;
          std::cout << "sample " << k << " (roll " << s0.phi1 / gearfem::units::deg << " deg) " << names[i] << ": Q h, h/2, h/4 "
                    << q0 << ", " << q1 << ", " << q2 << " (SI); estimate " << s0.error[i] << ", Q_{h/4} - Q_h "
                    << truth << ", ratio " << ratio << "\n";
          if (std::abs(truth) > floor * std::abs(q0))
            {
              ++compared, compared_ste += i == 0;
              EXPECT_GE(ratio, 0.5) << names[i] << ", sample " << k;
              EXPECT_LE(ratio, 2.0) << names[i] << ", sample " << k;
            }
        }
    }
  std::cout << compared << " of 12 estimates above the noise floor compared with the third level\n";
  EXPECT_GE(compared_ste, 2);
  EXPECT_GE(compared, 6);
}
