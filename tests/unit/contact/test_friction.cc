// Coulomb friction in the gear contact (docs/friction.md) on the coarse demo pair (Parker
// 50/50, m 3, b 20), and the friction-coefficient laws. References: the closed-form sliding
// speed of an involute pair v_s = (w1 + w2) |s| at distance s from the pitch point along the
// line of action; conservation of energy (input power = output power + dissipation + the work
// of the normal forces off the line of action); Coulomb's law itself (|f| = mu lambda where
// the flanks slide); the friction direction on a driver (away from the pitch point, Dudley's
// Handbook of Practical Gear Design); the laws' formulas evaluated here by hand.
#include "base/errors.h"
#include "base/units.h"
#include "common/fixtures.h"
#include "analytical/friction.h"
#include "contact/gear_contact.h"
#include "post/position.h"
#include "solve/input.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>

using namespace gearfem;
using namespace gearfem::contact;
using gearfem::units::pi;
namespace friction = gearfem::analytical::friction;

namespace
{
  const std::string demo_prm = gearfem::test::parker_pair(R"(
subsection Mesh
  set h_contact = 0.5
  set h_fillet = 0.5
  set h_body = 5
end
)");

  struct Setup
  {
    solve::GearContactInput in;
    Setup()
    {
      dealii::ParameterHandler prm;
      solve::declare_gear_contact_input(prm);
      prm.parse_input_from_string(demo_prm);
      in = solve::parse_gear_contact_input(prm);
    }
    std::unique_ptr<GearContactModel> model(double mu, Method method = Method::lagrange) const
    {
      ContactOptions o;
      o.friction = mu;
      o.method   = method;
      return std::make_unique<GearContactModel>(*in.pair, in.mesh, in.material, in.fe, o);
    }
  };
  Setup &setup()
  {
    static Setup s;
    return s;
  }
  GearContactModel &frictional()
  {
    static auto m = setup().model(0.05);
    return *m;
  }
  GearContactModel &frictionless()
  {
    static auto m = setup().model(0.0);
    return *m;
  }
  post::PositionResult evaluate(GearContactModel &m, const ContactState &s)
  {
    post::PostOptions o;
    o.pinion_speed = 1.0; // powers per unit pinion speed [W s/rad = N m]
    return post::evaluate_position(m, s, o);
  }
  const double pitch = 2 * pi / 50;
} // namespace

TEST(FrictionLaw, FormulasByHand)
{
  // AGMA 925-A03: 0.06 C_R, C_R = 1.13 / (1.13 - 0.5) for Ra 0.4 and 0.6 um.
  EXPECT_NEAR(friction::agma_925(0.4e-6, 0.6e-6), 0.06 * 1.13 / 0.63, 1e-15);
  EXPECT_NEAR(friction::agma_925(0.01e-6, 0.01e-6), 0.06 * 1.13 / 1.12, 1e-15);
  EXPECT_NEAR(friction::agma_925(0.8e-6, 0.8e-6), 0.18, 1e-12); // C_R = 3.4 capped at 3
  // ISO/TR 14179-2: 0.048 (500 / (10 * 12))^0.2 * 30^-0.05 * 0.5^0.25 * 1.
  friction::PitchPoint c;
  c.load_per_width = 500e3, c.v_sum = 10, c.rho_red = 12e-3;
  const double expected = 0.048 * std::pow(500.0 / 120.0, 0.2) * std::pow(30.0, -0.05) * std::pow(0.5, 0.25);
  EXPECT_NEAR(friction::iso_14179_2(c, 30e-3, 0.4e-6, 0.6e-6, 1.0) / expected, 1.0, 1e-12);
}

