#include "analytical/tooth.h"

#include "base/errors.h"

#include <cmath>

namespace gearfem::analytical
{
  ToothLoad involute_load(const InvoluteTooth &t, double r)
  {
    if (!(r >= t.rb && r <= t.r_tip * (1 + 1e-9)))
      throw InputError("contact radius", to_string_g(r) + " m",
                       "[" + to_string_g(t.rb) + ", " + to_string_g(t.r_tip) + "] m (base to tip)");
    const double a = std::acos(std::min(1.0, t.rb / r));
    const double gamma = t.psi_b - (std::tan(a) - a);
    ToothLoad l;
    l.phi = std::tan(a) - t.psi_b;
    l.y_contact = r * std::cos(gamma) - t.beam.root_radius;
    l.h = r * std::sin(gamma);
    l.rho = t.rb * std::tan(a);
    return l;
  }

  StiffnessModel stiffness_model_from_string(const std::string &s)
  {
    if (s == "weber cornell")
      return StiffnessModel::weber_cornell;
    if (s == "potential energy")
      return StiffnessModel::potential_energy;
    throw InputError("Analytical/Stiffness model", s, "weber cornell|potential energy");
  }

  const char *to_string(StiffnessModel m)
  {
    return m == StiffnessModel::weber_cornell ? "weber cornell" : "potential energy";
  }

  PairCompliance::PairCompliance(InvoluteTooth pinion, InvoluteTooth gear, const Material &m1,
                                 const Material &m2, double b, const PairLine &line,
                                 const PairModelOptions &opt)
    : t_{std::move(pinion), std::move(gear)}
    , e1_(plane_elastic(m1, opt.plane))
    , e2_(plane_elastic(m2, opt.plane))
    , b_(b)
    , line_(line)
    , opt_(opt)
  {
    require_greater("face width", b, 0.0, "m");
    require_greater("Analytical/Table points", opt.table_points, 3);
    if (!(line.g_E > line.g_A && line.g_A >= 0.0 && line.g_E <= line.length))
      throw InputError("pair line of action: need 0 <= g_A < g_E <= T1T2 (g_A = " +
                       to_string_g(line.g_A) + ", g_E = " + to_string_g(line.g_E) +
                       ", T1T2 = " + to_string_g(line.length) + " m)");
    const int n = opt.table_points;
    grid_.resize(n);
    for (auto &v : table_)
      v.resize(n);
    for (int i = 0; i < n; ++i)
      {
        grid_[i] = line.g_A + (line.g_E - line.g_A) * i / (n - 1);
        const Parts p = parts_exact(grid_[i], 1.0);
        table_[0][i] = p.beam1;
        table_[1][i] = p.foundation1;
        table_[2][i] = p.beam2;
        table_[3][i] = p.foundation2;
        table_[4][i] = weber_depth(0, grid_[i]);
        table_[5][i] = weber_depth(1, grid_[i]);
      }
  }

  double PairCompliance::interpolate(int k, double g) const
  {
    const int n = static_cast<int>(grid_.size());
    const double h = grid_[1] - grid_[0];
    double s = (g - grid_[0]) / h;
    s = std::max(0.0, std::min(s, n - 1.0));
    const int i = std::min(n - 2, static_cast<int>(s));
    const double u = s - i;
    const std::vector<double> &v = table_[k];
    // Catmull-Rom with one-sided ends.
    const double p0 = i > 0 ? v[i - 1] : 2 * v[i] - v[i + 1];
    const double p3 = i + 2 < n ? v[i + 2] : 2 * v[i + 1] - v[i];
    const double p1 = v[i], p2 = v[i + 1];
    return 0.5 * ((2 * p1) + (-p0 + p2) * u + (2 * p0 - 5 * p1 + 4 * p2 - p3) * u * u +
                  (-p0 + 3 * p1 - 3 * p2 + p3) * u * u * u);
  }

  double PairCompliance::weber_depth(int i, double g) const
  {
    const double r = i == 0 ? std::hypot(line_.rb1, g) : std::hypot(line_.rb2, line_.length - g);
    return involute_load(t_[i], std::min(r, t_[i].r_tip)).depth_to_axis();
  }

