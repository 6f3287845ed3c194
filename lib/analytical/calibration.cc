// Calibrated mesh model and the Levenberg-Marquardt fit of its factors.
#include "analytical/calibration.h"

#include "base/errors.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>

namespace gearfem::analytical
{
  CalibratedMesh::CalibratedMesh(const PairCompliance &pairs, const CalibrationFactors &f)
    : pairs_(pairs)
    , f_(f)
  {
    if (!(f.beam > 0) || !(f.foundation > 0) || !(f.hertz > 0) || !(f.body >= 0) || !(f.extended >= 0))
      throw InputError("calibration factors", "beam/foundation/hertz > 0, body >= 0, R_e >= 0",
                       "positive multipliers and non-negative compliances");
  }

  double CalibratedMesh::ste(double phi1, double F, std::vector<double> *loads) const
  {
    require_greater("mesh load", F, 0.0, "N");
    const PairLine &L = pairs_.line();
    const double g0   = L.g_C + L.rb1 * phi1;
    // Pairs on the path and, with extended contact, up to one base pitch beyond A and E.
    const double reach = f_.extended > 0 ? L.base_pitch : 0.0;
    struct Pair
    {
      double g, gap, c, F;
    };
    std::vector<Pair> pairs;
    const int jlo = int(std::floor((L.g_A - reach - g0) / L.base_pitch)) - 1;
    const int jhi = int(std::ceil((L.g_E + reach - g0) / L.base_pitch)) + 1;
    for (int j = jlo; j <= jhi; ++j)
      {
        const double g = g0 + j * L.base_pitch;
        if (g < L.g_A - reach || g >= L.g_E + reach)
          continue;
        double gap = 0;
        if (g < L.g_A || g >= L.g_E)
          {
            const double d = g < L.g_A ? L.g_A - g : g - L.g_E;
            gap            = d * d / (2 * f_.extended);
          }
        pairs.push_back({g, gap, 0.0, F});
      }
    if (pairs.empty())
      throw SolverError("calibrated mesh: no pair in contact at roll angle " + to_string_g(phi1));
    std::sort(pairs.begin(), pairs.end(), [](const Pair &a, const Pair &b) { return a.gap < b.gap; });
    double delta = 0;
    for (int it = 0; it < 60; ++it)
      {
        for (auto &p : pairs)
          {
            const double gc = std::clamp(p.g, L.g_A, L.g_E);
            const auto parts = pairs_.parts(gc, std::max(p.F, 1e-3 * F));
            p.c = f_.beam * (parts.beam1 + parts.beam2) + f_.foundation * (parts.foundation1 + parts.foundation2) +
                  f_.hertz * parts.hertz;
          }
        // Equal deflection with initial gaps: sum max(0, delta - gap_i)/c_i = F.
        double a = 0, b = 0;
        std::size_t k = 0;
        for (; k < pairs.size(); ++k)
          {
            a += 1 / pairs[k].c, b += pairs[k].gap / pairs[k].c;
            delta = (F + b) / a;
            if (k + 1 == pairs.size() || delta <= pairs[k + 1].gap)
              break;
          }
        double change = 0;
        for (std::size_t i = 0; i < pairs.size(); ++i)
          {
            const double Fi = i <= k ? std::max(0.0, delta - pairs[i].gap) / pairs[i].c : 0.0;
            change          = std::max(change, std::abs(Fi - pairs[i].F));
            pairs[i].F      = Fi;
          }
        if (change <= 1e-12 * F)
          break;
      }
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
    // Fixed point on the secant stiffness: F <- F delta / ste(F) (STE is close to linear).
    double F = delta * 3e8;
    for (int it = 0; it < 100; ++it)
      {
        const double s    = ste(phi1, F);
        const double next = F * delta / s;
        if (std::abs(next - F) <= 1e-12 * F)
          return next;
        F = next;
      }
    return F;
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

  FitResult fit_factors(const PairCompliance &pairs, const std::vector<SteSample> &samples,
                        const CalibrationFactors &start, const FitMask &mask)
  {
    if (samples.empty())
      throw InputError("calibration samples", "(none)", "at least one FE STE value");
    for (const auto &s : samples)
      if (!(s.ste > 0) || !(s.torque > 0))
        throw InputError("calibration samples", "STE " + to_string_g(s.ste) + " m at " + to_string_g(s.torque) + " N m",
                         "positive STE and torque");
    // Parameters: log multipliers; body = x^2 1e-9 m/N; R_e = x^2 1e-2 m.
    struct Par
    {
      std::string name;
      int which;
    };
    std::vector<Par> par;
    if (mask.beam)
      par.push_back({"beam", 0});
    if (mask.foundation)
      par.push_back({"foundation", 1});
    if (mask.hertz)
      par.push_back({"hertz", 2});
    if (mask.body)
      par.push_back({"body compliance", 3});
    if (mask.extended)
      par.push_back({"extended-contact radius", 4});
    const int p = int(par.size()), n = int(samples.size());
    if (p == 0)
      throw InputError("Calibration/Fit factors", "(none)", "at least one factor");
    if (n <= p)
      throw InputError("calibration samples", std::to_string(n), "more samples than fitted factors (" + std::to_string(p) + ")");

    auto to_factors = [&](const Eigen::VectorXd &x) {
      CalibrationFactors f = start;
      for (int i = 0; i < p; ++i)
        switch (par[i].which)
          {
            case 0: f.beam = std::exp(x[i]); break;
            case 1: f.foundation = std::exp(x[i]); break;
            case 2: f.hertz = std::exp(x[i]); break;
            case 3: f.body = x[i] * x[i] * 1e-9; break;
            default: f.extended = x[i] * x[i] * 1e-2; break;
          }
      return f;
    };
    Eigen::VectorXd x(p);
    for (int i = 0; i < p; ++i)
      switch (par[i].which)
        {
          case 0: x[i] = std::log(start.beam); break;
          case 1: x[i] = std::log(start.foundation); break;
          case 2: x[i] = std::log(start.hertz); break;
          case 3: x[i] = std::max(std::sqrt(start.body / 1e-9), 0.3); break;
          default: x[i] = std::max(std::sqrt(start.extended / 1e-2), 1.0); break;
        }
    // A trial step that leaves the admissible range (overflowing multiplier, no load path)
    // gets a huge residual, so that Levenberg-Marquardt rejects it and damps.
    auto residual = [&](const Eigen::VectorXd &xx) {
      Eigen::VectorXd r(n);
      try
        {
          const CalibratedMesh m(pairs, to_factors(xx));
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
    Eigen::VectorXd r = residual(x);
    double cost = r.squaredNorm(), lambda = 1e-3;
    Eigen::MatrixXd J = jacobian(x, r);
    for (res.iterations = 1; res.iterations <= 200; ++res.iterations)
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
    res.factors = to_factors(x);
    res.rms     = std::sqrt(cost / n);

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
            default: v = res.factors.extended, se = 2 * std::abs(x[i]) * 1e-2 * sx; break;
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
    return res;
  }
} // namespace gearfem::analytical
