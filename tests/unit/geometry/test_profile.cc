// Tooth generation against closed forms: involute, trochoid, undercut limit and key radii
// (all Siasos 2010), tip relief.
#include "geometry/conjugate.h"
#include "base/units.h"
#include "geometry/pair.h"
#include "geometry/profile.h"
#include "base/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace gearfem::geometry;
namespace cf = gearfem::geometry::closed_form;

namespace
{
  const double deg = gearfem::units::pi / 180, mm = 1e-3;

  GearParameters gear(int z, double x, double m = 3 * mm)
  {
    GearParameters g;
    g.name                = "Gear 1";
    g.teeth               = z;
    g.profile_shift       = x;
    g.face_width          = 20 * mm;
    g.rack.module         = m;
    g.rack.pressure_angle = 20 * deg;
    return g;
  }

  /// Half tooth-thickness angle on the base circle of the involute (closed form).
  double psi_b(const GearParameters &g)
  {
    const double m = g.rack.module, a = g.rack.pressure_angle;
    const double s = gearfem::units::pi * m / 2 + 2 * g.profile_shift * m * std::tan(a) - g.thickness_allowance;
    return s / (2 * g.reference_radius()) + cf::inv(a);
  }

  /// Distance of p from the closed-form involute, compared at the same radius.
  double involute_deviation(const GearParameters &g, const Vec2 &p)
  {
    const double rb = g.reference_radius() * std::cos(g.rack.pressure_angle);
    const double xi = std::sqrt(p.squaredNorm() / (rb * rb) - 1);
    return (p - cf::involute(rb, psi_b(g), xi)).norm();
  }

  /// Distance of p from the closed-form trochoid (Siasos 2010), minimised over theta.
  double trochoid_distance(const GearParameters &g, const Vec2 &p)
  {
    const double m = g.rack.module, a = g.rack.pressure_angle, x = g.profile_shift;
    const double r0 = g.reference_radius(), rc = g.rack.root_radius * m;
    const double hf = (g.rack.dedendum - x) * m;
    // Cutter tip-arc centre (rack coordinates): on the tip line + rc, rc from the flank.
    const double vc = -hf + rc;
    const double uc = gearfem::units::pi * m / 4 + (x * m - vc) * std::tan(a) + rc / std::cos(a);
    const double th_max = 2 * (std::abs(vc) / (r0 * std::tan(a)) + 1e-3);
    auto d = [&](double th) { return (cf::trochoid_gear_frame(r0, rc, hf, uc, th) - p).norm(); };
    double best = 1e9, bt = 0;
    const int n = 4000;
    for (int i = 0; i <= n; ++i)
      {
        const double th = -th_max + 2 * th_max * i / n;
        if (d(th) < best)
          best = d(th), bt = th;
      }
    double lo = bt - 2 * th_max / n, hi = bt + 2 * th_max / n;
    for (int i = 0; i < 200; ++i)
      {
        const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        if (d(m1) < d(m2))
          hi = m2;
        else
          lo = m1;
      }
    return d(0.5 * (lo + hi));
  }
} // namespace

// Generated flank = closed-form involute and generated fillet =
// closed-form trochoid (Siasos 2010), both <= 1e-9 m, for z = 12 (undercut),
// 19, 50, 100 and x = -0.3, 0, +0.5.
TEST(Profile, GeneratedFlankAndFilletMatchClosedForms)
{
  double worst_inv = 0, worst_tro = 0;
  for (int z : {12, 19, 50, 100})
    for (double x : {-0.3, 0.0, 0.5})
      {
        const auto g  = gear(z, x);
        const auto tp = ToothProfile::generate(g);
        double     e_inv = 0, e_tro = 0;
        int        n_inv = 0, n_tro = 0;
        for (const auto &q : tp.sample(0.05 * mm))
          {
            if (q.type == SegmentType::flank && q.side == Side::coast)
              e_inv = std::max(e_inv, involute_deviation(g, q.p)), ++n_inv;
            if (q.type == SegmentType::fillet && q.side == Side::coast)
              e_tro = std::max(e_tro, trochoid_distance(g, q.p)), ++n_tro;
          }
        EXPECT_GT(n_inv, 10);
        EXPECT_GT(n_tro, 3);
        worst_inv = std::max(worst_inv, e_inv), worst_tro = std::max(worst_tro, e_tro);
        EXPECT_LE(e_inv, 1e-9) << "z " << z << " x " << x;
        EXPECT_LE(e_tro, 1e-9) << "z " << z << " x " << x;
        const bool expect_undercut = z < minimum_teeth_without_undercut(20 * deg, 1.25, 0.25, x);
        EXPECT_EQ(tp.undercut().present, expect_undercut) << "z " << z << " x " << x;
        if (expect_undercut)
          {
            EXPECT_GT(tp.undercut().depth, 0.0);
            EXPECT_GT(tp.undercut().radius, tp.radii().base);
          }
      }
  std::cout << "[generation] max |flank - involute| = " << worst_inv
            << " m, max |fillet - trochoid| = " << worst_tro << " m" << std::endl;
}

