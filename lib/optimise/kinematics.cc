// Equivalent curvature from the pinion flank by involutisation and Euler-Savary; see
// kinematics.h for the conventions and docs/optimise.md for the derivation.
#include "optimise/kinematics.h"
#include "base/units.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>

namespace gearfem::optimise
{
  using geometry::perp;
  using geometry::rotate;

  namespace
  {
    double cross(const Vec2 &a, const Vec2 &b) { return a.x() * b.y() - a.y() * b.x(); }
  } // namespace

  FlankKinematics::FlankKinematics(geometry::CurvePtr flank, double r01, double r02)
    : flank_(std::move(flank))
    , r01_(r01)
    , r02_(r02)
  {
    // Outward normal of an x > 0 flank: the one of the two normals at mid-flank that points
    // to +x; the right normal for a root-to-tip traversal, the left one for tip-to-root.
    const double tm = 0.5 * (flank_->t_begin() + flank_->t_end());
    outward_sign_   = flank_->d1(tm).y() > 0 ? 1.0 : -1.0;
  }

  ContactSample FlankKinematics::at(double t) const
  {
    const Vec2   G = flank_->point(t), G1 = flank_->d1(t), G2 = flank_->d2(t);
    const double L = G1.norm();
    const double w = G.dot(G1) / (r01_ * L);
    if (!(std::abs(w) < 1.0) || !(L > 0))
      throw SolverError("flank point at radius " + to_string_g(G.norm() * 1e3) +
                        " mm: its normal cannot pass through the pitch point (|G.G'| >= r01 |G'|)");
    const double beta = std::atan2(G1.y(), G1.x()), as = std::asin(w);
    const double ta = std::remainder(beta - as, 2.0 * units::pi);
    const double tb = std::remainder(beta - units::pi + as, 2.0 * units::pi);
    // Of the two turns that put the normal through C, the contact is the one that turns the
    // outward normal towards gear 2 (n.y > 0); the other touches with the back of the flank.
    const Vec2 n  = outward_sign_ * Vec2(G1.y(), -G1.x()) / L;
    const bool ua = rotate(n, -ta).y() > 0, ub = rotate(n, -tb).y() > 0;

    ContactSample s;
    s.t       = t;
    s.r1      = G.norm();
    s.theta   = ua != ub ? (ua ? ta : tb) : (std::abs(ta) <= std::abs(tb) ? ta : tb);
    s.K       = r01_ * s.theta;
    s.contact = rotate(G, -s.theta);
    s.rack_u  = s.contact.x() - s.K;
    s.rack_v  = s.contact.y() - r01_;
    const Vec2 C(0.0, r01_), O2(0.0, r01_ + r02_);
    s.r2 = (s.contact - O2).norm();

    const Vec2 T = rotate(G1, -s.theta) / L; // unit tangent in the fixed frame
    Vec2       e = s.contact - C;
    e            = e.norm() > 1e-12 * r01_ ? Vec2(e.normalized()) : perp(T);
    if (e.y() < 0)
      e = -e;
    const double l  = (s.contact - C).dot(e);
    const double ks = cross(G1, G2) / (L * L * L); // signed, left of the direction of travel
    s.kappa1        = -ks * perp(T).dot(e);        // centre of curvature on the -e (pinion) side
    s.normal_sine   = e.y();
    const double S  = (1.0 / r01_ + 1.0 / r02_) / e.y();
    const double D  = l * s.kappa1 - 1.0;
    s.kappa2        = -(s.kappa1 + S * D) / (1.0 + l * S * D);
    s.kappa_eq      = s.kappa1 + s.kappa2;
    return s;
  }

  Statistics statistics(const std::vector<double> &v)
  {
    // Trapezoidal weights (ends half): the mean and standard deviation over the sampling
    // variable, i.e. the limit of unweighted point statistics as the count grows, to O(1/n^2).
    Statistics st;
    if (v.empty())
      return st;
    const std::size_t n = v.size();
    auto w = [&](std::size_t i) { return n < 2 ? 1.0 : (i == 0 || i + 1 == n) ? 0.5 : 1.0; };
    double W = 0, sum = 0, sum_abs = 0;
    st.min = v.front();
    for (std::size_t i = 0; i < n; ++i)
      {
        W += w(i), sum += w(i) * v[i], sum_abs += w(i) * std::abs(v[i]);
        st.max_abs = std::max(st.max_abs, std::abs(v[i]));
        st.min     = std::min(st.min, v[i]);
      }
    const double mean = sum / W;
    double       var  = 0;
    for (std::size_t i = 0; i < n; ++i)
      var += w(i) * (v[i] - mean) * (v[i] - mean);
    st.mean_abs = sum_abs / W;
    st.std      = std::sqrt(var / W);
    return st;
  }

  std::vector<ContactSample> sample_flank(const FlankKinematics &k, double ta, double tb, int n,
                                          Sampling sampling)
  {
    auto q = [&](const ContactSample &s) { return sampling == Sampling::pinion_radius ? s.r1 : s.rack_u; };
    // A coarse grid of the parameter brackets each target value.
    const int                  M = 64;
    std::vector<double>        tg(M + 1), qg(M + 1);
    std::vector<ContactSample> out;
    for (int j = 0; j <= M; ++j)
      {
        tg[j] = ta + (tb - ta) * j / M;
        qg[j] = q(k.at(tg[j]));
      }
    const double qa = qg.front(), qb = qg.back();
    const bool   up = qb > qa;
    for (int j = 0; j < M; ++j)
      if (!(up ? qg[j + 1] > qg[j] : qg[j + 1] < qg[j]))
        throw SolverError(std::string("the sampling quantity (") +
                          (sampling == Sampling::pinion_radius ? "pinion radius" : "rack abscissa") +
                          ") is not monotone along the flank near parameter " + to_string_g(tg[j]));
    int j = 0;
    for (int i = 0; i < n; ++i)
      {
        if (i == 0 || i == n - 1)
          {
            out.push_back(k.at(i == 0 ? ta : tb));
            continue;
          }
        const double target = qa + (qb - qa) * i / (n - 1);
        while (j < M - 1 && (up ? qg[j + 1] < target : qg[j + 1] > target))
          ++j;
        const double t = k.solve(q, target, tg[j], tg[j + 1], "flank parameter of a sample");
        out.push_back(k.at(t));
      }
    return out;
  }
} // namespace gearfem::optimise
