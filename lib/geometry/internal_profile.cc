#include "geometry/internal_profile.h"
#include "geometry/limits.h"

#include "base/errors.h"
#include "base/units.h"

#include <algorithm>
#include <cmath>

namespace gearfem::geometry
{
  namespace
  {
    using closed_form::inv;
    using units::pi;

    Eigen::Matrix2d rot(double t)
    {
      Eigen::Matrix2d R;
      R << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
      return R;
    }
    /// Counter-clockwise rotation by 90 deg.
    double cross(const Vec2 &a, const Vec2 &b) { return a.x() * b.y() - a.y() * b.x(); }
    /// e(phi) = (sin phi, cos phi): unit vector at angle phi clockwise from +y; e' = de/dphi.
    Vec2 e(double phi) { return Vec2(std::sin(phi), std::cos(phi)); }
    Vec2 ep(double phi) { return Vec2(std::cos(phi), -std::sin(phi)); }
    /// Polar angle measured clockwise from +y.
    double cw_angle(const Vec2 &p) { return std::atan2(p.x(), p.y()); }
    /// Generating angle at which the envelope's contact on the cutter rounding reaches the
    /// flank tangent point (flank normal n_form, cutter frame), from t_root; NaN if none.
    double fillet_end(const ShaperEnvelopeCurve &probe, const Vec2 &n_form, double t_root, double k)
    {
      const auto contact_angle = [&](double tt) {
        const Vec2 u = rot(-probe.cutter_rotation(tt)) * probe.offset_direction(tt);
        return std::atan2(cross(n_form, u), n_form.dot(u)); // angle from n_form to u
      };
      // Step away from t_root (in the direction in which the contact moves towards the flank)
      // until the contact angle changes sign, then bisect.
      const double f_root = contact_angle(t_root);
      double t_form       = std::nan("");
      const double h      = 1e-3 / (k + 1.0);
      for (const double dir : {1.0, -1.0})
        {
          if (!std::isnan(t_form) || std::abs(contact_angle(t_root + dir * h)) > std::abs(f_root))
            continue;
          double lo = t_root, flo = f_root;
          for (int i = 1; i < 4000; ++i)
            {
              double hi = t_root + dir * i * h;
              if (flo * contact_angle(hi) > 0.0)
                {
                  lo = hi, flo = contact_angle(hi);
                  continue;
                }
              for (int j = 0; j < 200 && std::abs(hi - lo) > 1e-15; ++j)
                {
                  const double mid = 0.5 * (lo + hi), fm = contact_angle(mid);
                  if (flo * fm <= 0.0)
                    hi = mid;
                  else
                    lo = mid, flo = fm;
                }
              t_form = 0.5 * (lo + hi);
              break;
            }
        }
      return t_form;
    }
  } // namespace

  // ---------------------------------------------------------------- ShaperEnvelopeCurve

  ShaperEnvelopeCurve::ShaperEnvelopeCurve(double a0, double k, const Vec2 &q, double rho, double t0,
                                           double t1)
    : a0_(a0), k_(k), rho_(rho), t0_(t0), t1_(t1), q_(q)
  {}

  Vec2 ShaperEnvelopeCurve::cutter_centre(double t) const { return rot(-t) * Vec2(0.0, a0_); }

  Vec2 ShaperEnvelopeCurve::centre(double t, int n) const
  {
    // d^n/dt^n R(c t) v = c^n R(c t + n pi/2) v.
    const double h = 0.5 * pi * n;
    return std::pow(-1.0, n) * (rot(-t + h) * Vec2(0.0, a0_)) + std::pow(k_, n) * (rot(k_ * t + h) * q_);
  }

  Vec2 ShaperEnvelopeCurve::offset_direction(double t) const
  {
    const Vec2 n = perp(centre(t, 1)).normalized();
    // The rounding arc faces away from the cutter axis: take the normal on that side.
    return n.dot(centre(t) - cutter_centre(t)) >= 0.0 ? n : Vec2(-n);
  }

  Vec2 ShaperEnvelopeCurve::point(double t) const { return centre(t) + rho_ * offset_direction(t); }

  Vec2 ShaperEnvelopeCurve::d1(double t) const
  {
    // Offset p = X + d N, N = perp(T): p' = w (1 - d kappa) T.
    const Vec2 X1 = centre(t, 1), X2 = centre(t, 2);
    const double w = X1.norm(), kappa = cross(X1, X2) / (w * w * w);
    const double d = rho_ * offset_direction(t).dot(perp(X1) / w);
    return (1.0 - d * kappa) * X1;
  }