// Siasos 2010: Z_min = 18.56 for x = 0, alpha = 20 deg, h_fP* = 1.25, rho_fP* = 0.25, and the
// generation itself agrees: for each z the limiting shift found by bisection on the
// generator's undercut detection equals the one from the formula.
TEST(Profile, UndercutLimitFromGeneration)
{
  EXPECT_NEAR(minimum_teeth_without_undercut(20 * deg, 1.25, 0.25, 0.0), 18.56, 0.005);
  std::cout << "[undercut] Z_min = " << minimum_teeth_without_undercut(20 * deg, 1.25, 0.25, 0.0)
            << ", z = 18 depth " << ToothProfile::generate(gear(18, 0.0)).undercut().depth / mm * 1e3
            << " um (m 3 mm)" << std::endl;
  EXPECT_TRUE(ToothProfile::generate(gear(18, 0.0)).undercut().present);
  EXPECT_FALSE(ToothProfile::generate(gear(19, 0.0)).undercut().present);
  const double s2 = std::pow(std::sin(20 * deg), 2);
  for (int z : {10, 14, 18})
    {
      double lo = -0.5, hi = 1.0; // undercut at lo, none at hi
      for (int i = 0; i < 30; ++i)
        {
          const double mid = 0.5 * (lo + hi);
          (ToothProfile::generate(gear(z, mid)).undercut().present ? lo : hi) = mid;
        }
      // Formula inverted for x: Z_min(x) = z.
      const double x_formula = 1.25 - 0.25 * (1 - std::sin(20 * deg)) - z * s2 / 2;
      EXPECT_NEAR(0.5 * (lo + hi), x_formula, 2e-4) << "z " << z;
      std::cout << "[undercut] z " << z << ": limiting x from generation " << 0.5 * (lo + hi)
                << ", from Z_min formula " << x_formula << std::endl;
    }
}

// Siasos 2010, 23/69, m 4: tip and root radii 50/41 mm and 142/133 mm.
TEST(Profile, KeyRadiiSeed001)
{
  const auto p1 = ToothProfile::generate(gear(23, 0, 4 * mm));
  const auto p2 = ToothProfile::generate(gear(69, 0, 4 * mm));
  EXPECT_NEAR(p1.radii().tip, 50 * mm, 1e-12);
  EXPECT_NEAR(p1.radii().root, 41 * mm, 1e-12);
  EXPECT_NEAR(p2.radii().tip, 142 * mm, 1e-12);
  EXPECT_NEAR(p2.radii().root, 133 * mm, 1e-12);
  // The generated outline really reaches them: the tip segment lies on r_a and the root
  // segment on r_f.
  for (const auto &q : p1.sample(0.1 * mm))
    {
      if (q.type == SegmentType::tip)
        EXPECT_NEAR(q.p.norm(), 50 * mm, 1e-12);
      if (q.type == SegmentType::root)
        EXPECT_NEAR(q.p.norm(), 41 * mm, 1e-12);
    }
}

