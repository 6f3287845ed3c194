// Generating racks (cutters) in ISO 53 terms. Rack coordinates: u along the pitch line
// (u = 0 at the middle of the cutter tooth space = the gear tooth axis), v positive away
// from the gear centre; the coast side (u > 0) is built, ordered from the gear tip to the
// gear root. See docs/geometry.md.
#include "geometry/rack.h"
#include "geometry/limits.h"

#include "base/errors.h"
#include "base/roots.h"
#include "base/units.h"
#include "geometry/conjugate.h"

#include <algorithm>
#include <cmath>

namespace gearfem::geometry
{
  namespace
  {

    /// Cutter tips whose arc ends this close to u = p/2 become full-round (1e-3 m).
    double full_round_tolerance(double half_pitch) { return 1e-3 * (2 * half_pitch / units::pi); }

    /// The full-round cutter tip: the straight extension l >= 0 along the flank end tangent
    /// d and the radius r of the arc tangent to it and to the tip line v = v_t that ends at
    /// u = p/2 (centre (p/2, v_t + r) = P + l d + r n). False when there is none.
    bool full_round_arc(const Vec2 &P, const Vec2 &d, const Vec2 &n, double v_t, double half_pitch, double &l,
                        double &r)
    {
      const double a11 = d.x(), a12 = n.x(), a21 = d.y(), a22 = n.y() - 1.0;
      const double b1 = half_pitch - P.x(), b2 = v_t - P.y(), det = a11 * a22 - a12 * a21;
      if (!(std::abs(det) > 1e-12))
        return false;
      l = (b1 * a22 - a12 * b2) / det, r = (a11 * b2 - a21 * b1) / det;
      if (l < 0 && l > -1e-12 * half_pitch)
        l = 0;
      return l >= 0 && r > 0;
    }

    /// Cutter tip for a rack flank ending at P (tangent d, pointing towards the gear root):
    /// the flank is continued along its end tangent until an arc of radius rho (the cutter
    /// tip radius rho_fP m) fits tangent to it and to the tip line v = v_t (the standard
    /// construction, with the end tangent in place of the straight flank); when the flank
    /// ends too low for that, the arc tangent at P itself is used. Then the tip flat to the
    /// middle of the cutter tooth u = p/2.
    ///
    /// Full-round cutter tip: when the arc of radius rho ends within 1e-3 m of u = p/2
    /// (on either side), the arc radius and the straight extension are solved so that the
    /// arc ends exactly at p/2, and there is no tip flat. (An optimiser that presses the
    /// cutter-tip constraint ends there; a 2e-11 m tip flat generated a 2e-8 mm root arc
    /// that gmsh could not mesh.) The radius changes by less than 1e-3 m.
    void append_cutter_tip(std::vector<RackSegment> &segments, const Curve &flank, double v_t,
                           double half_pitch, double rho, const std::string &gear_name)
    {
      Vec2       P = flank.point(flank.t_end());
      const Vec2 d = flank.d1(flank.t_end()).normalized();
      const Vec2 n = perp(d); // into the cutter tooth
      if (P.y() < v_t - 1e-12 * half_pitch || !(d.y() < 0))
        throw InputError("Rack/Dedendum coefficient", "cutter tip line at " +
                                                          to_string_g(v_t / units::mm) + " mm",
                         "below the end of the rack flank (" + to_string_g(P.y() / units::mm) +
                           " mm), which must run downwards",
                         "the rack flank of " + gear_name + " cannot be closed by the cutter tip");
      double a0 = 0;
      if (n.y() < 1.0 - 1e-12)
        {
          a0 = std::atan2(-n.y(), -n.x());
          if (a0 < 0)
            a0 += 2 * units::pi;
          if (!(a0 > units::pi && a0 < 1.5 * units::pi))
            throw InputError("Rack/Control points", "end tangent of the rack flank",
                             "a flank that ends going down and outwards (u' > 0, v' < 0)");
        }
      // Length of the straight extension for an arc of radius rho.
      const double lambda = (v_t + rho - P.y() - rho * n.y()) / d.y();
      const bool   extend = lambda > 1e-12 * half_pitch;
      if (n.y() < 1.0 - 1e-12)
        {
          const double r_nominal = extend ? rho : (P.y() - v_t) / (1.0 - n.y());
          const double c_x       = P.x() + (extend ? lambda : 0.0) * d.x() + r_nominal * n.x();
          double       l = 0, r = 0;
          if (std::abs(half_pitch - c_x) <= full_round_tolerance(half_pitch) &&
              full_round_arc(P, d, n, v_t, half_pitch, l, r))
            {
              const Vec2 Q = P + l * d;
              if (l > 1e-12 * half_pitch)
                segments.push_back({std::make_shared<LineSegment>(P, Q), nullptr, RackSegment::Generates::flank});
              segments.push_back({std::make_shared<CircularArc>(Q + r * n, r, a0, 1.5 * units::pi), nullptr,
                                  RackSegment::Generates::fillet});
              return; // no tip flat: the gear has no root land
            }
        }
      if (extend)
        {
          const Vec2 Q = P + lambda * d;
          segments.push_back({std::make_shared<LineSegment>(P, Q), nullptr, RackSegment::Generates::flank});
          P = Q;
        }
      Vec2 tip_start = P;
      if (n.y() < 1.0 - 1e-12)
        {
          const double r = (P.y() - v_t) / (1.0 - n.y());
          const Vec2   c = P + r * n;
          if (r > 1e-12 * half_pitch)
            segments.push_back({std::make_shared<CircularArc>(c, r, a0, 1.5 * units::pi), nullptr,
                                RackSegment::Generates::fillet});
          tip_start = Vec2(c.x(), v_t);
        }
      if (!(tip_start.x() < half_pitch))
        throw InputError("Rack/Root radius coefficient",
                         "cutter tip reaching u = " + to_string_g(tip_start.x() / units::mm) + " mm",
                         "< half a pitch (" + to_string_g(half_pitch / units::mm) + " mm)",
                         "the fillet arcs of neighbouring cutter teeth overlap for " + gear_name);
      segments.push_back({std::make_shared<LineSegment>(tip_start, Vec2(half_pitch, v_t)), nullptr,
                          RackSegment::Generates::root});
    }

