// Spur-pair kinematics: closed-form involute relations (ISO 21771 / AGMA 908 line-of-action
// construction, Siasos 2010) and a general gap-closing search on the exact outlines.
#include "geometry/pair.h"

#include "base/errors.h"
#include "base/roots.h"
#include "base/units.h"
#include "geometry/conjugate.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <sstream>
#include <limits>

namespace gearfem::geometry
{
  using closed_form::inv;

  namespace
  {
    /// Circular tooth thickness on the reference circle with profile shift and thickness
    /// allowance [m] (module m and pressure angle alpha of the pair).
    double reference_thickness(const GearParameters &g, double m, double alpha)
    {
      const double p = units::pi * m;
      return p / 2 + 2 * g.profile_shift * m * std::tan(alpha) - g.thickness_allowance;
    }
  } // namespace

  Vec2 Placement::apply(const Vec2 &x) const { return centre + rotate(x, angle); }
  Vec2 Placement::apply_vector(const Vec2 &v) const { return rotate(v, angle); }

  double minimum_teeth_without_undercut(double alpha, double dedendum, double root_radius,
                                        double shift)
  {
    const double s = std::sin(alpha);
    return 2 * ((dedendum - shift) - root_radius * (1 - s)) / (s * s);
  }

  double center_distance_from_shifts(double module, double alpha, int z1, int z2, double x1,
                                     double x2)
  {
    const double inv_w = inv(alpha) + 2 * std::tan(alpha) * (x1 + x2) / (z1 + z2);
    const double aw    = closed_form::inv_inverse(inv_w);
    return 0.5 * module * (z1 + z2) * std::cos(alpha) / std::cos(aw);
  }

  double GearPair::base_radius(int i) const { return gear(i).radii().base; }
  double GearPair::base_pitch() const { return 2 * units::pi * base_radius(1) / g1_.teeth(); }
  double GearPair::ratio() const { return double(g2_.teeth()) / g1_.teeth(); }

  double GearPair::flank_length_to_tip(int i, double r) const
  {
    const double rb = base_radius(i), rtf = gear(i).radii().tip_form;
    return std::max(0.0, (rtf * rtf - r * r) / (2 * rb));
  }

  bool GearPair::beyond_tip_form(int i, double r, double tol) const { return r >= gear(i).radii().tip_form - tol; }

  bool GearPair::has_relief(int i) const { return gear(i).parameters().relief.kind != TipRelief::Kind::none; }

  std::array<double, 2> GearPair::radii_of_curvature(const Vec2 &x, const std::array<Placement, 2> &P) const
  {
    const double rb1 = base_radius(1), rb2 = base_radius(2);
    const double r1 = (x - P[0].centre).norm(), r2 = (x - P[1].centre).norm();
    std::array<double, 2> rho{r1 > rb1 ? std::sqrt(r1 * r1 - rb1 * rb1) : 0, r2 > rb2 ? std::sqrt(r2 * r2 - rb2 * rb2) : 0};
    if (!involute_)
      {
        auto body = [&](int i) { return Eigen::Rotation2Dd(-P[i].angle) * (x - P[i].centre); };
        const double k1 = g1_.curvature_at(body(0)), k2 = g2_.curvature_at(body(1));
        rho = {k1 + k2 > 0 ? 1 / k1 : 0, k1 + k2 > 0 ? 1 / k2 : 0};
      }
    return rho;
  }

  double GearPair::tip_clearance(int i) const
  {
    return a_ - gear(i).radii().tip - gear(i == 1 ? 2 : 1).radii().root;
  }

  const LoaPoint &GearPair::point(const std::string &name) const
  {
    for (const auto &p : loa_)
      if (p.name == name)
        return p;
    throw std::out_of_range("GearPair::point: no point " + name);
  }

  GearPair::GearPair(ToothProfile gear1, ToothProfile gear2, const PairParameters &pair)
    : g1_(std::move(gear1))
    , g2_(std::move(gear2))
  {
    set_centre_distance(pair);
    set_backlash();
    set_path_of_contact(pair);
    check_design();
  }