// Closed form: tooth thickness on a circle of radius r on the involute,
// s(r) = 2 r (s/(2 r0) + inv a - inv a_r), and the outline is closed, continuous and
// counter-clockwise with outward normals.
TEST(Profile, ThicknessAndOutlineConsistency)
{
  auto g                = gear(27, 0.2);
  g.thickness_allowance = 0.1 * mm;
  const auto   tp = ToothProfile::generate(g);
  const double r0 = g.reference_radius(), a = 20 * deg, m = 3 * mm;
  const double s  = gearfem::units::pi * m / 2 + 2 * 0.2 * m * std::tan(a) - 0.1 * mm;
  for (double r : {r0 - 1 * mm, r0, r0 + 2 * mm})
    {
      const double ar = std::acos(r0 * std::cos(a) / r);
      EXPECT_NEAR(tp.thickness_at_radius(r), 2 * r * (s / (2 * r0) + cf::inv(a) - cf::inv(ar)),
                  1e-12);
    }
  const auto &seg = tp.segments();
  for (std::size_t i = 0; i + 1 < seg.size(); ++i)
    EXPECT_LT((seg[i].end() - seg[i + 1].start()).norm(), 1e-12) << "joint " << i;
  // First point at polar angle pi/2 - pi/z, last at pi/2 + pi/z, on the root circle.
  EXPECT_NEAR(std::atan2(seg.front().start().y(), seg.front().start().x()), gearfem::units::pi / 2 - gearfem::units::pi / 27, 1e-12);
  EXPECT_NEAR(std::atan2(seg.back().end().y(), seg.back().end().x()), gearfem::units::pi / 2 + gearfem::units::pi / 27, 1e-12);
  // Shoelace area of one tooth sector outline (with the origin) is positive (CCW), and each
  // normal points away from the tooth axis on the flanks.
  const auto pts  = tp.sample(0.05 * mm);
  double     area = 0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i)
    area += pts[i].p.x() * pts[i + 1].p.y() - pts[i + 1].p.x() * pts[i].p.y();
  EXPECT_GT(area, 0);
  for (const auto &q : pts)
    {
      if (q.type == SegmentType::flank)
        {
          EXPECT_GT(q.normal.x() * q.p.x(), 0.0);
          EXPECT_GT(q.curvature, 0.0); // involute flank is convex
        }
      if (q.type == SegmentType::fillet)
        EXPECT_LT(q.curvature, 0.0); // fillet is concave
    }
  // Whole gear: z copies of the tooth (the closing point shared), consecutive points close.
  const auto tooth = tp.sample(0.2 * mm);
  const auto all   = tp.sample_gear(0.2 * mm);
  EXPECT_EQ(all.size(), 27 * (tooth.size() - 1));
  for (std::size_t i = 0; i < all.size(); ++i)
    EXPECT_LT((all[(i + 1) % all.size()].p - all[i].p).norm(), 0.21 * mm);
  // half_width_at_height agrees with the sampled coast flank points.
  for (const auto &q : pts)
    if (q.type == SegmentType::flank && q.side == Side::coast)
      EXPECT_NEAR(tp.half_width_at_height(q.p.y()), q.p.x(), 1e-12);
}

