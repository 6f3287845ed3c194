// Internal gears: mesh kinematics against closed forms written out here from the sources
// (SDP-SI, Elements of Metric Gear Technology, 1996, table 5-1, in its own sign convention
// x2' = -x2; ISO 21771:2007 with z2 < 0), against agma::line_of_action_internal and the
// gearbox's planet-ring mesh (seed 001), the interference checks (SDP-SI eqs. 5-5..5-10,
// table 5-3a, and a sweep of the tip corners), and the shaper-cut ring outline (envelope,
// tangency, thickness).
#include "gearbox/stages.h"
#include "geometry/internal_profile.h"
#include "rating/agma.h"
#include "base/errors.h"
#include "base/units.h"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>

using namespace gearfem::geometry;

namespace
{
  const double pi = gearfem::units::pi, deg = pi / 180, mm = 1e-3;
  double inv(double a) { return std::tan(a) - a; }
  double inv_inverse(double v)
  {
    double a = std::cbrt(3 * v);
    for (int i = 0; i < 60; ++i)
      a -= (inv(a) - v) / (std::tan(a) * std::tan(a));
    return a;
  }

  /// The closed forms of one internal pair, written out independently of internal.cc.
  struct Expected
  {
    double aw, a, rb1, rb2, rw1, rw2, ra1, ra2, pb, eps, gA, gE, T1T2;
  };
  /// SDP-SI table 5-1 (KHK convention: x2' = -x2, h_a2 = (1 - x2') m) with the
  /// line-of-action lengths of Colbourne/ISO 21771 for an internal pair.
  Expected sdp_si(int z1, int z2, double m, double alpha, double x1, double x2_khk, double a_given = 0)
  {
    Expected e;
    e.aw  = inv_inverse(2 * std::tan(alpha) * (x2_khk - x1) / (z2 - z1) + inv(alpha));
    e.a   = (z2 - z1) * m / 2 * std::cos(alpha) / std::cos(e.aw);
    e.rb1 = z1 * m / 2 * std::cos(alpha), e.rb2 = z2 * m / 2 * std::cos(alpha);
    if (a_given > 0)
      e.a = a_given, e.aw = std::acos((e.rb2 - e.rb1) / a_given);
    e.rw1  = e.a * z1 / (z2 - z1), e.rw2 = e.a * z2 / (z2 - z1);
    e.ra1  = z1 * m / 2 + (1 + x1) * m;
    e.ra2  = z2 * m / 2 - (1 - x2_khk) * m;
    e.pb   = pi * m * std::cos(alpha);
    e.T1T2 = e.a * std::sin(e.aw);
    e.gA   = std::sqrt(e.ra2 * e.ra2 - e.rb2 * e.rb2) - e.T1T2;
    e.gE   = std::sqrt(e.ra1 * e.ra1 - e.rb1 * e.rb1);
    e.eps  = (std::sqrt(e.ra1 * e.ra1 - e.rb1 * e.rb1) - std::sqrt(e.ra2 * e.ra2 - e.rb2 * e.rb2) +
             e.a * std::sin(e.aw)) / e.pb;
    return e;
  }

