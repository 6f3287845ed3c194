#include "dynamics/mesh_force.h"
#include "base/units.h"

#include "base/errors.h"
#include "base/roots.h"

#include <algorithm>
#include <cmath>

namespace gearfem::dynamics
{
  namespace
  {
    constexpr double two_pi = 6.283185307179586476925;
  }

  ZoneInfo locate_zone(const std::vector<double> &breaks, double period, double theta)
  {
    ZoneInfo z;
    const std::size_t n = breaks.size();
    if (n == 0)
      return z;
    const double k = std::floor(theta / period);
    const double r = theta - k * period;
    const std::size_t j = std::upper_bound(breaks.begin(), breaks.end(), r) - breaks.begin();
    z.zone = static_cast<int>(j % n);
    z.prev = j == 0 ? (k - 1) * period + breaks[n - 1] : k * period + breaks[j - 1];
    z.next = j == n ? (k + 1) * period + breaks[0] : k * period + breaks[j];
    return z;
  }

  // ---------------------------------------------------------------- Fourier
  FourierStiffnessLaw::FourierStiffnessLaw(double kbar, int z1, std::vector<double> a,
                                           std::vector<double> b)
    : kbar_(kbar)
    , period_(two_pi / z1)
    , z_(z1)
    , a_(std::move(a))
    , b_(std::move(b))
  {
    require_greater("Mesh force/Mean stiffness", kbar, 0.0);
    require_greater("Pinion teeth", z1, 0.0);
    double s = 0;
    for (double v : a_)
      s += std::abs(v);
    for (double v : b_)
      s += std::abs(v);
    if (s >= 1.0)
      throw InputError("Mesh force/Fourier coefficients", "sum |a_n| + |b_n| = " + to_string_g(s),
                       "< 1", "the stiffness must stay positive");
  }

  double FourierStiffnessLaw::stiffness(double theta) const
  {
    double k = 1.0;
    const double w = z_ * theta;
    for (std::size_t n = 0; n < a_.size(); ++n)
      k += a_[n] * std::cos((n + 1) * w);
    for (std::size_t n = 0; n < b_.size(); ++n)
      k += b_[n] * std::sin((n + 1) * w);
    return kbar_ * k;
  }

  bool FourierStiffnessLaw::position_independent() const
  {
    for (const double c : a_)
      if (c != 0.0)
        return false;
    for (const double c : b_)
      if (c != 0.0)
        return false;
    return true;
  }

  double FourierStiffnessLaw::force(double theta, double delta, int) const
  {
    return stiffness(theta) * delta;
  }

  // ---------------------------------------------------------------- piecewise constant
  PiecewiseConstantLaw::PiecewiseConstantLaw(double k_single, double k_double, int z1,
                                             double contact_ratio, double theta_A)
    : period_(two_pi / z1)
    , eps_(contact_ratio)
    , theta_A_(theta_A)
    , k_single_(k_single)
    , k_double_(k_double)
  {
    require_greater("Mesh force/Single-pair stiffness", k_single, 0.0, "N/m");
    require_greater("Mesh force/Double-pair stiffness", k_double, 0.0, "N/m");
    require_range("Contact ratio", contact_ratio, 1.0, 1.999999);
    auto wrap = [&](double v) { return v - period_ * std::floor(v / period_); };
    const double bA = wrap(theta_A), bB = wrap(theta_A + (contact_ratio - 1.0) * period_);
    if (contact_ratio <= 1.0 + 1e-12)
      {
        breaks_ = {};
        k_      = {k_single};
        pairs_  = {1};
        return;
      }
    // Zone j is the interval [breaks[j-1], breaks[j]) (zone 0 wraps around).
    breaks_ = {std::min(bA, bB), std::max(bA, bB)};
    // The middle interval [min, max) is double contact iff bA < bB.
    const bool middle_double = bA < bB;
    k_     = {middle_double ? k_single : k_double, middle_double ? k_double : k_single};
    pairs_ = {middle_double ? 1 : 2, middle_double ? 2 : 1};
  }

  double PiecewiseConstantLaw::mean_stiffness() const
  {
    return (eps_ - 1.0) * k_double_ + (2.0 - eps_) * k_single_;
  }

  int PiecewiseConstantLaw::pairs_in_contact(double theta) const
  {
    return pairs_[locate_zone(breaks_, period_, theta).zone];
  }


  namespace
  {
    /// The drive part (delta >= 0) or the reverse part (delta_r = -delta - b >= 0, as
    /// positive torques) of a two-sided torque table, as a one-sided table.
    MeshTable one_side(const MeshTable &t, bool reverse)
    {
      MeshTable o = t;
      o.backlash = -1;
      o.second.clear();
      o.values.clear();
      const long j0 = io::node_at(t.second, 0.0), jb = io::node_at(t.second, -t.backlash);
      std::vector<long> cols;
      if (reverse)
        for (long j = jb; j >= 0; --j)
          cols.push_back(j);
      else
        for (long j = j0; j < long(t.second.size()); ++j)
          cols.push_back(j);
      for (long j : cols)
        o.second.push_back(reverse ? std::max(0.0, -t.second[j] - t.backlash) : std::max(0.0, t.second[j]));
      o.second.front() = 0.0;
      for (std::size_t i = 0; i < t.theta.size(); ++i)
        for (long j : cols)
          o.values.push_back(reverse ? -t.value(i, j) : t.value(i, j));
      return o;
    }
  } // namespace

