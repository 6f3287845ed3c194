// Calibrated mesh model and the Levenberg-Marquardt fit of its factors.
#include "calibration/model.h"

#include "base/errors.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>

namespace gearfem::calibration
{
  using namespace analytical; // the compliance models and the geometry bridge

  CalibratedMesh::CalibratedMesh(const PairCompliance &pairs, const CalibrationFactors &f)
    : pairs_(pairs)
    , f_(f)
    , geo_(analytical::corner_geometry(pairs.line()))
  {
    if (!(f.beam > 0) || !(f.foundation > 0) || !(f.hertz > 0) || !(f.body >= 0) || !(f.corner_radius >= 0))
      throw InputError("calibration factors", "beam/foundation/hertz > 0, body >= 0, corner radius >= 0",
                       "positive multipliers and non-negative compliances and radii");
  }

  double CalibratedMesh::ste(double phi1, double F, std::vector<double> *loads) const
  {
    require_greater("mesh load", F, 0.0, "N");
    const PairLine &L = pairs_.line();
    const double g0   = L.g_C + L.rb1 * phi1;
    // Pairs on the path and, with corner contact, up to one base pitch beyond A and E.
    const double reach = f_.corner ? L.base_pitch : 0.0;
    struct Pair
    {
      double g, gap, arm, c, F; // F: normal force along the touched flank's normal
      // Hertz on a tip corner: its radius and the mate's involute radius at the touching
      // point (rho_c = 0: involutes only), and the distance along the profile from the contact
      // to the corner (0: on the corner).
      bool pinion_corner;
      double rho_c, rho_m, e;
    };
    std::vector<Pair> pairs;
    const int jlo = int(std::floor((L.g_A - reach - g0) / L.base_pitch)) - 1;
    const int jhi = int(std::ceil((L.g_E + reach - g0) / L.base_pitch)) + 1;
    for (int j = jlo; j <= jhi; ++j)
      {
        const double g = g0 + j * L.base_pitch;
        if (g < L.g_A - reach || g >= L.g_E + reach)
          continue;
        CornerContact cc{0.0, 1.0};
        if (f_.corner)
          cc = corner_contact(geo_, g, GapFrame::pinion);
        if (!std::isfinite(cc.gap))
          continue;
        const bool end = g > L.g_C; // the pinion corner (near E) or the gear corner (near A)
        Pair p{g, cc.gap, cc.arm, 0.0, F, end, 0.0, 0.0, 0.0};
        if (f_.corner)
          {
            p.rho_c = f_.corner_radius > 0 ? f_.corner_radius : end ? geo_.rounding1 : geo_.rounding2;
            if (cc.on_corner)
              p.rho_m = cc.mate_curvature;
            else
              {
                // On the involute: mate radius of curvature and profile arc length to the corner
                // ((s_end^2 - s^2)/(2 rb) between rolls s and s_end on the corner's involute).
                const double s = end ? g : L.length - g, s_end = end ? L.g_E : L.length - L.g_A;
                const double rb = end ? L.rb1 : L.rb2;
                p.rho_m = L.length - s;
                p.e = std::max(0.0, (s_end * s_end - s * s) / (2 * rb));
              }
            if (!(p.rho_m > 0))
              p.rho_c = 0;
          }
        pairs.push_back(p);
      }
    if (pairs.empty())
      throw SolverError("calibrated mesh: no pair in contact at roll angle " + to_string_g(phi1));
    std::sort(pairs.begin(), pairs.end(), [](const Pair &a, const Pair &b) { return a.gap < b.gap; });
    // Fixed point on the pair loads (the compliances depend on them through the Hertz
    // term); a sweep that still changes a load by more than 1e-12 F after 60 passes is an
    // error, not a result.
    double delta = 0;
    bool converged = false;
    for (int it = 0; it < 60 && !converged; ++it)
      {
        for (auto &p : pairs)
          {
            const double gc = std::clamp(p.g, L.g_A, L.g_E);
            const double Fp = std::max(p.F, 1e-3 * F);
            const auto parts = pairs_.parts(gc, Fp);
            double hertz = parts.hertz;
            if (p.rho_c > 0)
              {
                // The corner's Hertz term on the corner; on the involute within a Hertz
                // half-width a of the corner the contact strip is cut by the corner: blend
                // linearly from the corner (e = 0) to the involute (e >= a), so that the
                // compliance is continuous at A and E.
                const double w = p.e > 0 ? std::clamp(1 - p.e / pairs_.hertz_half_width(gc, Fp), 0.0, 1.0) : 1.0;
                if (w > 0)
                  {
                    const double hc = p.pinion_corner ? pairs_.parts(gc, Fp, p.rho_c, p.rho_m).hertz
                                                      : pairs_.parts(gc, Fp, p.rho_m, p.rho_c).hertz;
                    hertz = (1 - w) * hertz + w * hc;
                  }
              }
            p.c = f_.beam * (parts.beam1 + parts.beam2) + f_.foundation * (parts.foundation1 + parts.foundation2) +
                  f_.hertz * hertz;
          }
        // Equal compression with initial gaps: a pair's normal approach is arm (delta - gap),
        // its normal force arm (delta - gap)/c and its share of the line-of-action load
        // arm^2 (delta - gap)/c: sum over the pairs with delta > gap = F.
        double a = 0, b = 0;
        std::size_t k = 0;
        for (; k < pairs.size(); ++k)
          {
            const double kk = pairs[k].arm * pairs[k].arm / pairs[k].c;
            a += kk, b += kk * pairs[k].gap;
            delta = (F + b) / a;
            if (k + 1 == pairs.size() || delta <= pairs[k + 1].gap)
              break;
          }
        double change = 0;
        for (std::size_t i = 0; i < pairs.size(); ++i)
          {
            const double Fi = i <= k ? pairs[i].arm * std::max(0.0, delta - pairs[i].gap) / pairs[i].c : 0.0;
            change          = std::max(change, std::abs(Fi - pairs[i].F));
            pairs[i].F      = Fi;
          }
        converged = change <= 1e-12 * F;
      }
    if (!converged)
      throw SolverError("calibrated mesh: the pair-load iteration did not converge in 60 passes at roll angle " +
                        to_string_g(phi1) + " rad, load " + to_string_g(F) + " N");
    if (loads)
      {
        loads->clear();
        for (const auto &p : pairs)
          if (p.F > 0)
            loads->push_back(p.F);
      }
    return delta + f_.body * F;
  }

