#include "condensed/table.h"

#include "analytical/from_geometry.h"
#include "base/errors.h"
#include "base/progress.h"
#include "base/units.h"
#include "calibration/model.h"

#include <algorithm>
#include <cmath>

namespace gearfem::condensed
{
  namespace
  {
    /// Pinion torque [N m] at position k and drive rotation q [rad] on the scene that the
    /// full solver takes at that torque (the lowest scene below the cycle's range).
    double torque_at(const CondensedCycle &c, std::size_t k, double q, const Eigen::VectorXd &none)
    {
      if (!(q > 0))
        return 0.0;
      const auto &scenes = c.cycle[k];
      std::size_t s = 0;
      for (int tries = 0; tries < 4; ++tries)
        {
          const double T = contact::solve_condensed_rotation(scenes[s], none, q).solution.load;
          std::size_t want = 0;
          while (want + 1 < scenes.size() && T > scenes[want].load_hi * (1 + 1e-12))
            ++want;
          if (want == s)
            return T;
          s = want;
        }
      return contact::solve_condensed_rotation(scenes[s], none, q).solution.load;
    }
  } // namespace

  io::MeshTable torque_table(const CondensedCycle &c, const geometry::GearPair &pair, const TableOptions &o,
                             std::ostream *out)
  {
    if (o.n_delta < 4)
      throw InputError("Condense/Table compressions", std::to_string(o.n_delta), ">= 4");
    const std::size_t n = c.positions.size();
    const double period = 2 * units::pi / pair.gear(1).teeth();
    const double rb1    = pair.base_radius(1);
    if (n < 8)
      throw InputError("Solve/Number of positions", std::to_string(n), ">= 8 for a torque table");
    for (std::size_t k = 1; k < n; ++k)
      if (std::abs(c.positions[k].second - c.positions[0].second - period * double(k) / double(n)) > 1e-9 * period)
        throw InputError("Solve (positions)", "not one pitch of equally spaced roll angles",
                         "Positions = cycle, Pitches = 1 (the theta axis of a mesh table spans one mesh period)");
    const Eigen::VectorXd none;
    // The largest compression every position reaches within the torque range.
    double delta_max = 1e300;
    for (std::size_t k = 0; k < n; ++k)
      {
        const auto s = contact::solve_condensed(c.at(k, c.torque_hi), none, c.torque_hi);
        delta_max    = std::min(delta_max, s.solution.q * rb1);
      }
    io::MeshTable t;
    t.kind = io::MeshTable::Kind::torque_vs_compression;
    t.period = period, t.base_radius = rb1, t.geometry_hash = geometry::geometry_fingerprint(pair);
    t.second_unit = "m", t.value_unit = "N*m";
    for (const auto &p : c.positions)
      t.theta.push_back(p.second);
    std::vector<double> drive;
    for (int j = 0; j < o.n_delta; ++j)
      drive.push_back(delta_max * j / (o.n_delta - 1));
    // The drive flank at every (theta, delta).
    std::vector<std::vector<double>> T(n, std::vector<double>(drive.size(), 0.0));
    Progress progress(out, n, "table position");
    for (std::size_t k = 0; k < n; ++k)
      {
        for (std::size_t j = 1; j < drive.size(); ++j)
          T[k][j] = torque_at(c, k, drive[j] / rb1, none);
        progress.step(k + 1);
      }
    // Drive-flank torque at any theta (periodic, linear between positions) and compression
    // (linear between nodes, 0 below 0).
    const auto drive_torque = [&](double theta, double delta) {
      if (!(delta > 0))
        return 0.0;
      double x = (theta - t.theta.front()) / period * double(n);
      x -= double(n) * std::floor(x / double(n));
      const auto i0 = std::size_t(std::floor(x)) % n, i1 = (i0 + 1) % n;
      const double w = x - std::floor(x);
      const double y = std::min(delta, drive.back()) / drive.back() * double(drive.size() - 1);
      const auto j0  = std::min(std::size_t(std::floor(y)), drive.size() - 2);
      const double v = y - double(j0);
      const auto at  = [&](std::size_t i) { return (1 - v) * T[i][j0] + v * T[i][j0 + 1]; };
      return (1 - w) * at(i0) + w * at(i1);
    };
    double psi = 0;
    if (o.backlash >= 0)
      {
        t.backlash = o.backlash;
        psi = calibration::reverse_offset(analytical::involute_tooth(pair.gear(1)), analytical::pair_line(pair),
                                          o.backlash);
      }
    t.second = io::torque_table_axis(drive, o.backlash);
    for (std::size_t k = 0; k < n; ++k)
      for (const double d : t.second)
        {
          if (d >= 0)
            {
              const auto j = std::size_t(std::lround(d / drive.back() * double(drive.size() - 1)));
              t.values.push_back(T[k][std::min(j, drive.size() - 1)]);
            }
          else if (d < -t.backlash)
            t.values.push_back(-drive_torque(psi - t.theta[k], -d - t.backlash));
          else
            t.values.push_back(0.0);
        }
    t.check();
    return t;
  }

  void check_cycle_torques(const CondensedCycle &c, const std::vector<double> &torques, const std::string &entry)
  {
    for (const double T : torques)
      if (!(T >= c.torque_lo * (1 - 1e-12) && T <= c.torque_hi * (1 + 1e-12)))
        throw InputError(entry, to_string_g(T) + " N m",
                         "[" + to_string_g(c.torque_lo) + ", " + to_string_g(c.torque_hi) + "] N m",
                         "the torque range the condensed cycle was built for (Condense/Torque range)");
  }

  std::vector<calibration::SteSample> ste_samples(const CondensedCycle &c, double rb1, std::vector<double> torques,
                                                  const std::string &entry)
  {
    if (torques.empty())
      for (int i = 0; i < 6; ++i)
        torques.push_back(c.torque_lo * std::pow(c.torque_hi / c.torque_lo, i / 5.0));
    check_cycle_torques(c, torques, entry);
    const Eigen::VectorXd none;
    std::vector<calibration::SteSample> out;
    for (const double T : torques)
      for (std::size_t k = 0; k < c.positions.size(); ++k)
        {
          const double t = std::min(std::max(T, c.torque_lo), c.torque_hi);
          const auto s   = contact::solve_condensed(c.at(k, t), none, t);
          out.push_back({t, c.positions[k].second, s.solution.q * rb1});
        }
    return out;
  }
} // namespace gearfem::condensed