  void GearPair::set_centre_distance(const PairParameters &pair)
  {
    const auto &p1 = g1_.parameters(), &p2 = g2_.parameters();
    if (p1.rack.module != p2.rack.module)
      throw InputError("Rack/Module", mm_text(p2.rack.module), mm_text(p1.rack.module),
                       "both gears of a pair need the same module");
    if (p1.rack.pressure_angle != p2.rack.pressure_angle)
      throw InputError("Rack/Pressure angle", to_string_g(p2.rack.pressure_angle / units::deg),
                       to_string_g(p1.rack.pressure_angle / units::deg),
                       "both gears of a pair need the same pressure angle");
    involute_ = p1.rack.kind == RackParameters::Kind::standard &&
                p2.rack.kind == RackParameters::Kind::standard;
    const int    z1 = p1.teeth, z2 = p2.teeth;
    const double m = p1.rack.module, alpha = p1.rack.pressure_angle, p = units::pi * m;
    const double rb1 = base_radius(1), rb2 = base_radius(2);
    const double r01 = g1_.radii().reference, r02 = g2_.radii().reference;
    const double ra1 = g1_.radii().tip, ra2 = g2_.radii().tip;
    const std::string a_name = "Pair/Centre distance";

    // Zero-backlash centre distance for the actual thicknesses (shifts and allowances).
    const double s1 = reference_thickness(p1, m, alpha), s2 = reference_thickness(p2, m, alpha);
    {
      const double inv0 = inv(alpha) + (s1 + s2 - p) / (m * (z1 + z2));
      if (!(inv0 > 0))
        throw InputError(p1.name + "/Thickness allowance", mm_text(p1.thickness_allowance), "smaller",
                         "the teeth are too thin to mesh at any centre distance");
      a0_ = (rb1 + rb2) / std::cos(closed_form::inv_inverse(inv0));
    }
    a_ = pair.center_distance > 0 ?
           pair.center_distance :
           center_distance_from_shifts(m, alpha, z1, z2, p1.profile_shift, p2.profile_shift);
    if (!involute_ && std::abs(a_ - (r01 + r02)) > 1e-9)
      throw InputError(a_name, mm_text(a_), mm_text(r01 + r02),
                       "B-spline pairs run at the reference centre distance");
    const double a_min = std::max({rb1 + rb2, ra1 + g2_.radii().root, ra2 + g1_.radii().root});
    const double a_max = ra1 + ra2;
    if (!(a_ >= a_min && a_ < a_max && a_ > rb1 + rb2))
      throw InputError(a_name, mm_text(a_), "[" + mm_text(a_min) + ", " + mm_text(a_max) + ")",
                       "the centre distance must leave tip clearance and overlap the tip circles");
    alpha_w_ = std::acos((rb1 + rb2) / a_);
    rw1_     = rb1 / std::cos(alpha_w_);
    rw2_     = rb2 / std::cos(alpha_w_);
  }

  void GearPair::set_backlash()
  {
    const auto  &p1 = g1_.parameters(), &p2 = g2_.parameters();
    const int    z1 = p1.teeth;
    const double m = p1.rack.module, alpha = p1.rack.pressure_angle;
    const double r01 = g1_.radii().reference, r02 = g2_.radii().reference;
    const double s1 = reference_thickness(p1, m, alpha), s2 = reference_thickness(p2, m, alpha);
    const std::string a_name = "Pair/Centre distance";

    // Thicknesses on the working pitch circles and the backlash.
    double sw1, sw2;
    if (involute_)
      {
        sw1 = 2 * rw1_ * (s1 / (2 * r01) + inv(alpha) - inv(alpha_w_));
        sw2 = 2 * rw2_ * (s2 / (2 * r02) + inv(alpha) - inv(alpha_w_));
      }
    else
      {
        sw1 = g1_.thickness_at_radius(rw1_);
        sw2 = g2_.thickness_at_radius(rw2_);
      }
    jt_ = 2 * units::pi * rw1_ / z1 - sw1 - sw2;
    if (std::abs(jt_) < 1e-13) // round-off of the zero-backlash case
      jt_ = 0.0;
    jn_ = jt_ * std::cos(alpha_w_);
    if (jt_ < -1e-12)
      throw InputError(a_name, mm_text(a_), ">= " + mm_text(a0_) + " (zero backlash)",
                       "negative backlash: circumferential backlash " + to_string_g(jt_ / units::um) +
                         " um");
    phase1_ = -sw1 / (2 * rw1_);
    phase2_ = units::pi - sw2 / (2 * rw2_);
  }