  Vec2 ShaperEnvelopeCurve::d2(double t) const
  {
    const Vec2 X1 = centre(t, 1), X2 = centre(t, 2), X3 = centre(t, 3);
    const double w = X1.norm(), w1 = X1.dot(X2) / w;
    const double kappa  = cross(X1, X2) / (w * w * w);
    const double kappa1 = cross(X1, X3) / (w * w * w) - 3.0 * cross(X1, X2) * w1 / (w * w * w * w);
    const Vec2 T = X1 / w, N = perp(T);
    const double d = rho_ * offset_direction(t).dot(N);
    return (w1 * (1.0 - d * kappa) - w * d * kappa1) * T + w * w * (1.0 - d * kappa) * kappa * N;
  }

  // -------------------------------------------------------------- InternalInvoluteCurve

  InternalInvoluteCurve::InternalInvoluteCurve(double rb, double psi_b, double xi0, double xi1)
    : rb_(rb), psi_b_(psi_b), xi0_(xi0), xi1_(xi1)
  {}

  Vec2 InternalInvoluteCurve::point(double xi) const
  {
    const double phi = psi_b_ + xi;
    return rb_ * e(phi) - rb_ * xi * ep(phi);
  }
  Vec2 InternalInvoluteCurve::d1(double xi) const
  {
    // d/dxi [e(phi) - xi e'(phi)] = e' - e' - xi e'' = xi e(phi)  (e'' = -e).
    return rb_ * xi * e(psi_b_ + xi);
  }
  Vec2 InternalInvoluteCurve::d2(double xi) const
  {
    const double phi = psi_b_ + xi;
    return rb_ * (e(phi) + xi * ep(phi));
  }

  // --------------------------------------------------------------- InternalToothProfile

  double InternalToothProfile::angular_pitch() const { return 2.0 * pi / gear_.teeth; }