  void expect_mesh(const InternalMesh &k, const Expected &e)
  {
    const double tol = 1e-9;
    EXPECT_NEAR(k.alpha_w, e.aw, 1e-12);
    EXPECT_NEAR(k.a, e.a, tol);
    EXPECT_NEAR(k.rw1, e.rw1, tol);
    EXPECT_NEAR(k.rw2, e.rw2, tol);
    EXPECT_NEAR(k.in.tip_radius1, e.ra1, tol);
    EXPECT_NEAR(k.in.tip_radius2, e.ra2, tol);
    EXPECT_NEAR(k.T1T2, e.T1T2, tol);
    EXPECT_NEAR(k.point("A").g, e.gA, tol);
    EXPECT_NEAR(k.point("E").g, e.gE, tol);
    EXPECT_NEAR(k.point("B").g, e.gE - e.pb, tol);
    EXPECT_NEAR(k.point("D").g, e.gA + e.pb, tol);
    EXPECT_NEAR(k.point("C").g, e.rw1 * std::sin(e.aw), tol);
    EXPECT_NEAR(k.point("T2").g, -e.T1T2, tol);
    EXPECT_NEAR(k.contact_ratio, e.eps, 1e-12);
    // Geometry of the points: C at (0, r_w1), A and E on the tip circles, T2 on the ring base circle.
    EXPECT_NEAR((k.point("C").position - Vec2(0, e.rw1)).norm(), 0.0, tol);
    EXPECT_NEAR(k.point("A").r2, e.ra2, tol);
    EXPECT_NEAR(k.point("E").r1, e.ra1, tol);
    EXPECT_NEAR(k.point("T2").r2, e.rb2, tol);
    EXPECT_NEAR(k.point("T1").r1, e.rb1, tol);
    // Curvatures at C: rho1 = r_b1 tan a_w, rho2 = r_b2 tan a_w.
    const double gC = k.point("C").g;
    EXPECT_NEAR(k.rho1(gC), e.rb1 * std::tan(e.aw), tol);
    EXPECT_NEAR(k.rho2(gC), e.rb2 * std::tan(e.aw), tol);
    EXPECT_NEAR(k.relative_curvature(gC), 1 / (e.rb1 * std::tan(e.aw)) - 1 / (e.rb2 * std::tan(e.aw)), 1e-9);
  }
} // namespace

TEST(InternalGear, StandardPairClosedForms)
{
  // z1 = 20, z2 = 60, m 3 mm, 20 deg, no shifts: a = 60 mm, a_w = a. The standard ring's
  // tip circle (r_a2 = 87 mm) lies inside |O2 T1| = 87.03 mm: involute interference, which
  // AGMA's line of action refuses too.
  const InternalMesh k = internal_mesh(internal_mesh_input(20, 60, 3 * mm, 20 * deg, 0, 0));
  const Expected e     = sdp_si(20, 60, 3 * mm, 20 * deg, 0, 0);
  expect_mesh(k, e);
  EXPECT_NEAR(k.a, 60 * mm, 1e-12);
  EXPECT_NEAR(k.backlash_t, 0.0, 1e-12);
  EXPECT_NEAR(k.clearance1, 0.25 * 3 * mm, 1e-12);
  std::cout << "20/60 m 3 x 0/0: eps_alpha = " << k.contact_ratio << ", g_A = " << k.point("A").g / mm << " mm\n";
  EXPECT_TRUE(involute_interference(k).interferes);
  EXPECT_THROW(gearfem::rating::agma::line_of_action_internal(20, 60, 3 * mm, 20 * deg, k.in.tip_radius1,
                                                               k.in.tip_radius2, k.a),
               gearfem::InputError);
  EXPECT_FALSE(tip_fouling_in_rotation(k).interferes);
  EXPECT_FALSE(tip_fouling_radial(k).interferes);
  // A shifted variant, x1 = 0.2 and the ring 0.5 in SDP-SI's sign (-0.5 in ISO's):
  // free of every interference.
  const InternalMesh ok = internal_mesh(internal_mesh_input(20, 60, 3 * mm, 20 * deg, 0.2, -0.5));
  expect_mesh(ok, sdp_si(20, 60, 3 * mm, 20 * deg, 0.2, 0.5));
  std::cout << "20/60 m 3 x 0.2/-0.5 (ISO): a_w = " << ok.alpha_w / deg << " deg, a = " << ok.a / mm
            << " mm, eps_alpha = " << ok.contact_ratio << "\n";
  for (const InterferenceDiagnosis &d : interference_checks(ok))
    EXPECT_FALSE(d.interferes) << d.message();
  EXPECT_LE(tip_corner_penetration(ok), 1e-9);
}