// Tip relief: the deviation of the outline from the closed-form
// involute (normal, = rb times the polar-angle difference at equal radius) equals C_a at
// the tip, follows the linear / parabolic law in roll angle, and is zero below the start.
TEST(Profile, TipReliefDeviation)
{
  for (auto kind : {TipRelief::Kind::linear, TipRelief::Kind::parabolic})
    {
      auto g          = gear(30, 0.0);
      g.relief.kind   = kind;
      g.relief.amount = 20e-6;
      g.relief.length = 2 * mm;
      const auto   tp = ToothProfile::generate(g);
      const double rb = tp.radii().base, ra = tp.radii().tip;
      auto dev = [&](const Vec2 &p) {
        const double xi = std::sqrt(p.squaredNorm() / (rb * rb) - 1);
        const Vec2   q  = cf::involute(rb, psi_b(g), xi);
        return rb * (std::atan2(q.x(), q.y()) - std::atan2(p.x(), p.y()));
      };
      const double xi_a = std::sqrt(ra * ra / (rb * rb) - 1), xi_s = xi_a - 2 * mm / rb;
      EXPECT_NEAR(tp.radii().relief_start, rb * std::sqrt(1 + xi_s * xi_s), 1e-12);
      double r_top = 0;
      int    below = 0, above = 0;
      for (const auto &q : tp.sample(0.02 * mm))
        {
          if (q.type != SegmentType::flank || q.side != Side::coast)
            continue;
          const double r = q.p.norm(), xi = std::sqrt(r * r / (rb * rb) - 1);
          if (r > r_top)
            r_top = r;
          if (xi <= xi_s)
            {
              EXPECT_LT(std::abs(dev(q.p)), 1e-9);
              ++below;
            }
          else
            {
              const double z   = (xi - xi_s) / (xi_a - xi_s);
              const double law = 20e-6 * (kind == TipRelief::Kind::linear ? z : z * z);
              EXPECT_NEAR(dev(q.p), law, 1e-9);
              EXPECT_NEAR(tp.relief_at_radius(r), law, 1e-12);
              ++above;
            }
        }
      const auto &top = tp.segments()[tp.flank_segments(Side::coast).back()];
      EXPECT_NEAR(top.end().norm(), ra, 1e-12);
      EXPECT_NEAR(dev(top.end()), 20e-6, 1e-9);
      std::cout << "[tip relief] " << (kind == TipRelief::Kind::linear ? "linear" : "parabolic")
                << ": deviation at the tip " << dev(top.end()) * 1e6 << " um (C_a = 20 um)" << std::endl;
      EXPECT_GT(below, 10);
      EXPECT_GT(above, 10);
      EXPECT_EQ(tp.relief_at_radius(tp.radii().reference), 0.0);
    }
}

// Design checks of a single gear throw InputError naming the parameter.
TEST(Profile, DesignChecksNameTheParameter)
{
  auto expect_error = [](GearParameters g, const std::string &name) {
    try
      {
        ToothProfile::generate(g);
        ADD_FAILURE() << "no error for " << name;
      }
    catch (const gearfem::InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      }
  };
  expect_error(gear(4, 0), "Gear 1/Number of teeth");
  expect_error(gear(20, 0, 0.0), "Rack/Module");
  auto g = gear(20, 0);
  g.rack.pressure_angle = 40 * deg;
  expect_error(g, "Rack/Pressure angle");
  expect_error(gear(10, 1.2), "Gear 1/Profile shift coefficient"); // pointed tip
  // Small tip thickness: a warning, not an error.
  const auto tp = ToothProfile::generate(gear(12, 0.75));
  ASSERT_GT(tp.tip_thickness(), 0);
  EXPECT_LT(tp.tip_thickness(), 0.2 * 3 * mm);
  bool warned = false;
  for (const auto &w : tp.warnings())
    warned |= w.find("tip thickness") != std::string::npos;
  EXPECT_TRUE(warned);
}

// Undercut depth near the onset, against a brute-force sweep of the cutter (independent of
// the generator): the deepest point of the removed involute is its cusp on the base circle,
// and its largest penetration into the moving cutter tooth (straight flank above the tip-arc
// tangent point, or the tip arc) over all rack positions is the depth.
TEST(Profile, UndercutDepthBySweptRack)
{
  for (int z : {17, 18})
    {
      const auto   g  = gear(z, 0.0);
      const auto   tp = ToothProfile::generate(g);
      const double m = 3 * mm, a = 20 * deg, r0 = g.reference_radius(), rb = r0 * std::cos(a);
      const double rho = 0.25 * m, vt = -1.25 * m, vc = vt + rho;
      auto         ufl = [&](double v) { return gearfem::units::pi * m / 4 - v * std::tan(a); };
      const double uc = ufl(vc) + rho / std::cos(a), vtan = vc - rho * std::sin(a);
      const Vec2   q  = cf::involute(rb, psi_b(g), 0.0); // the cusp
      auto pen = [&](double s) {
        const double th = s / r0;
        const Vec2   f(std::cos(th) * q.x() + std::sin(th) * q.y(), -std::sin(th) * q.x() + std::cos(th) * q.y());
        const double u = f.x() - s, v = f.y() - r0, d = (u - ufl(v)) * std::cos(a);
        if (v - d * std::sin(a) >= vtan)
          return d;
        return rho - std::hypot(u - uc, v - vc);
      };
      double best = -1, bs = 0;
      for (int i = 0; i <= 200000; ++i)
        {
          const double s = -0.5 * r0 + r0 * 0.5 * i / 200000;
          if (pen(s) > best)
            best = pen(s), bs = s;
        }
      double lo = bs - r0 / 200000, hi = bs + r0 / 200000;
      for (int i = 0; i < 200; ++i)
        {
          const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
          (pen(m1) < pen(m2) ? lo : hi) = (pen(m1) < pen(m2) ? m1 : m2);
        }
      best = pen(0.5 * (lo + hi));
      ASSERT_TRUE(tp.undercut().present);
      EXPECT_GT(best, 0.0);
      EXPECT_NEAR(tp.undercut().depth, best, 0.02 * best) << "z " << z;
      std::cout << "[undercut] z " << z << ": depth " << tp.undercut().depth * 1e9
                << " nm, swept-cutter penetration of the cusp " << best * 1e9 << " nm" << std::endl;
    }
}