  double CalibratedMesh::load_at(double phi1, double delta) const
  {
    if (!(delta > 0))
      return 0.0;
    // ste(F) = delta, ste increasing in F and close to linear: one secant-stiffness step
    // F <- F delta / ste(F), then secant iterations (safeguarded to stay positive).
    double F0 = delta * 3e8, s0 = ste(phi1, F0) - delta;
    double F1 = F0 * delta / (s0 + delta);
    for (int it = 0; it < 60; ++it)
      {
        const double s1 = ste(phi1, F1) - delta;
        if (std::abs(s1) <= 1e-13 * delta)
          return F1;
        double next = s1 != s0 ? F1 - s1 * (F1 - F0) / (s1 - s0) : F1 * delta / (s1 + delta);
        if (!(next > 0) || !std::isfinite(next))
          next = F1 * delta / (s1 + delta);
        F0 = F1, s0 = s1, F1 = next;
        if (std::abs(F1 - F0) <= 1e-13 * F1)
          return F1;
      }
    throw SolverError("calibrated mesh: load at compression " + to_string_g(delta) +
                      " m did not converge at roll angle " + to_string_g(phi1) + " rad");
  }

  double CalibratedMesh::torque(double phi1, double delta, double b, double psi) const
  {
    const double rb1 = base_radius();
    if (delta > 0)
      return rb1 * load_at(phi1, delta);
    if (delta >= -b)
      return 0.0;
    return -rb1 * load_at(psi - phi1, -delta - b);
  }

  double reverse_offset(const InvoluteTooth &pinion, const PairLine &L, double b)
  {
    if (!(L.center_distance > 0) || !(L.rb1 > 0) || !(L.rb2 > 0))
      throw InputError("reverse-flank offset: the pair line has no centre distance");
    const double rw1     = L.center_distance * L.rb1 / (L.rb1 + L.rb2);
    const double alpha_w = std::acos(L.rb1 / rw1);
    return 2 * (pinion.psi_b - (std::tan(alpha_w) - alpha_w)) - b / (2 * L.rb1);
  }

  std::vector<SteErrors> ste_errors(const PairCompliance &pairs, const CalibrationFactors &f,
                                    const std::vector<SteSample> &samples)
  {
    const CalibratedMesh m(pairs, f);
    std::map<double, SteErrors> by;
    std::map<double, int> count;
    for (const auto &s : samples)
      {
        const double e = std::abs(m.ste(s.roll_angle, s.torque / m.base_radius()) / s.ste - 1);
        auto &x        = by[s.torque];
        x.torque       = s.torque;
        x.mean_abs += e;
        x.max_abs = std::max(x.max_abs, e);
        ++count[s.torque];
      }
    std::vector<SteErrors> out;
    for (auto &[T, x] : by)
      {
        x.mean_abs /= count[T];
        out.push_back(x);
      }
    return out;
  }

  namespace
  {
    /// A fitted factor: its name and which of the five (0 beam, 1 foundation, 2 Hertz,
    /// 3 body compliance, 4 corner radius).
    struct FitParameter
    {
      std::string name;
      int which;
    };

