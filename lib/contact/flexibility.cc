// TwoBodyContact: the flexibility cache, columns of K^-1 on the surface DoFs of each body
// computed on demand by block solves of the factorised body and kept across positions, and
// the elastic displacements they give.
#include "contact/two_body.h"

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
    double since(Clock::time_point t0)
    {
      return std::chrono::duration<double>(Clock::now() - t0).count();
    }
  } // namespace

  std::size_t TwoBodyContact::cached_columns(int body) const
  {
    const auto &h = cache_[body - 1].flex->have;
    return std::size_t(std::count(h.begin(), h.end(), 1));
  }

  void TwoBodyContact::ensure_columns(int body, const std::vector<int> &idx, double &seconds)
  {
    auto &c = cache_[body - 1];
    auto &F = *c.flex;
    std::vector<int> missing;
    for (const int i : idx)
      if (!F.have[i])
        {
          missing.push_back(i);
          F.have[i] = 2; // queued
        }
    if (missing.empty())
      return;
    const auto t0 = Clock::now();
    std::vector<unsigned int> dofs;
    for (const int i : missing)
      dofs.push_back(c.dofs[i]);
    // Rows: the universe, then the support of the observed functionals.
    std::vector<unsigned int> rows = c.dofs;
    rows.insert(rows.end(), c.observed_dofs.begin(), c.observed_dofs.end());
    const std::vector<double> X = surface(body).body().compliance_columns(dofs, rows);
    const std::size_t n = c.dofs.size(), nr = rows.size();
    for (std::size_t j = 0; j < missing.size(); ++j)
      {
        const double *x = X.data() + j * nr;
        for (std::size_t i = 0; i < n; ++i)
          F.C(i, missing[j]) = x[i];
        for (std::size_t r = 0; r < c.observed_rows.size(); ++r)
          {
            double v = 0;
            for (const auto &[k, coef] : c.observed_rows[r])
              v += coef * x[k];
            F.S(r, missing[j]) = v;
          }
        F.have[missing[j]] = 1;
      }
    seconds += since(t0);
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
        return;
      }
    c.observed_dofs = std::move(support);
    c.observed_rows = std::move(local);
    c.flex          = std::make_shared<Flexibility>();
    c.flex->C       = Eigen::MatrixXd::Zero(c.dofs.size(), c.dofs.size());
    c.flex->S       = Eigen::MatrixXd::Zero(c.observed_rows.size(), c.dofs.size());
    c.flex->have.assign(c.dofs.size(), 0);
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