  void GearPair::set_path_of_contact(const PairParameters &pair)
  {
    const auto  &p1 = g1_.parameters(), &p2 = g2_.parameters();
    const double rb1 = base_radius(1), rb2 = base_radius(2);
    const double r01 = g1_.radii().reference;
    const double ra1 = g1_.radii().tip, ra2 = g2_.radii().tip;
    const std::string a_name = "Pair/Centre distance";

    // Line of action (pair frame): T1 = rb1 (sin aw, cos aw), direction d = (-cos aw, sin aw).
    const double sa = std::sin(alpha_w_), ca = std::cos(alpha_w_);
    const Vec2   T1(rb1 * sa, rb1 * ca), d(-ca, sa), O2(0.0, a_);
    const double T1T2 = a_ * sa, gC = rw1_ * sa, pb = base_pitch();
    double       gA, gE;
    if (involute_)
      {
        // End of the active flank: the tip circle, or the start of the tip rounding (ISO
        // 21771 d_Na); contact on the rounding itself is corner contact under load.
        const double rN1 = g1_.radii().tip_form, rN2 = g2_.radii().tip_form;
        gE = std::sqrt(rN1 * rN1 - rb1 * rb1);
        gA = T1T2 - std::sqrt(rN2 * rN2 - rb2 * rb2);
      }
    else
      {
        // Rack-generated path of contact: ends where it leaves the tip circles.
        // A closed rack's fillet is conjugate profile too: the path runs over it.
        const bool            closed = g1_.rack().closed();
        std::vector<CurvePtr> rack_flanks;
        for (const auto &rs : g1_.rack().segments())
          if (rs.generates == RackSegment::Generates::flank || (closed && rs.generates == RackSegment::Generates::fillet))
            rack_flanks.insert(rack_flanks.begin(), rs.curve); // root to tip
        std::vector<int> fl = g1_.flank_segments(Side::coast); // root to tip
        if (closed)
          for (int i = 0; i < static_cast<int>(g1_.segments().size()); ++i)
            if (g1_.segments()[i].type == SegmentType::fillet && g1_.segments()[i].side == Side::coast)
              fl.insert(fl.begin(), i);
        for (std::size_t j = 0; j < fl.size() && j < rack_flanks.size(); ++j)
          {
            const auto &sg = g1_.segments()[fl[j]];
            path_.push_back({rack_flanks[j], std::min(sg.t0, sg.t1), std::max(sg.t0, sg.t1)});
          }
        auto phi_of = [&](const PathPiece &pc, double t) {
          return ConjugateCurve(pc.rack, r01).rack_displacement(t) / r01 - phase1_;
        };
        auto pt = [&](const PathPiece &pc, double t) {
          const Vec2 q = ConjugateCurve(pc.rack, r01).contact_point(t);
          return Vec2(-q.x(), q.y());
        };
        // Pinion position where f(point) changes sign along the path; NaN if nowhere.
        auto solve = [&](auto f) {
          for (const auto &pc : path_)
            {
              double a = pc.tl, b = pc.th, fa = f(pt(pc, a)), fb = f(pt(pc, b));
              if (std::abs(fa) < 1e-12)
                return phi_of(pc, a);
              if (std::abs(fb) < 1e-12)
                return phi_of(pc, b);
              if ((fa < 0) == (fb < 0))
                continue;
              return phi_of(pc, base::bisect_bracket([&](double t) { return f(pt(pc, t)); }, a, b, fa < 0,
                                                     "end of the path of contact"));
            }
          return std::numeric_limits<double>::quiet_NaN();
        };
        double phiE = solve([&](const Vec2 &q) { return q.norm() - ra1; });
        const double phiA = solve([&](const Vec2 &q) { return (q - O2).norm() - ra2; });
        if (std::isnan(phiA))
          throw InputError("Rack/Control points", "the generated flank of " + p1.name,
                           "a flank that reaches the start of active profile",
                           "tip-to-fillet interference: the tip of " + p2.name +
                             " meets " + p1.name + " below its flank (form radius " +
                             mm_text(g1_.radii().form) + ")");
        if (std::isnan(phiE))
          phiE = phi_of(path_.back(), path_.back().tl);
        // One contact point per tooth pair: the pinion angle must change one way along the
        // active path (inside both tip circles). Racks like the sinusoid of Koronaios 2021 reverse it
        // (K(u) = -u + m sin(4u/m)): several points of a flank touch at once.
        // (Each piece on its own: pieces may run in either parameter direction.)
        for (const auto &pc : path_)
          for (double k = 0, phi_prev = std::numeric_limits<double>::quiet_NaN(), trend = 0; k <= 400; ++k)
            {
              const double t = pc.tl + (pc.th - pc.tl) * k / 400;
              const Vec2   q = pt(pc, t);
              if (q.norm() > ra1 || (q - O2).norm() > ra2)
                continue;
              const double phi = phi_of(pc, t), step = phi - phi_prev;
              if (std::abs(step) > 1e-6 * std::abs(phiE - phiA))
                {
                  if (trend * step < 0)
                    throw InputError("Rack/Control points", "the path of contact of " + p1.name + " and " + p2.name,
                                     "a path along which the contact point moves one way",
                                     "the contact reverses at r1 = " + mm_text(q.norm()) +
                                       ": several points of one flank touch at once, which the path model "
                                       "(one contact point per tooth pair) does not follow");
                  trend = step;
                }
              phi_prev = phi;
            }
        gE = gC + rb1 * phiE, gA = gC + rb1 * phiA;
      }
    eps_alpha_ = (gE - gA) / pb;
    if (eps_alpha_ < 1.0)
      throw InputError(pair.center_distance > 0 && a_ > a0_ ? a_name : std::string("Rack/Addendum coefficient"),
                       pair.center_distance > 0 && a_ > a0_ ? mm_text(a_) : to_string_g(p1.rack.addendum),
                       "a value giving a transverse contact ratio >= 1",
                       "contact ratio " + to_string_g(eps_alpha_) + " < 1");

    auto make = [&](const std::string &name, double g) {
      LoaPoint q;
      q.name       = name;
      q.g          = g;
      q.roll_angle = (g - gC) / rb1;
      q.position   = (involute_ || name == "T1" || name == "T2") ? Vec2(T1 + g * d) :
                                                                   path_point(q.roll_angle);
      q.r1         = q.position.norm();
      q.r2         = (q.position - O2).norm();
      return q;
    };
    loa_ = {make("T1", 0.0), make("T2", T1T2), make("A", gA), make("B", gE - pb),
            make("C", gC),   make("D", gA + pb), make("E", gE)};
  }

