#include "analytical/from_geometry.h"
#include "geometry/rim.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace gearfem::analytical
{
  namespace
  {
    // Uniform table with Catmull-Rom interpolation (C1).
    struct UniformTable
    {
      double y0, h;
      std::vector<double> v;
      double operator()(double y) const
      {
        const int n = static_cast<int>(v.size());
        double s = std::max(0.0, std::min((y - y0) / h, n - 1.0));
        const int i = std::min(n - 2, static_cast<int>(s));
        const double u = s - i;
        const double p0 = i > 0 ? v[i - 1] : 2 * v[i] - v[i + 1];
        const double p3 = i + 2 < n ? v[i + 2] : 2 * v[i + 1] - v[i];
        const double p1 = v[i], p2 = v[i + 1];
        return 0.5 * ((2 * p1) + (-p0 + p2) * u + (2 * p0 - 5 * p1 + 4 * p2 - p3) * u * u +
                      (-p0 + 3 * p1 - 3 * p2 + p3) * u * u * u);
      }
    };
    double inv(double a) { return std::tan(a) - a; }
  } // namespace

  InvoluteTooth involute_tooth(const geometry::ToothProfile &p, double rim, int n)
  {
    require_greater("tooth thickness table points", n, 3);
    const geometry::KeyRadii &r = p.radii();
    InvoluteTooth t;
    t.rb = r.base;
    t.r_tip = r.tip;
    // Half tooth angle at the base circle from the generated flank at a radius between the
    // form radius and the end of the flank.
    const double lo = std::max(r.form, r.base), hi = r.tip_form > lo ? r.tip_form : r.tip;
    const double rr = std::min(std::max(r.reference, lo + 0.05 * (hi - lo)), hi - 0.05 * (hi - lo));
    t.psi_b = p.thickness_at_radius(rr) / (2.0 * rr) + inv(std::acos(r.base / rr));
    // The beam: tabulated thickness along the axis, with the slice at the tip clamped to a
    // small positive value so that 1/t stays finite.
    auto table = std::make_shared<UniformTable>();
    table->y0 = 0.0;
    table->h = (r.tip - r.root) / (n - 1);
    table->v.resize(n);
    for (int i = 0; i < n; ++i)
      table->v[i] = 2.0 * p.half_width_at_height(r.root + table->h * i);
    const double t_min = 1e-3 * table->v[0];
    for (double &v : table->v)
      v = std::max(v, t_min);
    t.beam.thickness = [table](double y) { return (*table)(y); };
    t.beam.height = r.tip - r.root;
    for (const auto &sg : p.segments()) // the fillet/flank junction is a curvature kink
      if (sg.type == geometry::SegmentType::fillet && sg.side == geometry::Side::coast)
        {
          const double y_form = sg.end().y() - r.root;
          if (y_form > 0.0 && y_form < t.beam.height)
            t.beam.breakpoints.push_back(y_form);
        }
    t.beam.root_radius = r.root;
    t.beam.rim_inner_radius = rim > 0 ? rim : geometry::rim_inner_radius(p);
    return t;
  }

  PairLine pair_line(const geometry::GearPair &pair)
  {
    PairLine l;
    l.rb1 = pair.base_radius(1);
    l.rb2 = pair.base_radius(2);
    l.length = pair.center_distance() * std::sin(pair.working_pressure_angle());
    l.g_A = pair.point("A").g;
    l.g_C = pair.point("C").g;
    l.g_E = pair.point("E").g;
    l.base_pitch = pair.base_pitch();
    l.center_distance = pair.center_distance();
    for (int i : {1, 2})
      {
        const geometry::ToothProfile &p = pair.gear(i);
        (i == 1 ? l.r_tip1 : l.r_tip2) = p.radii().tip;
        (i == 1 ? l.r_form1 : l.r_form2) = p.radii().form;
        (i == 1 ? l.rounding1 : l.rounding2) = p.parameters().rack.tip_radius * p.parameters().rack.module;
      }
    return l;
  }

  analytical::PlaneCurve fillet_curve(const geometry::ToothProfile &p)
  {
    for (const auto &sg : p.segments())
      if (sg.type == geometry::SegmentType::fillet && sg.side == geometry::Side::coast)
        {
          const geometry::CurvePtr c = sg.curve;
          analytical::PlaneCurve pc;
          pc.t0 = sg.t0;
          pc.t1 = sg.t1;
          pc.x = [c](double t, int k) {
            return k == 0 ? c->point(t).x() : k == 1 ? c->d1(t).x() : c->d2(t).x();
          };
          pc.y = [c](double t, int k) {
            return k == 0 ? c->point(t).y() : k == 1 ? c->d1(t).y() : c->d2(t).y();
          };
          return pc;
        }
    throw InputError(p.parameters().name + ": the generated profile has no fillet segment "
                     "(root radius of the rack = 0?)");
  }

  PairCompliance pair_compliance(const geometry::GearPair &pair, const Material &m1, const Material &m2,
                                 const PairModelOptions &options, double rim1, double rim2)
  {
    return PairCompliance(involute_tooth(pair.gear(1), rim1), involute_tooth(pair.gear(2), rim2), m1, m2,
                          std::min(pair.gear(1).parameters().face_width, pair.gear(2).parameters().face_width),
                          pair_line(pair), options);
  }
} // namespace gearfem::analytical