  TableLaw::TableLaw(const MeshTable &table, ThetaInterpolation interpolation)
    : interp_(interpolation)
    , period_(table.period)
  {
    table.check();
    if (table.kind == MeshTable::Kind::ste_vs_torque)
      throw InputError("mesh table/values", "transmission error STE(theta, T)",
                       "a torque T(theta, delta) or stiffness k(theta, F) table",
                       "an STE table is not a mesh-force law (use Law = STE)");
    const MeshTable t = table.two_sided() ? one_side(table, false) : table;
    if (table.two_sided())
      {
        backlash_ = table.backlash;
        reverse_ = std::make_unique<TableLaw>(one_side(table, true), interpolation);
      }
    nt_ = t.theta.size();
    theta0_ = t.theta.front();
    dtheta_ = t.period / nt_;
    for (std::size_t i = 1; i < nt_; ++i)
      if (std::abs(t.theta[i] - t.theta[0] - i * dtheta_) > 1e-9 * t.period)
        throw InputError("mesh table/theta axis", "non-uniform",
                         "uniform spacing period/n (periodic grid)");
    if (t.kind == MeshTable::Kind::torque_vs_compression)
      {
        d_ = t.second;
        F_.resize(t.values.size());
        for (std::size_t k = 0; k < F_.size(); ++k)
          F_[k] = t.values[k] / t.base_radius;
        if (d_[0] > 0)
          throw InputError("mesh table/delta axis", to_string_g(d_[0]), "starts at 0");
      }
    else
      {
        // delta(theta, F) = F / k(theta, F), then F on a common delta grid.
        const std::size_t nf = t.second.size();
        double dmin = 1e300;
        for (std::size_t i = 0; i < nt_; ++i)
          dmin = std::min(dmin, t.second[nf - 1] / t.value(i, nf - 1));
        const std::size_t nd = 2 * nf;
        d_.resize(nd);
        for (std::size_t j = 0; j < nd; ++j)
          d_[j] = dmin * j / (nd - 1);
        F_.resize(nt_ * nd);
        for (std::size_t i = 0; i < nt_; ++i)
          {
            std::vector<double> dd(nf + 1), ff(nf + 1);
            dd[0] = 0, ff[0] = 0;
            for (std::size_t j = 0; j < nf; ++j)
              dd[j + 1] = t.second[j] / t.value(i, j), ff[j + 1] = t.second[j];
            for (std::size_t j = 1; j <= nf; ++j)
              if (!(dd[j] > dd[j - 1]))
                throw InputError("mesh table/values", "F/k not increasing in F",
                                 "a monotone force-deflection curve");
            for (std::size_t j = 0; j < nd; ++j)
              {
                const std::size_t q =
                  std::min<std::size_t>(std::upper_bound(dd.begin(), dd.end(), d_[j]) -
                                          dd.begin(),
                                        nf);
                const double w = (d_[j] - dd[q - 1]) / (dd[q] - dd[q - 1]);
                F_[i * nd + j] = ff[q - 1] + w * (ff[q] - ff[q - 1]);
              }
          }
      }
    // Fritsch-Carlson monotone slopes in theta (periodic), per delta column.
    const std::size_t nd = d_.size();
    slope_.assign(F_.size(), 0.0);
    for (std::size_t j = 0; j < nd; ++j)
      for (std::size_t i = 0; i < nt_; ++i)
        {
          const double fm = F_[((i + nt_ - 1) % nt_) * nd + j], f0 = F_[i * nd + j],
                       fp = F_[((i + 1) % nt_) * nd + j];
          const double s0 = (f0 - fm) / dtheta_, s1 = (fp - f0) / dtheta_;
          slope_[i * nd + j] = (s0 * s1 <= 0) ? 0.0 : 2.0 / (1.0 / s0 + 1.0 / s1); // harmonic
        }
    // Mean stiffness for damping: mean secant at mid-range of the delta axis.
    const std::size_t jm = std::max<std::size_t>(1, nd / 2);
    double s = 0;
    for (std::size_t i = 0; i < nt_; ++i)
      s += F_[i * nd + jm] / d_[jm];
    kbar_ = s / nt_;
  }

  TableLaw::TableLaw(const TableLaw &o)
    : MeshForceLaw(o)
    , interp_(o.interp_)
    , period_(o.period_)
    , theta0_(o.theta0_)
    , dtheta_(o.dtheta_)
    , d_(o.d_)
    , F_(o.F_)
    , slope_(o.slope_)
    , nt_(o.nt_)
    , kbar_(o.kbar_)
    , out_(0)
    , backlash_(o.backlash_)
    , reverse_(o.reverse_ ? std::make_unique<TableLaw>(*o.reverse_) : nullptr)
  {}

