// Exact rigid corner gap (see corner.h and docs/analytical.md, "Corner contact").
#include "analytical/corner.h"
#include "base/units.h"

#include "base/errors.h"
#include "base/roots.h"

#include <algorithm>
#include <cmath>

namespace gearfem::analytical
{
  namespace
  {
    using units::pi;
    constexpr double inf = std::numeric_limits<double>::infinity();

    double inv(double a) { return std::tan(a) - a; }
    double wrap(double a) { return a - 2 * pi * std::floor((a + pi) / (2 * pi)); } // (-pi, pi]

    struct P2
    {
      double x, y;
    };

    // One side of the pair in the frame of the tooth that carries the corner ("c"): O_c at
    // the origin, its base tangent point T_c = (rb_c, 0), the line of action along +y from T_c
    // to T_m = (rb_c, L), the mate's centre O_m = (rb_c + rb_m, L). Angles of the corner tooth
    // about O_c, counter-clockwise; angles of the mate about O_m measured from O_m T_m (the
    // frame turned by pi). In both, the tooth material lies at angles below the flank, and
    // the flank of a tooth whose involute touches the line of action at roll s lies at the
    // polar angle s/rb - inv(acos(rb/r)) at radius r (the involute starts on the base circle
    // at the angle s/rb).
    struct Side
    {
      double rb_c, rb_m, L;
      double r_form_m, r_tip_m; // the mate's involute runs from r_form_m to r_tip_m (0: no limit)
      double rounding, r_tip_c;
      double s_end; // roll of the corner tooth where its flank ends (the path end)

      // Angle of the corner tooth's flank at radius r, at rigid roll s.
      double flank_c(double s, double r) const { return s / rb_c - inv(std::acos(std::min(1.0, rb_c / r))); }

      // The mate's outward normal distance from the point p (exact: involutes of one base
      // circle are parallel curves, rb_m times the angular offset at the point's radius);
      // +inf where the point lies below the mate's involute. Also the outward normal.
      double distance(double s, const P2 &p, P2 *normal = nullptr, double *curvature = nullptr) const
      {
        const double qx = -(p.x - (rb_c + rb_m)), qy = -(p.y - L); // mate frame (turned by pi)
        const double r = std::hypot(qx, qy);
        if (!(r >= std::max(rb_m, r_form_m)) || (r_tip_m > 0 && r > r_tip_m))
          return inf;
        const double a = std::atan2(qy, qx);
        const double theta = (L - s) / rb_m - inv(std::acos(std::min(1.0, rb_m / r)));
        if (curvature)
          *curvature = std::sqrt(std::max(0.0, r * r - rb_m * rb_m));
        if (normal)
          {
            // Along the involute normal through p (tangent to the mate's base circle) in the
            // direction of growing roll: mate-frame angle a - atan(roll/rb_m) + pi/2.
            const double tau = a - std::atan(std::sqrt(std::max(0.0, r * r - rb_m * rb_m)) / rb_m) + 0.5 * pi;
            *normal = {-std::cos(tau), -std::sin(tau)}; // back to the corner frame
          }
        return rb_m * wrap(a - theta);
      }