  PairCompliance::Parts PairCompliance::parts_exact(double g, double F) const
  {
    const double r1 = std::hypot(line_.rb1, g), r2 = std::hypot(line_.rb2, line_.length - g);
    const ToothLoad l1 = involute_load(t_[0], r1), l2 = involute_load(t_[1], r2);
    Parts p;
    p.beam1 = beam_compliance(t_[0].beam, l1, b_, e1_);
    p.beam2 = beam_compliance(t_[1].beam, l2, b_, e2_);
    if (opt_.model == StiffnessModel::weber_cornell)
      {
        p.foundation1 = odonnell_foundation_compliance(t_[0].beam, l1, b_, e1_, opt_.odonnell);
        p.foundation2 = odonnell_foundation_compliance(t_[1].beam, l2, b_, e2_, opt_.odonnell);
      }
    else
      {
        p.foundation1 = sainsot_foundation_compliance(t_[0].beam, l1, b_, e1_);
        p.foundation2 = sainsot_foundation_compliance(t_[1].beam, l2, b_, e2_);
      }
    p.hertz = hertz(g, F, weber_depth(0, g), weber_depth(1, g));
    return p;
  }

  PairCompliance::Parts PairCompliance::parts(double g, double F) const
  {
    Parts p{};
    if (!grid_.empty())
      {
        p.beam1 = interpolate(0, g);
        p.foundation1 = interpolate(1, g);
        p.beam2 = interpolate(2, g);
        p.foundation2 = interpolate(3, g);
      }
    if (!grid_.empty() && opt_.model == StiffnessModel::weber_cornell)
      p.hertz = hertz(g, F, interpolate(4, g), interpolate(5, g));
    else
      p.hertz = hertz(g, F, 0.0, 0.0);
    return p;
  }

  double PairCompliance::hertz(double g, double F, double h1, double h2) const
  {
    return hertz_radii(F, g, line_.length - g, h1, h2);
  }

  double PairCompliance::hertz_radii(double F, double rho1, double rho2, double h1, double h2) const
  {
    if (opt_.model == StiffnessModel::potential_energy)
      return 1.0 / hertz_stiffness_pe(e1_, e2_, b_);
    require_greater("tooth pair load", F, 0.0, "N");
    const HertzLineContact h = hertz_line_contact(F / b_, rho1, rho2, e1_, e2_);
    return (weber_hertz_approach(F, b_, h.half_width, h1, e1_) +
            weber_hertz_approach(F, b_, h.half_width, h2, e2_)) / F;
  }

  double PairCompliance::hertz_half_width(double g, double F) const
  {
    require_greater("tooth pair load", F, 0.0, "N");
    return hertz_line_contact(F / b_, g, line_.length - g, e1_, e2_).half_width;
  }

  PairCompliance::Parts PairCompliance::parts(double g, double F, double rho1, double rho2) const
  {
    Parts p = parts(g, F);
    if (opt_.model == StiffnessModel::weber_cornell)
      {
        const bool table = !grid_.empty();
        p.hertz = hertz_radii(F, rho1, rho2, table ? interpolate(4, g) : 0.0, table ? interpolate(5, g) : 0.0);
      }
    return p;
  }

  CornerGeometry corner_geometry(const PairLine &l)
  {
    CornerGeometry c;
    c.rb1 = l.rb1, c.rb2 = l.rb2, c.length = l.length, c.g_A = l.g_A, c.g_E = l.g_E;
    c.r_form1 = l.r_form1, c.r_form2 = l.r_form2;
    c.r_tip1 = l.r_tip1, c.r_tip2 = l.r_tip2;
    c.rounding1 = l.rounding1, c.rounding2 = l.rounding2;
    return c;
  }

  MeshModel PairCompliance::mesh_model(bool with_corners) const
  {
    MeshModel m;
    m.g_A = line_.g_A;
    m.g_C = line_.g_C;
    m.g_E = line_.g_E;
    m.base_pitch = line_.base_pitch;
    m.rb1 = line_.rb1;
    const PairCompliance self = *this;
    m.pair_compliance = [self](double g, double F) { return self(g, F); };
    if (with_corners)
      {
        const CornerGeometry geo = corner_geometry(line_);
        m.corner = [geo](double g) { return corner_contact(geo, g, GapFrame::pinion); };
      }
    return m;
  }
} // namespace gearfem::analytical
