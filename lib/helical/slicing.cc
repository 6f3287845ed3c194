// The helical pair on the condensed cycle of its transverse section (helical/slicing.h).
#include "helical/slicing.h"
#include "base/number.h"
#include "base/progress.h"
#include "helical/slicing_detail.h"

#include "contact/ncp.h"

#include "base/errors.h"
#include "base/units.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <set>

namespace gearfem::helical
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
    long floor_div(long a, long n) { return a >= 0 ? a / n : -((-a + n - 1) / n); }
    /// Candidates first taken into the coupled problem: loaded at the build, or within this
    /// gap of contact there; the others join where they would penetrate.
    constexpr double initial_gap = 1e-6;

  } // namespace

  std::vector<std::pair<std::string, double>> Grid::positions() const
  {
    std::vector<std::pair<std::string, double>> p;
    for (int g = 0; g < size; ++g)
      p.emplace_back("", phi0 + g * step);
    return p;
  }

  SlicedPair::SlicedPair(const condensed::CondensedCycle &cycle, const solve::GearContactInput &section,
                         SlicingOptions options)
    : cycle_(cycle)
    , in_(section)
    , o_(std::move(options))
    , resolver_(cycle, section)
  {
    section.require_external("Helical");
    if (int(cycle.positions.size()) != o_.grid.size)
      throw InputError("Helical", std::to_string(cycle.positions.size()) + " stored positions",
                       std::to_string(o_.grid.size) + " (the grid of the slices)");
    rb1_  = section.pair->base_radius(1);
    z_[0] = section.pair->gear(1).teeth();
    z_[1] = section.pair->gear(2).teeth();
  }

  std::vector<SlicedPair::Sub> SlicedPair::subs(double phi1) const
  {
    const int N = o_.slices, G = o_.grid.size;
    const auto zc = slice_centres(o_.helix.face_width, N);
    std::vector<Sub> out;
    for (int k = 0; k < N; ++k)
      {
        const double u = (phi1 + o_.helix.roll_per_length * zc[std::size_t(k)] - o_.grid.phi0) / o_.grid.step;
        long g0        = long(std::floor(u));
        double t       = u - double(g0);
        if (t > 1 - 1e-9)
          ++g0, t = 0;
        for (const auto &[gi, w] : {std::pair<long, double>{g0, 1 - t}, {g0 + 1, t}})
          if (w > 1e-9)
            {
              Sub s;
              s.slice  = k;
              s.g      = std::size_t(wrap_index(gi, G));
              s.wrap   = floor_div(gi, G);
              s.weight = w / N;
              out.push_back(std::move(s));
            }
      }
    return out;
  }

  Eigen::MatrixXd SlicedPair::section_stiffness(const contact::CondensedPosition &p,
                                                const std::vector<std::pair<int, int>> &pairs) const
  {
    auto key = std::make_pair(static_cast<const void *>(&p), pairs);
    if (const auto it = section_.find(key); it != section_.end())
      return it->second;
    // The stored candidates of these pairs, and the arm of each on its pair's torque.
    const int n = int(pairs.size());
    std::vector<int> idx, row;
    for (std::size_t c = 0; c < p.size(); ++c)
      for (int r = 0; r < n; ++r)
        if (p.cand[c].point.tooth(1) == pairs[std::size_t(r)].first &&
            p.cand[c].point.tooth(2) == pairs[std::size_t(r)].second)
          idx.push_back(int(c)), row.push_back(r);
    const int m = int(idx.size());
    Eigen::MatrixXd Ws(m, m), P = Eigen::MatrixXd::Zero(n, m);
    for (int i = 0; i < m; ++i)
      {
        P(row[std::size_t(i)], i) = -p.a[idx[std::size_t(i)]];
        for (int j = 0; j < m; ++j)
          Ws(i, j) = p.W(idx[std::size_t(i)], idx[std::size_t(j)]);
      }
    // min over lambda with pair torques tau of lambda^T W lambda = tau^T (P W^-1 P^T)^-1 tau:
    // P W^-1 P^T is the section's stiffness at the level of its tooth pairs [N m/rad].
    Eigen::MatrixXd G = P * Ws.ldlt().solve(P.transpose());
    section_.emplace(std::move(key), G);
    return G;
  }

  void SlicedPair::couple(System &s, const std::vector<Sub> &sub) const
  {
    const double l = o_.coupling_length;
    if (!(l > 0) && !o_.face)
      return;
    const int N     = o_.slices;
    const double dz = o_.helix.face_width / N;
    // The tooth pairs of every stored configuration in use, all of their candidates (not only
    // those in the problem), so that the coupling does not depend on which candidates were
    // taken in: each slice's stiffness over its tooth pairs is the sum over its sub-slices of
    // weight x the stored section's pair-level stiffness (parallel springs).
    std::vector<std::map<long, std::pair<int, int>>> labels(sub.size()); // absolute key -> stored labels
    for (std::size_t j = 0; j < sub.size(); ++j)
      for (const auto &cd : sub[j].p->cand)
        {
          const auto &pt = cd.point;
          const long key = long(((pt.tooth(1) - sub[j].wrap) % z_[0] + z_[0]) % z_[0]) * z_[1] +
                           ((pt.tooth(2) + sub[j].wrap) % z_[1] + z_[1]) % z_[1];
          labels[j].emplace(key, std::make_pair(pt.tooth(1), pt.tooth(2)));
          s.pair_index.try_emplace(key, int(s.pair_index.size()));
        }
    const int P = int(s.pair_index.size());
    s.n_pairs   = P;
    s.K.assign(std::size_t(N), Eigen::MatrixXd::Zero(P, P));
    for (std::size_t j = 0; j < sub.size(); ++j)
      {
        const Sub &u = sub[j];
        std::vector<std::pair<int, int>> stored;
        std::vector<int> q;
        for (const auto &[key, t] : labels[j])
          stored.push_back(t), q.push_back(s.pair_index.at(key));
        if (stored.empty())
          continue;
        const Eigen::MatrixXd G = section_stiffness(*u.p, stored);
        for (std::size_t r = 0; r < q.size(); ++r)
          for (std::size_t t = 0; t < q.size(); ++t)
            s.K[std::size_t(u.slice)](q[r], q[t]) += u.weight * G(Eigen::Index(r), Eigen::Index(t));
      }
    // The tooth is there where its pair does not touch: the nearest slice's stiffness of the
    // pair (diagonal) carries the coupling through those slices.
    std::vector<std::vector<char>> present(std::size_t(N), std::vector<char>(std::size_t(P), 0));
    Eigen::MatrixXd d(N, P); // stiffness of each pair's section per slice
    for (int q = 0; q < P; ++q)
      {
        std::vector<int> on;
        for (int k = 0; k < N; ++k)
          if (s.K[std::size_t(k)](q, q) > 0)
            on.push_back(k), present[std::size_t(k)][std::size_t(q)] = 1;
        for (int k = 0; k < N; ++k)
          {
            int best = on.front();
            for (const int p : on)
              if (std::abs(p - k) < std::abs(best - k))
                best = p;
            d(k, q) = s.K[std::size_t(best)](q, q);
            if (!present[std::size_t(k)][std::size_t(q)])
              s.K[std::size_t(k)](q, q) = d(k, q);
          }
      }
    const int n = N * P;
    if (o_.face)
      {
        face_correction(s, sub);
        return;
      }
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    for (int k = 0; k < N; ++k)
      A.block(k * P, k * P, P, P) = s.K[std::size_t(k)];
    for (int q = 0; q < P; ++q)
      if (o_.coupling == Coupling::shear) // a Pasternak layer between neighbours
        for (int k = 0; k + 1 < N; ++k)
          {
            const double G = l * l * std::sqrt(d(k, q) * d(k + 1, q)) / (dz * dz);
            const int a = k * P + q, b = (k + 1) * P + q;
            A(a, a) += G, A(b, b) += G, A(a, b) -= G, A(b, a) -= G;
          }
      else // bending: EI (w'')^2 / 2 along the face, EI = k l^4 / 4, free ends
        for (int k = 0; k + 2 < N; ++k)
          {
            const double c = std::pow(l / dz, 4) * std::cbrt(d(k, q) * d(k + 1, q) * d(k + 2, q)) / 4;
            const int i[3]    = {k * P + q, (k + 1) * P + q, (k + 2) * P + q};
            const double e[3] = {1, -2, 1};
            for (int r = 0; r < 3; ++r)
              for (int t = 0; t < 3; ++t)
                A(i[r], i[t]) += c * e[r] * e[t];
          }
    // dC = (K + B)^-1 - K^-1 on the pairs each slice touches with: negative semi-definite.
    s.dC = A.ldlt().solve(Eigen::MatrixXd::Identity(n, n));
    for (int k = 0; k < N; ++k)
      {
        std::vector<int> on;
        for (int q = 0; q < P; ++q)
          if (present[std::size_t(k)][std::size_t(q)])
            on.push_back(q);
        const int m = int(on.size());
        Eigen::MatrixXd Kp(m, m);
        for (int r = 0; r < m; ++r)
          for (int t = 0; t < m; ++t)
            Kp(r, t) = s.K[std::size_t(k)](on[std::size_t(r)], on[std::size_t(t)]);
        const Eigen::MatrixXd C = Kp.ldlt().solve(Eigen::MatrixXd::Identity(m, m));
        for (int r = 0; r < m; ++r)
          for (int t = 0; t < m; ++t)
            s.dC(k * P + on[std::size_t(r)], k * P + on[std::size_t(t)]) -= C(r, t);
      }
    index_unknowns(s, sub);
  }

  void SlicedPair::index_unknowns(System &s, const std::vector<Sub> &sub) const
  {
    // The coupled operator is W = blockdiag(W_j / weight_j) + U dC U^T, U(i, at_i) = a_i.
    s.at.resize(std::size_t(s.m));
    for (int i = 0; i < s.m; ++i)
      s.at[std::size_t(i)] = s.index(sub[std::size_t(s.sub[std::size_t(i)])].slice, s.pair[std::size_t(i)]);
  }

  void SlicedPair::face_correction(System &s, const std::vector<Sub> &sub) const
  {
    // The contact of each tooth pair in each slice: its radius on each gear, from the stored
    // candidates of the pair (the force-weighted mean of those that carry load at the build,
    // else the closest), the sub-slices of a slice weighted by their widths.
    const int N = o_.slices, P = s.n_pairs;
    Eigen::MatrixXd r[2] = {Eigen::MatrixXd::Zero(N, P), Eigen::MatrixXd::Zero(N, P)};
    Eigen::MatrixXd w = Eigen::MatrixXd::Zero(N, P);
    for (std::size_t j = 0; j < sub.size(); ++j)
      {
        const auto &p = *sub[j].p;
        std::map<long, std::array<double, 4>> acc; // sum F r1, sum F r2, sum F, (closest gap)
        std::map<long, std::array<double, 3>> closest; // gap, r1, r2
        for (const auto &cd : p.cand)
          {
            const auto &pt  = cd.point;
            const long key  = pair_key(pt.tooth(1), pt.tooth(2), sub[j].wrap);
            const contact::Vec2 on1  = pt.slave_body == 1 ? pt.x : pt.master_point;
            const contact::Vec2 on2  = pt.slave_body == 1 ? pt.master_point : pt.x;
            const double r1 = (on1 - p.placement[0].centre).norm(), r2 = (on2 - p.placement[1].centre).norm();
            auto &a = acc.try_emplace(key, std::array<double, 4>{0, 0, 0, 0}).first->second;
            if (pt.force > 0)
              a[0] += pt.force * r1, a[1] += pt.force * r2, a[2] += pt.force;
            auto it = closest.find(key);
            if (it == closest.end() || pt.gap < it->second[0])
              closest[key] = {pt.gap, r1, r2};
          }
        for (const auto &[key, a] : acc)
          {
            const int q = s.pair_index.at(key), k = sub[j].slice;
            const auto &c = closest.at(key);
            const double r1 = a[2] > 0 ? a[0] / a[2] : c[1], r2 = a[2] > 0 ? a[1] / a[2] : c[2];
            r[0](k, q) += sub[j].weight * r1, r[1](k, q) += sub[j].weight * r2, w(k, q) += sub[j].weight;
          }
      }
    s.dC = Eigen::MatrixXd::Zero(N * P, N * P);
    s.radius[0] = s.radius[1] = Eigen::MatrixXd::Zero(N, P);
    const double rb2 = rb1_ * rb1_;
    for (int q = 0; q < P; ++q)
      {
        std::vector<int> on;
        for (int k = 0; k < N; ++k)
          if (w(k, q) > 0)
            on.push_back(k);
        if (on.empty())
          continue;
        // Slices where the pair has no candidate carry no force: any radius (the nearest).
        std::vector<double> r1(static_cast<std::size_t>(N)), r2(static_cast<std::size_t>(N));
        for (int k = 0; k < N; ++k)
          {
            int best = on.front();
            for (const int p : on)
              if (std::abs(p - k) < std::abs(best - k))
                best = p;
            r1[std::size_t(k)] = r[0](best, q) / w(best, q), r2[std::size_t(k)] = r[1](best, q) / w(best, q);
          }
        for (int k = 0; k < N; ++k)
          s.radius[0](k, q) = r1[std::size_t(k)], s.radius[1](k, q) = r2[std::size_t(k)];
        const Eigen::MatrixXd C = o_.face(r1, r2);
        for (int k = 0; k < N; ++k)
          for (int kk = 0; kk < N; ++kk)
            s.dC(k * P + q, kk * P + q) = C(k, kk) / rb2;
      }
    index_unknowns(s, sub);
  }

  long SlicedPair::pair_key(int t1, int t2, long wrap) const
  {
    return long(wrap_index(t1 - wrap, z_[0])) * z_[1] + wrap_index(t2 + wrap, z_[1]);
  }

  void SlicedPair::prepare(Sub &u, double load, const LeadModification &lead) const
  {
    const double b = o_.helix.face_width;
    u.p      = &cycle_.at(u.g, std::clamp(load, cycle_.torque_lo, cycle_.torque_hi));
    u.offset = offsets(u, lead);
    u.keep.clear();
    for (std::size_t c = 0; c < u.p->size(); ++c)
      if (u.p->cand[c].point.force > 0 || u.p->cand[c].point.gap < initial_gap)
        u.keep.push_back(int(c));
  }

  Eigen::VectorXd SlicedPair::offsets(const Sub &u, const LeadModification &lead) const
  {
    const double b = o_.helix.face_width;
    return resolver_.offsets(*u.p).array() + lead_gap(lead, slice_centres(b, o_.slices)[std::size_t(u.slice)], b, o_.alpha_wt);
  }

  double SlicedPair::assemble(System &s, std::vector<Sub> &sub, double torque) const
  {
    s   = System();
    s.m = 0;
    for (auto &u : sub)
      u.first = s.m, s.m += int(u.keep.size());
    const int m = s.m;
    s.a.resize(m), s.curvature.resize(m), s.q_build.resize(m), s.ghat.resize(m), s.D.resize(m), s.lambda0.resize(m);
    double q = 0; // start: each sub-slice's build rotation scaled to the torque, weighted
    for (std::size_t j = 0; j < sub.size(); ++j)
      {
        const Sub &u  = sub[j];
        const auto &p = *u.p;
        const int n   = int(u.keep.size());
        Eigen::MatrixXd &B = s.block.emplace_back(n, n);
        for (int r = 0; r < n; ++r)
          {
            const int c = u.keep[std::size_t(r)], i = u.first + r;
            const auto &pt = p.cand[std::size_t(c)].point;
            for (int t = 0; t < n; ++t)
              B(r, t) = p.W(c, u.keep[std::size_t(t)]) / u.weight;
            s.a[i]         = p.a[c];
            s.curvature[i] = p.curvature[c];
            s.q_build[i]   = p.q_build;
            s.ghat[i]      = p.ghat[c] + u.offset[c];
            s.D[i]         = p.D.size() ? p.D[c] / u.weight : 0.0;
            s.lambda0[i]   = p.load_build > 0 ? std::max(0.0, pt.force) * u.weight * torque / p.load_build : 0.0;
            s.sub.push_back(int(j));
            s.pair.push_back(pair_key(pt.tooth(1), pt.tooth(2), u.wrap));
          }
        q += u.weight * (p.load_build > 0 ? p.q_build * torque / p.load_build : p.q_build);
      }
    couple(s, sub);
    return q;
  }

  int SlicedPair::rotate(System &s, const std::vector<Sub> &sub, double torque, double q) const
  {
    // Newton on the curvature of the rigid gaps, the complementarity problem at each step.
    // The shared curvature Newton of the condensed re-solve, on the coupled operator.
    SlicedOperator op(s, sub);
    contact::CurvatureNewton cn = contact::curvature_newton(
      s.a, s.curvature, s.ghat, s.q_build, Eigen::VectorXd(), q, s.lambda0, false, 1e-10, "",
      [&](const Eigen::VectorXd &arm, const Eigen::VectorXd &gl, double, const Eigen::VectorXd &lambda0) {
        return contact::solve_ncp_spd(op, arm, gl, torque, lambda0, 400);
      });
    s.arm      = std::move(cn.arm);
    s.solution = std::move(cn.ncp);
    s.q        = cn.q;
    return cn.iterations;
  }

  bool SlicedPair::rescene(std::vector<Sub> &sub, const System &s, const LeadModification &lead) const
  {
    // The scene of each sub-slice at its own load per unit width (as the 2-D section's).
    bool changed = false;
    for (auto &u : sub)
      {
        double T = 0;
        for (int r = 0; r < int(u.keep.size()); ++r)
          T -= s.arm[u.first + r] * s.solution.lambda[u.first + r];
        const auto *p = &cycle_.at(u.g, std::clamp(T / u.weight, cycle_.torque_lo, cycle_.torque_hi));
        if (T > 0 && p != u.p)
          prepare(u, T / u.weight, lead), changed = true;
      }
    return changed;
  }

  bool SlicedPair::grow(std::vector<Sub> &sub, const System &s) const
  {
    // Candidates left out that would penetrate join the problem.
    const Eigen::VectorXd &lambda = s.solution.lambda;
    const Eigen::VectorXd shift = s.coupled() ? Eigen::VectorXd(s.dC * s.pair_torques(sub, lambda)) : Eigen::VectorXd();
    bool changed = false;
    for (auto &u : sub)
      {
        const auto &p = *u.p;
        std::vector<char> in(p.size(), 0);
        for (const int c : u.keep)
          in[std::size_t(c)] = 1;
        std::vector<int> add;
        const double dq = s.q - p.q_build;
        for (std::size_t c = 0; c < p.size(); ++c)
          {
            if (in[c])
              continue;
            const auto k = Eigen::Index(c);
            double g     = p.ghat[k] + u.offset[k] + p.a[k] * s.q + 0.5 * p.curvature[k] * dq * dq;
            for (int r = 0; r < int(u.keep.size()); ++r)
              g += p.W(k, u.keep[std::size_t(r)]) * lambda[u.first + r] / u.weight;
            const long key = pair_key(p.cand[c].point.tooth(1), p.cand[c].point.tooth(2), u.wrap);
            if (s.coupled() && s.pair_index.count(key))
              g -= p.a[k] * shift[s.index(u.slice, key)];
            if (g < 0)
              add.push_back(int(c));
          }
        if (!add.empty())
          {
            u.keep.insert(u.keep.end(), add.begin(), add.end());
            std::sort(u.keep.begin(), u.keep.end());
            changed = true;
          }
      }
    return changed;
  }

  void SlicedPair::check_coverage(const std::vector<Sub> &sub, const System &s) const
  {
    // The stored candidates must cover the contact (as contact::solve_condensed checks).
    for (const auto &u : sub)
      {
        const auto &p   = *u.p;
        const double dq = s.q - p.q_build;
        for (int r = 0; r < int(u.keep.size()); ++r)
          {
            const int c     = u.keep[std::size_t(r)];
            const auto &cnd = p.cand[std::size_t(c)];
            const double l  = s.solution.lambda[u.first + r];
            if (!cnd.smooth && l > 0 && std::abs(dq) > 1e-3 * std::abs(p.q_build))
              throw SolverError("stored candidate slave node " + std::to_string(cnd.point.node) + " of body " +
                                std::to_string(cnd.point.slave_body) +
                                ", whose gap is not smooth in the rotation, carries load away from the build "
                                "torque: build the condensed cycle nearer this load");
            if (!cnd.edge)
              continue;
            double dW = 0;
            for (int t = 0; t < int(u.keep.size()); ++t)
              dW += p.W(c, u.keep[std::size_t(t)]) *
                    (s.solution.lambda[u.first + t] / u.weight - p.cand[std::size_t(u.keep[std::size_t(t)])].point.force);
            const double approach = -(p.a[c] * dq + 0.5 * p.curvature[c] * dq * dq + dW);
            if (approach > 0.5 * p.search_distance)
              throw SolverError("the contact of slice " + std::to_string(u.slice + 1) +
                                " reaches the edge of the stored candidates: build the condensed cycle at a "
                                "higher torque or with a larger Contact/Search distance");
          }
      }
  }

  HelicalResult SlicedPair::solve(double phi1, double torque) const { return solve(phi1, torque, o_.lead); }

  HelicalResult SlicedPair::solve(double phi1, double torque, const LeadModification &lead) const
  {
    return evaluate(solve_forces(phi1, torque, lead));
  }

  SlicedPair::Solved SlicedPair::solve_forces(double phi1, double torque, const LeadModification &lead,
                                              const Solved *warm) const
  {
    check_profile(lead, o_.helix.face_width);
    require_greater("Solve/Torques", torque, 0.0, "N m");
    (void)cycle_.at(0, torque); // SolverError naming the cycle's torque range outside it
    auto st    = std::make_shared<State>();
    st->start  = Clock::now();
    st->phi1   = phi1, st->torque = torque, st->lead = lead;
    auto &sub  = st->sub;
    System &s  = st->s;
    const State *w = warm && warm->state && warm->state->phi1 == phi1 && warm->state->torque == torque
                       ? warm->state.get()
                       : nullptr;
    if (w)
      {
        sub = w->sub;
        for (auto &u : sub)
          u.offset = offsets(u, lead);
      }
    else
      {
        sub = subs(phi1);
        for (auto &u : sub)
          prepare(u, torque, lead);
      }
    int iterations = 0;
    try
      {
        for (int pass = 0;; ++pass)
          {
            if (pass == 12)
              throw SolverError("the scenes and candidate sets of the slices did not settle in 12 passes");
            double q = assemble(s, sub, torque);
            if (pass == 0 && w && w->s.m == s.m)
              s.lambda0 = w->s.solution.lambda, q = w->s.q;
            iterations += rotate(s, sub, torque, q);
            s.iterations = iterations;
            if ((pass < 6 && rescene(sub, s, lead)) || grow(sub, s))
              continue;
            break;
          }
        check_coverage(sub, s);
      }
    catch (const SolverError &e)
      {
        throw SolverError("helical position phi1 = " + to_string_g(phi1 / units::deg) + " deg, torque " +
                          to_string_g(torque) + " N m: " + e.what());
      }
    st->iterations = iterations;
    Solved out;
    out.force.assign(std::size_t(o_.slices), 0.0);
    for (const auto &u : sub)
      out.force[std::size_t(u.slice)] += sub_torque(u, s) / rb1_;
    out.state = std::move(st);
    return out;
  }

  HelicalResult SlicedPair::evaluate(const Solved &solved) const
  {
    const State &st = *solved.state;
    HelicalResult h = evaluate(st.phi1, st.torque, st.sub, st.s, st.lead);
    h.iterations    = st.iterations;
    h.seconds       = since(st.start);
    return h;
  }
} // namespace gearfem::helical