TEST(InternalGear, ShiftedPairClosedFormsBothConventions)
{
  // Seed 001 stage 1 planet/ring (Siasos 2010): z 28/74, m 6 mm, x_planet 0.6, x_ring -0.9
  // (ISO / gearbox sign) = +0.9 in SDP-SI's convention. Zero backlash from the shifts.
  const InternalMesh k = internal_mesh(internal_mesh_input(28, 74, 6 * mm, 20 * deg, 0.6, -0.9));
  expect_mesh(k, sdp_si(28, 74, 6 * mm, 20 * deg, 0.6, 0.9));
  EXPECT_NEAR(k.backlash_t, 0.0, 1e-12);
  // ISO 21771 with z2 < 0 (the external formula): inv a_w = inv a + 2 tan a (x1 + x2)/(z1 + z2).
  EXPECT_NEAR(k.alpha_w, inv_inverse(inv(20 * deg) + 2 * std::tan(20 * deg) * (0.6 - 0.9) / (28 - 74)), 1e-12);
  std::cout << "28/74 m 6 x 0.6/-0.9: a_w = " << k.alpha_w / deg << " deg, a = " << k.a / mm
            << " mm, eps_alpha = " << k.contact_ratio << "\n";
  // Ring shift +0.5 in ISO's sign (thicker ring teeth, a_w < a).
  const InternalMesh k2 = internal_mesh(internal_mesh_input(20, 60, 3 * mm, 20 * deg, 0.2, 0.5));
  expect_mesh(k2, sdp_si(20, 60, 3 * mm, 20 * deg, 0.2, -0.5));
  EXPECT_NEAR(k2.backlash_t, 0.0, 1e-12);
  // Unlike an external pair, a SMALLER centre distance opens backlash:
  // j_t = 2 r_w1 (inv a - inv a_w)(z2 - z1)/z1 for unshifted teeth.
  for (const double a : {59.7 * mm, 60.3 * mm})
    {
      InternalMeshInput in = internal_mesh_input(20, 60, 3 * mm, 20 * deg, 0, 0);
      in.center_distance   = a;
      const InternalMesh k3 = internal_mesh(in);
      expect_mesh(k3, sdp_si(20, 60, 3 * mm, 20 * deg, 0, 0, a));
      EXPECT_NEAR(k3.backlash_t, 2 * k3.rw1 * (inv(20 * deg) - inv(k3.alpha_w)) * 40 / 20, 1e-12);
      EXPECT_EQ(k3.backlash_t > 0, a < 60 * mm);
    }
}

