// Pair kinematics against the source theses' published numbers and against independent
// computations (conjugate search, law of gearing, outline-measured backlash).
#include "geometry/pair.h"
#include "base/units.h"
#include "base/errors.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace gearfem::geometry;

namespace
{
  const double deg = gearfem::units::pi / 180, mm = 1e-3;

  GearParameters gear(const std::string &name, int z, double m, double x = 0)
  {
    GearParameters g;
    g.name                = name;
    g.teeth               = z;
    g.profile_shift       = x;
    g.face_width          = 20 * mm;
    g.rack.module         = m;
    g.rack.pressure_angle = 20 * deg;
    return g;
  }

  GearPair make_pair(int z1, int z2, double m, double x1 = 0, double x2 = 0, double a = 0)
  {
    auto g1 = ToothProfile::generate(gear("Gear 1", z1, m, x1));
    auto g2 = ToothProfile::generate(gear("Gear 2", z2, m, x2));
    return GearPair(g1, g2, PairParameters{a});
  }

  /// The B-spline rack used for the non-involute checks: a 20 deg rack flank with a hollow
  /// of 0.03 m (steeper near the tooth root, so no undercut for z = 19), degree 4,
  /// 5 control points (Koronaios 2021 case 1 shape).
  std::vector<Vec2> bulged_rack()
  {
    std::vector<Vec2> cp;
    for (double v : {1.0, 0.5, 0.0, -0.5, -1.0})
      cp.emplace_back(gearfem::units::pi / 4 - v * std::tan(20 * deg) - 0.03 * (1 - v * v), v);
    return cp;
  }

  /// Law of gearing at pinion position phi1: the contact point lies on both placed flanks,
  /// the normals are opposite, and the common normal passes through the pitch point C.
  /// Returns the largest residual [m].
  double gearing_residual(const GearPair &pair, double phi1)
  {
    const Vec2 P = pair.contact_point(phi1), C(0.0, pair.working_pitch_radius(1));
    double     res = 0;
    Vec2       n[3];
    for (int i : {1, 2})
      {
        const auto pl = pair.placement(i, phi1);
        double     best = 1e9;
        for (int k = -1; k <= 1; ++k)
          for (int s : pair.gear(i).flank_segments(Side::drive))
            {
              const auto &sg = pair.gear(i).segments()[s];
              Placement   plk{pl.centre, pl.angle + k * pair.gear(i).angular_pitch()};
              const Vec2  qb = Eigen::Rotation2Dd(-plk.angle) * (P - plk.centre);
              const double tc = sg.curve->closest_parameter_in(qb, sg.t0, sg.t1);
              const double d  = (sg.curve->point(tc) - qb).norm();
              if (d < best)
                best = d, n[i] = plk.apply_vector((sg.t1 >= sg.t0 ? 1.0 : -1.0) * sg.curve->right_normal(tc));
            }
        res = std::max(res, best);
      }
    const Vec2 CP = C - P;
    res = std::max(res, std::abs(n[1].x() * CP.y() - n[1].y() * CP.x()));
    res = std::max(res, (n[1] + n[2]).norm() * CP.norm());
    return res;
  }
} // namespace

// Gkimisis 2019, Table 1 pair: 32/60, m 3, alpha 20 deg: R_g1 = 45.105 mm and
// contact ratio 1.72-1.73.
TEST(Pair, Seed000Table1)
{
  const auto pair = make_pair(32, 60, 3 * mm);
  EXPECT_NEAR(pair.base_radius(1), 45.105 * mm, 0.0005 * mm);
  EXPECT_GE(pair.contact_ratio(), 1.72);
  EXPECT_LE(pair.contact_ratio(), 1.73);
  std::cout << "[Gkimisis 2019] R_g1 = " << pair.base_radius(1) / mm
            << " mm, eps = " << pair.contact_ratio() << std::endl;
}