  void GearPair::check_design()
  {
    const auto  &p1 = g1_.parameters(), &p2 = g2_.parameters();
    const double m = p1.rack.module;
    const double rb1 = base_radius(1), rb2 = base_radius(2);
    const double ra1 = g1_.radii().tip, ra2 = g2_.radii().tip;
    const double T1T2 = a_ * std::sin(alpha_w_), gA = point("A").g, gE = point("E").g;
    const std::string a_name = "Pair/Centre distance";

    // Design checks on the path of contact. k_min: the tip shortening of the mate that
    // brings its tip circle to radius r_max (involute pairs).
    auto k_min = [&](const GearParameters &mate, double ra_mate, double r_max) {
      return ">= " + to_string_g(mate.tip_shortening + (ra_mate - r_max) / m);
    };
    if (involute_ && gA < 0)
      throw InputError(p2.name + "/Tip shortening coefficient", to_string_g(p2.tip_shortening),
                       k_min(p2, ra2, std::sqrt(T1T2 * T1T2 + rb2 * rb2)),
                       "tip-to-fillet interference: the tip of " + p2.name + " passes T1 by " +
                         mm_text(-gA));
    if (involute_ && gE > T1T2)
      throw InputError(p1.name + "/Tip shortening coefficient", to_string_g(p1.tip_shortening),
                       k_min(p1, ra1, std::sqrt(T1T2 * T1T2 + rb1 * rb1)),
                       "tip-to-fillet interference: the tip of " + p1.name + " passes T2 by " +
                         mm_text(gE - T1T2));
    const double rA1 = point("A").r1, rE2 = point("E").r2;
    auto check_active = [&](ToothProfile &g, const GearParameters &own, const GearParameters &mate,
                            double r_sap) {
      auto &u = g.undercut_;
      if (u.present && r_sap < u.radius)
        {
          u.cuts_active_profile = true;
          throw InputError(own.name + "/Profile shift coefficient", to_string_g(own.profile_shift),
                           ">= " + to_string_g(own.profile_shift + (u.radius - r_sap) / m) +
                             " (approximately)",
                           "undercut removes active profile of " + own.name + ": contact starts at r = " +
                             mm_text(r_sap) + " but the undercut reaches r = " + mm_text(u.radius));
        }
      if (r_sap < g.radii().form * (1 - 1e-12))
        {
          // Largest mate tip radius that keeps contact at or above r_Ff of `own`.
          const double rb_own = g.radii().base, rb_mate = (&g == &g1_) ? rb2 : rb1;
          const double gF     = std::sqrt(std::max(0.0, g.radii().form * g.radii().form - rb_own * rb_own));
          const double ra_m   = (&g == &g1_) ? ra2 : ra1;
          throw InputError(mate.name + "/Tip shortening coefficient", to_string_g(mate.tip_shortening),
                           involute_ ? k_min(mate, ra_m, std::hypot(T1T2 - gF, rb_mate)) :
                                       std::string("a tip that keeps contact above the form circle"),
                         "tip-to-fillet interference: the tip of " + mate.name + " reaches r = " +
                           mm_text(r_sap) + " on " + own.name + ", below its form circle r_Ff = " +
                           mm_text(g.radii().form));
        }
    };
    check_active(g1_, p1, p2, rA1);
    check_active(g2_, p2, p1, rE2);
    for (int i : {1, 2})
      if (tip_clearance(i) < 0.1 * m)
        warnings_.push_back("warning [" + a_name + "]: tip clearance of gear " + std::to_string(i) +
                            " is " + mm_text(tip_clearance(i)) + " (< 0.1 m)");
  }

