#include "geometry/internal.h"
#include "geometry/limits.h"

#include "base/errors.h"
#include "base/units.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gearfem::geometry
{
  namespace
  {
    using closed_form::inv;
    using units::pi;


    LoaPoint make_point(const InternalMesh &m, const std::string &name, double g)
    {
      LoaPoint p;
      p.name       = name;
      p.g          = g;
      p.position   = m.position(g);
      p.roll_angle = (g - m.rw1 * std::sin(m.alpha_w)) / m.rb1;
      p.r1         = p.position.norm();
      p.r2         = (p.position - m.center(2)).norm();
      return p;
    }

    InterferenceDiagnosis diagnosis(const std::string &name, double margin, const std::string &unit)
    {
      InterferenceDiagnosis d;
      d.name       = name;
      d.margin     = margin;
      d.unit       = unit;
      d.interferes = !(margin > 0.0);
      return d;
    }

    /// Half tooth angles at radius r (r >= r_b): pinion s1/(2 r1) + inv a - inv a_r, ring
    /// s2/(2 r2) - inv a + inv a_r (ring teeth widen outwards).
    double half_angle_pinion(const InternalMesh &m, double r)
    {
      const double r1 = 0.5 * m.in.module * m.in.z1, a = m.in.pressure_angle;
      const double s1 = m.in.module * (0.5 * pi + 2 * m.in.x1 * std::tan(a));
      return s1 / (2 * r1) + inv(a) - inv(std::acos(m.rb1 / r));
    }
    double half_angle_ring(const InternalMesh &m, double r)
    {
      const double r2 = 0.5 * m.in.module * m.in.z2, a = m.in.pressure_angle;
      const double s2 = m.in.module * (0.5 * pi + 2 * m.in.x2 * std::tan(a));
      return s2 / (2 * r2) - inv(a) + inv(std::acos(m.rb2 / r));
    }
    /// Angle wrapped to (-period/2, period/2].
    double wrap(double t, double period) { return t - period * std::round(t / period); }
  } // namespace

  InternalMeshInput internal_mesh_input(int z1, int z2, double m, double alpha, double x1, double x2,
                                        double ha, double hf, double k)
  {
    InternalMeshInput in;
    in.z1 = z1, in.z2 = z2, in.module = m, in.pressure_angle = alpha, in.x1 = x1, in.x2 = x2;
    const double r1 = 0.5 * m * z1, r2 = 0.5 * m * z2;
    in.tip_radius1  = r1 + (ha + x1 - k) * m;
    in.root_radius1 = r1 - (hf - x1) * m;
    in.tip_radius2  = r2 - (ha + x2 - k) * m;
    in.root_radius2 = r2 + (hf - x2) * m;
    return in;
  }

  double internal_working_pressure_angle(double alpha, int z1, int z2, double x1, double x2)
  {
    const double v = inv(alpha) - 2 * std::tan(alpha) * (x1 + x2) / (z2 - z1);
    if (!(v > 0.0))
      throw InputError("Ring/Profile shift coefficient", to_string_g(x2),
                       "< " + to_string_g((z2 - z1) * inv(alpha) / (2 * std::tan(alpha)) - x1),
                       "inv a_w = inv a - 2 tan a (x1 + x2)/(z2 - z1) must be positive");
    return closed_form::inv_inverse(v);
  }

  double internal_center_distance_from_shifts(double m, double alpha, int z1, int z2, double x1,
                                              double x2)
  {
    const double aw = internal_working_pressure_angle(alpha, z1, z2, x1, x2);
    return 0.5 * m * (z2 - z1) * std::cos(alpha) / std::cos(aw);
  }

  const LoaPoint &InternalMesh::point(const std::string &name) const
  {
    for (const LoaPoint &p : loa)
      if (p.name == name)
        return p;
    throw std::out_of_range("InternalMesh::point: no point named " + name);
  }

  Vec2 InternalMesh::position(double g) const
  {
    const double s = std::sin(alpha_w), c = std::cos(alpha_w);
    return rb1 * Vec2(s, c) + g * Vec2(-c, s);
  }

  InternalMesh internal_mesh(const InternalMeshInput &in)
  {
    const std::string P = in.pinion_name + "/", R = in.ring_name + "/";
    limits::check_teeth(P + "Number of teeth", in.z1);
    if (in.z2 <= in.z1)
      throw InputError(R + "Number of teeth", std::to_string(in.z2), "> " + std::to_string(in.z1),
                       "an internal gear has more teeth than its pinion");
    require_greater("Rack/Module", in.module, 0.0, "m");
    limits::check_pressure_angle("Rack/Pressure angle", in.pressure_angle);

    InternalMesh m;
    m.in             = in;
    const double al  = in.pressure_angle, mod = in.module;
    m.rb1            = 0.5 * mod * in.z1 * std::cos(al);
    m.rb2            = 0.5 * mod * in.z2 * std::cos(al);
    m.pb             = pi * mod * std::cos(al);
    m.a              = in.center_distance > 0.0 ?
                         in.center_distance :
                         internal_center_distance_from_shifts(mod, al, in.z1, in.z2, in.x1, in.x2);
    const double c   = (m.rb2 - m.rb1) / m.a;
    if (!(c < 1.0))
      throw InputError("Pair/Centre distance", mm_text(m.a), "> r_b2 - r_b1 = " + mm_text(m.rb2 - m.rb1),
                       "no line of action below the difference of the base radii");
    m.alpha_w = std::acos(c);
    m.rw1     = m.rb1 / c;
    m.rw2     = m.rb2 / c;
    m.T1T2    = m.a * std::sin(m.alpha_w);
    if (!(in.tip_radius1 > m.rb1))
      throw InputError(P + "Tip diameter", mm_text(2 * in.tip_radius1), "> base diameter " + mm_text(2 * m.rb1));
    if (!(in.tip_radius2 > m.rb2))
      throw InputError(R + "Tip diameter", mm_text(2 * in.tip_radius2), "> base diameter " + mm_text(2 * m.rb2),
                       "the ring's teeth are involutes only outside its base circle");

    // Path of contact: starts where the ring tip circle cuts the line of action (nearer
    // root of |O2 P| = r_a2 on the C side of T2), ends where the pinion tip circle does.
    const double gA = std::sqrt(in.tip_radius2 * in.tip_radius2 - m.rb2 * m.rb2) - m.T1T2;
    const double gE = std::sqrt(in.tip_radius1 * in.tip_radius1 - m.rb1 * m.rb1);
    const double gC = m.rw1 * std::sin(m.alpha_w);
    m.contact_ratio = (gE - gA) / m.pb;
    m.loa           = {make_point(m, "T2", -m.T1T2), make_point(m, "T1", 0.0), make_point(m, "A", gA),
                       make_point(m, "B", gE - m.pb), make_point(m, "C", gC),  make_point(m, "D", gA + m.pb),
                       make_point(m, "E", gE)};
    std::stable_sort(m.loa.begin(), m.loa.end(), [](const LoaPoint &p, const LoaPoint &q) { return p.g < q.g; });

    const double r1 = 0.5 * mod * in.z1, r2 = 0.5 * mod * in.z2;
    const double s1 = mod * (0.5 * pi + 2 * in.x1 * std::tan(al));
    const double s2 = mod * (0.5 * pi + 2 * in.x2 * std::tan(al));
    const double sw1 = 2 * m.rw1 * (s1 / (2 * r1) + inv(al) - inv(m.alpha_w));
    const double sw2 = 2 * m.rw2 * (s2 / (2 * r2) - inv(al) + inv(m.alpha_w));
    m.backlash_t     = 2 * pi * m.rw1 / in.z1 - sw1 - sw2;
    m.backlash_n     = m.backlash_t * std::cos(m.alpha_w);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    m.clearance1     = in.root_radius2 > 0.0 ? in.root_radius2 - m.a - in.tip_radius1 : nan;
    m.clearance2     = in.root_radius1 > 0.0 ? in.tip_radius2 - m.a - in.root_radius1 : nan;
    return m;
  }

  std::string InterferenceDiagnosis::message() const
  {
    return InputError(parameter, value, allowed, name + (detail.empty() ? "" : ": " + detail)).what();
  }

  void InterferenceDiagnosis::raise() const
  {
    if (interferes)
      throw InputError(parameter, value, allowed, name + (detail.empty() ? "" : ": " + detail));
  }

  InterferenceDiagnosis involute_interference(const InternalMesh &m)
  {
    InterferenceDiagnosis d = diagnosis("involute interference", m.point("A").g, "m");
    const double limit      = std::hypot(m.rb2, m.T1T2); // |O2 T1|
    d.parameter             = m.in.ring_name + "/Tip diameter";
    d.value                 = mm_text(2 * m.in.tip_radius2);
    d.allowed               = "> " + mm_text(2 * limit);
    d.detail = "the ring tip circle cuts the line of action " + mm_text(-d.margin) +
               " inside T1 (the ring tip would meet the pinion below its base circle)";
    if (!d.interferes)
      d.detail = "start of contact A lies " + mm_text(d.margin) + " beyond T1";
    return d;
  }

  InterferenceDiagnosis ring_tip_pinion_fillet_interference(const InternalMesh &m)
  {
    const double rF   = std::max(m.in.form_radius1, m.rb1);
    const double gF   = std::sqrt(rF * rF - m.rb1 * m.rb1);
    InterferenceDiagnosis d = diagnosis("ring tip against the pinion fillet", m.point("A").g - gF, "m");
    d.parameter       = m.in.ring_name + "/Tip diameter";
    d.value           = mm_text(2 * m.in.tip_radius2);
    d.allowed         = ">= " + mm_text(2 * std::hypot(m.rb2, gF + m.T1T2));
    d.detail          = "start of contact at pinion radius " + mm_text(m.point("A").r1) +
                        ", pinion form radius r_Ff1 = " + mm_text(rF);
    return d;
  }

  InterferenceDiagnosis pinion_tip_ring_fillet_interference(const InternalMesh &m)
  {
    const double rhoE = m.rho2(m.point("E").g);
    const double free = std::numeric_limits<double>::infinity();
    const double rhoF = m.in.form_radius2 > 0.0 ?
                          std::sqrt(std::max(0.0, m.in.form_radius2 * m.in.form_radius2 - m.rb2 * m.rb2)) :
                          free;
    InterferenceDiagnosis d = diagnosis("pinion tip against the ring fillet", rhoF - rhoE, "m");
    d.parameter       = m.in.pinion_name + "/Tip diameter";
    d.value           = mm_text(2 * m.in.tip_radius1);
    d.allowed         = m.in.form_radius2 > 0.0 ? "<= " + mm_text(2 * std::hypot(m.rb1, rhoF - m.T1T2)) : "any";
    d.detail          = "end of contact at ring radius " + mm_text(m.point("E").r2) +
                        (m.in.form_radius2 > 0.0 ? ", ring form radius r_Ff2 = " + mm_text(m.in.form_radius2) : "");
    return d;
  }

  InterferenceDiagnosis root_clearance(const InternalMesh &m)
  {
    double c = std::numeric_limits<double>::infinity();
    if (std::isfinite(m.clearance1))
      c = m.clearance1;
    if (std::isfinite(m.clearance2))
      c = std::min(c, m.clearance2);
    InterferenceDiagnosis d = diagnosis("tip clearance", c, "m");
    d.parameter = "Pair/Centre distance";
    d.value     = mm_text(m.a);
    d.allowed   = "a value that leaves both tip clearances positive";
    d.detail    = "pinion tip to ring root " + mm_text(m.clearance1) + ", ring tip to pinion root " +
               mm_text(m.clearance2);
    return d;
  }

  InterferenceDiagnosis tip_fouling_in_rotation(const InternalMesh &m)
  {
    const double a = m.a, ra1 = m.in.tip_radius1, ra2 = m.in.tip_radius2;
    const double aa1 = std::acos(m.rb1 / ra1), aa2 = std::acos(m.rb2 / ra2);
    // The tip circles cross when the path of contact exists (r_a2 - r_a1 < a); the clamp
    // only guards against rounding at tangency.
    const auto acos_c = [](double v) { return std::acos(std::clamp(v, -1.0, 1.0)); };
    const double th1 = acos_c((ra2 * ra2 - ra1 * ra1 - a * a) / (2 * a * ra1)) + inv(aa1) - inv(m.alpha_w);
    const double th2 = acos_c((a * a + ra2 * ra2 - ra1 * ra1) / (2 * a * ra2));
    const double margin = th1 * m.in.z1 / m.in.z2 + inv(m.alpha_w) - inv(aa2) - th2;
    InterferenceDiagnosis d = diagnosis("tip fouling in rotation (trochoid interference)", margin, "rad");
    d.parameter = m.in.ring_name + "/Number of teeth";
    d.value     = std::to_string(m.in.z2);
    d.allowed   = "a tooth-count difference z2 - z1 that satisfies SDP-SI eq. 5-6";
    d.detail    = "theta1 z1/z2 + inv a_w - inv a_a2 - theta2 = " + to_string_g(margin) +
               " rad (the pinion tip leaving mesh enters a ring tooth)";
    return d;
  }

  InterferenceDiagnosis tip_fouling_radial(const InternalMesh &m)
  {
    const double ra1 = m.in.tip_radius1, ra2 = m.in.tip_radius2;
    const double aa1 = std::acos(m.rb1 / ra1), aa2 = std::acos(m.rb2 / ra2);
    const double c12 = std::cos(aa1) / std::cos(aa2), u = double(m.in.z2) / m.in.z1;
    const auto asin_sqrt = [](double v) { return std::asin(std::sqrt(std::clamp(v, 0.0, 1.0))); };
    const double th1 = asin_sqrt((1 - c12 * c12) / (1 - 1 / (u * u)));
    const double th2 = asin_sqrt((1 / (c12 * c12) - 1) / (u * u - 1));
    const double margin = th1 + inv(aa1) - inv(m.alpha_w) - u * (th2 + inv(aa2) - inv(m.alpha_w));
    InterferenceDiagnosis d = diagnosis("tip fouling on radial withdrawal (trimming interference)", margin, "rad");
    d.parameter = m.in.ring_name + "/Number of teeth";
    d.value     = std::to_string(m.in.z2);
    d.allowed   = "a tooth-count difference z2 - z1 that satisfies SDP-SI eq. 5-9";
    d.detail    = "margin " + to_string_g(margin) +
               " rad: the pinion cannot be withdrawn radially (assemble it axially)";
    return d;
  }

  std::vector<InterferenceDiagnosis> interference_checks(const InternalMesh &m)
  {
    return {involute_interference(m),   ring_tip_pinion_fillet_interference(m),
            pinion_tip_ring_fillet_interference(m), root_clearance(m),
            tip_fouling_in_rotation(m), tip_fouling_radial(m)};
  }

  double tip_corner_penetration(const InternalMesh &m, int samples, double pitches)
  {
    const int z1 = m.in.z1, z2 = m.in.z2;
    const double ra1 = m.in.tip_radius1, ra2 = m.in.tip_radius2;
    const double rmax2 = m.in.root_radius2 > 0.0 ? m.in.root_radius2 : std::numeric_limits<double>::infinity();
    const double p1 = 2 * pi / z1, p2 = 2 * pi / z2;
    const Vec2 O2   = m.center(2);
    // Body angles (counter-clockwise, tooth 0 axis at pi/2 + angle) with the drive flanks
    // (pinion: counter-clockwise side; ring: clockwise side) touching at C at phi1 = 0.
    const double b10 = -half_angle_pinion(m, m.rw1), b20 = half_angle_ring(m, m.rw2);
    const int nk     = int(std::ceil(pitches)) + 2;
    double worst     = -std::numeric_limits<double>::infinity();
    for (int i = 0; i <= samples; ++i)
      {
        const double phi = pitches * p1 * (2.0 * i / samples - 1.0);
        const double b1 = b10 + phi, b2 = b20 + phi * z1 / z2;
        for (int k = -nk; k <= nk; ++k)
          for (const double side : {-1.0, 1.0})
            {
              // Pinion tip corner against the ring teeth.
              const double t1 = 0.5 * pi + b1 + k * p1 + side * half_angle_pinion(m, ra1);
              const Vec2 q    = ra1 * Vec2(std::cos(t1), std::sin(t1)) - O2;
              const double r  = q.norm();
              if (r > ra2 && r < rmax2)
                {
                  const double off = wrap(std::atan2(q.y(), q.x()) - 0.5 * pi - b2, p2);
                  worst            = std::max(worst, r * (half_angle_ring(m, r) - std::abs(off)));
                }
              // Ring tip corner against the pinion teeth.
              const double t2 = 0.5 * pi + b2 + k * p2 + side * half_angle_ring(m, ra2);
              const Vec2 w    = O2 + ra2 * Vec2(std::cos(t2), std::sin(t2));
              const double s  = w.norm();
              if (s > m.rb1 && s < ra1)
                {
                  const double off = wrap(std::atan2(w.y(), w.x()) - 0.5 * pi - b1, p1);
                  worst            = std::max(worst, s * (half_angle_pinion(m, s) - std::abs(off)));
                }
            }
      }
    return worst;
  }
} // namespace gearfem::geometry