      // Mate-frame gap at rigid roll s of the corner tooth (> s_end) and the touching point.
      double gap(double s, P2 *touch = nullptr, P2 *normal = nullptr, double *curvature = nullptr) const
      {
        if (rounding <= 0)
          {
            const double r = std::sqrt(rb_c * rb_c + s_end * s_end);
            const double a = flank_c(s, r);
            const P2 p{r * std::cos(a), r * std::sin(a)};
            if (touch)
              *touch = p;
            return distance(s, p, normal, curvature);
          }
        // Rounding arc of radius rho, centre c at radius r_tip - rho and rho inside the flank
        // (parallel involute), from the flank tangent point (direction psi_t from c) to the
        // tip circle (radial direction phi_c).
        const double rc = r_tip_c - rounding;
        const double phi_c = flank_c(s, rc) - rounding / rb_c;
        const P2 c{rc * std::cos(phi_c), rc * std::sin(phi_c)};
        const double psi_t = phi_c - std::atan(std::sqrt(rc * rc - rb_c * rb_c) / rb_c) + 0.5 * pi;
        P2 n;
        const double dc = distance(s, c, &n);
        const double psi = std::atan2(-n.y, -n.x); // towards the mate's flank
        const double off = wrap(psi - phi_c);
        auto on_arc = [&](double ang) { return P2{c.x + rounding * std::cos(ang), c.y + rounding * std::sin(ang)}; };
        double best = inf, bk = 0;
        P2 bp{0, 0}, bn{0, 0};
        auto consider = [&](const P2 &p) {
          P2 np;
          double k = 0;
          const double d = distance(s, p, &np, &k);
          if (d < best)
            best = d, bp = p, bn = np, bk = k;
        };
        if (std::isfinite(dc) && off >= 0 && off <= psi_t - phi_c)
          consider(on_arc(psi)); // the interior point: dc - rounding
        else
          {
            consider(on_arc(phi_c));
            consider(on_arc(psi_t));
          }
        if (touch)
          *touch = bp;
        if (normal)
          *normal = bn;
        if (curvature)
          *curvature = bk;
        return best;
      }
    };

    void check(const CornerGeometry &g)
    {
      if (!(g.rb1 > 0 && g.rb2 > 0 && g.length > 0 && g.g_A < g.g_E && g.g_A >= 0 && g.g_E <= g.length))
        throw InputError("corner geometry: inconsistent line of action (rb1 = " + to_string_g(g.rb1) +
                         ", rb2 = " + to_string_g(g.rb2) + ", T1T2 = " + to_string_g(g.length) +
                         ", g_A = " + to_string_g(g.g_A) + ", g_E = " + to_string_g(g.g_E) + " m)");
      for (int i = 0; i < 2; ++i)
        {
          const double rho = i ? g.rounding2 : g.rounding1, ra = i ? g.r_tip2 : g.r_tip1, rb = i ? g.rb2 : g.rb1;
          if (!(rho >= 0) || (rho > 0 && !(ra - rho > rb)))
            throw InputError("corner geometry: tip rounding " + to_string_g(rho) + " m of gear " + std::to_string(i + 1) +
                             " with tip radius " + to_string_g(ra) + " m (need tip radius - rounding > base radius " +
                             to_string_g(rb) + " m)");
        }
    }

    // The two sides: BΓ (pinion corner beyond E) and OA (gear corner before A).
    Side side(const CornerGeometry &g, bool pinion_corner)
    {
      Side sd;
      sd.L = g.length;
      sd.rb_c = pinion_corner ? g.rb1 : g.rb2;
      sd.rb_m = pinion_corner ? g.rb2 : g.rb1;
      sd.r_form_m = pinion_corner ? g.r_form2 : g.r_form1;
      sd.r_tip_m = pinion_corner ? g.r_tip2 : g.r_tip1;
      sd.rounding = pinion_corner ? g.rounding1 : g.rounding2;
      sd.r_tip_c = pinion_corner ? g.r_tip1 : g.r_tip2;
      if (sd.rounding > 0)
        {
          // The flank ends at the tangent point: roll of the centre's parallel involute + rho.
          const double rc = sd.r_tip_c - sd.rounding;
          sd.s_end = std::sqrt(rc * rc - sd.rb_c * sd.rb_c) + sd.rounding;
        }
      else
        sd.s_end = pinion_corner ? g.g_E : g.length - g.g_A;
      return sd;
    }