  Placement GearPair::placement(int i, double phi1) const
  {
    if (i == 1)
      return {Vec2::Zero(), phase1_ + phi1};
    return {Vec2(0.0, a_), conjugate_angle(phi1)};
  }

  double GearPair::conjugate_angle(double phi1) const
  {
    if (involute_)
      return phase2_ - phi1 / ratio();
    return conjugate_angle_by_search(phi1);
  }

  double GearPair::signed_gap(double beta, double phi1) const
  {
    // Smallest signed distance (positive = clearance) from the drive flanks of gear 2 at
    // angle beta to the drive flanks of the pinion at position phi1, over the teeth in mesh.
    const double ang1 = phase1_ + phi1, pitch1 = g1_.angular_pitch(), pitch2 = g2_.angular_pitch();
    const auto   f1 = g1_.flank_segments(Side::drive), f2 = g2_.flank_segments(Side::drive);
    const Vec2   O2(0.0, a_);
    auto dist = [&](const ProfileSegment &s2, int j, double t) {
      const Vec2 q  = O2 + rotate(rotate(s2.curve->point(t), j * pitch2), beta); // pair frame
      Vec2       qb = rotate(q, -ang1);                                          // pinion body
      // Into the frame of the pinion tooth whose drive flank (the x < 0 side) faces the
      // point: theta = atan2(x, y) from that tooth's axis in (-pitch, 0]. (theta grows
      // clockwise, so the tooth n pitches clockwise is reached by turning n pitches
      // counter-clockwise. The former reduction turned the wrong way and to the nearest
      // tooth axis: a gear-2 tip in a tooth space measured against a flank two pitches away
      // gave -14 mm, a spurious root of the gap, at 4 of 20 positions of the case-2
      // optimum of Koronaios 2021.)
      const int  k  = static_cast<int>(std::ceil(std::atan2(qb.x(), qb.y()) / pitch1));
      qb            = rotate(qb, k * pitch1);
      double best   = std::numeric_limits<double>::infinity();
      for (int i : f1)
        {
          const auto  &s1 = g1_.segments()[i];
          const double tc = s1.curve->closest_parameter_in(qb, s1.t0, s1.t1);
          if (tc == std::min(s1.t0, s1.t1) || tc == std::max(s1.t0, s1.t1))
            continue; // the projection is not on this piece
          const double sign = s1.t1 >= s1.t0 ? 1.0 : -1.0;
          const double dd   = (qb - s1.curve->point(tc)).dot(sign * s1.curve->right_normal(tc));
          best              = std::min(best, dd);
        }
      return best;
    };
    double best = std::numeric_limits<double>::infinity();
    for (int j = -2; j <= 2; ++j)
      for (int i : f2)
        {
          const auto &s2 = g2_.segments()[i];
          const int   n  = 40;
          double      bt = s2.t0, bd = std::numeric_limits<double>::infinity();
          for (int k = 0; k <= n; ++k)
            {
              const double t = s2.t0 + (s2.t1 - s2.t0) * k / n, dd = dist(s2, j, t);
              if (dd < bd)
                bd = dd, bt = t;
            }
          if (!std::isfinite(bd))
            continue;
          // Golden-section refinement of the minimum around the best sample.
          const double h = std::abs(s2.t1 - s2.t0) / n;
          double a = std::max(std::min(s2.t0, s2.t1), bt - h), b = std::min(std::max(s2.t0, s2.t1), bt + h);
          const double gr = 0.5 * (std::sqrt(5.0) - 1);
          double c = b - gr * (b - a), e = a + gr * (b - a), fc = dist(s2, j, c), fe = dist(s2, j, e);
          for (int it = 0; it < 80 && b - a > 1e-15 * std::max(1.0, std::abs(b)); ++it)
            if (fc < fe)
              b = e, e = c, fe = fc, c = b - gr * (b - a), fc = dist(s2, j, c);
            else
              a = c, c = e, fc = fe, e = a + gr * (b - a), fe = dist(s2, j, e);
          best = std::min({best, bd, fc, fe});
        }
    return best;
  }