    /// A rack flank that ends level in the middle of the cutter tooth (u = p/2): the
    /// closed-rack construction, not the cutter tip, completes it.
    bool ends_level_at_half_pitch(const Curve &c, double half_pitch)
    {
      const Vec2 b = c.point(c.t_end()), db = c.d1(c.t_end());
      return std::abs(b.x() - half_pitch) <= 1e-9 * half_pitch && std::abs(db.y()) <= 1e-9 * db.norm();
    }

    /// Split a closed rack (level crest at u = 0 on the tooth axis, level trough at u = p/2)
    /// into the pieces that generate flank, fillet and root: the fillet from the inflection
    /// nearest the trough (the convex cutter-tip part, whose conjugate is the concave tooth
    /// root), the root the last 0.05 m (at most half the fillet) before the trough. The
    /// crest must lie at v = h_aP* m and the trough at v = -h_fP* m, so that the tip and
    /// root circles of both gears are those of the rack.
    void split_closed_rack(GeneratingRack &rack, const CurvePtr &full, double half_pitch, double ha, double hf,
                           const std::string &gear_name)
    {
      const double m = rack.module();
      const Vec2   a = full->point(full->t_begin()), b = full->point(full->t_end());
      const Vec2   da = full->d1(full->t_begin());
      if (!(std::abs(a.x()) <= 1e-9 * half_pitch && std::abs(da.y()) <= 1e-9 * da.norm()))
        throw InputError("Rack/Control points", "first point (" + to_string_g(a.x() / m) + ", " + to_string_g(a.y() / m) + ")",
                         "a level crest at u = 0 for a rack that ends level at u = p/2 (a closed rack)",
                         "the rack of " + gear_name + " must span the tooth axis to the middle of the cutter tooth");
      auto require_level = [&](const std::string &name, double coeff, double v, const std::string &what) {
        if (std::abs(coeff * m - v) > 1e-9 * m)
          throw InputError(name, to_string_g(coeff), to_string_g(v / m) + " (the " + what + " of the closed rack, in modules)",
                           "the " + what + " of a closed rack sets the " + (what == "crest" ? "tip" : "root") +
                             " circle of " + gear_name);
      };
      require_level("Rack/Addendum coefficient", ha, a.y(), "crest");
      require_level("Rack/Dedendum coefficient", hf, -b.y(), "trough");
      const double t0 = full->t_begin(), t1 = full->t_end();
      const int    n  = 2000;
      double       ti    = t0;
      bool         found = false;
      for (int k = n - 1; k >= 1 && !found; --k)
        {
          const double ta = t0 + (t1 - t0) * k / n, tb = t0 + (t1 - t0) * (k + 1) / n;
          if ((found = full->curvature(ta) <= 0 && full->curvature(tb) > 0))
            ti = base::bisect_bracket([&](double t) { return full->curvature(t) > 0 ? 1.0 : -1.0; }, ta, tb, true,
                                      "inflection of the closed rack of " + gear_name);
        }
      if (!found)
        throw InputError("Rack/Control points", "a closed rack without an inflection",
                         "a rack that turns from its level crest down to its level trough",
                         "the rack of " + gear_name + " has no convex part near its trough to generate a fillet");
      const double ur = std::max(half_pitch - 0.05 * m, 0.5 * (full->point(ti).x() + half_pitch));
      const double tr = base::bisect_bracket([&](double t) { return full->point(t).x() - ur; }, ti, t1, true,
                                             "root piece of the closed rack of " + gear_name);
      rack.segments_.push_back({std::make_shared<TrimmedCurve>(full, t0, ti), nullptr, RackSegment::Generates::flank});
      rack.segments_.push_back({std::make_shared<TrimmedCurve>(full, ti, tr), nullptr, RackSegment::Generates::fillet});
      rack.segments_.push_back({std::make_shared<TrimmedCurve>(full, tr, t1), nullptr, RackSegment::Generates::root});
      rack.closed_ = full;
      rack.v_root_ = b.y();
    }

