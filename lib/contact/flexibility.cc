// TwoBodyContact: the flexibility cache, columns of K^-1 on the surface DoFs of each body
// computed on demand by block solves of the factorised body and kept across positions, and
// the elastic displacements they give.
#include "contact/two_body.h"
#include "base/progress.h"

#include "base/errors.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <limits>
#include <set>
#include <sstream>

namespace gearfem::contact
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
  } // namespace

  std::size_t TwoBodyContact::cached_columns(int body) const
  {
    const auto &h = cache_[body - 1].flex->have;
    return std::size_t(std::count(h.begin(), h.end(), 1));
  }

  void TwoBodyContact::Flexibility::reset(std::size_t n, std::size_t n_observed)
  {
    C = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
    S = Eigen::MatrixXd::Zero(Eigen::Index(n_observed), Eigen::Index(n));
    have.assign(n, 0);
    filled.assign(n * n, 0);
  }

  void TwoBodyContact::ensure_columns(int body, const std::vector<int> &idx, double &seconds,
                                      const std::vector<int> &extra_rows)
  {
    auto &c             = cache_[body - 1];
    auto &F             = *c.flex;
    const std::size_t n = c.dofs.size();
    // The rows every column needs now (the zone's and the extra ones), and those a request
    // fills (the wider zone's too).
    const auto merged = [&](const std::vector<int> &zone) {
      std::vector<int> r = zone;
      r.insert(r.end(), extra_rows.begin(), extra_rows.end());
      std::sort(r.begin(), r.end());
      r.erase(std::unique(r.begin(), r.end()), r.end());
      return r;
    };
    const std::vector<int> want = merged(c.zone), fill = merged(c.fill_zone);
    std::vector<int> cols;
    std::vector<std::vector<unsigned int>> rows;
    std::vector<char> queued(n, 0);
    for (const int j : idx)
      {
        if (queued[j])
          continue;
        queued[j] = 1;
        std::vector<unsigned int> r;
        const char *done = F.filled.data() + std::size_t(j) * n;
        if (F.have[j] != 1)
          {
            // A new column: its zone and observed rows, and the functionals' support.
            std::vector<int> u = fill;
            u.insert(u.end(), c.observed_universe.begin(), c.observed_universe.end());
            std::sort(u.begin(), u.end());
            u.erase(std::unique(u.begin(), u.end()), u.end());
            for (const int i : u)
              r.push_back(c.dofs[i]);
            r.insert(r.end(), c.observed_dofs.begin(), c.observed_dofs.end());
          }
        else if (std::any_of(want.begin(), want.end(), [&](int i) { return !done[i]; }))
          for (const int i : fill)
            if (!done[i])
              r.push_back(c.dofs[i]);
        if (r.empty())
          continue;
        cols.push_back(j);
        rows.push_back(std::move(r));
      }
    if (cols.empty())
      return;
    const auto t0 = Clock::now();
    std::vector<unsigned int> dofs;
    for (const int j : cols)
      dofs.push_back(c.dofs[j]);
    const std::vector<std::vector<double>> X = surface(body).body().compliance_columns(dofs, rows);
    std::vector<double> x(n + c.observed_dofs.size());
    for (std::size_t k = 0; k < cols.size(); ++k)
      {
        const int j     = cols[k];
        char *done      = F.filled.data() + std::size_t(j) * n;
        const bool is_new = F.have[j] != 1;
        for (std::size_t i = 0; i < rows[k].size(); ++i)
          {
            const unsigned int d = rows[k][i];
            const int u          = d < c.index.size() ? c.index[d] : -1;
            if (u >= 0)
              {
                F.C(u, j) = X[k][i];
                done[u]   = 1;
                x[std::size_t(u)] = X[k][i];
              }
            else
              x[n + i - (rows[k].size() - c.observed_dofs.size())] = X[k][i]; // the observed tail
          }
        if (!is_new)
          continue;
        for (std::size_t r = 0; r < c.observed_rows.size(); ++r)
          {
            double v = 0;
            for (const auto &[i, coef] : c.observed_rows[r])
              v += coef * x[std::size_t(i)];
            F.S(r, j) = v;
          }
        F.have[j] = 1;
      }
    seconds += since(t0);
  }

  void TwoBodyContact::set_zone(const Scene &scene, double q, double margin)
  {
    for (int b = 1; b <= 2; ++b)
      {
        auto &c                      = cache_[b - 1];
        const ContactSurface &s      = surface(b), &o = surface(3 - b);
        const geometry::Placement Pb = placed(scene, b, q), Po = placed(scene, 3 - b, q);
        const double co = std::cos(-Po.angle), so = std::sin(-Po.angle);
        c.node_zone.assign(s.nodes().size(), 0);
        c.zone.clear();
        c.fill_zone.clear();
        for (std::size_t n = 0; n < s.nodes().size(); ++n)
          {
            const auto &nd = s.nodes()[n];
            const Vec2 d   = Pb.apply(nd.x) - Po.centre;
            const Vec2 y(co * d.x() - so * d.y(), so * d.x() + co * d.y()); // in the other body's frame
            const double reach = options_.search_distance + margin + c.node_h[n];
            const double wide  = reach + 2 * options_.search_distance;
            const double lb    = o.distance_lower_bound(y, wide);
            if (lb > wide)
              continue;
            c.fill_zone.insert(c.fill_zone.end(), {c.index[nd.dof_x], c.index[nd.dof_y]});
            if (lb > reach)
              continue;
            c.zone.insert(c.zone.end(), {c.index[nd.dof_x], c.index[nd.dof_y]});
            c.node_zone[n] = 1;
          }
        for (auto *z : {&c.zone, &c.fill_zone})
          {
            std::sort(z->begin(), z->end());
            z->erase(std::unique(z->begin(), z->end()), z->end());
          }
      }
    zone_q_      = q;
    zone_margin_ = margin;
    zone_breach_ = false;
  }

  bool TwoBodyContact::zone_holds(double q) const
  {
    if (zone_breach_)
      return false;
    double u_max = 0;
    for (const auto &c : cache_)
      for (const int i : c.zone)
        u_max = std::max(u_max, std::abs(c.u[i]));
    const double move = std::abs(q - zone_q_) * (drive_.kind == Drive::Kind::rotation ? cache_[0].r_max : 1.0);
    return move + 4 * u_max <= zone_margin_;
  }

  void TwoBodyContact::set_displacements(const std::vector<std::pair<int, double>> forces[2], double &seconds)
  {
    for (int b = 0; b < 2; ++b)
      {
        auto &c = cache_[b];
        std::vector<int> idx;
        for (const auto &[i, f] : forces[b])
          idx.push_back(i);
        ensure_columns(b + 1, idx, seconds);
        c.u.setZero();
        for (const auto &[i, f] : forces[b])
          c.u += f * c.flex->C.col(i);
      }
  }

  Eigen::VectorXd TwoBodyContact::observed_response(int body,
                                                    const std::vector<std::pair<unsigned int, double>> &forces) const
  {
    const auto &c = cache_[body - 1];
    const auto &F = *c.flex;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(F.S.rows());
    for (const auto &[d, f] : forces)
      {
        const int i = d < c.index.size() ? c.index[d] : -1;
        if (i < 0 || F.have[i] != 1)
          throw SolverError("observed response: a force at DoF " + std::to_string(d) + " of body " +
                            std::to_string(body) + " has no computed flexibility column");
        r += f * F.S.col(i);
      }
    return r;
  }

  void TwoBodyContact::compute_columns(int body, const std::vector<int> &idx)
  {
    double t = 0;
    ensure_columns(body, idx, t);
  }

  void TwoBodyContact::observe(int body, const std::vector<std::vector<std::pair<unsigned int, double>>> &rows)
  {
    if (body != 1 && body != 2)
      throw InputError("observed body", std::to_string(body), "1 | 2");
    auto &c = cache_[body - 1];
    std::map<unsigned int, int> where;
    std::vector<unsigned int> support;
    std::vector<std::vector<std::pair<int, double>>> local(rows.size());
    // Entries index the rows of a flexibility block: the universe first, then the DoFs of
    // the functionals' support outside it (a DoF must not be requested twice).
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (const auto &[d, v] : rows[r])
        {
          if (c.index.at(d) >= 0)
            {
              local[r].emplace_back(c.index[d], v);
              continue;
            }
          auto it = where.find(d);
          if (it == where.end())
            {
              it = where.emplace(d, int(c.dofs.size() + support.size())).first;
              support.push_back(d);
            }
          local[r].emplace_back(it->second, v);
        }
    // Identical gears share one flexibility: observing the same functionals on the second
    // side keeps the sharing; different ones give that side its own cache.
    const auto &other = cache_[2 - body];
    const bool shared = other.flex == c.flex;
    if (shared && other.observed_dofs == support && other.observed_rows == local)
      {
        c.observed_dofs = support, c.observed_rows = local;
        c.observed_universe = other.observed_universe;
        return;
      }
    c.observed_dofs = std::move(support);
    c.observed_rows = std::move(local);
    c.observed_universe.clear();
    for (const auto &row : c.observed_rows)
      for (const auto &[i, v] : row)
        if (i < int(c.dofs.size()))
          c.observed_universe.push_back(i);
    std::sort(c.observed_universe.begin(), c.observed_universe.end());
    c.observed_universe.erase(std::unique(c.observed_universe.begin(), c.observed_universe.end()),
                              c.observed_universe.end());
    c.flex = std::make_shared<Flexibility>();
    c.flex->reset(c.dofs.size(), c.observed_rows.size());
    // A body observed like the other side's identical body shares its cache again.
    if (&s1_->body() == &s2_->body() && cache_[0].dofs == cache_[1].dofs &&
        other.observed_dofs == c.observed_dofs && other.observed_rows == c.observed_rows)
      c.flex = other.flex;
  }

  Vec2 TwoBodyContact::displacement(int body, int node) const
  {
    const auto &c  = cache_[body - 1];
    const auto &nd = surface(body).nodes()[node];
    return Vec2(c.u[c.index[nd.dof_x]], c.u[c.index[nd.dof_y]]);
  }

  Vec2 TwoBodyContact::interpolate(int body, int face, const std::vector<double> &shape) const
  {
    const auto &f = surface(body).faces()[face];
    Vec2 u(0, 0);
    for (std::size_t j = 0; j < f.nodes.size(); ++j)
      u += shape[j] * displacement(body, f.nodes[j]);
    return u;
  }
} // namespace gearfem::contact
