// Koronaios 2021 designs: parametrisation, start points, evaluation with named constraints.
#include "optimise/design.h"
#include "geometry/curve.h"
#include "base/units.h"

#include "base/errors.h"
#include "geometry/conjugate.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace gearfem::optimise
{
  using geometry::rotate;

  using geometry::BSplineCurve;
  using geometry::ConjugateCurve;
  using geometry::CurvePtr;

  namespace
  {

    /// The thesis' sinusoidal rack y = m sin(2x/m) in rack coordinates, half a period from
    /// the crest (u = 0, gear tip) to the trough (u = p/2): v = m cos(2u/m), t = u.
    class SinusoidRack : public geometry::Curve
    {
    public:
      explicit SinusoidRack(double m)
        : m_(m)
      {}
      double t_begin() const override { return 0.0; }
      double t_end() const override { return 0.5 * units::pi * m_; }
      Vec2 point(double t) const override { return Vec2(t, m_ * std::cos(2 * t / m_)); }
      Vec2 d1(double t) const override { return Vec2(1.0, -2 * std::sin(2 * t / m_)); }
      Vec2 d2(double t) const override { return Vec2(0.0, -4 / m_ * std::cos(2 * t / m_)); }
      Vec2 d3(double t) const override { return Vec2(0.0, 8 / (m_ * m_) * std::sin(2 * t / m_)); }

    private:
      double m_;
    };

    double bernstein4(int i, double t)
    {
      static const double c[5] = {1, 4, 6, 4, 1};
      return c[i] * std::pow(t, i) * std::pow(1 - t, 4 - i);
    }

    /// Case 2's involute data: base radius, half base thickness angle, roll angles.
    struct Involute
    {
      double rb, psi_b;
      Vec2 at_radius(double r) const
      {
        return geometry::closed_form::involute(rb, psi_b, std::sqrt(r * r - rb * rb) / rb);
      }
    };
    Involute involute_of(const PairData &p)
    {
      const double a = p.pressure_angle, r = p.r01();
      return {r * std::cos(a), units::pi * p.module / 2 / (2 * r) + std::tan(a) - a};
    }

    /// Start of active profile on the involute (gear-2 tip circle on the line of action) [m].
    double involute_sap(const PairData &p)
    {
      const double a = p.pressure_angle, rb1 = p.r01() * std::cos(a), rb2 = p.r02() * std::cos(a);
      const double T1T2 = (p.r01() + p.r02()) * std::sin(a), ra2 = p.tip_radius(2);
      const double g = T1T2 - std::sqrt(ra2 * ra2 - rb2 * rb2);
      return std::sqrt(g * g + rb1 * rb1);
    }
  } // namespace

  const char *to_string(DesignKind k)
  {
    switch (k)
      {
        case DesignKind::involute: return "involute";
        case DesignKind::sinusoid: return "sinusoid";
        case DesignKind::case1_rack: return "case 1";
        case DesignKind::case2_flank: return "case 2";
      }
    return "";
  }

  const char *constraint_name(int c)
  {
    static const char *names[] = {"flank strictly decreasing in position 2",
                                  "flanks of a tooth do not overlap (x >= 0 in position 1)",
                                  "contact ratio >= minimum",
                                  "relative curvature 1/R > 0 (no interference)",
                                  "tip-to-fillet interference: the path of contact meets the tip circle of gear 2 on the designed flank",
                                  "recovered rack above the cutter tip line (dedendum)",
                                  "recovered rack u strictly monotone"};
    return names[c];
  }

  Design::Design(DesignKind kind, const PairData &pair, FixedEnd fixed_end)
    : kind_(kind)
    , pair_(pair)
    , fixed_end_(fixed_end)
  {
    const Involute inv = involute_of(pair);
    // 0.001 m beyond the tip circle, so that the flank written to optimum.prm (12 digits)
    // still reaches the tip circle when gearfem generates it; sampling stops at r_a1.
    tip_point_ = inv.at_radius(pair.tip_radius(1) + 1e-3 * pair.module) / pair.module;
    if (kind_ == DesignKind::case2_flank)
      root_point_ = involute_fit().front();
  }

  int Design::n_free() const
  {
    return kind_ == DesignKind::case1_rack ? 4 : kind_ == DesignKind::case2_flank ? 8 : 0;
  }

  std::vector<std::string> Design::free_names() const
  {
    if (kind_ == DesignKind::case1_rack)
      return {"u1", "u2", "v2", "u3"};
    if (kind_ == DesignKind::case2_flank && fixed_end_ == FixedEnd::root)
      return {"x1", "y1", "x2", "y2", "x3", "y3", "x4", "y4"};
    if (kind_ == DesignKind::case2_flank)
      return {"x0", "y0", "x1", "y1", "x2", "y2", "x3", "y3"};
    return {};
  }

  std::vector<double> Design::default_start() const
  {
    if (kind_ == DesignKind::case1_rack)
      return {units::pi / 8, units::pi / 4, 0.0, 3 * units::pi / 8};
    if (kind_ != DesignKind::case2_flank)
      return {};
    std::vector<Vec2> P = involute_fit();
    if (fixed_end_ == FixedEnd::tip)
      P.pop_back();
    else
      P.erase(P.begin());
    std::vector<double> x;
    for (const Vec2 &q : P)
      x.push_back(q.x()), x.push_back(q.y());
    return x;
  }

  std::vector<Vec2> Design::involute_fit() const
  {
    // Least-squares fit of P0..P3 (P4 fixed at the tip point) to the involute, parameters
    // uniform in roll angle.
    const Involute inv = involute_of(pair_);
    const double   m = pair_.module, r0 = inv.rb + 0.5 * (involute_sap(pair_) - inv.rb);
    const double   x0 = std::sqrt(r0 * r0 - inv.rb * inv.rb) / inv.rb;
    const double   ra = pair_.tip_radius(1), x1 = std::sqrt(ra * ra - inv.rb * inv.rb) / inv.rb;
    const int      J = 200;
    Eigen::MatrixXd A(J + 1, 4), B(J + 1, 2);
    for (int j = 0; j <= J; ++j)
      {
        const double t = double(j) / J;
        const Vec2   X = geometry::closed_form::involute(inv.rb, inv.psi_b, x0 + (x1 - x0) * t) / m;
        for (int i = 0; i < 4; ++i)
          A(j, i) = bernstein4(i, t);
        const Vec2 rhs = X - bernstein4(4, t) * tip_point_;
        B(j, 0) = rhs.x(), B(j, 1) = rhs.y();
      }
    const Eigen::MatrixXd P = A.colPivHouseholderQr().solve(B);
    std::vector<Vec2>     cp;
    for (int i = 0; i < 4; ++i)
      cp.emplace_back(P(i, 0), P(i, 1));
    cp.push_back(tip_point_);
    return cp;
  }

  std::vector<Vec2> Design::control_points(const std::vector<double> &x) const
  {
    if (static_cast<int>(x.size()) != n_free())
      throw InputError("Optimise/Start point", std::to_string(x.size()) + " coordinates",
                       std::to_string(n_free()) + " for " + to_string(kind_));
    if (kind_ == DesignKind::case1_rack)
      return {Vec2(0, 1), Vec2(x[0], 1), Vec2(x[1], x[2]), Vec2(x[3], -1), Vec2(units::pi / 2, -1)};
    if (kind_ == DesignKind::case2_flank && fixed_end_ == FixedEnd::root)
      return {root_point_, Vec2(x[0], x[1]), Vec2(x[2], x[3]), Vec2(x[4], x[5]), Vec2(x[6], x[7])};
    if (kind_ == DesignKind::case2_flank)
      return {Vec2(x[0], x[1]), Vec2(x[2], x[3]), Vec2(x[4], x[5]), Vec2(x[6], x[7]), tip_point_};
    return {};
  }

  CurvePtr Design::rack(const std::vector<double> &x) const
  {
    const double m = pair_.module;
    switch (kind_)
      {
        case DesignKind::involute:
          {
            const double ta = std::tan(pair_.pressure_angle), h = pair_.addendum * m;
            auto u = [&](double v) { return units::pi * m / 4 - v * ta; };
            return std::make_shared<geometry::LineSegment>(Vec2(u(h), h), Vec2(u(-h), -h));
          }
        case DesignKind::sinusoid: return std::make_shared<SinusoidRack>(m);
        case DesignKind::case1_rack:
          {
            std::vector<Vec2> cp;
            for (const Vec2 &q : control_points(x))
              cp.push_back(q * m);
            return std::make_shared<BSplineCurve>(cp, 4);
          }
        case DesignKind::case2_flank: return nullptr;
      }
    return nullptr;
  }

  CurvePtr Design::flank(const std::vector<double> &x) const
  {
    if (kind_ != DesignKind::case2_flank)
      return std::make_shared<ConjugateCurve>(rack(x), pair_.r01());
    std::vector<Vec2> cp;
    for (const Vec2 &q : control_points(x))
      cp.push_back(q * pair_.module);
    return std::make_shared<BSplineCurve>(cp, 4);
  }

  geometry::GearParameters Design::gear_parameters(int i, const std::vector<double> &x) const
  {
    geometry::GearParameters g;
    g.name                = "Gear " + std::to_string(i);
    g.teeth               = i == 1 ? pair_.z1 : pair_.z2;
    g.face_width          = 20e-3;
    g.rack.kind           = kind_ == DesignKind::case1_rack ? geometry::RackParameters::Kind::bspline_rack :
                                                              geometry::RackParameters::Kind::bspline_flank;
    g.rack.module         = pair_.module;
    g.rack.pressure_angle = pair_.pressure_angle;
    g.rack.addendum       = pair_.addendum;
    g.rack.dedendum       = pair_.dedendum;
    g.rack.root_radius    = pair_.root_radius;
    g.rack.control_points = control_points(x);
    g.rack.spline_degree  = 4;
    return g;
  }

  double objective(DesignKind kind, const Statistics &st, double integral, double eps,
                   const std::array<double, 3> &w)
  {
    const double k = 1e-3; // 1/m -> 1/mm
    if (kind == DesignKind::case1_rack || kind == DesignKind::sinusoid)
      return k * (st.max_abs + st.mean_abs + st.std);
    return w[0] * integral + w[1] * k * st.std + w[2] / eps;
  }

  Evaluation Design::evaluate(const std::vector<double> &x, const EvaluationSettings &s) const
  {
    try
      {
        return evaluate_unchecked(x, s);
      }
    catch (const std::exception &e)
      {
        Evaluation ev;
        ev.reason = e.what();
        return ev;
      }
  }
} // namespace gearfem::optimise