TEST(FrictionLaw, PitchPointAndOhlendorfOfTheDemoPair)
{
  const auto &pair = *setup().in.pair;
  // Standard 50/50 m 3 pair at a = 150 mm: r_w = 75 mm, alpha_w = 20 deg, r_b = 75 cos 20,
  // tip radius 78 mm (ISO 21771).
  const double a20 = 20 * pi / 180, rb = 75e-3 * std::cos(a20), ra = 78e-3, pb = 2 * pi * rb / 50;
  const auto c = friction::pitch_point(pair, 200.0, 100.0, 20e-3);
  EXPECT_NEAR(c.load_per_width / (200.0 / rb / 20e-3), 1.0, 1e-9);
  EXPECT_NEAR(c.v_sum / (2 * 100.0 * 75e-3 * std::sin(a20)), 1.0, 1e-9);
  EXPECT_NEAR(c.rho_red / (0.5 * rb * std::tan(a20)), 1.0, 1e-9);
  // Addendum contact ratios from the tip and base radii; H_V of ISO/TR 14179-2.
  const double eps1 = (std::sqrt(ra * ra - rb * rb) - 75e-3 * std::sin(a20)) / pb;
  const double hv   = pi * 2.0 / 50.0 * (1.0 - 2 * eps1 + 2 * eps1 * eps1);
  EXPECT_NEAR(friction::ohlendorf_hv(pair) / hv, 1.0, 1e-6);
}

TEST(FrictionLaw, LawWithoutItsInputsNamesTheEntry)
{
  friction::LawInputs in;
  in.law          = friction::Law::iso_14179_2;
  in.pinion_speed = 100;
  in.Ra1 = in.Ra2 = 0.4e-6;
  try
    {
      friction::check(in);
      FAIL() << "no error";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("Contact/Oil viscosity"), std::string::npos) << e.what();
    }
  in.law = friction::Law::constant;
  in.mu  = 1.5;
  EXPECT_THROW(friction::check(in), InputError);
}

TEST(Friction, ZeroCoefficientIsTheFrictionlessSolveBitForBit)
{
  auto zero       = setup().model(0.0);
  const double phi = 0.3 * pitch;
  const auto a    = frictionless().solve(phi, 200.0);
  const auto b    = zero->solve(phi, 200.0);
  EXPECT_EQ(a.solution.q, b.solution.q);
  ASSERT_EQ(a.solution.points.size(), b.solution.points.size());
  for (std::size_t i = 0; i < a.solution.points.size(); ++i)
    {
      EXPECT_EQ(a.solution.points[i].force, b.solution.points[i].force);
      EXPECT_EQ(b.solution.points[i].friction, 0.0);
    }
}

TEST(Friction, EnergyBalanceAndClosedFormSlidingSpeed)
{
  const auto &pair = *setup().in.pair;
  const double mu = 0.05, T = 200.0, rb1 = pair.base_radius(1);
  const double phiA = pair.point("A").roll_angle;
  for (const double phi : {phiA + 0.3 * pitch, -0.3 * pitch * 0.3, 0.1 * pitch})
    {
      const auto s = frictional().solve(phi, T);
      const auto r = evaluate(frictional(), s);
      ASSERT_TRUE(s.solution.converged);
      // The torque target includes the friction moments.
      EXPECT_NEAR(r.torque_contact / T, 1.0, 1e-9);
      // Conservation (w1 = 1): T1 - T2 z1/z2 = dissipation + work of the normal forces, to
      // 0.5 % of the dissipation (the moments act at the nodes, the velocities are taken at
      // the gap points: on this 0.5 mm mesh they differ by 1e-4 of the loss).
      const double balance = r.torque_contact - r.torque_gear - (r.power_loss + r.normal_power);
      EXPECT_LT(std::abs(balance), 5e-3 * r.power_loss) << "phi " << phi;
      // Coulomb: |f| = mu lambda at every contact point that slides faster than the ramp.
      for (const auto &p : s.solution.points)
        if (p.force > 0 && std::abs(p.sliding) > 1e-3 * 75e-3)
          EXPECT_NEAR(std::abs(p.friction), mu * p.force, 1e-9 * p.force);
      // The dissipation against the closed form: pair i at distance s_i = r_b1 (phi - psi_C +
      // k 2 pi / z1) from C slides at (1 + z1/z2) |s_i| per unit pinion speed.
      double closed = 0;
      for (const auto &tp : r.pairs)
        {
          const double si = rb1 * (frictional().tooth_roll(1, tp.pinion_tooth, phi));
          closed += mu * tp.force * 2.0 * std::abs(si);
        }
      std::cout << "phi " << phi / pitch << " pitches: loss " << r.power_loss << " N m/rad, closed form " << closed
                << ", normal-force power " << r.normal_power << "\n";
      EXPECT_NEAR(r.power_loss / closed, 1.0, 0.03);
    }
}