  double GearPair::conjugate_angle_by_search(double phi1) const
  {
    // Secant iteration on the gap, started from the nominal ratio.
    double b0 = phase2_ - phi1 / ratio(), b1 = b0 + 1e-6;
    double f0 = signed_gap(b0, phi1), f1 = signed_gap(b1, phi1);
    for (int it = 0; it < 60; ++it)
      {
        if (!std::isfinite(f0) || !std::isfinite(f1))
          throw SolverError("conjugate search: no flank pair in mesh at phi1 = " + to_string_g(phi1));
        if (f1 == f0)
          break;
        const double b2 = b1 - f1 * (b1 - b0) / (f1 - f0);
        b0 = b1, f0 = f1, b1 = b2, f1 = signed_gap(b1, phi1);
        if (std::abs(b1 - b0) < 1e-15 || std::abs(f1) < 1e-15)
          break;
      }
    if (!(std::abs(f1) < 1e-10))
      throw SolverError("conjugate search did not close the gap at phi1 = " + to_string_g(phi1) +
                        " (residual " + to_string_g(f1) + " m)");
    // The gap is periodic in beta with gear 2's angular pitch, and the secant iteration can
    // land on a root whole pitches away (the case-2 optimum of Koronaios 2021: two pitches at
    // four of twenty positions). Every root is the same contact up to the numbering of gear 2's
    // teeth, but a sector model has only the teeth that mesh at the nominal angle: return
    // the root nearest the nominal ratio.
    const double nominal = phase2_ - phi1 / ratio(), pitch2 = g2_.angular_pitch();
    const double reduced = nominal + std::remainder(b1 - nominal, pitch2);
    if (reduced != b1)
      {
        const double fr = signed_gap(reduced, phi1);
        if (!(std::abs(fr) < 1e-10))
          throw SolverError("conjugate search: the gap closed " + to_string_g((b1 - nominal) / pitch2) +
                            " gear-2 pitches from the nominal angle at phi1 = " + to_string_g(phi1) +
                            " but not within half a pitch of it (residual " + to_string_g(fr) + " m)");
      }
    return reduced;
  }

  std::pair<int, double> GearPair::path_parameter(double phi1) const
  {
    const double r01 = g1_.radii().reference;
    for (int j = 0; j < static_cast<int>(path_.size()); ++j)
      {
        ConjugateCurve cc(path_[j].rack, r01);
        auto   f  = [&](double t) { return cc.rack_displacement(t) / r01 - phase1_ - phi1; };
        double a  = path_[j].tl, b = path_[j].th, fa = f(a), fb = f(b);
        if (std::abs(fa) < 1e-12)
          return {j, a};
        if (std::abs(fb) < 1e-12)
          return {j, b};
        if ((fa < 0) == (fb < 0))
          continue;
        return {j, base::bisect_bracket(f, a, b, fa < 0, "path parameter at pinion position " + to_string_g(phi1))};
      }
    throw SolverError("pinion position " + to_string_g(phi1) + " rad is outside the generated flank");
  }