  InternalToothProfile InternalToothProfile::generate(const InternalGearParameters &g)
  {
    const std::string P = g.name + "/";
    const ShaperCutter &c = g.cutter;
    limits::check_teeth(P + "Number of teeth", g.teeth);
    limits::check_teeth(P + "Cutter teeth", c.teeth);
    limits::check_module(P + "Module", g.module);
    limits::check_pressure_angle(P + "Pressure angle", g.pressure_angle);
    if (g.teeth <= c.teeth)
      throw InputError(P + "Cutter teeth", std::to_string(c.teeth), "< " + std::to_string(g.teeth),
                       "a shaper cutter for an internal gear has fewer teeth than the gear");
    require_greater(P + "Cutter tip radius coefficient", c.tip_radius, 0.0);

    InternalToothProfile t;
    t.gear_         = g;
    const double m  = g.module, al = g.pressure_angle;
    // Generating mesh (internal, zero backlash).
    t.alpha_w0_     = internal_working_pressure_angle(al, c.teeth, g.teeth, c.shift, g.profile_shift);
    t.a0_           = 0.5 * m * (g.teeth - c.teeth) * std::cos(al) / std::cos(t.alpha_w0_);
    // Cutter: involute flank (coast side, x > 0) and the rounding centre Cc, on the flank
    // normal at roll length lambda + rho, at radius r_a0 - rho.
    const double r0 = 0.5 * m * c.teeth, rb0 = r0 * std::cos(al), rho = c.tip_radius * m;
    const double ra0 = r0 + (c.addendum + c.shift) * m;
    const double psi_b0 = (0.5 * pi + 2 * c.shift * std::tan(al)) * m / (2 * r0) + inv(al);
    if (!(ra0 - rho > rb0))
      throw InputError(P + "Cutter tip radius coefficient", to_string_g(c.tip_radius),
                       "< " + to_string_g((ra0 - rb0) / m),
                       "the rounding centre must lie outside the cutter's base circle");
    const double lambda = std::sqrt((ra0 - rho) * (ra0 - rho) - rb0 * rb0);
    const double phi_c  = psi_b0 - (lambda + rho) / rb0;
    const Vec2 Cc       = rb0 * e(phi_c) + lambda * ep(phi_c);
    const double gamma  = cw_angle(Cc);
    if (!(gamma > 0.0))
      throw InputError(P + "Cutter tip radius coefficient", to_string_g(c.tip_radius),
                       "a smaller value (the cutter tip roundings cross its tooth axis)");

    // Ring radii.
    const double r2 = 0.5 * m * g.teeth, rb2 = r2 * std::cos(al);
    const double psi_b2 = (0.5 * pi + 2 * g.profile_shift * std::tan(al)) * m / (2 * r2) - inv(al);
    const double ra2    = r2 - (g.addendum + g.profile_shift - g.tip_shortening) * m;
    const double rf2    = t.a0_ + ra0;
    const double T0T2   = t.a0_ * std::sin(t.alpha_w0_);
    const double rF2    = std::hypot(rb2, lambda + rho + T0T2);
    if (!(ra2 > rb2))
      throw InputError(P + "Addendum coefficient", to_string_g(g.addendum),
                       "< " + to_string_g(r2 / m - g.profile_shift + g.tip_shortening - rb2 / m),
                       "the tip (inner) circle " + mm_text(2 * ra2) + " lies inside the base circle " + mm_text(2 * rb2));
    if (!(std::sqrt(ra2 * ra2 - rb2 * rb2) > T0T2))
      throw InputError(P + "Cutter teeth", std::to_string(c.teeth), "fewer teeth (or a smaller ring shift)",
                       "involute interference in generation: the ring tip circle cuts the generating "
                       "line of action inside the cutter's base tangent point T0, so the cutter would "
                       "relieve the ring tip below the involute (not modelled)");
    if (!(rF2 > ra2))
      throw InputError(P + "Cutter tip radius coefficient", to_string_g(c.tip_radius), "a smaller value",
                       "the generated fillet reaches the tip circle (form radius " + mm_text(rF2) + ")");
    t.radii_.base = rb2, t.radii_.reference = r2, t.radii_.tip = ra2, t.radii_.root = rf2;
    t.radii_.form = rF2, t.radii_.tip_form = ra2, t.radii_.relief_start = ra2;

    // Fillet: envelope of the rounding arc, from the root point (t_root, the arc's tip point
    // on the line of centres) to the arc's flank tangent point (t_form).
    const double k      = double(g.teeth) / c.teeth - 1.0;
    const double t_root = gamma / (k + 1.0);
    const ShaperEnvelopeCurve probe(t.a0_, k, Cc, rho, t_root, t_root);
    const double t_form = fillet_end(probe, ep(phi_c), t_root, k);
    if (std::isnan(t_form))
      throw SolverError(P + "fillet: the envelope of the cutter tip rounding does not reach the flank");
    t.envelope_ = std::make_shared<ShaperEnvelopeCurve>(t.a0_, k, Cc, rho, t_root, t_form);

    // Tooth frame: the generating frame has a tooth space on +y and generates its right side;
    // mirror it to the space's left side and turn by -pi/z2, which puts tooth 0 on +y.
    const double half_pitch = pi / g.teeth;
    t.map_ = rot(-half_pitch) * Eigen::Vector2d(-1.0, 1.0).asDiagonal();
    const CurvePtr fillet = std::make_shared<AffineCurve>(t.envelope_, t.map_, Vec2::Zero(), false);
    const double xiF = std::sqrt(rF2 * rF2 - rb2 * rb2) / rb2, xiA = std::sqrt(ra2 * ra2 - rb2 * rb2) / rb2;
    const CurvePtr flank = std::make_shared<InternalInvoluteCurve>(rb2, psi_b2, xiA, xiF);
    const double psi_a   = psi_b2 + inv(std::acos(rb2 / ra2));
    const double th_root = 0.5 * pi - half_pitch; // middle of the right space
    const CurvePtr root_r = std::make_shared<CircularArc>(Vec2::Zero(), rf2, th_root, th_root + t_root);
    const CurvePtr root_l =
      std::make_shared<CircularArc>(Vec2::Zero(), rf2, pi - th_root - t_root, pi - th_root);
    const CurvePtr tip = std::make_shared<CircularArc>(Vec2::Zero(), ra2, 0.5 * pi - psi_a, 0.5 * pi + psi_a);
    const CurvePtr fillet_l = mirrored(fillet), flank_l = mirrored(flank);
    using S = SegmentType;
    t.segments_ = {{S::root, Side::drive, root_r, th_root, th_root + t_root},
                   {S::fillet, Side::drive, fillet, t_root, t_form},
                   {S::flank, Side::drive, flank, xiF, xiA},
                   {S::tip, Side::none, tip, 0.5 * pi - psi_a, 0.5 * pi + psi_a},
                   {S::flank, Side::coast, flank_l, xiA, xiF},
                   {S::fillet, Side::coast, fillet_l, t_form, t_root},
                   {S::root, Side::coast, root_l, pi - th_root - t_root, pi - th_root}};
    if (!(psi_a > 0.0))
      throw InputError(P + "Profile shift coefficient", to_string_g(g.profile_shift), "a larger value",
                       "the ring tooth is pointed at its tip circle");

    // The generating mesh's own tip-fouling conditions (SDP-SI eqs. 5-6, 5-9): warnings,
    // since they concern the cutting process (overcut of the ring tips).
    InternalMeshInput gm;
    gm.pinion_name = P + "Cutter", gm.ring_name = g.name;
    gm.z1 = c.teeth, gm.z2 = g.teeth, gm.module = m, gm.pressure_angle = al;
    gm.x1 = c.shift, gm.x2 = g.profile_shift, gm.tip_radius1 = ra0, gm.tip_radius2 = ra2;
    gm.center_distance = t.a0_;
    const InternalMesh mesh = internal_mesh(gm);
    for (const InterferenceDiagnosis &d : {tip_fouling_in_rotation(mesh), tip_fouling_radial(mesh)})
      if (d.interferes)
        t.warnings_.push_back("generation with the " + std::to_string(c.teeth) + "-tooth cutter: " + d.name +
                              " (margin " + to_string_g(d.margin) + " rad)");
    return t;
  }