TEST(Friction, ForceOnTheDrivingPinionPointsAwayFromThePitchPoint)
{
  const auto &pair = *setup().in.pair;
  const double phiA = pair.point("A").roll_angle;
  const auto s      = frictional().solve(phiA + 0.3 * pitch, 200.0);
  const auto r      = evaluate(frictional(), s);
  ASSERT_EQ(r.pairs.size(), 2u);
  for (const auto &tp : r.pairs)
    {
      const double psi = frictional().tooth_roll(1, tp.pinion_tooth, phiA + 0.3 * pitch);
      // Approach (psi < 0, contact below the pitch circle of the pinion): towards its root.
      EXPECT_EQ(tp.friction < 0, psi < 0) << "tooth " << tp.pinion_tooth << " at " << psi;
      EXPECT_NEAR(std::abs(tp.friction), 0.05 * tp.force, 1e-6 * tp.force);
    }
}

TEST(Friction, PenaltyAgreesWithLagrangeAndTangentIsConsistent)
{
  auto pen         = setup().model(0.05, Method::penalty);
  const double phi = 0.3 * pitch;
  const auto a     = frictional().solve(phi, 200.0);
  const auto b     = pen->solve(phi, 200.0);
  const auto ra = evaluate(frictional(), a), rb = evaluate(*pen, b);
  EXPECT_NEAR(rb.ste / ra.ste, 1.0, 0.005);
  EXPECT_NEAR(rb.power_loss / ra.power_loss, 1.0, 0.005);
  // Rotation control at the rotation torque targeting found gives back the torque, and the
  // consistent (non-symmetric) tangent matches a finite difference.
  const auto rr = frictional().solve_rotation(phi, a.rotation());
  EXPECT_NEAR(rr.torque / 200.0, 1.0, 1e-6);
  const auto c = frictional().solve(phi, 202.0, &a.solution);
  const double k_fd = (c.torque - a.torque) / (c.rotation() - a.rotation());
  EXPECT_NEAR(a.solution.tangent / k_fd, 1.0, 0.02);
}

TEST(Friction, ReversesAsTheContactCrossesThePitchPoint)
{
  // The sliding speed of a point is 2 w1 times its distance from C along the line of action
  // (1:1 pair); a patch lies across the line of action, so all its points slide alike and the
  // whole patch reverses as the contact passes C. 1e-3 rad of roll either side of C (70 um of
  // path) is far outside the ramp (1e-4 of the pitch-line speed, 3.8 um of path): every point
  // carries mu lambda, against its sliding, and the two sides have opposite signs.
  // A 3-tooth sector pair with 0.05 mm contact elements: about 12 nodes across the patch.
  dealii::ParameterHandler prm;
  solve::declare_gear_contact_input(prm);
  prm.parse_input_from_string(gearfem::test::parker_pair(R"(
subsection Mesh
  set Model        = sector
  set Sector teeth = 3
  set h_contact    = 0.05
  set h_fillet     = 0.5
  set h_body       = 5
end
)"));
  const auto in = solve::parse_gear_contact_input(prm);
  ContactOptions o;
  o.friction = 0.05;
  GearContactModel model(*in.pair, in.mesh, in.material, in.fe, o);
  const double rb1 = in.pair->base_radius(1);
  for (const double phi : {-1e-3, 1e-3})
    {
      const auto s = model.solve(phi, 200.0);
      int n = 0;
      for (const auto &p : s.solution.points)
        {
          if (!(p.force > 0))
            continue;
          ++n;
          // Closed form: v_s = 2 (phi rb1) per unit pinion speed, to the elastic shift of the
          // material points in contact (a few um of path).
          EXPECT_NEAR(std::abs(p.sliding), 2 * std::abs(phi) * rb1, 0.1 * 2 * std::abs(phi) * rb1);
          EXPECT_NEAR(std::abs(p.friction), 0.05 * p.force, 1e-9 * p.force);
          EXPECT_LT(p.friction * p.sliding, 0.0); // against the slave's sliding
          EXPECT_EQ(p.sliding > 0, phi < 0) << "the sign flips between approach and recess";
        }
      EXPECT_GE(n, 5) << "contact points across the patch";
    }
}