TEST(InternalGear, AgreesWithAgmaAndTheGearbox)
{
  // agma::line_of_action_internal at the same radii and centre distance (unit module).
  for (const auto &[z1, z2, x1, x2] : {std::tuple{20, 60, 0.2, -0.5}, std::tuple{28, 74, 0.6, -0.9},
                                       std::tuple{44, 117, 0.6, -0.9}, std::tuple{24, 80, 0.0, 0.0}})
    {
      const double m = 3 * mm;
      const InternalMesh k = internal_mesh(internal_mesh_input(z1, z2, m, 20 * deg, x1, x2));
      const auto l = gearfem::rating::agma::line_of_action_internal(z1, z2, m, 20 * deg, k.in.tip_radius1,
                                                                     k.in.tip_radius2, k.a);
      EXPECT_NEAR(l.phi_r, k.alpha_w, 1e-13);
      EXPECT_NEAR(l.C1 * m, k.point("A").g, 1e-12);
      EXPECT_NEAR(l.C2 * m, k.point("B").g, 1e-12);
      EXPECT_NEAR(l.C3 * m, k.point("C").g, 1e-12);
      EXPECT_NEAR(l.C4 * m, k.point("D").g, 1e-12);
      EXPECT_NEAR(l.C5 * m, k.point("E").g, 1e-12);
      EXPECT_NEAR(l.C6 * m, k.T1T2, 1e-12);
      EXPECT_NEAR(l.contact_ratio, k.contact_ratio, 1e-12);
      std::cout << z1 << "/" << z2 << ": eps_alpha = " << k.contact_ratio << " (AGMA 908 m_p " << l.contact_ratio
                << ", difference " << k.contact_ratio - l.contact_ratio << ")\n";
    }
  // The gearbox's planet-ring meshes of seed 001 (Siasos' working radii r_o -+ x m, so its
  // centre distance is given, not the zero-backlash one).
  namespace gb = gearfem::gearbox;
  gb::StageInput s;
  s.z_sun = 16, s.z_planet = 28, s.z_ring = 74, s.x_sun = 0.7, s.x_planet = 0.6, s.x_ring = -0.9;
  s.module = 6 * mm, s.face_width = 110 * mm, s.planets = 3;
  for (int stage = 1; stage <= 2; ++stage)
    {
      if (stage == 2)
        s.z_sun = 27, s.z_planet = 44, s.z_ring = 117, s.module = 3.5 * mm, s.face_width = 50 * mm;
      const gb::Stage st = gb::build_stage(s, gb::AgmaFactors());
      const gb::MeshGeometry &g = st.meshes[1];
      ASSERT_TRUE(g.internal);
      InternalMeshInput in = internal_mesh_input(g.z1, g.z2, g.module, g.alpha, g.x1, g.x2);
      in.center_distance   = g.a;
      const InternalMesh k = internal_mesh(in);
      EXPECT_NEAR(k.in.tip_radius1, g.r_a1, 1e-12);
      EXPECT_NEAR(k.in.tip_radius2, g.r_a2, 1e-12);
      EXPECT_NEAR(k.in.root_radius2, g.r_f2, 1e-12);
      EXPECT_NEAR(k.alpha_w, g.loa.phi_r, 1e-13);
      EXPECT_NEAR(k.point("A").g, g.loa.C1 * g.module, 1e-12);
      EXPECT_NEAR(k.point("E").g, g.loa.C5 * g.module, 1e-12);
      EXPECT_NEAR(k.contact_ratio, g.loa.contact_ratio, 1e-12);
      EXPECT_FALSE(involute_interference(k).interferes);
      EXPECT_FALSE(tip_fouling_in_rotation(k).interferes);
      std::cout << "seed 001 stage " << stage << " planet-ring: a = " << k.a / mm << " mm (zero backlash "
                << internal_center_distance_from_shifts(g.module, g.alpha, g.z1, g.z2, g.x1, g.x2) / mm
                << " mm), eps_alpha = " << k.contact_ratio << ", backlash j_n = " << k.backlash_n / mm << " mm\n";
    }
}

TEST(InternalGear, InvoluteInterferenceLikeAgma)
{
  // 20/40 standard: the ring tip circle cuts the line of action inside T1.
  const InternalMesh k = internal_mesh(internal_mesh_input(20, 40, 3 * mm, 20 * deg, 0, 0));
  const InterferenceDiagnosis d = involute_interference(k);
  EXPECT_TRUE(d.interferes);
  EXPECT_LT(k.point("A").g, 0.0);
  EXPECT_NEAR(d.margin, std::sqrt(57. * 57 - std::pow(60 * std::cos(20 * deg), 2)) * mm - 30 * std::sin(20 * deg) * mm,
              1e-12);
  try
    {
      d.raise();
      FAIL() << "no InputError";
    }
  catch (const gearfem::InputError &e)
    {
      EXPECT_EQ(e.parameter(), "Ring/Tip diameter");
      EXPECT_NE(std::string(e.what()).find("involute interference"), std::string::npos) << e.what();
    }
  EXPECT_THROW(gearfem::rating::agma::line_of_action_internal(20, 40, 3 * mm, 20 * deg, k.in.tip_radius1,
                                                               k.in.tip_radius2, k.a),
               gearfem::InputError);
  // SDP-SI eq. 5-5: z1/z2 >= 1 - tan a_a2/tan a_w fails as well.
  EXPECT_LT(20. / 40, 1 - std::tan(std::acos(k.rb2 / k.in.tip_radius2)) / std::tan(k.alpha_w));
}