    void check_monotone(const Curve &c, const std::string &what)
    {
      const int n = 400;
      for (int i = 0; i <= n; ++i)
        {
          const double t = c.t_begin() + (c.t_end() - c.t_begin()) * i / n;
          if (!(c.d1(t).x() > 0.0))
            throw InputError("Rack/Control points", what,
                             "a rack flank with u strictly increasing from the tooth tip to the root",
                             "u' <= 0 at spline parameter " + to_string_g(t));
        }
    }
  } // namespace

  GeneratingRack GeneratingRack::from_parameters(const GearParameters &gear)
  {
    const RackParameters &r = gear.rack;
    limits::check_module("Rack/Module", r.module);
    limits::check_pressure_angle("Rack/Pressure angle", r.pressure_angle);
    limits::check_teeth(gear.name + "/Number of teeth", gear.teeth);
    limits::check_addendum("Rack/Addendum coefficient", r.addendum);
    require_greater("Rack/Dedendum coefficient", r.dedendum, 0.0);
    if (!(r.root_radius > 0.0 && r.root_radius <= 1.0))
      throw InputError("Rack/Root radius coefficient", to_string_g(r.root_radius), "(0, 1]",
                       "the cutter tip radius generates the root fillet");
    // A rounding far below the mesh sizes is a sharp tip that gmsh cannot mesh (1e-12 m ran
    // past any time limit): 0 or a radius of at least 0.005 m.
    if (!(r.tip_radius == 0.0 || (r.tip_radius >= min_tip_radius && r.tip_radius <= 1.0)))
      throw InputError("Rack/Tip radius coefficient", to_string_g(r.tip_radius),
                       "0 (a sharp tip) or " + to_string_g(min_tip_radius) + " to 1",
                       "a smaller tooth tip rounding is below any mesh size");
    require_range(gear.name + "/Tip shortening coefficient", gear.tip_shortening, 0.0, 1.0);

    GeneratingRack rack;
    const double   m = r.module, a = r.pressure_angle, x = gear.profile_shift;
    const double   p = units::pi * m;
    rack.m_          = m;
    rack.r0_         = gear.reference_radius();
    const double v_t = (x - r.dedendum) * m; // cutter tip line (gear root)
    const double v_b = (x + r.addendum) * m; // cutter space bottom (gear tip, unshortened)
    rack.v_root_     = v_t;

    if (r.kind == RackParameters::Kind::standard)
      {
        const double u_p  = p / 4 - gear.thickness_allowance / 2;
        auto         u_fl = [&](double v) { return u_p + (x * m - v) * std::tan(a); };
        if (!(u_fl(v_t) < p / 2))
          throw InputError("Rack/Dedendum coefficient", to_string_g(r.dedendum),
                           "a cutter tooth of positive tip width",
                           "the cutter flanks meet before the tip line");
        double       rho     = r.root_radius * m;
        const double rho_max = (p / 2 - u_fl(v_t)) * std::cos(a) / (1 - std::sin(a));
        if (rho > rho_max + full_round_tolerance(p / 2))
          throw InputError("Rack/Root radius coefficient", to_string_g(r.root_radius),
                           "<= " + to_string_g(rho_max / m) + " for this dedendum and pressure angle",
                           "the fillet arcs of one cutter tooth overlap");
        if (std::abs(rho - rho_max) <= full_round_tolerance(p / 2))
          rho = rho_max; // full-round cutter tip (append_cutter_tip)
        const Vec2 nf(std::cos(a), std::sin(a)); // flank normal into the cutter tooth
        // The flank runs up to the cutter space bottom. (Tooth tip rounding is applied to
        // the generated outline in ToothProfile: the envelope of a corner arc in the cutter
        // space bottom lies entirely outside the tip circle; see docs/geometry.md.)
        const Vec2 top(u_fl(v_b), v_b);
        // Flank: straight line down to the tangent point of the cutter tip arc.
        Vec2 bottom(u_fl(v_t), v_t);
        if (rho > 0)
          {
            const Vec2 c(u_fl(v_t + rho) + rho / std::cos(a), v_t + rho);
            bottom = c - rho * nf;
          }
        auto flank = std::make_shared<LineSegment>(top, bottom);
        rack.segments_.push_back({flank, nullptr, RackSegment::Generates::flank});
        append_cutter_tip(rack.segments_, *flank, v_t, p / 2, rho, gear.name);
        return rack;
      }

    // B-spline kinds: no shift or allowance (the mate is generated from the complement).
    if (gear.profile_shift != 0.0)
      throw InputError(gear.name + "/Profile shift coefficient", to_string_g(x), "0",
                       "B-spline racks and flanks are generated without profile shift");
    if (gear.thickness_allowance != 0.0)
      throw InputError(gear.name + "/Thickness allowance",
                       to_string_g(gear.thickness_allowance / units::mm) + " mm", "0 mm",
                       "not supported for B-spline racks and flanks");
    std::vector<Vec2> cp;
    for (const auto &q : r.control_points)
      cp.push_back(q * m);
    if (r.kind == RackParameters::Kind::bspline_rack)
      {
        if (cp.size() >= 2 && cp.front().y() < cp.back().y())
          std::reverse(cp.begin(), cp.end());
        CurvePtr spline = std::make_shared<BSplineCurve>(cp, r.spline_degree);
        check_monotone(*spline, "B-spline rack");
        if (ends_level_at_half_pitch(*spline, p / 2))
          {
            split_closed_rack(rack, spline, p / 2, r.addendum, r.dedendum, gear.name);
            return rack;
          }
        rack.segments_.push_back({spline, nullptr, RackSegment::Generates::flank});
        append_cutter_tip(rack.segments_, *spline, v_t, p / 2, r.root_radius * m, gear.name);
        return rack;
      }
    // bspline_flank: the gear flank (x > 0 side), ordered root to tip; rack recovered by
    // involutisation, both traversed tip to root.
    if (cp.size() >= 2 && cp.front().norm() > cp.back().norm())
      std::reverse(cp.begin(), cp.end());
    for (const auto &q : cp)
      if (!(q.x() > 0))
        throw InputError("Rack/Control points", "(" + to_string_g(q.x() / m) + ", " +
                                                  to_string_g(q.y() / m) + ")",
                         "points of the x > 0 flank of the tooth (x > 0)");
    CurvePtr flank_gear = std::make_shared<BSplineCurve>(cp, r.spline_degree);
    CurvePtr flank_rack = reversed(std::make_shared<InverseConjugateCurve>(flank_gear, rack.r0_));
    check_monotone(*flank_rack, "rack recovered from the B-spline flank");
    rack.segments_.push_back({flank_rack, reversed(flank_gear), RackSegment::Generates::flank});
    append_cutter_tip(rack.segments_, *flank_rack, v_t, p / 2, r.root_radius * m, gear.name);
    return rack;
  }