// Siasos 2010, 23/69, m 4 (AGMA 908): C2, C3, C4 per unit module 3.33, 3.93,
// 4.22 and contact ratio ~1.70.
TEST(Pair, Seed001LineOfAction)
{
  const double m    = 4 * mm;
  const auto   pair = make_pair(23, 69, m);
  const double c2 = pair.point("B").g / m, c3 = pair.point("C").g / m, c4 = pair.point("D").g / m;
  EXPECT_NEAR(c2, 3.33, 0.005);
  EXPECT_NEAR(c3, 3.93, 0.005);
  EXPECT_NEAR(c4, 4.22, 0.005);
  EXPECT_NEAR(pair.contact_ratio(), 1.70, 0.01);
  std::cout << "[Siasos 2010] C2 = " << c2 << ", C3 = " << c3 << ", C4 = " << c4
            << ", eps = " << pair.contact_ratio() << std::endl;
  // Independent: the LoA points lie on their circles (A on gear 2's tip, E on the pinion's).
  EXPECT_NEAR(pair.point("E").r1, 50 * mm, 1e-12);
  EXPECT_NEAR(pair.point("A").r2, 142 * mm, 1e-12);
  EXPECT_NEAR(pair.point("C").r1, 46 * mm, 1e-12);
  EXPECT_NEAR(pair.point("T1").r1, pair.base_radius(1), 1e-12);
  EXPECT_NEAR(pair.point("T2").r2, pair.base_radius(2), 1e-12);
  EXPECT_NEAR(pair.tip_clearance(1), 0.25 * m, 1e-12); // a - ra1 - rf2 = c* m
}

// Koronaios 2021, 19/55, m 2.5: pitch-point equivalent curvature 0.1656 1/mm
// (digest's recomputation) and contact ratio 1.657.
TEST(Pair, Seed003Curvature)
{
  const auto   pair = make_pair(19, 55, 2.5 * mm);
  const double k    = pair.equivalent_curvature(0.0) * mm;
  EXPECT_NEAR(k, 0.1656, 0.0001);
  EXPECT_NEAR(pair.contact_ratio(), 1.657, 0.001);
  std::cout << "[Koronaios 2021] 1/R(C) = " << k << " 1/mm, eps = " << pair.contact_ratio() << std::endl;
  // Independent: the profile curvatures of the generated outlines at the pitch point.
  double kp = 0;
  for (int i : {1, 2})
    {
      const auto &g = pair.gear(i);
      for (int s : g.flank_segments(Side::coast))
        {
          const auto  &sg = g.segments()[s];
          const double r  = pair.working_pitch_radius(i);
          // Find the coast flank point at the pitch radius by bisection.
          double a = sg.t0, b = sg.t1;
          for (int it = 0; it < 200; ++it)
            {
              const double c = 0.5 * (a + b);
              ((sg.curve->point(c).norm() > r) == (sg.curve->point(sg.t1).norm() > r) ? b : a) = c;
            }
          kp += -sg.curve->curvature(0.5 * (a + b)); // traversed with decreasing t
        }
    }
  EXPECT_NEAR(kp * mm, k, 1e-6);
}

// FZG type C: z 16/24, m 4.5, x 0.1817/0.1715: the centre distance from the shifts is
// 91.5 mm (<= 0.05 mm).
TEST(Pair, FzgTypeCCentreDistance)
{
  const double a = center_distance_from_shifts(4.5 * mm, 20 * deg, 16, 24, 0.1817, 0.1715);
  EXPECT_NEAR(a, 91.5 * mm, 0.05 * mm);
  std::cout << "[FZG C] a = " << a / mm << " mm" << std::endl;
  const auto pair = make_pair(16, 24, 4.5 * mm, 0.1817, 0.1715);
  EXPECT_NEAR(pair.center_distance(), a, 1e-15);
  EXPECT_NEAR(pair.circumferential_backlash(), 0.0, 1e-12); // zero-backlash by definition
}

// Backlash from the allowances and from a centre distance above the zero-backlash one,
// against the thickness measured on the generated outlines at the working pitch circles.
TEST(Pair, BacklashMatchesOutline)
{
  auto g1                = gear("Gear 1", 21, 3 * mm, 0.1);
  auto g2                = gear("Gear 2", 37, 3 * mm, -0.05);
  g1.thickness_allowance = 0.05 * mm;
  g2.thickness_allowance = 0.08 * mm;
  GearPair pair(ToothProfile::generate(g1), ToothProfile::generate(g2), PairParameters{88.4 * mm});
  const double rw1 = pair.working_pitch_radius(1), rw2 = pair.working_pitch_radius(2);
  const double jt  = 2 * gearfem::units::pi * rw1 / 21 - pair.gear(1).thickness_at_radius(rw1) -
                    pair.gear(2).thickness_at_radius(rw2);
  EXPECT_NEAR(pair.circumferential_backlash(), jt, 1e-12);
  EXPECT_NEAR(pair.normal_backlash(), jt * std::cos(pair.working_pressure_angle()), 1e-12);
  EXPECT_GT(jt, 0.13 * mm);
  EXPECT_NEAR(rw1 + rw2, 88.4 * mm, 1e-12);
  // Zero-backlash centre distance: the backlash vanishes there.
  GearPair tight(ToothProfile::generate(g1), ToothProfile::generate(g2),
                 PairParameters{pair.zero_backlash_center_distance()});
  EXPECT_NEAR(tight.circumferential_backlash(), 0.0, 1e-12);
  // Below it: negative backlash is an error naming the centre distance.
  EXPECT_THROW(GearPair(ToothProfile::generate(g1), ToothProfile::generate(g2),
                        PairParameters{pair.zero_backlash_center_distance() - 0.01 * mm}),
               gearfem::InputError);
}