// Tooth tip rounding rho_aP* m: an arc tangent to the flank and internally tangent to the
// tip circle (closed form: every point at distance rho from a centre at radius r_a - rho);
// the outline is tangent-continuous at every joint.
TEST(Profile, TipRoundingAndTangentContinuity)
{
  auto g            = gear(30, 0.1);
  g.rack.tip_radius = 0.2;
  const auto   tp  = ToothProfile::generate(g);
  const double rho = 0.2 * 3 * mm, ra = tp.radii().tip;
  int          n   = 0;
  for (const auto &s : tp.segments())
    if (s.type == SegmentType::tip_rounding)
      {
        // The coast rounding is a CircularArc; the drive one is its mirror image (x -> -x).
        const auto *arc = s.side == Side::coast ? dynamic_cast<const CircularArc *>(s.curve.get()) :
                                                  nullptr;
        const Vec2  c   = arc ? arc->centre() : Vec2::Zero();
        for (double u : {0.0, 0.3, 0.7, 1.0})
          {
            const Vec2 p = s.point(u);
            if (arc)
              EXPECT_NEAR((p - c).norm(), rho, 1e-12);
            EXPECT_LE(p.norm(), ra + 1e-12);
          }
        if (arc)
          EXPECT_NEAR(c.norm(), ra - rho, 1e-12);
        EXPECT_EQ(s.side == Side::coast, arc != nullptr);
        ++n;
      }
  EXPECT_EQ(n, 2);
  EXPECT_NEAR(tp.segments()[tp.flank_segments(Side::coast).back() + 1].end().norm(), ra, 1e-12);
  EXPECT_LT(tp.radii().tip_form, ra);
  // Tangent continuity at all joints (flank -> rounding -> tip included).
  const auto &seg = tp.segments();
  for (std::size_t i = 0; i + 1 < seg.size(); ++i)
    {
      auto tangent = [](const ProfileSegment &s, double at) {
        const double t = s.t0 + at * (s.t1 - s.t0);
        return Vec2((s.t1 >= s.t0 ? 1.0 : -1.0) * s.curve->d1(t).normalized());
      };
      const Vec2 t_end = tangent(seg[i], 1.0), t_start = tangent(seg[i + 1], 0.0);
      EXPECT_LT((t_end - t_start).norm(), 1e-6)
        << to_string(seg[i].type) << " -> " << to_string(seg[i + 1].type);
    }
}

