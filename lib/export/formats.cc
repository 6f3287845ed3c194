#include "export/formats.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/table.h"
#include "base/units.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace gearfem::exports
{
  namespace
  {
    /// Column j (one torque) of a theta-major grid array.
    std::vector<double> column(const std::vector<double> &v, std::size_t n_torque, std::size_t j)
    {
      std::vector<double> c(v.size() / n_torque);
      for (std::size_t i = 0; i < c.size(); ++i)
        c[i] = v[i * n_torque + j];
      return c;
    }

    std::string json_array(const std::vector<double> &v)
    {
      std::ostringstream s;
      s << std::setprecision(17) << "[";
      for (std::size_t i = 0; i < v.size(); ++i)
        s << (i ? ", " : "") << v[i];
      s << "]";
      return s.str();
    }

    std::string json_string(const std::string &x)
    {
      std::string r = "\"";
      for (const char c : x)
        r += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
      return r + "\"";
    }

    std::string torque_label(double T)
    {
      std::ostringstream s;
      s << std::setprecision(12) << T;
      return s.str();
    }
  } // namespace

  RossArrays ross_arrays(const CycleGrid &g, const PairInfo &pair)
  {
    const std::size_t n = g.theta.size(), m = g.torque.size();
    // Shifted nodes, wrapped into [0, period), in increasing order.
    std::vector<std::pair<double, std::size_t>> s;
    for (std::size_t i = 0; i < n; ++i)
      {
        double x = std::fmod(g.theta[i] - pair.theta_A, g.period);
        if (x < 0)
          x += g.period;
        if (x > g.period * (1 - 1e-12))
          x = 0; // a node at A up to round-off
        s.push_back({x, i});
      }
    std::sort(s.begin(), s.end());
    RossArrays r;
    r.torque       = g.torque;
    r.mesh_periods = g.pitches;
    const bool node_at_A = s.front().first < g.period * 1e-12;
    if (!node_at_A)
      r.theta_range.push_back(0);
    for (const auto &p : s)
      r.theta_range.push_back(node_at_A && p.second == s.front().second ? 0.0 : p.first);
    r.theta_range.push_back(g.period);
    for (std::size_t j = 0; j < m; ++j)
      {
        const auto k = column(g.stiffness, m, j);
        std::vector<double> out;
        const double kA = node_at_A ? k[s.front().second] : periodic_linear(g.theta, k, g.period, pair.theta_A);
        if (!node_at_A)
          out.push_back(kA);
        for (const auto &p : s)
          out.push_back(k[p.second]);
        out.push_back(kA);
        r.stiffness_range.push_back(out);
      }
    return r;
  }

  void write_ross_json(const std::filesystem::path &file, const RossArrays &r, const PairInfo &pair,
                       const std::string &source)
  {
    std::ostringstream s;
    s << std::setprecision(17);
    s << "{\n  \"format\": \"gearfem-ross-mesh\",\n  \"format_version\": 1,\n"
      << "  \"follows\": \"petrobras/ross ross/gear_element.py class Mesh (commit 82d2c69145871bd4e2d053bc7d7e462b6232cdaa): "
         "theta_range, stiffness_range\",\n"
      << "  \"source\": " << json_string(source) << ",\n"
      << "  \"geometry_hash\": " << json_string(pair.geometry_hash) << ",\n"
      << "  \"driving_gear\": \"pinion\",\n  \"n_tooth_driving\": " << pair.z1 << ",\n  \"n_tooth_driven\": " << pair.z2
      << ",\n  \"base_radius_driving_m\": " << pair.base_radius << ",\n"
      << "  \"theta_reference\": \"rotation of the driving pinion from the start of contact A [rad]; gearfem roll angle = theta + theta_A\",\n"
      << "  \"theta_A_rad\": " << pair.theta_A << ",\n  \"n_mesh_period\": " << r.mesh_periods << ",\n"
      << "  \"interpolation\": \"linear (numpy.interp), periodic in max(theta_range)\",\n"
      << "  \"units\": {\"theta_range\": \"rad\", \"torque\": \"N m\", \"stiffness_range\": \"N/m\"},\n"
      << "  \"theta_range\": " << json_array(r.theta_range) << ",\n"
      << "  \"torque\": " << json_array(r.torque) << ",\n  \"stiffness_range\": [\n";
    for (std::size_t j = 0; j < r.stiffness_range.size(); ++j)
      s << "    " << json_array(r.stiffness_range[j]) << (j + 1 < r.stiffness_range.size() ? ",\n" : "\n");
    s << "  ]\n}\n";
    write_file_atomically(file, s.str());
  }

  void write_spline_csv(const std::filesystem::path &file, const CycleGrid &g, const std::string &which)
  {
    const bool ste = which == "ste";
    Table t;
    t.add_column("roll angle", "deg");
    for (const double T : g.torque)
      t.add_column((ste ? "STE at " : "k_secant at ") + torque_label(T) + " N m", ste ? "um" : "N/m");
    const std::size_t n = g.theta.size(), m = g.torque.size();
    for (std::size_t r = 0; r <= n; ++r)
      {
        const std::size_t i = r % n;
        std::vector<double> row{(g.theta[i] + (r == n ? g.period : 0.0)) / units::deg};
        for (std::size_t j = 0; j < m; ++j)
          row.push_back(ste ? g.ste_at(i, j) * 1e6 : g.k_at(i, j));
        t.add_row(row);
      }
    t.write_csv(file, 17);
  }

  void write_te_table(const std::filesystem::path &file, const CycleGrid &g, const PairInfo &pair, bool revolution,
                      const std::string &source)
  {
    const std::size_t n = g.theta.size(), m = g.torque.size();
    std::vector<double> mean(m, 0.0);
    for (std::size_t j = 0; j < m; ++j)
      {
        const auto c = column(g.ste, m, j);
        mean[j] = std::accumulate(c.begin(), c.end(), 0.0) / n;
      }
    // One period of rows from A (a row at A interpolated periodically when no node is there),
    // repeated `copies` times and closed at the span by the row at A.
    const int copies = revolution && g.pitches == 1 ? pair.z1 : 1;
    const double span = g.period * copies;
    std::vector<std::pair<double, std::vector<double>>> rows;
    {
      const RossArrays a = ross_arrays(g, pair); // theta_range from A, closed; the same wrap
      std::vector<std::vector<double>> e(m);
      for (std::size_t j = 0; j < m; ++j)
        {
          const auto c = column(g.ste, m, j);
          for (const double x : a.theta_range)
            e[j].push_back(periodic_linear(g.theta, c, g.period, x + pair.theta_A) - mean[j]);
        }
      for (std::size_t r = 0; r + 1 < a.theta_range.size(); ++r)
        {
          std::vector<double> v;
          for (std::size_t j = 0; j < m; ++j)
            v.push_back(e[j][r]);
          rows.push_back({a.theta_range[r], v});
        }
    }
    std::ostringstream o;
    o << std::setprecision(17);
    o << "% gearfem transmission-error table (docs/export.md), " << (revolution ? "per revolution" : "per mesh cycle") << "\n"
      << "% source: " << source << "\n"
      << "% pair: z1 " << pair.z1 << " (pinion, drives), z2 " << pair.z2 << ", geometry " << pair.geometry_hash << "\n"
      << "% column 1: pinion rotation from the start of contact A [rad] (gearfem roll angle = this + theta_A, theta_A = "
      << pair.theta_A << " rad); span " << span << " rad = " << span / (2 * units::pi) << " pinion revolution(s)\n"
      << "% columns 2..: TE fluctuation e = STE - mean(STE) along the line of action [m], positive = pinion lagging"
         " behind the rigid conjugate position (gear held), one column per torque\n";
    for (std::size_t j = 0; j < m; ++j)
      o << "% column " << j + 2 << ": T1 = " << torque_label(g.torque[j]) << " N m, mean STE " << mean[j] << " m\n";
    auto put = [&](double x, const std::vector<double> &v) {
      o << x;
      for (const double e : v)
        o << ' ' << e;
      o << '\n';
    };
    for (int c = 0; c < copies; ++c)
      for (const auto &r : rows)
        put(r.first + c * g.period, r.second);
    put(span, rows.front().second);
    write_file_atomically(file, o.str());
  }
} // namespace gearfem::exports