// The gap-closing search on the exact outlines reproduces the closed-form conjugate angle
// of an involute pair, and the law of gearing holds at every sampled contact point.
TEST(Pair, ConjugateSearchAndLawOfGearingInvolute)
{
  const auto pair = make_pair(19, 55, 2.5 * mm, 0.2, 0.1, 0);
  for (double phi1 = -gearfem::units::pi / 19; phi1 <= gearfem::units::pi / 19 + 1e-12; phi1 += gearfem::units::pi / 19 / 4)
    {
      EXPECT_NEAR(pair.conjugate_angle_by_search(phi1), pair.conjugate_angle(phi1), 1e-10)
        << "phi1 " << phi1;
      EXPECT_LT(gearing_residual(pair, phi1), 1e-9) << "phi1 " << phi1;
    }
}

// Law of gearing for a B-spline rack pair (Koronaios 2021 case 1 construction): gear 1 from the
// B-spline rack, gear 2 from the complementary rack, gear 2 placed by the search.
TEST(Pair, LawOfGearingBSplineRack)
{
  auto g1                = gear("Gear 1", 19, 2.5 * mm);
  auto g2                = gear("Gear 2", 55, 2.5 * mm);
  g1.rack.kind           = RackParameters::Kind::bspline_rack;
  g1.rack.control_points = bulged_rack();
  const auto p1          = ToothProfile::generate(g1);
  const auto p2          = ToothProfile::generate_mate(g2, p1);
  GearPair   pair(p1, p2, PairParameters{});
  EXPECT_FALSE(pair.is_involute());
  EXPECT_GT(pair.contact_ratio(), 1.0);
  const double phiA = pair.point("A").roll_angle, phiE = pair.point("E").roll_angle;
  EXPECT_LT(phiA, 0.0);
  EXPECT_GT(phiE, 0.0);
  for (double phi1 = -gearfem::units::pi / 19; phi1 <= gearfem::units::pi / 19 + 1e-12; phi1 += gearfem::units::pi / 19 / 4)
    EXPECT_LT(gearing_residual(pair, phi1), 1e-9) << "phi1 " << phi1;
  // The transmission is uniform: gear 2 turns by exactly -phi1 z1/z2 (conjugate racks).
  const double b0 = pair.conjugate_angle(0.0), b1 = pair.conjugate_angle(0.1);
  EXPECT_NEAR(b1 - b0, -0.1 * 19.0 / 55.0, 1e-9);
  // At the pitch point the rack curvature cancels between the two gears (Euler-Savary:
  // both see the same rack with opposite curvature) and the equivalent curvature equals the
  // involute pair's, as the rack's local pressure angle there is 20 deg; away from C the
  // hollow rack changes it.
  const auto inv = make_pair(19, 55, 2.5 * mm);
  EXPECT_NEAR(pair.equivalent_curvature(0.0), inv.equivalent_curvature(0.0), 1e-9 / mm);
  EXPECT_GT(std::abs(pair.equivalent_curvature(0.12) - inv.equivalent_curvature(0.12)),
            0.001 / mm);
}