    std::vector<FitParameter> fit_parameters(const FitMask &mask)
    {
      std::vector<FitParameter> par;
      if (mask.beam)
        par.push_back({"beam", 0});
      if (mask.foundation)
        par.push_back({"foundation", 1});
      if (mask.hertz)
        par.push_back({"hertz", 2});
      if (mask.body)
        par.push_back({"body compliance", 3});
      if (mask.corner_radius)
        par.push_back({"corner radius", 4});
      return par;
    }

    /// Parameters: log multipliers; body = x^2 1e-9 m/N; corner radius = x^2 1e-4 m.
    CalibrationFactors factors_of(const CalibrationFactors &start, const std::vector<FitParameter> &par,
                                  const Eigen::VectorXd &x)
    {
      CalibrationFactors f = start;
      for (int i = 0; i < int(par.size()); ++i)
        switch (par[i].which)
          {
            case 0: f.beam = std::exp(x[i]); break;
            case 1: f.foundation = std::exp(x[i]); break;
            case 2: f.hertz = std::exp(x[i]); break;
            case 3: f.body = x[i] * x[i] * 1e-9; break;
            default: f.corner_radius = x[i] * x[i] * 1e-4; break;
          }
      return f;
    }

    /// The parameter vector of the start factors (inverse of factors_of; the square-root
    /// parameters start at 0.3 or more, away from the flat point at 0).
    Eigen::VectorXd parameters_of(const CalibrationFactors &start, const std::vector<FitParameter> &par)
    {
      Eigen::VectorXd x(par.size());
      for (int i = 0; i < int(par.size()); ++i)
        switch (par[i].which)
          {
            case 0: x[i] = std::log(start.beam); break;
            case 1: x[i] = std::log(start.foundation); break;
            case 2: x[i] = std::log(start.hertz); break;
            case 3: x[i] = std::max(std::sqrt(start.body / 1e-9), 0.3); break;
            default: x[i] = std::max(std::sqrt(start.corner_radius / 1e-4), 0.3); break;
          }
      return x;
    }

    /// Levenberg-Marquardt from x (in/out) with residual(x) and jacobian(x, r): on return
    /// x, r, J and cost (= |r|^2) are those of the last accepted step. Returns the number
    /// of iterations as counted by the fit report (201 when the limit of 200 ends it).
    template <typename Residual, typename Jacobian>
    int levenberg_marquardt(const Residual &residual, const Jacobian &jacobian, Eigen::VectorXd &x,
                            Eigen::VectorXd &r, Eigen::MatrixXd &J, double &cost)
    {
      const int p = int(x.size());
      r           = residual(x);
      cost        = r.squaredNorm();
      double lambda = 1e-3;
      J             = jacobian(x, r);
      int iterations = 1;
      for (; iterations <= 200; ++iterations)
        {
          const Eigen::MatrixXd A = J.transpose() * J;
          const Eigen::VectorXd g = J.transpose() * r;
          Eigen::MatrixXd Ad      = A;
          for (int i = 0; i < p; ++i)
            Ad(i, i) += lambda * std::max(A(i, i), 1e-12);
          const Eigen::VectorXd dx = Ad.ldlt().solve(-g);
          const Eigen::VectorXd xn = x + dx;
          const Eigen::VectorXd rn = residual(xn);
          const double cn          = rn.squaredNorm();
          if (cn < cost)
            {
              const bool small = cost - cn <= 1e-14 * std::max(cost, 1e-30) || dx.norm() <= 1e-10 * (1 + x.norm());
              x = xn, r = rn, cost = cn;
              lambda = std::max(lambda / 3, 1e-12);
              J      = jacobian(x, r);
              if (small)
                break;
            }
          else
            {
              lambda *= 5;
              if (lambda > 1e12)
                break;
            }
        }
      return iterations;
    }