  GeneratingRack GeneratingRack::complement_for(const GearParameters &mate) const
  {
    if (mate.profile_shift != 0.0)
      throw InputError(mate.name + "/Profile shift coefficient", to_string_g(mate.profile_shift),
                       "0", "the mate of a B-spline gear is generated without profile shift");
    limits::check_teeth(mate.name + "/Number of teeth", mate.teeth);
    GeneratingRack rack;
    rack.m_          = m_;
    rack.r0_         = mate.reference_radius();
    const double   p = units::pi * m_;
    Eigen::Matrix2d M;
    M << -1, 0, 0, -1;
    if (closed_)
      {
        // The complement of a closed rack is closed: its crest is this trough, its trough
        // this crest.
        auto c = std::make_shared<AffineCurve>(closed_, M, Vec2(p / 2, 0.0), true);
        check_monotone(*c, "complementary rack of the mating gear");
        split_closed_rack(rack, c, p / 2, mate.rack.addendum, mate.rack.dedendum, mate.name);
        return rack;
      }
    for (auto it = segments_.rbegin(); it != segments_.rend(); ++it)
      if (const auto &seg = *it; seg.generates == RackSegment::Generates::flank)
        {
          auto c = std::make_shared<AffineCurve>(seg.curve, M, Vec2(p / 2, 0.0), true);
          check_monotone(*c, "complementary rack of the mating gear");
          rack.segments_.push_back({c, nullptr, RackSegment::Generates::flank});
        }
    const double v_t = (mate.profile_shift - mate.rack.dedendum) * m_;
    rack.v_root_     = v_t;
    append_cutter_tip(rack.segments_, *rack.segments_.back().curve, v_t, p / 2,
                      mate.rack.root_radius * m_, mate.name);
    return rack;
  }
} // namespace gearfem::geometry