  double TableLaw::interp_theta(std::size_t j, double theta) const
  {
    const std::size_t nd = d_.size();
    double u = (theta - theta0_) / dtheta_;
    u -= nt_ * std::floor(u / nt_);
    std::size_t i = static_cast<std::size_t>(u);
    if (i >= nt_)
      i = nt_ - 1;
    const double w = u - i;
    const std::size_t i1 = (i + 1) % nt_;
    const double f0 = F_[i * nd + j], f1 = F_[i1 * nd + j];
    if (interp_ == ThetaInterpolation::linear)
      return f0 + w * (f1 - f0);
    const double m0 = slope_[i * nd + j] * dtheta_, m1 = slope_[i1 * nd + j] * dtheta_;
    const double w2 = w * w, w3 = w2 * w;
    return (2 * w3 - 3 * w2 + 1) * f0 + (w3 - 2 * w2 + w) * m0 + (-2 * w3 + 3 * w2) * f1 +
           (w3 - w2) * m1;
  }

  double TableLaw::force(double theta, double delta, int) const
  {
    const std::size_t nd = d_.size();
    std::size_t j;
    if (delta <= d_[0])
      j = 0; // extension below 0: linear from the first cell (mode freezing only)
    else if (delta >= d_[nd - 1])
      {
        j = nd - 2;
        if (delta > d_[nd - 1])
          out_.fetch_add(1, std::memory_order_relaxed);
      }
    else
      j = std::upper_bound(d_.begin(), d_.end(), delta) - d_.begin() - 1;
    const double Fa = interp_theta(j, theta), Fb = interp_theta(j + 1, theta);
    return Fa + (delta - d_[j]) * (Fb - Fa) / (d_[j + 1] - d_[j]);
  }

  double TableLaw::mean_secant_stiffness(double F) const
  {
    // At 64 angles over the period, the compression that carries F: bisection on the table
    // force between no compression and the last table compression (F must be inside the
    // table; beyond it the interpolation would extrapolate).
    double s = 0;
    const int n = 64;
    for (int i = 0; i < n; ++i)
      {
        const double th = theta0_ + period_ * i / n;
        const double delta = base::find_root_bisection([&](double d) { return force(th, d, 0) - F; }, 0.0,
                                                       d_.back(), "mesh-force table: compression carrying the reference load " +
                                                                    to_string_g(F) + " N at angle " + to_string_g(th) + " rad");
        s += F / delta;
      }
    return s / n;
  }

  // ---------------------------------------------------------------- STE excitation
  SteExcitationLaw::SteExcitationLaw(double kbar, std::vector<double> theta,
                                     std::vector<double> ste, double period)
    : kbar_(kbar)
    , period_(period)
    , th_(std::move(theta))
    , e_(std::move(ste))
  {
    require_greater("Mesh force/Mean stiffness", kbar, 0.0, "N/m");
    if (th_.size() < 2 || th_.size() != e_.size())
      throw InputError("STE table", std::to_string(th_.size()) + " angles, " +
                                      std::to_string(e_.size()) + " values",
                       ">= 2 nodes, equal sizes");
    for (std::size_t i = 1; i < th_.size(); ++i)
      if (!(th_[i] > th_[i - 1]))
        throw InputError("STE table positions", to_string_g(th_[i] / units::deg) + " deg after " +
                                                  to_string_g(th_[i - 1] / units::deg) + " deg",
                         "strictly increasing");
    if (th_.back() - th_.front() >= period_ * (1 - 1e-12))
      throw InputError("STE table positions", "span " + to_string_g((th_.back() - th_.front()) / units::deg) + " deg",
                       "less than one mesh period " + to_string_g(period_ / units::deg) + " deg",
                       "give one period of STE (it is repeated periodically)");
    double mean = 0;
    for (double v : e_)
      mean += v;
    mean /= e_.size();
    for (double &v : e_)
      v -= mean;
  }

  double SteExcitationLaw::fluctuation(double theta) const
  {
    const double t0 = th_.front();
    double u = theta - t0;
    u -= period_ * std::floor(u / period_);
    const double t = t0 + u;
    std::size_t j = std::upper_bound(th_.begin(), th_.end(), t) - th_.begin();
    // Periodic wrap between the last node and the first node + period.
    const double xa = j == 0 ? th_.back() - period_ : th_[j - 1];
    const double ya = j == 0 ? e_.back() : e_[j - 1];
    const double xb = j == th_.size() ? th_.front() + period_ : th_[j];
    const double yb = j == th_.size() ? e_.front() : e_[j];
    return ya + (t - xa) * (yb - ya) / (xb - xa);
  }

  double SteExcitationLaw::force(double theta, double delta, int) const
  {
    return kbar_ * (delta - fluctuation(theta));
  }
} // namespace gearfem::dynamics
