#include "analytical/mesh_cycle.h"

#include "base/errors.h"
#include "base/roots.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gearfem::analytical
{
  namespace
  {
    void check(const MeshModel &m)
    {
      if (!m.pair_compliance)
        throw InputError("mesh model: no pair compliance function");
      if (!(m.base_pitch > 0.0 && m.rb1 > 0.0 && m.g_E > m.g_A))
        throw InputError("mesh model: inconsistent line of action (g_A = " + to_string_g(m.g_A) +
                         ", g_E = " + to_string_g(m.g_E) + ", p_b = " + to_string_g(m.base_pitch) + ")");
    }

    // F = x / lambda(g, F), fixed point (lambda decreases slowly with F: Hertz log term).
    double pair_load_at(const MeshModel &m, double g, double x)
    {
      double F = x / m.pair_compliance(g, 1.0);
      for (int it = 0; it < 200; ++it)
        {
          const double Fn = x / m.pair_compliance(g, F);
          if (std::abs(Fn - F) <= 1e-13 * std::abs(Fn))
            return Fn;
          F = Fn;
        }
      throw SolverError("load at compression: fixed point did not converge at g = " + to_string_g(g));
    }
  } // namespace

  std::vector<double> contact_positions(const MeshModel &m, double phi)
  {
    check(m);
    const double g0 = m.g_C + m.rb1 * phi;
    // Shift to the first position >= g_A.
    const double j0 = std::ceil((m.g_A - g0) / m.base_pitch - 1e-12);
    std::vector<double> g;
    for (double gj = g0 + j0 * m.base_pitch; gj < m.g_E; gj += m.base_pitch)
      if (gj >= m.g_A - 1e-12 * m.base_pitch)
        g.push_back(gj);
    return g;
  }

  namespace
  {
    /// The pairs that carry load at compression x with corner contact (load_at_compression):
    /// their positions g and loads along the line of action k_i F_i [N].
    double corner_pairs(const MeshModel &m, double phi, double x, std::vector<double> *gs,
                        std::vector<double> *loads)
    {
      const double g0 = m.g_C + m.rb1 * phi, lo = m.g_A - m.base_pitch, hi = m.g_E + m.base_pitch;
      double F = 0.0;
      for (double g = g0 + std::ceil((lo - g0) / m.base_pitch) * m.base_pitch; g < hi; g += m.base_pitch)
        {
          const CornerContact c = (g >= m.g_A && g <= m.g_E) ? CornerContact{0.0, 1.0} : m.corner(g);
          if (!(x > c.gap))
            continue;
          const double f = c.arm * pair_load_at(m, std::clamp(g, m.g_A, m.g_E), c.arm * (x - c.gap));
          F += f;
          if (gs)
            gs->push_back(g), loads->push_back(f);
        }
      return F;
    }

    /// Load sharing with corner contact: the compression x at which the pairs on the path
    /// and in corner contact carry `load`: TOMS 748 on the monotone load_at_compression
    /// between no compression (no load) and the path-only solution (the corner pairs only
    /// add load, so the path-only compression carries at least `load`).
    MeshState solve_with_corners(const MeshModel &m, double phi, double load, const MeshState &path)
    {
      auto f = [&](double x) { return corner_pairs(m, phi, x, nullptr, nullptr) - load; };
      double x1 = path.deflection;
      int it = 0;
      if (std::abs(f(x1)) > 1e-12 * load)
        {
          // The upper end has a margin for the round-off of the path-only iteration (1e-12).
          // (The roll angle is added to the message only on failure: this runs per position.)
          try
            {
              x1 = base::find_root(f, 0.0, x1 * (1 + 1e-9), 1e-14, 100, "mesh position with corner contact", &it);
            }
          catch (const SolverError &e)
            {
              throw SolverError(std::string(e.what()) + " at roll angle " + to_string_g(phi) + " rad");
            }
        }
      MeshState s;
      s.roll_angle = phi, s.load = load, s.deflection = x1, s.iterations = path.iterations + it;
      corner_pairs(m, phi, x1, &s.g, &s.pair_load);
      const double sum = std::accumulate(s.pair_load.begin(), s.pair_load.end(), 0.0);
      for (double &f : s.pair_load) // remove the 1e-12 residual: the loads sum to `load`
        f *= load / sum;
      for (double f : s.pair_load)
        s.pair_stiffness.push_back(f / x1);
      s.stiffness = load / x1;
      return s;
    }
  } // namespace

  MeshState solve_mesh_position(const MeshModel &m, double phi, double load)
  {
    require_greater("mesh load", load, 0.0, "N");
    MeshState s;
    s.roll_angle = phi;
    s.load = load;
    s.g = contact_positions(m, phi);
    const std::size_t n = s.g.size();
    if (n == 0)
      throw SolverError("no tooth pair in contact at roll angle " + to_string_g(phi) + " rad");
    s.pair_load.assign(n, load / n);
    s.pair_stiffness.assign(n, 0.0);
    for (int it = 1; it <= 200; ++it)
      {
        double ksum = 0.0;
        for (std::size_t i = 0; i < n; ++i)
          {
            s.pair_stiffness[i] = 1.0 / m.pair_compliance(s.g[i], s.pair_load[i]);
            ksum += s.pair_stiffness[i];
          }
        s.deflection = load / ksum;
        double change = 0.0;
        for (std::size_t i = 0; i < n; ++i)
          {
            const double F = s.deflection * s.pair_stiffness[i];
            change = std::max(change, std::abs(F - s.pair_load[i]) / load);
            s.pair_load[i] = F;
          }
        s.iterations = it;
        if (change < 1e-12)
          {
            s.stiffness = ksum;
            if (!std::isfinite(s.deflection) || !(s.deflection > 0.0))
              throw SolverError("mesh position: non-positive deflection at roll angle " + to_string_g(phi));
            return m.corner ? solve_with_corners(m, phi, load, s) : s;
          }
      }
    throw SolverError("mesh position: Hertz load iteration did not converge at roll angle " +
                      to_string_g(phi) + " rad");
  }

  std::vector<MeshState> mesh_cycle(const MeshModel &m, double load, int n, int pitches)
  {
    check(m);
    require_greater("number of mesh positions", n, 0);
    require_greater("number of pitches", pitches, 0);
    const double phiA = (m.g_A - m.g_C) / m.rb1;
    const double span = pitches * m.base_pitch / m.rb1;
    std::vector<MeshState> out;
    out.reserve(n);
    for (int i = 0; i < n; ++i)
      out.push_back(solve_mesh_position(m, phiA + span * i / n, load));
    return out;
  }

  double load_at_compression(const MeshModel &m, double phi, double x)
  {
    if (!(x > 0.0))
      return 0.0;
    if (!m.corner)
      {
        double F = 0.0;
        for (double g : contact_positions(m, phi))
          F += pair_load_at(m, g, x);
        return F;
      }
    check(m);
    // Every pair within one base pitch beyond A and E (each once).
    return corner_pairs(m, phi, x, nullptr, nullptr);
  }

  std::vector<std::vector<double>> torque_table(const MeshModel &m, const std::vector<double> &phis,
                                                const std::vector<double> &xs)
  {
    std::vector<std::vector<double>> T(phis.size(), std::vector<double>(xs.size(), 0.0));
    for (std::size_t i = 0; i < phis.size(); ++i)
      for (std::size_t j = 0; j < xs.size(); ++j)
        T[i][j] = m.rb1 * load_at_compression(m, phis[i], xs[j]);
    return T;
  }
} // namespace gearfem::analytical