  Vec2 GearPair::contact_point(double phi1) const
  {
    return path_point(std::remainder(phi1, g1_.angular_pitch()));
  }

  Vec2 GearPair::path_point(double phi) const
  {
    if (involute_)
      {
        const double sa = std::sin(alpha_w_), ca = std::cos(alpha_w_);
        const double g  = rw1_ * sa + base_radius(1) * phi;
        return Vec2(base_radius(1) * sa, base_radius(1) * ca) + g * Vec2(-ca, sa);
      }
    const auto [j, t] = path_parameter(phi);
    const Vec2 q      = ConjugateCurve(path_[j].rack, g1_.radii().reference).contact_point(t);
    return Vec2(-q.x(), q.y());
  }

  double GearPair::equivalent_curvature(double phi1) const
  {
    return path_curvature(std::remainder(phi1, g1_.angular_pitch()));
  }

  double GearPair::path_curvature(double phi) const
  {
    if (involute_)
      {
        const double g = rw1_ * std::sin(alpha_w_) + base_radius(1) * phi;
        const double rho1 = g, rho2 = a_ * std::sin(alpha_w_) - g;
        if (!(rho1 > 0 && rho2 > 0))
          throw InputError("pinion position", to_string_g(phi),
                           "inside T1..T2 on the line of action");
        return 1 / rho1 + 1 / rho2;
      }
    const Vec2 P = path_point(phi);
    double     k = 0;
    for (int i : {1, 2})
      {
        // The gear at its placement for phi; the tooth that carries P is the one nearest.
        const auto pl = placement(i, phi);
        Vec2       qb = rotate(P - pl.centre, -pl.angle);
        const double pitch = gear(i).angular_pitch();
        qb = rotate(qb, -std::lround(std::atan2(qb.x(), qb.y()) / pitch) * pitch);
        double best = std::numeric_limits<double>::infinity(), kk = 0;
        for (int s : gear(i).flank_segments(Side::drive))
          {
            const auto  &sg = gear(i).segments()[s];
            const double tc = sg.curve->closest_parameter_in(qb, sg.t0, sg.t1);
            const double dd = (sg.curve->point(tc) - qb).norm();
            if (dd < best)
              best = dd, kk = (sg.t1 >= sg.t0 ? 1.0 : -1.0) * sg.curve->curvature(tc);
          }
        k += kk;
      }
    return k;
  }

  std::string geometry_fingerprint(const GearPair &pair)
  {
    std::ostringstream s;
    s.precision(12);
    for (int i = 1; i <= 2; ++i)
      {
        const auto &g = pair.gear(i);
        const auto &p = g.parameters();
        s << g.teeth() << ' ' << p.rack.module << ' ' << p.rack.pressure_angle << ' ' << p.profile_shift << ' '
          << p.face_width << ' ' << g.radii().tip << ' ' << g.radii().root << ' ' << g.radii().base
          << ' ' << g.tip_thickness() << ' ' << p.relief.amount << ' ' << p.rack.tip_radius << ';';
      }
    s << pair.center_distance();
    return text_fingerprint(s.str());
  }

  std::string text_fingerprint(const std::string &text)
  {
    std::uint64_t h = 1469598103934665603ull;
    for (const char c : text)
      {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ull;
      }
    std::ostringstream hex;
    hex << std::hex << h;
    return hex.str();
  }

  std::vector<int> loaded_teeth(const GearPair &pair, const std::vector<double> &roll, double margin_pitches)
  {
    const double tau = 2 * M_PI / pair.teeth(1);
    const double lo  = pair.point("A").roll_angle - margin_pitches * tau;
    const double hi  = pair.point("E").roll_angle + margin_pitches * tau;
    std::set<int> k;
    for (const double phi : roll)
      for (int i = int(std::ceil((lo - phi) / tau)); i <= int(std::floor((hi - phi) / tau)); ++i)
        k.insert(i);
    return {k.begin(), k.end()};
  }
} // namespace gearfem::geometry