TEST(InternalGear, TipFoulingOfCloseToothCounts)
{
  // 40/44 standard: tips foul in rotation and on radial withdrawal; the sweep sees it too.
  const InternalMesh bad = internal_mesh(internal_mesh_input(40, 44, 3 * mm, 20 * deg, 0, 0));
  EXPECT_FALSE(involute_interference(bad).interferes);
  const InterferenceDiagnosis rot = tip_fouling_in_rotation(bad), rad = tip_fouling_radial(bad);
  EXPECT_TRUE(rot.interferes);
  EXPECT_TRUE(rad.interferes);
  EXPECT_GT(tip_corner_penetration(bad), 1e-4);
  EXPECT_THROW(rot.raise(), gearfem::InputError);
  std::cout << "40/44: " << rot.message() << "\n";
  // The closed form (SDP-SI eq. 5-6) and the sweep agree on the side of the limit, which for
  // standard pairs lies at z2 - z1 = 9 (SDP-SI: "larger than 9"; Siasos 2010: z_R >= z_P + 10).
  for (const auto &[z1, z2] : {std::pair{40, 47}, std::pair{40, 48}, std::pair{40, 49}, std::pair{40, 50},
                               std::pair{30, 38}, std::pair{30, 39}, std::pair{60, 69}, std::pair{20, 60}})
    {
      const InternalMesh k = internal_mesh(internal_mesh_input(z1, z2, 3 * mm, 20 * deg, 0, 0));
      const double margin = tip_fouling_in_rotation(k).margin, pen = tip_corner_penetration(k);
      EXPECT_EQ(margin > 0, pen < 1e-9) << z1 << "/" << z2 << ": margin " << margin << " rad, sweep " << pen << " m";
    }
}

TEST(InternalGear, RadialTipFoulingReproducesSdpSiTable)
{
  // SDP-SI table 5-3a: smallest internal gear (x2 = 0) a pinion cutter of z_c teeth (x_c = 0,
  // addendum 1.25 m) can be withdrawn from radially, 20 deg.
  const int table[][2] = {{17, 35}, {18, 36}, {19, 37}, {20, 38}, {21, 39}, {22, 40}, {24, 42}, {25, 43},
                          {27, 45}, {28, 46}, {30, 48}, {31, 49}, {32, 50}, {33, 51}, {34, 52}, {35, 53},
                          {38, 56}, {40, 58}, {42, 60}, {44, 62}, {48, 66}, {50, 68}, {56, 74}, {60, 78},
                          {64, 82}, {66, 84}, {80, 98}, {96, 114}, {100, 118}};
  const auto margin = [](int zc, int z2) {
    InternalMeshInput in = internal_mesh_input(zc, z2, 1 * mm, 20 * deg, 0, 0);
    in.tip_radius1       = (0.5 * zc + 1.25) * mm;
    return tip_fouling_radial(internal_mesh(in)).margin;
  };
  for (const auto &row : table)
    {
      EXPECT_GE(margin(row[0], row[1]), 0.0) << row[0] << "/" << row[1];
      EXPECT_LT(margin(row[0], row[1] - 1), 0.0) << row[0] << "/" << row[1] - 1;
    }
  // The table's 15/34 and 16/34: below 34 teeth a standard ring's tip lies inside its base circle.
  EXPECT_THROW(internal_mesh(internal_mesh_input(16, 33, 1 * mm, 20 * deg, 0, 0)), gearfem::InputError);
}

namespace
{
  InternalGearParameters ring(int z2, double m, double x2, int z0, double x0)
  {
    InternalGearParameters g;
    g.teeth = z2, g.module = m, g.pressure_angle = 20 * deg, g.profile_shift = x2;
    g.cutter.teeth = z0, g.cutter.shift = x0;
    return g;
  }
  double cross(const Vec2 &a, const Vec2 &b) { return a.x() * b.y() - a.y() * b.x(); }
  Eigen::Matrix2d rot(double t)
  {
    Eigen::Matrix2d R;
    R << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
    return R;
  }
} // namespace

