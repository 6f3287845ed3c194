#include "export/grid.h"

#include "base/errors.h"
#include "base/units.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace gearfem::exports
{
  namespace
  {
    std::string list_text(const std::vector<double> &v, double scale = 1)
    {
      std::ostringstream s;
      for (std::size_t i = 0; i < v.size(); ++i)
        s << (i ? ", " : "") << to_string_g(v[i] * scale);
      return s.str();
    }

    /// Index of x in v within a relative tolerance of 1e-9; -1: none.
    long find_value(const std::vector<double> &v, double x)
    {
      for (std::size_t i = 0; i < v.size(); ++i)
        if (std::abs(v[i] - x) <= 1e-9 * std::max(1.0, std::abs(x)))
          return static_cast<long>(i);
      return -1;
    }

    /// Linear interpolation of y over the increasing x at xq inside [x.front(), x.back()];
    /// a node returns its own value (a copy).
    double linear(const std::vector<double> &x, const std::vector<double> &y, double xq)
    {
      const long n = find_value(x, xq);
      if (n >= 0)
        return y[n];
      const auto it = std::upper_bound(x.begin(), x.end(), xq);
      const std::size_t j = std::clamp<std::size_t>(it - x.begin(), 1, x.size() - 1);
      const double w = (xq - x[j - 1]) / (x[j] - x[j - 1]);
      return y[j - 1] + w * (y[j] - y[j - 1]);
    }

    void require_sorted_torques(std::vector<double> &t, const std::string &parameter)
    {
      std::sort(t.begin(), t.end());
      for (std::size_t j = 1; j < t.size(); ++j)
        if (!(t[j] > t[j - 1]))
          throw InputError(parameter, list_text(t) + " N m", "distinct torques", "a torque is listed twice");
    }
  } // namespace

  double PairInfo::mesh_period() const { return 2 * units::pi / z1; }

  double periodic_linear(const std::vector<double> &x, const std::vector<double> &y, double period, double xq)
  {
    const std::size_t n = x.size();
    double t = x[0] + std::fmod(xq - x[0], period);
    if (t < x[0])
      t += period;
    const auto it = std::upper_bound(x.begin(), x.end(), t);
    const std::size_t j = it - x.begin(); // x[j-1] <= t < x[j] (j = n: the wrapping segment)
    const double x0 = x[j - 1], y0 = y[j - 1];
    const double x1 = j < n ? x[j] : x[0] + period, y1 = j < n ? y[j] : y[0];
    if (t == x0)
      return y0;
    return y0 + (t - x0) / (x1 - x0) * (y1 - y0);
  }

  CycleGrid grid_from_solve(const io::SolveResults &results, const PairInfo &pair,
                            const std::vector<double> &torques_in, const std::string &parameter)
  {
    const Table &s = results.sweep;
    if (s.n_rows() == 0)
      throw InputError("the solve result has no sweep rows (" + parameter + ")");
    const auto T = s.column("torque"), phi = s.column("roll angle"), ste = s.column("STE");
    std::map<double, std::vector<std::pair<double, double>>> by_torque; // T -> (theta, STE)
    for (std::size_t r = 0; r < T.size(); ++r)
      by_torque[T[r]].push_back({phi[r] * units::deg, ste[r] * 1e-6});
    std::vector<double> available;
    for (const auto &[t, rows] : by_torque)
      available.push_back(t);
    std::vector<double> torques = torques_in.empty() ? available : torques_in;
    require_sorted_torques(torques, parameter);

    CycleGrid g;
    g.torque = torques;
    for (const double t : torques)
      {
        const long k = find_value(available, t);
        if (k < 0)
          throw InputError(parameter, to_string_g(t) + " N m", "the torques of the solve result: " + list_text(available) + " N m",
                           "a solve result is exported as computed (no interpolation between FE torques)");
        auto rows = by_torque[available[k]];
        std::sort(rows.begin(), rows.end());
        std::vector<double> th;
        for (const auto &r : rows)
          th.push_back(r.first);
        if (g.theta.empty())
          g.theta = th;
        else if (th.size() != g.theta.size() ||
                 !std::equal(th.begin(), th.end(), g.theta.begin(), [](double a, double b) { return std::abs(a - b) < 1e-12; }))
          throw InputError("the solve result has other roll angles at " + to_string_g(t) + " N m than at " +
                           to_string_g(torques[0]) + " N m (" + parameter + "): export needs one angle grid");
      }
    const std::size_t n = g.theta.size();
    if (n < 4)
      throw InputError("the solve result has " + std::to_string(n) + " positions per torque (at least 4 needed to export)");
    for (std::size_t i = 1; i < n; ++i)
      if (!(g.theta[i] > g.theta[i - 1]))
        throw InputError("the solve result has a roll angle twice at one torque: not a sweep over the cycle");
    const double p = pair.mesh_period(), h = (g.theta.back() - g.theta.front()) / (n - 1);
    g.pitches = std::max(1, static_cast<int>(std::lround((g.theta.back() - g.theta.front() + h) / p)));
    g.period = g.pitches * p;
    if (!(g.theta.back() - g.theta.front() < g.period * (1 - 1e-9)))
      throw InputError("the solve result's roll angles span " + to_string_g((g.theta.back() - g.theta.front()) / units::deg) +
                       " deg, more than whole mesh periods of " + to_string_g(p / units::deg) + " deg: not a cycle sweep");
    g.ste.resize(n * torques.size());
    g.stiffness.resize(n * torques.size());
    for (std::size_t j = 0; j < torques.size(); ++j)
      {
        auto rows = by_torque[available[find_value(available, torques[j])]];
        std::sort(rows.begin(), rows.end());
        const double F = torques[j] / pair.base_radius;
        for (std::size_t i = 0; i < n; ++i)
          {
            if (!(rows[i].second > 0))
              throw InputError("the solve result has STE " + to_string_g(rows[i].second * 1e6) + " um at " +
                               to_string_g(torques[j]) + " N m, roll angle " + to_string_g(rows[i].first / units::deg) +
                               " deg: a stiffness needs STE > 0");
            g.ste[i * torques.size() + j]       = rows[i].second;
            g.stiffness[i * torques.size() + j] = F / rows[i].second;
          }
      }
    return g;
  }

  namespace
  {
    /// Compression at which a torque table reaches T at row i (drive side, delta >= 0).
    double invert_torque_row(const io::MeshTable &t, std::size_t i, double T)
    {
      const std::size_t m = t.second.size();
      std::size_t j0 = 0;
      while (j0 < m && t.second[j0] < 0)
        ++j0;
      for (std::size_t j = j0 + 1; j < m; ++j)
        if (t.value(i, j) >= T)
          {
            const double T0 = t.value(i, j - 1), T1 = t.value(i, j);
            if (T1 == T)
              return t.second[j];
            return t.second[j - 1] + (T - T0) / (T1 - T0) * (t.second[j] - t.second[j - 1]);
          }
      return -1;
    }
    /// The torque range every roll angle of a table reaches, as text [N m].
    std::string reachable_text(const io::MeshTable &t)
    {
      using Kind = io::MeshTable::Kind;
      if (t.kind == Kind::stiffness_vs_load)
        return to_string_g(t.second.front() * t.base_radius) + " to " + to_string_g(t.second.back() * t.base_radius) + " N m";
      if (t.kind == Kind::ste_vs_torque)
        return to_string_g(t.second.front()) + " to " + to_string_g(t.second.back()) + " N m";
      double top = 1e300;
      for (std::size_t i = 0; i < t.theta.size(); ++i)
        top = std::min(top, t.value(i, t.second.size() - 1));
      return "> 0 and <= " + to_string_g(top) + " N m (the smallest torque of the table's largest compression)";
    }
  } // namespace

  CycleGrid grid_from_table(const io::MeshTable &t, const PairInfo &pair, const std::vector<double> &torques_in,
                            const std::string &parameter)
  {
    using Kind = io::MeshTable::Kind;
    const double rb = t.base_radius;
    std::vector<double> torques = torques_in;
    if (torques.empty())
      {
        if (t.kind == Kind::torque_vs_compression)
          throw InputError(parameter, "(empty)", "one or more torques > 0 [N m]",
                           "a torque table T(theta, delta) has no torque nodes of its own: name the torques to export");
        for (const double x : t.second)
          if (x > 0)
            torques.push_back(t.kind == Kind::stiffness_vs_load ? x * rb : x);
      }
    require_sorted_torques(torques, parameter);
    CycleGrid g;
    g.theta  = t.theta;
    g.torque = torques;
    g.period = t.period, g.pitches = 1;
    const std::size_t n = t.theta.size(), m = torques.size();
    g.ste.resize(n * m), g.stiffness.resize(n * m);
    for (std::size_t i = 0; i < n; ++i)
      {
        const std::vector<double> row(t.values.begin() + i * t.second.size(), t.values.begin() + (i + 1) * t.second.size());
        for (std::size_t j = 0; j < m; ++j)
          {
            const double T = torques[j], F = T / rb;
            double ste = -1, k = -1;
            if (t.kind == Kind::torque_vs_compression)
              ste = invert_torque_row(t, i, T), k = ste > 0 ? F / ste : -1;
            else
              {
                const double x = t.kind == Kind::stiffness_vs_load ? F : T;
                if (x >= t.second.front() * (1 - 1e-12) && x <= t.second.back() * (1 + 1e-12))
                  {
                    const double v = linear(t.second, row, std::clamp(x, t.second.front(), t.second.back()));
                    if (t.kind == Kind::stiffness_vs_load)
                      k = v, ste = F / v;
                    else
                      ste = v, k = v > 0 ? F / v : -1;
                  }
              }
            if (!(ste > 0 && k > 0))
              throw InputError(parameter, to_string_g(T) + " N m", "a torque the table reaches at every roll angle: " +
                                                                     reachable_text(t),
                               "not reached at roll angle " + to_string_g(t.theta[i] / units::deg) + " deg");
            g.ste[i * m + j] = ste, g.stiffness[i * m + j] = k;
          }
      }
    (void)pair;
    return g;
  }
} // namespace gearfem::exports
