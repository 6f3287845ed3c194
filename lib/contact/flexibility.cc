// TwoBodyContact: the flexibility cache, columns of K^-1 on the surface DoFs of each body
// computed on demand by block solves of the factorised body and kept across positions, and
// the elastic displacements they give.
#include "contact/two_body.h"

#include "base/errors.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
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
    const std::vector<double> X = surface(body).body().compliance_columns(dofs, c.dofs);
    const std::size_t n = c.dofs.size();
    for (std::size_t j = 0; j < missing.size(); ++j)
      {
        for (std::size_t i = 0; i < n; ++i)
          F.C(i, missing[j]) = X[j * n + i];
        F.have[missing[j]] = 1;
      }
    seconds += since(t0);
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