  double InternalToothProfile::involute_thickness_at_radius(double r) const
  {
    const double m = gear_.module, al = gear_.pressure_angle, r2 = radii_.reference;
    const double s2 = m * (0.5 * pi + 2 * gear_.profile_shift * std::tan(al));
    return 2 * r * (s2 / (2 * r2) - inv(al) + inv(std::acos(radii_.base / r)));
  }

  double InternalToothProfile::thickness_at_radius(double r) const
  {
    if (!(r >= radii_.tip * (1 - 1e-12) && r <= radii_.root * (1 + 1e-12)))
      throw InputError(gear_.name + "/thickness radius", mm_text(r),
                       "[" + mm_text(radii_.tip) + ", " + mm_text(radii_.root) + "]");
    const ProfileSegment &s = r <= radii_.form ? segments_[2] : segments_[1];
    const double rr = std::clamp(r, std::min(s.start().norm(), s.end().norm()),
                                 std::max(s.start().norm(), s.end().norm()));
    const double tt = parameter_at_radius(*s.curve, s.t0, s.t1, rr);
    return 2 * r * cw_angle(s.curve->point(tt));
  }

  std::vector<ProfilePoint> InternalToothProfile::sample(double max_spacing) const
  {
    std::vector<ProfilePoint> pts;
    for (std::size_t i = 0; i < segments_.size(); ++i)
      {
        const ProfileSegment &s = segments_[i];
        const double len = s.curve->arc_length(std::min(s.t0, s.t1), std::max(s.t0, s.t1));
        const int n = std::max(1, int(std::ceil(len / max_spacing)));
        const double sign = s.t1 >= s.t0 ? 1.0 : -1.0;
        for (int j = (i == 0 ? 0 : 1); j <= n; ++j)
          {
            ProfilePoint p;
            p.s         = double(j) / n;
            const double tt = s.t0 + p.s * (s.t1 - s.t0);
            p.p         = s.curve->point(tt);
            p.normal    = -sign * s.curve->right_normal(tt); // left of travel: out of the material
            p.curvature = -sign * s.curve->curvature(tt);
            p.tooth = 0, p.segment = int(i), p.type = s.type, p.side = s.side;
            pts.push_back(p);
          }
      }
    return pts;
  }

  std::vector<ProfilePoint> InternalToothProfile::sample_gear(double max_spacing) const
  {
    const std::vector<ProfilePoint> one = sample(max_spacing);
    std::vector<ProfilePoint> all;
    for (int k = 0; k < gear_.teeth; ++k)
      {
        const Eigen::Matrix2d R = rot(k * angular_pitch());
        for (std::size_t j = (k == 0 ? 0 : 1); j < one.size(); ++j)
          {
            ProfilePoint p = one[j];
            p.p = R * p.p, p.normal = R * p.normal, p.tooth = k;
            all.push_back(p);
          }
      }
    return all;
  }

  void InternalToothProfile::fill_mesh_input(InternalMeshInput &in) const
  {
    in.ring_name = gear_.name;
    in.z2 = gear_.teeth, in.module = gear_.module, in.pressure_angle = gear_.pressure_angle;
    in.x2 = gear_.profile_shift;
    in.tip_radius2 = radii_.tip, in.root_radius2 = radii_.root, in.form_radius2 = radii_.form;
  }
} // namespace gearfem::geometry
