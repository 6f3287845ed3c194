// Tooth outline by rack generation: clipping at the tip circle, undercut trimming, tip
// relief, sampling and queries. See profile.h for the frame and docs/geometry.md.
#include "geometry/profile.h"
#include "geometry/limits.h"

#include "base/errors.h"
#include "base/roots.h"
#include "base/units.h"
#include "geometry/conjugate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace gearfem::geometry
{
  const char *to_string(SegmentType t)
  {
    switch (t)
      {
        case SegmentType::root: return "root";
        case SegmentType::fillet: return "fillet";
        case SegmentType::flank: return "flank";
        case SegmentType::tip_rounding: return "tip_rounding";
        case SegmentType::tip: return "tip";
      }
    return "?";
  }
  const char *to_string(Side s)
  {
    switch (s)
      {
        case Side::coast: return "coast";
        case Side::drive: return "drive";
        case Side::none: return "none";
      }
    return "?";
  }

  Vec2 ProfileSegment::point(double s) const { return curve->point(t0 + s * (t1 - t0)); }

  namespace closed_form
  {
    double inv(double a) { return std::tan(a) - a; }

    double inv_inverse(double value)
    {
      if (!(value >= 0.0))
        throw std::domain_error("inv_inverse: negative argument");
      // inv a >= a^3 / 3 on [0, pi/2): the root lies in [0, cbrt(3 value)], and Newton from
      // the upper end (inv is convex) approaches it from above.
      const double hi = std::min(std::cbrt(3.0 * value), 1.5707963267948966);
      return base::find_root_newton(
        [value](double a) {
          const double t = std::tan(a);
          return std::make_pair(t - a - value, t * t);
        },
        0.0, hi, hi, 4e-16, 100, "inverse involute function inv a = " + to_string_g(value));
    }

    Vec2 involute(double rb, double psi_b, double xi)
    {
      const double phi = psi_b - xi; // tangent point on the base circle (angle from +y)
      return rb * Vec2(std::sin(phi), std::cos(phi)) +
             rb * xi * Vec2(std::cos(phi), -std::sin(phi));
    }

    Vec2 trochoid(double r0, double rc, double hf, double theta)
    {
      const double c = std::cos(theta), s = std::sin(theta);
      // [note] Siasos prints A = atan(num/den); that picks the wrong side of the centre
      // trochoid where den < 0 (theta < 0). atan2 keeps the offset towards the gear centre
      // on both branches (at theta = 0 the point is r0 - hf below the centre, as required).
      const double A = std::atan2(-theta * r0 * s + (hf - rc) * c, theta * r0 * c + (hf - rc) * s);
      return Vec2(theta * r0 * c - (r0 + rc - hf) * s + rc * std::cos(A),
                  theta * r0 * s + (r0 + rc - hf) * c - rc * std::sin(A));
    }

    Vec2 trochoid_gear_frame(double r0, double rc, double hf, double uc, double theta)
    {
      const Vec2   p = trochoid(r0, rc, hf, theta);
      const double g = -uc / r0;
      return Vec2(std::cos(g) * p.x() - std::sin(g) * p.y(),
                  std::sin(g) * p.x() + std::cos(g) * p.y());
    }
  } // namespace closed_form

  namespace
  {

    /// Tip relief as a rotation of the generated involute about the gear centre by
    /// gamma = delta(xi)/rb: for an involute this is a normal offset by exactly delta,
    /// and the radius (hence the roll angle xi) of each point is unchanged.
    class RelievedCurve : public Curve
    {
    public:
      RelievedCurve(CurvePtr base, double xi0, double xi1, double xi_s, double xi_a, double Ca,
                    double rb, TipRelief::Kind kind)
        : base_(std::move(base)), xi0_(xi0), xi1_(xi1), xi_s_(xi_s), xi_a_(xi_a), Ca_(Ca), rb_(rb),
          parabolic_(kind == TipRelief::Kind::parabolic)
      {}
      double t_begin() const override { return base_->t_begin(); }
      double t_end() const override { return base_->t_end(); }
      Vec2   point(double t) const override { return rotate(base_->point(t), gamma(t)[0]); }
      Vec2   d1(double t) const override
      {
        const auto g = gamma(t);
        const Vec2 p = base_->point(t), p1 = base_->d1(t);
        return rotate(p1 + g[1] * perp(p), g[0]);
      }
      Vec2 d2(double t) const override
      {
        const auto g = gamma(t);
        const Vec2 p = base_->point(t), p1 = base_->d1(t), p2 = base_->d2(t);
        return rotate(p2 + 2 * g[1] * perp(p1) + g[2] * perp(p) - g[1] * g[1] * p, g[0]);
      }

    private:
      std::array<double, 3> gamma(double t) const
      {
        const double xi = xi0_ + xi1_ * t, L = xi_a_ - xi_s_;
        if (xi <= xi_s_)
          return {0.0, 0.0, 0.0};
        const double z = (xi - xi_s_) / L, k = Ca_ / rb_;
        if (parabolic_)
          return {k * z * z, k * 2 * z * xi1_ / L, k * 2 * xi1_ * xi1_ / (L * L)};
        return {k * z, k * xi1_ / L, 0.0};
      }
      CurvePtr       base_;
      double         xi0_, xi1_, xi_s_, xi_a_, Ca_, rb_;
      bool           parabolic_;
    };

    /// Trajectory in the gear frame of one rack point P (rack coordinates) as the rack
    /// moves by s: Rot(s/r0) (P.u + s, r0 + P.v); parameter s [m].
    class PointPathCurve : public Curve
    {
    public:
      PointPathCurve(const Vec2 &P, double r0, double s0, double s1)
        : P_(P), r0_(r0), s0_(s0), s1_(s1)
      {}
      double t_begin() const override { return s0_; }
      double t_end() const override { return s1_; }
      Vec2   point(double s) const override { return rotate(Q(s), s / r0_); }
      Vec2   d1(double s) const override { return rotate(Vec2(1, 0) + perp(Q(s)) / r0_, s / r0_); }
      Vec2   d2(double s) const override
      {
        return rotate(2.0 / r0_ * Vec2(0, 1) - Q(s) / (r0_ * r0_), s / r0_);
      }

    private:
      Vec2 Q(double s) const { return Vec2(P_.x() + s, r0_ + P_.y()); }
      Vec2   P_;
      double r0_, s0_, s1_;
    };

    /// First intersection (smallest t on A) of curve A on [a0, a1] with curve B on
    /// [b0, b1], ignoring the joint point A(a1) = B(b0). Returns false if none.
    bool first_intersection(const Curve &A, double a0, double a1, const Curve &B, double b0,
                            double b1, double &ta, double &tb)
    {
      const int         n = 300;
      std::vector<Vec2> pa(n + 1), pb(n + 1);
      for (int i = 0; i <= n; ++i)
        {
          pa[i] = A.point(a0 + (a1 - a0) * i / n);
          pb[i] = B.point(b0 + (b1 - b0) * i / n);
        }
      const Vec2   joint = A.point(a1);
      const double scale = joint.norm();
      bool         found = false;
      for (int i = 0; i < n && !found; ++i)
        for (int j = 0; j < n; ++j)
          {
            const Vec2   d1 = pa[i + 1] - pa[i], d2 = pb[j + 1] - pb[j], w = pb[j] - pa[i];
            const double den = d1.x() * d2.y() - d1.y() * d2.x();
            if (den == 0.0)
              continue;
            const double la = (w.x() * d2.y() - w.y() * d2.x()) / den;
            const double lb = (w.x() * d1.y() - w.y() * d1.x()) / den;
            if (la < 0 || la > 1 || lb < 0 || lb > 1)
              continue;
            const Vec2 x = pa[i] + la * d1;
            if ((x - joint).norm() < 1e-8 * scale)
              continue;
            ta    = a0 + (a1 - a0) * (i + la) / n;
            tb    = b0 + (b1 - b0) * (j + lb) / n;
            found = true;
            break;
          }
      if (!found)
        return false;
      for (int it = 0; it < 50; ++it) // Newton on A(ta) - B(tb) = 0
        {
          const Vec2 F = A.point(ta) - B.point(tb), Ja = A.d1(ta), Jb = -B.d1(tb);
          const double det = Ja.x() * Jb.y() - Ja.y() * Jb.x();
          if (det == 0.0)
            break;
          const double dta = (F.x() * Jb.y() - F.y() * Jb.x()) / det;
          const double dtb = (Ja.x() * F.y() - Ja.y() * F.x()) / det;
          ta -= dta, tb -= dtb;
          if (std::abs(dta) + std::abs(dtb) < 1e-15 * (1 + std::abs(ta) + std::abs(tb)))
            break;
        }
      return true;
    }

    double polar_from_y(const Vec2 &p) { return std::atan2(p.x(), p.y()); }
  } // namespace

  ToothProfile ToothProfile::generate(const GearParameters &gear)
  {
    return generate(gear, GeneratingRack::from_parameters(gear));
  }

  ToothProfile ToothProfile::generate_mate(const GearParameters &mate, const ToothProfile &gear1)
  {
    if (gear1.parameters().rack.kind == RackParameters::Kind::standard)
      return generate(mate);
    GearParameters m = mate;
    m.rack           = gear1.parameters().rack;
    return generate(m, gear1.rack().complement_for(m));
  }

  namespace
  {
    /// The state of ToothProfile::generate between its phases: the curves generated by the
    /// rack segments (coast side, tip to root), their parameter ranges as trimmed so far,
    /// the roles of the segments, and the extra boundary pieces (undercut end-point path,
    /// tip rounding arc).
    struct Generation
    {
      double m = 0, r0 = 0, rb = 0, ra = 0, rf = 0; ///< module; reference, base, tip, root radii
      std::string shift_name;
      std::vector<CurvePtr> gc;
      std::vector<double>   lo, hi;
      int i_tip = -1, i_flank0 = -1, i_flank = -1, i_fillet = -1, i_root = -1;
      int i_top = -1, i_first = -1; ///< the segment cut by the tip circle; the highest flank piece
      CurvePtr end_path;            ///< undercut by the end point of the rack flank (or null)
      double   path_lo = 0, path_hi = 0;
      bool     closed = false;      ///< a closed rack: the fillet is conjugate (active) profile
      CurvePtr tip_arc;             ///< tip rounding (or null)
      double   tip_a0 = 0, tip_a1 = 0;
    };

    /// Phase 1: the generated curves and the roles of the rack segments.
    void generate_curves(const GeneratingRack &rack, Generation &G)
    {
      // Generated curves (coast side, tip to root) and their parameter ranges.
      const auto         &rs = rack.segments();
      const int           n  = static_cast<int>(rs.size());
      G.gc.resize(n), G.lo.resize(n), G.hi.resize(n);
      auto &gc = G.gc;
      auto &lo = G.lo, &hi = G.hi;
      // i_flank0..i_flank: the rack flank pieces (a B-spline flank may be continued by a
      // straight tangent piece before the cutter tip arc); i_flank is next to the fillet.
      int &i_tip = G.i_tip, &i_flank0 = G.i_flank0, &i_flank = G.i_flank, &i_fillet = G.i_fillet, &i_root = G.i_root;
      for (int i = 0; i < n; ++i)
        {
          gc[i] = rs[i].gear_curve ? rs[i].gear_curve :
                                     std::make_shared<ConjugateCurve>(rs[i].curve, G.r0);
          lo[i] = gc[i]->t_begin(), hi[i] = gc[i]->t_end();
          switch (rs[i].generates)
            {
              case RackSegment::Generates::tip: i_tip = i; break;
              case RackSegment::Generates::flank:
                i_flank = i;
                if (i_flank0 < 0)
                  i_flank0 = i;
                break;
              case RackSegment::Generates::fillet: i_fillet = i; break;
              case RackSegment::Generates::root: i_root = i; break;
            }
        }
      // (No root segment: a full-round cutter tip, whose fillets meet in the middle of the
      // tooth space.)
      if (i_flank < 0 || (i_root < 0 && i_fillet < 0))
        throw std::logic_error("GeneratingRack without flank, or without both fillet and root");
    }

    /// Phase 2: undercut trimming of the flank and fillet (with the warning).
    void trim_undercut(const GearParameters &gear, const GeneratingRack &rack, Generation &G, ToothProfile &tp)
    {
      const auto &rs = rack.segments();
      auto &gc = G.gc;
      auto &lo = G.lo, &hi = G.hi;
      const int i_flank = G.i_flank, i_fillet = G.i_fillet;
      const double m = G.m, r0 = G.r0;
      const std::string &shift_name = G.shift_name;
      auto &end_path = G.end_path;
      double &path_lo = G.path_lo, &path_hi = G.path_hi;
      // Undercut. The generated flank has a cusp on the base circle when the straight part
      // of the rack reaches below the interference point; the material near the cusp is then
      // removed by the sweep of the rack flank's lower end point (its trajectory, near the
      // onset) or by the fillet envelope (deeper undercut). The outline follows the flank
      // down to the highest of these intersections, then the cutting curve. See
      // docs/geometry.md.
      if (i_fillet >= 0)
        {
          const Curve &F = *gc[i_flank];
          // Cusp: the radius along the flank has an interior minimum.
          double t_cusp = hi[i_flank], rmin = F.point(hi[i_flank]).norm();
          for (int k = 0; k <= 400; ++k)
            {
              const double t = lo[i_flank] + (hi[i_flank] - lo[i_flank]) * k / 400.0;
              if (F.point(t).norm() < rmin)
                rmin = F.point(t).norm(), t_cusp = t;
            }
          {
            double a = std::max(lo[i_flank], t_cusp - (hi[i_flank] - lo[i_flank]) / 400.0);
            double b = std::min(hi[i_flank], t_cusp + (hi[i_flank] - lo[i_flank]) / 400.0);
            for (int it = 0; it < 100; ++it)
              {
                const double c = a + (b - a) / 3, d = b - (b - a) / 3;
                (F.point(c).norm() < F.point(d).norm() ? b : a) = (F.point(c).norm() < F.point(d).norm() ? d : c);
              }
            t_cusp = 0.5 * (a + b);
          }
          const bool cusp = hi[i_flank] - t_cusp > 1e-9 * (hi[i_flank] - lo[i_flank]);
          const double b1_end = cusp ? t_cusp : hi[i_flank];
          double tf_best = std::numeric_limits<double>::infinity(), tf, tr, t_cut = 0;
          bool   by_path = false;
          if (first_intersection(F, lo[i_flank], b1_end, *gc[i_fillet], lo[i_fillet], hi[i_fillet], tf, tr) ||
              (!cusp && first_intersection(F, lo[i_flank], hi[i_flank], *gc[i_fillet], lo[i_fillet],
                                           hi[i_fillet], tf, tr)))
            tf_best = tf, t_cut = tr;
          if (cusp)
            {
              const Vec2 Pe = rs[i_flank].curve->point(rs[i_flank].curve->t_end());
              const double sJ = ConjugateCurve(rs[i_flank].curve, r0).rack_displacement(rs[i_flank].curve->t_end());
              auto path = std::make_shared<PointPathCurve>(Pe, r0, sJ - 2 * m, sJ + 2 * m);
              double ts, sp;
              if (first_intersection(F, lo[i_flank], b1_end, *path, sJ - 2 * m, sJ + 2 * m, ts, sp) &&
                  ts < tf_best)
                {
                  tf_best = ts, by_path = true, end_path = path, path_lo = sp, path_hi = sJ;
                  // The fillet envelope may take over before J.
                  double ty, tz;
                  if (first_intersection(*path, sp, sJ, *gc[i_fillet], lo[i_fillet], hi[i_fillet], ty, tz) &&
                      std::abs(ty - sJ) > 1e-9 * m)
                    path_hi = ty, t_cut = tz;
                  else
                    t_cut = lo[i_fillet];
                }
            }
          if (std::isfinite(tf_best) || cusp)
            {
              auto &u   = tp.undercut_;
              u.present = true;
              if (!std::isfinite(tf_best))
                tf_best = t_cusp, t_cut = lo[i_fillet];
              u.radius = F.point(tf_best).norm();
              // Depth: largest distance from the removed flank (down to the cusp) to the new
              // boundary (end-point path and/or fillet).
              for (int k = 1; k <= 200; ++k)
                {
                  const double t = tf_best + (b1_end - tf_best) * k / 200.0;
                  const Vec2   q = F.point(t);
                  double       dist = (gc[i_fillet]->point(gc[i_fillet]->closest_parameter_in(q, t_cut, hi[i_fillet])) - q).norm();
                  if (by_path)
                    dist = std::min(dist, (end_path->point(end_path->closest_parameter_in(q, path_lo, path_hi)) - q).norm());
                  u.depth = std::max(u.depth, dist);
                }
              hi[i_flank] = tf_best, lo[i_fillet] = t_cut;
              std::ostringstream w;
              w << "warning [" << shift_name << "]: undercut of depth " << u.depth / units::um
                << " um below radius " << u.radius / units::mm << " mm";
              tp.warnings_.push_back(w.str());
            }
        }
    }

    /// Phase 3: clip at the tip circle, pointed-tip check, tip thickness.
    void clip_at_tip_circle(const GearParameters &gear, Generation &G, ToothProfile &tp)
    {
      auto &gc = G.gc;
      auto &lo = G.lo, &hi = G.hi;
      const int i_flank0 = G.i_flank0, i_flank = G.i_flank;
      const double m = G.m, ra = G.ra;
      const std::string &shift_name = G.shift_name;
      const auto &r = gear.rack;
      int &i_tip = G.i_tip, &i_top = G.i_top, &i_first = G.i_first;
      // Tip: clip at the tip circle, from the top segment downwards.
      std::vector<int> from_top;
      if (i_tip >= 0)
        from_top.push_back(i_tip);
      for (int i = i_flank0; i <= i_flank; ++i)
        from_top.push_back(i);
      for (int i : from_top)
        {
          const double r_lo = gc[i]->point(lo[i]).norm(), r_hi = gc[i]->point(hi[i]).norm();
          if (r_hi <= ra && r_lo >= ra)
            {
              // Stops at 4 eps max(1, |t|), as the generator always has: the tip point and
            // the sampled outline (hence the gmsh mesh) stay the same to the last bit.
            lo[i] = parameter_at_radius(*gc[i], lo[i], hi[i], ra, 4 * std::numeric_limits<double>::epsilon());
              i_top = i;
              break;
            }
        }
      if (i_top < 0)
        throw InputError(r.kind == RackParameters::Kind::standard ? gear.name + "/Tip shortening coefficient" :
                                                                    "Rack/Control points",
                         "tip circle radius " + to_string_g(ra / units::mm) + " mm",
                         "reachable by the generated flank",
                         "the generated flank of " + gear.name + " does not reach the tip circle");
      // Pointed tip: the coast flank must stay right of the tooth axis up to the tip circle.
      // Scan upwards (root to tip); at the first crossing, bisect for the radius of the point.
      for (int i = i_flank; i >= i_top; --i)
        for (int k = 100; k > 0; --k)
          {
            const double tb = lo[i] + (hi[i] - lo[i]) * k / 100.0, ta = lo[i] + (hi[i] - lo[i]) * (k - 1) / 100.0;
            if (gc[i]->point(ta).x() > 0.0)
              continue;
            // x(ta) <= 0 < x(tb): x > 0 counts as the positive side, x = 0 as the negative.
            const double tp = base::bisect_bracket([&](double t) { return gc[i]->point(t).x() > 0.0 ? 1.0 : -1.0; },
                                                   ta, tb, true, "pointed-tip radius of " + gear.name);
            const double rp = gc[i]->point(tp).norm();
            if (r.kind != RackParameters::Kind::standard) // no shift: the tip circle is lowered instead
              throw InputError(gear.name + "/Tip shortening coefficient", to_string_g(gear.tip_shortening),
                               ">= " + to_string_g(gear.tip_shortening + (ra - rp) / m + 1e-3) +
                                 " (a tip circle below the pointed-tooth radius " + to_string_g(rp / units::mm) + " mm)",
                               "pointed tooth: the flanks of " + gear.name + " meet at radius " +
                                 to_string_g(rp / units::mm) + " mm (tip thickness <= 0)");
            throw InputError(shift_name, to_string_g(gear.profile_shift),
                             "a value for which the tip circle (" + to_string_g(ra / units::mm) +
                               " mm) stays below the pointed-tooth radius " +
                               to_string_g(rp / units::mm) + " mm",
                             "pointed tooth: the flanks of " + gear.name + " meet at radius " +
                               to_string_g(rp / units::mm) + " mm (tip thickness <= 0)");
          }
      const Vec2 tip_point = gc[i_top]->point(lo[i_top]);
      tp.tip_thickness_    = 2 * ra * polar_from_y(tip_point);
      if (!(tp.tip_thickness_ > 0))
        throw InputError(r.kind == RackParameters::Kind::standard ? shift_name : gear.name + "/Tip shortening coefficient",
                         to_string_g(r.kind == RackParameters::Kind::standard ? gear.profile_shift : gear.tip_shortening),
                         "a value that leaves a positive tip thickness", "pointed tooth " + gear.name);
      if (tp.tip_thickness_ < 0.2 * m)
        tp.warnings_.push_back("warning [" + shift_name + "]: tip thickness " +
                               to_string_g(tp.tip_thickness_ / units::mm) + " mm is below 0.2 m = " +
                               to_string_g(0.2 * m / units::mm) + " mm");
      if (i_top != i_tip)
        i_tip = -1; // the tip rounding lies above the tip circle
      i_first = std::max(i_top, i_flank0); // highest flank piece kept
    }

    /// Phase 4: the tooth tip rounding arc, tangent to the flank and the tip circle.
    void round_tip(const GearParameters &gear, Generation &G)
    {
      auto &gc = G.gc;
      auto &lo = G.lo, &hi = G.hi;
      const double m = G.m, ra = G.ra;
      const auto &r = gear.rack;
      const int i_tip = G.i_tip, i_first = G.i_first;
      auto &tip_arc = G.tip_arc;
      double &tip_a0 = G.tip_a0, &tip_a1 = G.tip_a1;
      // Tooth tip rounding: an arc of radius rho_aP* m tangent to the flank and internally
      // tangent to the tip circle; centre c = p + rho (inward normal) with |c| = r_a - rho.
      if (r.tip_radius > 0 && i_tip < 0)
        {
          const std::string tn  = "Rack/Tip radius coefficient";
          const double      rho = r.tip_radius * m;
          if (gear.relief.kind != TipRelief::Kind::none)
            throw InputError(gear.name + "/Tip relief", "linear/parabolic",
                             "none when " + tn + " > 0", "tip relief and tip rounding exclude each other");
          const Curve &F = *gc[i_first];
          auto centre = [&](double t) { return Vec2(F.point(t) + rho * F.right_normal(t)); };
          auto f      = [&](double t) { return centre(t).norm() - (ra - rho); };
          double a = lo[i_first], b = hi[i_first];
          if (!(f(a) > 0 && f(b) < 0))
            throw InputError(tn, to_string_g(r.tip_radius), "a smaller value",
                             "the tip rounding of " + gear.name + " does not fit on the flank");
          // f(a) > 0 > f(b); f = 0 counts as the b side.
          const double ts = base::bisect_bracket([&](double t) { return f(t) > 0 ? -1.0 : 1.0; }, a, b, true,
                                                 "tip rounding tangent point of " + gear.name);
          const Vec2   c  = centre(ts), p = F.point(ts), q = c * (ra / c.norm());
          if (!(q.x() > 0))
            throw InputError(tn, to_string_g(r.tip_radius), "a rounding that fits on half the tooth tip",
                             "the tip roundings of the two flanks of " + gear.name + " overlap");
          tip_a0 = std::atan2(p.y() - c.y(), p.x() - c.x());
          tip_a1 = std::atan2(q.y() - c.y(), q.x() - c.x());
          if (tip_a1 < tip_a0)
            tip_a1 += 2 * units::pi;
          tip_arc = std::make_shared<CircularArc>(c, rho, tip_a0, tip_a1);
          lo[i_first] = ts;
        }
    }

    /// Phase 5: key radii, the coast side (root to tip, with tip relief), the tip arc and
    /// the mirrored drive side.
    void assemble_outline(const GearParameters &gear, const Generation &G, ToothProfile &tp)
    {
      const auto &gc = G.gc;
      const auto &lo = G.lo, &hi = G.hi;
      const int i_flank = G.i_flank, i_fillet = G.i_fillet, i_root = G.i_root;
      const double r0 = G.r0, rb = G.rb, ra = G.ra, rf = G.rf;
      const auto &r = gear.rack;
      const int i_tip = G.i_tip, i_first = G.i_first;
      const auto &end_path = G.end_path;
      const double path_lo = G.path_lo, path_hi = G.path_hi;
      const auto &tip_arc = G.tip_arc;
      const double tip_a0 = G.tip_a0, tip_a1 = G.tip_a1;
      tp.radii_.base      = rb;
      tp.radii_.reference = r0;
      tp.radii_.tip       = ra;
      tp.radii_.root      = rf;
      // Form circle: the lowest point of the conjugate profile (a closed rack's fillet is).
      tp.radii_.form      = G.closed ? gc[i_fillet]->point(hi[i_fillet]).norm() : gc[i_flank]->point(hi[i_flank]).norm();
      tp.radii_.tip_form  = gc[i_first]->point(lo[i_first]).norm();
      tp.radii_.relief_start = ra;

      // Coast side, root to tip.
      std::vector<ProfileSegment> coast;
      if (i_root >= 0)
        coast.push_back({SegmentType::root, Side::coast, gc[i_root], hi[i_root], lo[i_root]});
      if (i_fillet >= 0)
        coast.push_back({SegmentType::fillet, Side::coast, gc[i_fillet], hi[i_fillet], lo[i_fillet]});
      if (end_path)
        coast.push_back({SegmentType::fillet, Side::coast, end_path, path_hi, path_lo});
      const auto &rel = gear.relief;
      if (rel.kind != TipRelief::Kind::none)
        {
          const std::string rn = gear.name + "/Tip relief";
          if (r.kind != RackParameters::Kind::standard || i_first != i_flank)
            throw InputError(rn, "linear/parabolic", "none for B-spline profiles",
                             "tip relief is defined on involute flanks only");
          require_greater(rn + " amount", rel.amount / units::um, 0.0, "um");
          // Practical reliefs are tens of um (a few hundredths of the module); a tenth of the
          // module already removes much of the tip land, and far beyond it the relieved flank
          // has no meaning (and its construction no bound on its cost).
          if (rel.amount > 0.1 * r.module)
            throw InputError(rn + " amount", to_string_g(rel.amount / units::um) + " um",
                             "(0, " + to_string_g(0.1 * r.module / units::um) + "] um (a tenth of the module)");
          const Curve &f   = *gc[i_flank];
          auto         xi  = [&](double t) { return std::sqrt(std::max(0.0, f.point(t).squaredNorm() / (rb * rb) - 1)); };
          const double ta  = lo[i_flank], tm = 0.5 * (lo[i_flank] + hi[i_flank]);
          const double xi1 = (xi(tm) - xi(ta)) / (tm - ta); // roll angle is affine in t
          const double xia = xi(ta), xi0 = xia - xi1 * ta;
          const double span = rel.roll_angle > 0 ? rel.roll_angle : rel.length / rb;
          if (!(span > 0))
            throw InputError(rn + " length", to_string_g(rel.length / units::mm) + " mm", "> 0 mm");
          const double xis = xia - span, xif = xi(hi[i_flank]);
          if (!(xis > xif))
            throw InputError(rel.roll_angle > 0 ? rn + " roll angle" : rn + " length",
                             rel.roll_angle > 0 ? to_string_g(rel.roll_angle / units::deg) + " deg" :
                                                  to_string_g(rel.length / units::mm) + " mm",
                             "less than the flank roll " +
                               (rel.roll_angle > 0 ? to_string_g((xia - xif) / units::deg) + " deg" :
                                                     to_string_g((xia - xif) * rb / units::mm) + " mm"),
                             "tip relief must start above the form circle");
          const double ts = (xis - xi0) / xi1;
          coast.push_back({SegmentType::flank, Side::coast, gc[i_flank], hi[i_flank], ts});
          auto relieved = std::make_shared<RelievedCurve>(gc[i_flank], xi0, xi1, xis, xia, rel.amount,
                                                          rb, rel.kind);
          coast.push_back({SegmentType::flank, Side::coast, relieved, ts, lo[i_flank]});
          tp.radii_.relief_start = rb * std::sqrt(1 + xis * xis);
        }
      else
        for (int i = i_flank; i >= i_first; --i)
          coast.push_back({SegmentType::flank, Side::coast, gc[i], hi[i], lo[i]});
      if (i_tip >= 0)
        coast.push_back({SegmentType::tip_rounding, Side::coast, gc[i_tip], hi[i_tip], lo[i_tip]});
      if (tip_arc)
        coast.push_back({SegmentType::tip_rounding, Side::coast, tip_arc, tip_a0, tip_a1});

      const double phi_c = std::atan2(coast.back().end().y(), coast.back().end().x());
      tp.segments_       = coast;
      tp.segments_.push_back({SegmentType::tip, Side::none,
                              std::make_shared<CircularArc>(Vec2::Zero(), ra, phi_c, units::pi - phi_c),
                              phi_c, units::pi - phi_c});
      for (auto it = coast.rbegin(); it != coast.rend(); ++it)
        tp.segments_.push_back({it->type, Side::drive, mirrored(it->curve), it->t1, it->t0});
    }
  } // namespace

  ToothProfile ToothProfile::generate(const GearParameters &gear, const GeneratingRack &rack)
  {
    ToothProfile tp;
    tp.gear_             = gear;
    tp.rack_             = rack;
    const auto  &r       = gear.rack;
    const double m       = r.module;
    limits::check_module("Rack/Module", m);
    limits::check_pressure_angle("Rack/Pressure angle", r.pressure_angle);
    limits::check_teeth(gear.name + "/Number of teeth", gear.teeth);
    Generation G;
    G.m          = m;
    G.r0         = rack.generating_pitch_radius();
    G.rb         = G.r0 * std::cos(r.pressure_angle);
    G.ra         = G.r0 + (r.addendum + gear.profile_shift - gear.tip_shortening) * m;
    G.rf         = G.r0 + rack.root_line(); // (x - h_fP*) m; a closed rack's trough
    G.shift_name = gear.name + "/Profile shift coefficient";
    G.closed     = rack.closed();
    generate_curves(rack, G);
    trim_undercut(gear, rack, G, tp);
    clip_at_tip_circle(gear, G, tp);
    round_tip(gear, G);
    assemble_outline(gear, G, tp);
    return tp;
  }

  double ToothProfile::angular_pitch() const { return 2 * units::pi / gear_.teeth; }

  std::vector<int> ToothProfile::flank_segments(Side side) const
  {
    std::vector<int> r;
    for (int i = 0; i < static_cast<int>(segments_.size()); ++i)
      if (segments_[i].type == SegmentType::flank && segments_[i].side == side)
        r.push_back(i);
    return r;
  }

  double ToothProfile::curvature_at(const Vec2 &p) const
  {
    // Tooth k stands at polar angle atan2(x, y) = -k pitch (rotate_to_tooth turns
    // counter-clockwise): turn p back to tooth 0.
    const double pitch = angular_pitch();
    const Vec2   q     = rotate(p, std::round(std::atan2(p.x(), p.y()) / pitch) * pitch);
    double best = std::numeric_limits<double>::infinity(), kappa = 0;
    for (const auto &sg : segments_)
      {
        const double t = sg.curve->closest_parameter_in(q, std::min(sg.t0, sg.t1), std::max(sg.t0, sg.t1));
        const double d = (sg.curve->point(t) - q).norm();
        if (d < best)
          best = d, kappa = (sg.t1 >= sg.t0 ? 1.0 : -1.0) * sg.curve->curvature(t);
      }
    return kappa;
  }

  Vec2 ToothProfile::rotate_to_tooth(const Vec2 &p, int k) const
  {
    return rotate(p, k * angular_pitch());
  }

  std::vector<ProfilePoint> ToothProfile::sample(double max_spacing) const
  {
    if (!(max_spacing > 0))
      throw InputError("sample spacing", to_string_g(max_spacing), "> 0 m");
    std::vector<ProfilePoint> pts;
    for (int i = 0; i < static_cast<int>(segments_.size()); ++i)
      {
        const auto  &sg   = segments_[i];
        const double L    = sg.curve->arc_length(std::min(sg.t0, sg.t1), std::max(sg.t0, sg.t1));
        // Arc-length table on a fine grid, inverted linearly.
        const int           nf = 400;
        std::vector<double> cum(nf + 1, 0.0);
        for (int k = 1; k <= nf; ++k)
          cum[k] = cum[k - 1] + (sg.point(double(k) / nf) - sg.point(double(k - 1) / nf)).norm();
        const int    nseg = std::max(1, static_cast<int>(std::ceil(1.02 * L / max_spacing)));
        const double sign = sg.t1 >= sg.t0 ? 1.0 : -1.0;
        const bool   last = i + 1 == static_cast<int>(segments_.size());
        for (int k = 0; k < (last ? nseg + 1 : nseg); ++k)
          {
            const double target = cum[nf] * k / nseg;
            const auto   it     = std::lower_bound(cum.begin(), cum.end(), target);
            int          j      = std::max(1, static_cast<int>(it - cum.begin()));
            j                   = std::min(j, nf);
            const double f = cum[j] > cum[j - 1] ? (target - cum[j - 1]) / (cum[j] - cum[j - 1]) : 0;
            const double s = std::min(1.0, (j - 1 + f) / nf);
            const double t = sg.t0 + s * (sg.t1 - sg.t0);
            ProfilePoint pp;
            pp.p         = sg.curve->point(t);
            pp.normal    = sign * sg.curve->right_normal(t);
            pp.curvature = sign * sg.curve->curvature(t);
            pp.tooth = 0, pp.segment = i, pp.s = s, pp.type = sg.type, pp.side = sg.side;
            pts.push_back(pp);
          }
      }
    return pts;
  }

  std::vector<ProfilePoint> ToothProfile::sample_gear(double max_spacing) const
  {
    auto tooth = sample(max_spacing);
    tooth.pop_back(); // the end of tooth k is the start of tooth k + 1
    std::vector<ProfilePoint> all;
    for (int k = 0; k < gear_.teeth; ++k)
      for (auto q : tooth)
        {
          q.p = rotate_to_tooth(q.p, k), q.normal = rotate_to_tooth(q.normal, k), q.tooth = k;
          all.push_back(q);
        }
    return all;
  }

  namespace
  {
    /// All parameters of segment sg (tip arc restricted to x >= 0) where f(point) = 0.
    template <typename F>
    std::vector<Vec2> coast_roots(const std::vector<ProfileSegment> &segs, F f)
    {
      std::vector<Vec2> out;
      for (const auto &sg : segs)
        {
          if (sg.side == Side::drive)
            continue;
          double a = sg.t0, b = sg.t1;
          if (sg.type == SegmentType::tip)
            b = units::pi / 2;
          const int n  = 100;
          double    tp = a, fp = f(sg.curve->point(a));
          if (fp == 0.0)
            out.push_back(sg.curve->point(a));
          for (int k = 1; k <= n; ++k)
            {
              const double t = a + (b - a) * k / n, ft = f(sg.curve->point(t));
              if ((fp < 0) != (ft < 0) && ft != 0.0)
                {
                  const double x = base::bisect_bracket([&](double u) { return f(sg.curve->point(u)); }, tp, t,
                                                        fp < 0, "profile crossing");
                  out.push_back(sg.curve->point(x));
                }
              else if (ft == 0.0)
                out.push_back(sg.curve->point(t));
              tp = t, fp = ft;
            }
        }
      return out;
    }
  } // namespace

  double ToothProfile::half_width_at_height(double y) const
  {
    const auto roots = coast_roots(segments_, [y](const Vec2 &p) { return p.y() - y; });
    if (roots.empty())
      {
        if (y >= radii_.tip)
          return 0.0;
        return y * std::tan(units::pi / gear_.teeth); // below the root arc: the tooth sector
      }
    double w = std::numeric_limits<double>::infinity();
    for (const auto &p : roots)
      w = std::min(w, std::max(0.0, p.x()));
    return w;
  }

  double ToothProfile::thickness_at_radius(double r) const
  {
    if (r > radii_.tip * (1 + 1e-12))
      return 0.0;
    if (r >= radii_.tip)
      return tip_thickness_;
    const auto roots = coast_roots(segments_, [r](const Vec2 &p) { return p.norm() - r; });
    if (roots.empty())
      return 2 * r * units::pi / gear_.teeth; // below the root circle: the whole sector
    double psi = std::numeric_limits<double>::infinity();
    for (const auto &p : roots)
      psi = std::min(psi, polar_from_y(p));
    return 2 * r * psi;
  }

  double ToothProfile::relief_at_radius(double r) const
  {
    const auto &rel = gear_.relief;
    if (rel.kind == TipRelief::Kind::none || r <= radii_.relief_start)
      return 0.0;
    const double rb = radii_.base;
    auto         xi = [rb](double rr) { return std::sqrt(std::max(0.0, rr * rr / (rb * rb) - 1)); };
    const double z  = (xi(std::min(r, radii_.tip)) - xi(radii_.relief_start)) /
                     (xi(radii_.tip_form) - xi(radii_.relief_start));
    return rel.amount * (rel.kind == TipRelief::Kind::parabolic ? z * z : z);
  }
} // namespace gearfem::geometry