// B-spline flank (Koronaios 2021 case 2): the gear-1 flank is the spline itself; its rack is
// recovered by involutisation and the mate is generated from the complementary rack.
// An involute given as a B-spline-free control polygon is not exact, so we check the
// law of gearing and that the gear-1 flank passes through its control-point spline.
TEST(Pair, BSplineFlankPair)
{
  const double m  = 2.5 * mm;
  auto         g1 = gear("Gear 1", 19, m);
  auto         g2 = gear("Gear 2", 55, m);
  // Control points close to the involute of the standard 19-tooth gear (x > 0 side).
  const auto ref = ToothProfile::generate(g1);
  const auto &fl = ref.segments()[ref.flank_segments(Side::coast).front()];
  std::vector<Vec2> cp;
  for (int k = 0; k < 9; ++k) // degree 4, 9 control points from above the base circle to past the tip
    cp.push_back(fl.curve->point(fl.t0 + (0.15 + 0.88 * k / 8) * (fl.t1 - fl.t0)) / m);
  g1.rack.kind           = RackParameters::Kind::bspline_flank;
  g1.rack.control_points = cp;
  const auto p1          = ToothProfile::generate(g1);
  const auto p2          = ToothProfile::generate_mate(g2, p1);
  GearPair   pair(p1, p2, PairParameters{});
  for (double phi1 = -gearfem::units::pi / 19; phi1 <= gearfem::units::pi / 19 + 1e-12; phi1 += gearfem::units::pi / 19 / 4)
    EXPECT_LT(gearing_residual(pair, phi1), 1e-9) << "phi1 " << phi1;
  EXPECT_NEAR(pair.contact_ratio(), make_pair(19, 55, m).contact_ratio(), 0.05);
}

// The case-2 optimum of Koronaios 2021 (gearfem optimise, SLSQP): a B-spline flank whose
// recovered rack presses the cutter-tip constraint, so the cutter tip is a full round (no root land on
// the pinion; Profile.FullRoundCutterTip). Gear 2 is generated from the complementary
// rack, so the transmission is exactly uniform (conservation of the conjugate motion):
// the gap-closing search must give beta = beta_A - (phi1 - phi_A) z1/z2 over the whole mesh
// cycle. Landing two gear-2 pitches away (at 4 of 20 positions, a wrong tooth reduction in
// the gap) would put the FE sector's teeth out of mesh (STE 350-580 um).
TEST(Pair, ConjugateSearchWholeCycleSeed003Case2Optimum)
{
  auto g1 = gear("Gear 1", 19, 2.5 * mm), g2 = gear("Gear 2", 55, 2.5 * mm);
  g1.rack.kind           = RackParameters::Kind::bspline_flank;
  g1.rack.spline_degree  = 4;
  g1.rack.control_points = {Vec2(1.0035311649, 8.64301808927), Vec2(0.849228676792, 9.45855974839),
                            Vec2(0.841196850787, 9.33073590815), Vec2(0.960357936752, 9.69383419948),
                            Vec2(0.343635708986, 10.4953759103)};
  const auto p1 = ToothProfile::generate(g1);
  const auto p2 = ToothProfile::generate_mate(g2, p1);
  for (const auto &s : p1.segments())
    EXPECT_NE(s.type, SegmentType::root) << "full-round cutter tip: no root land";
  GearPair     pair(p1, p2, PairParameters{});
  const double phiA = pair.point("A").roll_angle, b0 = pair.conjugate_angle(phiA);
  for (int k = 0; k <= 40; ++k)
    {
      const double phi1 = phiA + 2 * gearfem::units::pi / 19 * k / 40;
      EXPECT_NEAR(pair.conjugate_angle(phi1), b0 - (phi1 - phiA) * 19.0 / 55.0, 1e-9) << "position " << k;
      EXPECT_LT(gearing_residual(pair, phi1), 1e-9) << "position " << k;
    }
}

// Pair design checks: interference / undercut cutting the active profile, contact ratio.
TEST(Pair, DesignChecks)
{
  auto expect_error = [](auto f, const std::string &name) {
    try
      {
        f();
        ADD_FAILURE() << "no error for " << name;
      }
    catch (const gearfem::InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      }
  };
  // z = 10 pinion, no shift, against a large gear: the undercut removes active profile.
  expect_error([] { make_pair(14, 14, 3 * mm); }, "Gear 1/Profile shift coefficient");
  // z = 10 pinion against a large gear: the gear's tip passes the interference point T1.
  expect_error([] { make_pair(10, 60, 3 * mm); }, "Gear 2/Tip shortening coefficient");
  // Centre distance too large: contact ratio below 1.
  expect_error([] { make_pair(20, 20, 3 * mm, 0, 0, 62.5 * mm); }, "Pair/Centre distance");
  // Centre distance below the tip clearance limit.
  expect_error([] { make_pair(20, 40, 3 * mm, 0, 0, 88 * mm); }, "Pair/Centre distance");
}