    /// The pinion-frame gap: the root of F(x) = x - G(g + x) with G(g) > 0 (F(0) < 0). The
    /// fixed-point iteration x <- G(g + x) converges when G' ~ d/R << 1, but far beyond E
    /// (FZG type C, 16/24: x ~ 4 mm at g = 29.9 mm) G' approaches 1 and it stalls; then the
    /// root is bracketed by doubling steps and bisected. G is not finite where the corner
    /// leaves the mate flank: if it becomes so before F changes sign, there is no contact
    /// (the result is not finite).
    double pinion_frame_gap(const Side &e, double g, double length)
    {
      double x = e.gap(g);
      for (int it = 0; it < 100 && std::isfinite(x); ++it)
        {
          const double next = e.gap(g + x);
          if (std::abs(next - x) <= 1e-15 * length)
            return next;
          x = next;
        }
      if (!std::isfinite(x))
        return x;
      auto F = [&](double y) { return y - e.gap(g + y); };
      double lo = 0, hi = e.gap(g), f_hi = F(hi);
      for (int k = 0; !(f_hi >= 0); ++k)
        {
          if (!std::isfinite(f_hi))
            return f_hi;
          if (k == 60 || hi > length)
            throw SolverError("corner contact: no root of x = G(g + x) within the line of action at g = " +
                              to_string_g(g) + " m (last x = " + to_string_g(hi) + " m)");
          lo = hi, hi *= 2, f_hi = F(hi);
        }
      return base::bisect_bracket(F, lo, hi, true, "corner contact: pinion-frame gap x = G(g + x)");
    }
  } // namespace

  CornerContact corner_contact(const CornerGeometry &geo, double g, GapFrame frame)
  {
    check(geo);
    CornerContact out;
    const Side e = side(geo, true), a = side(geo, false);
    if (g > e.s_end)
      {
        // BΓ. The mate (gear) turning closes the mate-frame gap G(g) directly; with the pinion
        // turning by x/rb1 instead, the configuration is that of rigid position g + x with the
        // gear turned back by x/rb2, so x solves x = G(g + x) (a contraction: G' ~ d/R << 1).
        double x = e.gap(g);
        if (frame == GapFrame::pinion && std::isfinite(x) && x > 0)
          x = pinion_frame_gap(e, g, geo.length);
        if (!std::isfinite(x))
          return out;
        out.gap = std::max(0.0, x);
        // The force acts along the gear-flank normal through the touching point, in the
        // configuration where the gap has just closed: the pinion at rigid position g + gap
        // (pinion frame) or g (mating frame; the turned gear flank is the parallel involute
        // through the corner, with the same normal).
        const double s = frame == GapFrame::pinion ? g + out.gap : g;
        P2 p{0, 0}, n{0, 0};
        e.gap(s, &p, &n, &out.mate_curvature);
        out.arm = std::abs(p.x * n.y - p.y * n.x) / geo.rb1;
        out.on_corner = true;
        return out;
      }
    const double s = geo.length - g; // roll of the gear's involute
    if (s > a.s_end)
      {
        // OA: the mate is the pinion, so both frames coincide (gear held, pinion turned).
        const double x = a.gap(s, nullptr, nullptr, &out.mate_curvature);
        if (!std::isfinite(x))
          return out;
        out.gap = std::max(0.0, x);
        out.arm = 1.0; // the normal of the pinion flank is tangent to the pinion base circle
        out.on_corner = true;
        return out;
      }
    out.gap = 0.0;
    out.arm = 1.0;
    return out;
  }

  double corner_path_end(const CornerGeometry &geo, bool at_end)
  {
    check(geo);
    return at_end ? side(geo, true).s_end : geo.length - side(geo, false).s_end;
  }

  double corner_gap(const CornerGeometry &geo, double g, GapFrame frame) { return corner_contact(geo, g, frame).gap; }

  double corner_gap_curvature_radius(const CornerGeometry &geo, bool at_end)
  {
    check(geo);
    const double rb = at_end ? geo.rb1 : geo.rb2;
    const double rho_c = at_end ? geo.g_E : geo.length - geo.g_A;
    const double rho_m = geo.length - rho_c;
    return rb * rb * rho_m / (rho_c * (rho_c + rho_m));
  }
} // namespace gearfem::analytical