// Full-round cutter tip: at the largest cutter tip radius rho_max = (p/2 - u_fl(v_t)) cos a /
// (1 - sin a) (closed form: the arc tangent to the flank and to the tip line ends at the
// middle of the cutter tooth) the tooth has no root land; the two fillets meet on the root
// circle in the middle of the tooth space, tangent to it. At rho_max the fillet is still the
// closed-form trochoid (to 1e-9 mm). Within 1e-3 m of rho_max the arc is made to end at p/2
// (the radius moves by less than 1e-3 m, so the fillet stays within 1e-3 m of the nominal
// trochoid); further away the root land remains.
TEST(Profile, FullRoundCutterTip)
{
  for (const double z : {19.0, 40.0})
    {
      auto         g   = gear(int(z), 0.0);
      const double m = g.rack.module, a = g.rack.pressure_angle, p = gearfem::units::pi * m;
      const double u_tip   = p / 4 + g.rack.dedendum * m * std::tan(a);
      const double rho_max = (p / 2 - u_tip) * std::cos(a) / (1 - std::sin(a));
      for (const double d_rho : {0.0, -0.5e-3 * m, 0.5e-3 * m, -0.02 * m})
        {
          g.rack.root_radius = (rho_max + d_rho) / m;
          SCOPED_TRACE("z " + std::to_string(z) + ", rho* " + std::to_string(g.rack.root_radius));
          const auto tp  = ToothProfile::generate(g);
          const auto &sg = tp.segments();
          const bool full = std::abs(d_rho) < 1e-3 * m;
          int n_root = 0;
          for (const auto &s : sg)
            n_root += s.type == SegmentType::root;
          EXPECT_EQ(n_root, full ? 0 : 2);
          // Outline continuous; its ends in the middle of the tooth spaces, on the root circle.
          for (std::size_t i = 0; i + 1 < sg.size(); ++i)
            EXPECT_LT((sg[i].end() - sg[i + 1].start()).norm(), 1e-12) << "joint " << i;
          const double rf = tp.radii().root;
          EXPECT_NEAR(rf, g.reference_radius() - g.rack.dedendum * m, 1e-12);
          EXPECT_NEAR(std::atan2(sg.front().start().y(), sg.front().start().x()), gearfem::units::pi / 2 - gearfem::units::pi / z, 1e-12);
          EXPECT_NEAR(sg.front().start().norm(), rf, 1e-12);
          if (full)
            {
              // The fillet starts tangent to the root circle: its normal is radial there.
              const auto pts = tp.sample(0.01 * mm);
              ASSERT_EQ(pts.front().type, SegmentType::fillet);
              EXPECT_NEAR(std::abs(pts.front().normal.dot(pts.front().p.normalized())), 1.0, 1e-9);
            }
          double worst = 0;
          for (const auto &q : tp.sample(0.02 * mm))
            if (q.type == SegmentType::fillet && q.side == Side::coast)
              worst = std::max(worst, trochoid_distance(g, q.p));
          EXPECT_LT(worst, full && d_rho != 0.0 ? 1e-3 * m : 1e-9) << "fillet off the nominal trochoid";
        }
      // Beyond the tolerance the arcs of one cutter tooth overlap: a named input error.
      g.rack.root_radius = (rho_max + 2e-3 * m) / m;
      EXPECT_THROW(ToothProfile::generate(g), gearfem::InputError);
    }
}

// ToothProfile::curvature_at, used for the Hertz pressure of non-involute pairs: on the
// involute flanks of any tooth it is the closed form 1/sqrt(r^2 - r_b^2) (convex, > 0), and
// on the Siasos trochoid fillet it is concave (< 0).
TEST(Profile, CurvatureAtAnyToothMatchesInvolute)
{
  const auto   g  = gear(23, 0.1);
  const auto   tp = ToothProfile::generate(g);
  const double rb = tp.radii().base;
  int n = 0;
  for (const auto &q : tp.sample(0.3 * mm))
    for (const int k : {0, 1, 7, 22})
      {
        if (q.s < 1e-9 || q.s > 1 - 1e-9)
          continue; // a joint belongs to both of its segments
        const Vec2 p = tp.rotate_to_tooth(q.p, k);
        if (q.type == SegmentType::flank)
          {
            const double r = q.p.norm();
            EXPECT_NEAR(tp.curvature_at(p), 1 / std::sqrt(r * r - rb * rb), 1e-6 / mm) << "r " << r / mm << " tooth " << k;
            ++n;
          }
        if (q.type == SegmentType::fillet)
          EXPECT_LT(tp.curvature_at(p), 0.0);
      }
  EXPECT_GT(n, 20);
}