// Closed racks (Koronaios 2021 case 1 and the sinusoid: a level crest on the tooth axis, a level
// trough in the middle of the cutter tooth; no cutter tip). The case-1 start, the sinusoid
// fit (0, 1), (pi/8, 1), (pi/4, 0), (3pi/8, -1), (pi/2, -1) in module units.
TEST(Pair, ClosedRackTeethAndRefusedPath)
{
  const double m  = 2.5 * mm;
  auto         g1 = gear("Gear 1", 19, m);
  auto         g2 = gear("Gear 2", 55, m);
  g1.rack.kind           = RackParameters::Kind::bspline_rack;
  g1.rack.control_points = {{0, 1}, {gearfem::units::pi / 8, 1}, {gearfem::units::pi / 4, 0}, {3 * gearfem::units::pi / 8, -1}, {gearfem::units::pi / 2, -1}};
  g1.rack.dedendum       = 1.0;
  g1.tip_shortening = g2.tip_shortening = 0.05;
  const auto rack = GeneratingRack::from_parameters(g1);
  ASSERT_TRUE(rack.closed());
  ASSERT_EQ(rack.segments().size(), 3u);
  using G = RackSegment::Generates;
  EXPECT_EQ(rack.segments()[0].generates, G::flank);
  EXPECT_EQ(rack.segments()[1].generates, G::fillet);
  EXPECT_EQ(rack.segments()[2].generates, G::root);
  // The pieces join (one spline), the fillet starts at the inflection (curvature 0) and the
  // root ends on the trough, which is the root line.
  const auto &f = *rack.segments()[0].curve, &fi = *rack.segments()[1].curve, &rt = *rack.segments()[2].curve;
  EXPECT_EQ(f.point(f.t_end()), fi.point(fi.t_begin()));
  EXPECT_NEAR(fi.curvature(fi.t_begin()) * m, 0.0, 1e-9);
  EXPECT_NEAR(rack.root_line(), -m, 1e-15);
  EXPECT_NEAR(rt.point(rt.t_end()).x(), gearfem::units::pi * m / 2, 1e-15);

  // The teeth: root circle at the trough (r0 - m), tip circle r0 + (1 - 0.05) m; the
  // outline is continuous and the root ends in the middle of the tooth space (pi/z from
  // the tooth axis): the neighbouring tooth continues it.
  const auto p1 = ToothProfile::generate(g1);
  const auto p2 = ToothProfile::generate_mate(g2, p1);
  for (const auto *p : {&p1, &p2})
    {
      const double r0 = p->radii().reference;
      const int    z  = p->teeth();
      EXPECT_NEAR(p->radii().root, r0 - m, 1e-12);
      EXPECT_NEAR(p->radii().tip, r0 + 0.95 * m, 1e-12);
      const auto &segs = p->segments();
      for (std::size_t i = 0; i + 1 < segs.size(); ++i)
        EXPECT_LT((segs[i].end() - segs[i + 1].start()).norm(), 1e-9 * m) << "joint " << i;
      const Vec2 q = segs.front().start();
      EXPECT_NEAR(std::atan2(q.x(), q.y()), gearfem::units::pi / z, 1e-9);
      EXPECT_NEAR(q.norm(), r0 - m, 1e-9 * m);
      // The form circle is the lowest conjugate point: the end of the fillet.
      EXPECT_LT(p->radii().form, r0 - 0.5 * m);
    }
  EXPECT_TRUE(p2.rack().closed());

  // The crest must be the addendum: a clear error otherwise.
  auto bad           = g1;
  bad.rack.addendum  = 1.25;
  try
    {
      (void)GeneratingRack::from_parameters(bad);
      FAIL() << "no error";
    }
  catch (const gearfem::InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("Rack/Addendum coefficient"), std::string::npos) << e.what();
    }
  // The pair is refused with the reason: along this rack the contact point reverses.
  // Independently: the rack displacement of the contact is K(u) = -(u + v v'), with
  // dK/du = -(1 + v'^2 + v v''); at the crest v' = 0, v = m and v'' < -1/m (the crest's radius
  // of curvature is below m), so K first grows, while mid-flank (v = 0) it falls.
  try
    {
      GearPair pair(p1, p2, PairParameters{});
      FAIL() << "no error";
    }
  catch (const gearfem::InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("contact reverses"), std::string::npos) << e.what();
    }
}