    /// Standard errors, condition number and identifiability warnings of a converged fit.
    void add_fit_statistics(const std::vector<FitParameter> &par, const Eigen::MatrixXd &J,
                            const Eigen::VectorXd &x, double cost, int n, FitResult &res)
    {
      const int p = int(par.size());
      // Standard errors and identifiability from the scaled normal matrix (pseudo-inverse, so
      // that one undetermined direction does not hide the others).
      const Eigen::MatrixXd A = J.transpose() * J;
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
      const auto sv = svd.singularValues();
      res.condition = sv[p - 1] > 0 ? sv[0] / sv[p - 1] : 1e300;
      const double s2 = n > p ? cost / (n - p) : 0.0;
      Eigen::VectorXd inv_sv(p);
      std::vector<bool> null_part(p, false);
      for (int k = 0; k < p; ++k)
        {
          const bool null_dir = !(sv[k] > 1e-10 * sv[0]);
          inv_sv[k] = null_dir ? 0.0 : 1.0 / sv[k];
          if (null_dir)
            for (int i = 0; i < p; ++i)
              if (std::abs(svd.matrixV()(i, k)) > 0.3)
                null_part[i] = true;
        }
      const Eigen::MatrixXd cov = s2 * svd.matrixV() * inv_sv.asDiagonal() * svd.matrixV().transpose();
      for (int i = 0; i < p; ++i)
        {
          res.names.push_back(par[i].name);
          const double sx = std::sqrt(std::max(cov(i, i), 0.0));
          double v = 0, se = 0;
          switch (par[i].which)
            {
              case 0: v = res.factors.beam, se = v * sx; break;
              case 1: v = res.factors.foundation, se = v * sx; break;
              case 2: v = res.factors.hertz, se = v * sx; break;
              case 3: v = res.factors.body, se = 2 * std::abs(x[i]) * 1e-9 * sx; break;
              default: v = res.factors.corner_radius, se = 2 * std::abs(x[i]) * 1e-4 * sx; break;
            }
          res.values.push_back(v);
          res.std_error.push_back(se);
          if (null_part[i] || (par[i].which <= 2 && v < 1e-3))
            res.warnings.push_back("factor '" + par[i].name + "' is not identifiable from these samples (the fit drives it to " +
                                   to_string_g(v) + " or leaves it undetermined): fix it or drop it from Fit factors");
          else if (v > 0 && se / v > 0.5)
            res.warnings.push_back("factor '" + par[i].name + "' is poorly determined (standard error " +
                                   to_string_g(100 * se / v) + " % of its value)");
        }
      for (int i = 0; i < p; ++i)
        for (int j = i + 1; j < p; ++j)
          {
            if (null_part[i] || null_part[j])
              continue;
            const double c = cov(i, j) / std::sqrt(std::max(cov(i, i) * cov(j, j), 1e-300));
            if (std::abs(c) > 0.98)
              res.warnings.push_back("factors '" + par[i].name + "' and '" + par[j].name +
                                     "' are not separately identifiable (correlation " + to_string_g(c) +
                                     "): only their combination is determined");
          }
      if (res.condition > 1e10)
        res.warnings.push_back("ill-conditioned fit (condition number " + to_string_g(res.condition) + ")");
    }
  } // namespace

  FitResult fit_factors(const PairCompliance &pairs, const std::vector<SteSample> &samples,
                        const CalibrationFactors &start, const FitMask &mask)
  {
    if (samples.empty())
      throw InputError("calibration samples", "(none)", "at least one FE STE value");
    for (const auto &s : samples)
      if (!(s.ste > 0) || !(s.torque > 0))
        throw InputError("calibration samples", "STE " + to_string_g(s.ste) + " m at " + to_string_g(s.torque) + " N m",
                         "positive STE and torque");
    const std::vector<FitParameter> par = fit_parameters(mask);
    const int p = int(par.size()), n = int(samples.size());
    if (p == 0)
      throw InputError("Calibration/Fit factors", "(none)", "at least one factor");
    if (n <= p)
      throw InputError("calibration samples", std::to_string(n), "more samples than fitted factors (" + std::to_string(p) + ")");

    // A trial step that leaves the admissible range (overflowing multiplier, no load path)
    // gets a huge residual, so that Levenberg-Marquardt rejects it and damps.
    auto residual = [&](const Eigen::VectorXd &xx) {
      Eigen::VectorXd r(n);
      try
        {
          const CalibratedMesh m(pairs, factors_of(start, par, xx));
          for (int i = 0; i < n; ++i)
            r[i] = m.ste(samples[i].roll_angle, samples[i].torque / m.base_radius()) / samples[i].ste - 1;
          if (!r.allFinite())
            r.setConstant(1e150);
        }
      catch (const std::exception &)
        {
          r.setConstant(1e150);
        }
      return r;
    };
    auto jacobian = [&](const Eigen::VectorXd &xx, const Eigen::VectorXd &r0) {
      Eigen::MatrixXd J(n, p);
      for (int j = 0; j < p; ++j)
        {
          Eigen::VectorXd y = xx;
          const double h    = 1e-6 * std::max(1.0, std::abs(xx[j]));
          y[j] += h;
          J.col(j) = (residual(y) - r0) / h;
        }
      return J;
    };

    FitResult res;
    Eigen::VectorXd x = parameters_of(start, par), r;
    Eigen::MatrixXd J;
    double cost = 0;
    res.iterations = levenberg_marquardt(residual, jacobian, x, r, J, cost);
    res.factors = factors_of(start, par, x);
    res.rms     = std::sqrt(cost / n);
    add_fit_statistics(par, J, x, cost, n, res);
    return res;
  }
} // namespace gearfem::calibration