TEST(InternalGear, ShaperCutRingOutline)
{
  for (const auto &[z2, x2, z0, x0] : {std::tuple{60, -0.5, 20, 0.0}, std::tuple{74, -0.9, 28, 0.1},
                                       std::tuple{117, -0.9, 25, 0.0}})
    {
      const double m = 3 * mm, al = 20 * deg;
      const InternalToothProfile t = InternalToothProfile::generate(ring(z2, m, x2, z0, x0));
      const auto &seg = t.segments();
      ASSERT_EQ(seg.size(), 7u);
      // Generating centre distance (internal mesh of cutter and ring, zero backlash).
      const double aw0 = inv_inverse(inv(al) - 2 * std::tan(al) * (x0 + x2) / (z2 - z0));
      const double a0  = m * (z2 - z0) * std::cos(al) / (2 * std::cos(aw0));
      EXPECT_NEAR(t.generating_center_distance(), a0, 1e-12);
      // Radii: root = a0 + r_a0, tip = r2 - (1 + x2) m, form = the cutter flank end's mate.
      const double r0 = 0.5 * m * z0, rb0 = r0 * std::cos(al), ra0 = r0 + (1.25 + x0) * m, rho = 0.25 * m;
      const double rb2 = 0.5 * m * z2 * std::cos(al);
      const double lam = std::sqrt((ra0 - rho) * (ra0 - rho) - rb0 * rb0);
      EXPECT_NEAR(t.radii().root, a0 + ra0, 1e-12);
      EXPECT_NEAR(t.radii().tip, 0.5 * m * z2 - (1 + x2) * m, 1e-12);
      EXPECT_NEAR(t.radii().form, std::hypot(rb2, lam + rho + a0 * std::sin(aw0)), 1e-12);
      // The outline is continuous, and tangent-continuous at every junction.
      for (std::size_t i = 0; i + 1 < seg.size(); ++i)
        {
          EXPECT_LT((seg[i].end() - seg[i + 1].start()).norm(), 1e-9) << "junction " << i;
          const auto dir = [](const ProfileSegment &s, double tt) {
            return Vec2((s.t1 > s.t0 ? 1.0 : -1.0) * s.curve->d1(tt).normalized());
          };
          if (seg[i].type != SegmentType::tip && seg[i + 1].type != SegmentType::tip)
            EXPECT_LT(std::abs(cross(dir(seg[i], seg[i].t1), dir(seg[i + 1], seg[i + 1].t0))), 1e-9)
              << "normal continuity at junction " << i << " (" << to_string(seg[i].type) << " -> "
              << to_string(seg[i + 1].type) << ")";
        }
      EXPECT_NEAR(seg[1].end().norm(), t.radii().form, 1e-9);
      EXPECT_NEAR(seg[0].start().norm(), t.radii().root, 1e-12);
      EXPECT_NEAR(std::atan2(seg[0].start().x(), seg[0].start().y()), pi / z2, 1e-12);
      // Flank: polar angle (clockwise from +y) psi_b + inv a_r, s2 = m (pi/2 + 2 x2 tan a).
      const double s2 = m * (0.5 * pi + 2 * x2 * std::tan(al)), r2 = 0.5 * m * z2;
      for (double s = 0; s <= 1.0; s += 0.125)
        {
          const Vec2 p = seg[2].point(s);
          const double r = p.norm();
          EXPECT_NEAR(std::atan2(p.x(), p.y()), s2 / (2 * r2) - inv(al) + inv(std::acos(rb2 / r)), 1e-12);
          EXPECT_NEAR(t.thickness_at_radius(r), t.involute_thickness_at_radius(r), 1e-9);
        }
      EXPECT_NEAR(t.involute_thickness_at_radius(r2), 2 * r2 * (s2 / (2 * r2)), 1e-12);
      // Fillet = envelope of the cutter tip rounding: the distance of each fillet point from
      // the rounding centre at its generating position is the radius, the cutter point's
      // velocity relative to the ring is tangent to the rounding there, and no other cutter
      // position comes nearer (no overcut: the true envelope).
      const double k = double(z2) / z0 - 1, psi_b0 = (0.5 * pi + 2 * x0 * std::tan(al)) * m / (2 * r0) + inv(al);
      const double phi_c = psi_b0 - (lam + rho) / rb0;
      const Vec2 Cc = rb0 * Vec2(std::sin(phi_c), std::cos(phi_c)) + lam * Vec2(std::cos(phi_c), -std::sin(phi_c));
      const Eigen::Matrix2d M = t.fillet_map();
      const auto centre = [&](double tt) { return Vec2(rot(-tt) * Vec2(0, a0) + rot(k * tt) * Cc); };
      const auto J = [](const Vec2 &v) { return Vec2(-v.y(), v.x()); };
      const ProfileSegment &f = seg[1];
      double worst_d = 0, worst_v = 0, worst_min = 0;
      for (int i = 0; i <= 40; ++i)
        {
          const double tt = f.t0 + (f.t1 - f.t0) * i / 40.0;
          const Vec2 p = M.inverse() * f.curve->point(tt); // generating frame
          const Vec2 O0 = rot(-tt) * Vec2(0, a0);
          worst_d = std::max(worst_d, std::abs((p - centre(tt)).norm() - rho));
          const Vec2 v = -J(O0) + k * J(p - O0); // d/dt of the cutter-fixed point at p
          worst_v = std::max(worst_v, std::abs(v.normalized().dot((p - centre(tt)).normalized())));
          double dmin = 1e9;
          for (int j = -3000; j <= 3000; ++j)
            dmin = std::min(dmin, (p - centre(tt + j * 2e-5)).norm());
          worst_min = std::max(worst_min, rho - dmin);
        }
      EXPECT_LT(worst_d, 1e-9);
      EXPECT_LT(worst_v, 1e-9);
      EXPECT_LT(worst_min, 1e-9);
      // Sampled outline: outward normals point out of the material (towards the centre at the tip).
      const auto pts = t.sample(m / 20);
      for (const ProfilePoint &p : pts)
        if (p.type == SegmentType::tip)
          EXPECT_NEAR(p.normal.dot(-p.p.normalized()), 1.0, 1e-12);
        else if (p.type == SegmentType::flank)
          EXPECT_LT(p.curvature, 0.0); // concave ring flank seen from the gap
      // Kinematics with a pinion of the cutter's size on this ring's generated radii.
      InternalMeshInput in = internal_mesh_input(z0, z2, m, al, 0.6, x2);
      t.fill_mesh_input(in);
      const InternalMesh km = internal_mesh(in);
      std::cout << z2 << " teeth, x2 " << x2 << ", cutter " << z0 << "/" << x0 << ": r_f2 = " << t.radii().root / mm
                << " mm (rack " << (r2 + (1.25 - x2) * m) / mm << "), r_Ff2 = " << t.radii().form / mm
                << " mm; with a " << z0 << "-tooth pinion, x1 0.6: eps_alpha " << km.contact_ratio
                << ", pinion tip/ring fillet margin " << pinion_tip_ring_fillet_interference(km).margin / mm << " mm\n";
      for (const std::string &w : t.warnings())
        std::cout << "  warning: " << w << "\n";
    }
}

TEST(InternalGear, GenerationErrorsNameTheEntry)
{
  // A cutter as large as the ring, and a ring whose tip lies inside its base circle.
  try
    {
      InternalToothProfile::generate(ring(30, 3 * mm, 0, 30, 0));
      FAIL();
    }
  catch (const gearfem::InputError &e)
    {
      EXPECT_EQ(e.parameter(), "Ring/Cutter teeth");
    }
  try
    {
      InternalToothProfile::generate(ring(30, 3 * mm, 0, 12, 0));
      FAIL();
    }
  catch (const gearfem::InputError &e)
    {
      EXPECT_EQ(e.parameter(), "Ring/Addendum coefficient") << e.what();
    }
}
