// The helical pair on the condensed cycle of its transverse section (helical/slicing.h).
#include "helical/slicing.h"
#include "helical/slicing_detail.h"

#include "base/errors.h"
#include "base/units.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <set>

namespace gearfem::helical
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
    double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
    int mod(long a, long n) { return int(((a % n) + n) % n); }
    long floor_div(long a, long n) { return a >= 0 ? a / n : -((-a + n - 1) / n); }
    /// Candidates first taken into the coupled problem: loaded at the build, or within this
    /// gap of contact there; the others join where they would penetrate.
    constexpr double initial_gap = 10e-6;

    /// The symmetric complementarity problem g = ghat + a q + W lambda under load control
    /// (-a^T lambda = T), primal-dual active set (as contact::solve_ncp, with the bordered
    /// system solved by Cholesky of the active block: W is symmetric positive definite).
    Pdas pdas(const Eigen::MatrixXd &W, const Eigen::VectorXd &D, const Eigen::VectorXd &a, const Eigen::VectorXd &ghat,
              double T, const Eigen::VectorXd &lambda0, int max_iterations)
    {
      const int m = int(W.rows());
      Pdas r;
      r.lambda = Eigen::VectorXd::Zero(m);
      std::vector<char> active(std::size_t(m), 0);
      bool any = false;
      for (int k = 0; k < m; ++k)
        if (lambda0[k] > 0)
          active[std::size_t(k)] = 1, any = true;
      if (!any)
        {
          int best = -1;
          double qmin = 1e300;
          for (int k = 0; k < m; ++k)
            if (a[k] < 0 && ghat[k] / -a[k] < qmin)
              qmin = ghat[k] / -a[k], best = k;
          if (best >= 0)
            active[std::size_t(best)] = 1;
        }
      std::set<std::vector<char>> seen;
      for (r.iterations = 1; r.iterations <= max_iterations; ++r.iterations)
        {
          std::vector<int> A;
          for (int k = 0; k < m; ++k)
            if (active[std::size_t(k)])
              A.push_back(k);
          const int n = int(A.size());
          if (n == 0)
            {
              r.why = "no candidate can close its gap as the pinion turns (no contact)";
              return r;
            }
          Eigen::MatrixXd M(n, n);
          Eigen::VectorXd gA(n), aA(n);
          for (int i = 0; i < n; ++i)
            {
              for (int j = 0; j < n; ++j)
                M(i, j) = W(A[i], A[j]);
              M(i, i) += D[A[i]];
              gA[i] = ghat[A[i]], aA[i] = a[A[i]];
            }
          const Eigen::LLT<Eigen::MatrixXd> llt(M);
          if (llt.info() != Eigen::Success)
            {
              r.why = "the coupled operator is not positive definite on the active set";
              return r;
            }
          const Eigen::VectorXd x1 = llt.solve(gA), x2 = llt.solve(aA);
          const double den = aA.dot(x2);
          if (!(den > 0))
            {
              r.why = "the active candidates cannot carry the torque";
              return r;
            }
          r.q = (T - aA.dot(x1)) / den;
          r.lambda.setZero();
          for (int i = 0; i < n; ++i)
            r.lambda[A[i]] = -x1[i] - x2[i] * r.q;
          r.gap = ghat + a * r.q + W * r.lambda;
          std::vector<char> next(std::size_t(m), 0);
          for (int k = 0; k < m; ++k)
            next[std::size_t(k)] = r.lambda[k] - r.gap[k] / W(k, k) > 0;
          if (next == active)
            {
              r.ok      = true;
              r.active  = active;
              r.tangent = den;
              return r;
            }
          if (!seen.insert(active).second)
            {
              r.why = "the active set cycles";
              return r;
            }
          active = next;
        }
      r.why = "the active set did not settle in " + std::to_string(max_iterations) + " iterations";
      return r;
    }
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
              s.g      = std::size_t(mod(gi, G));
              s.wrap   = floor_div(gi, G);
              s.weight = w / N;
              out.push_back(std::move(s));
            }
      }
    return out;
  }

  double SlicedPair::pair_compliance(const contact::CondensedPosition &p, int t1, int t2) const
  {
    const auto key = std::make_tuple(static_cast<const void *>(&p), t1, t2);
    if (const auto it = kappa_.find(key); it != kappa_.end())
      return it->second;
    std::vector<int> idx;
    for (std::size_t c = 0; c < p.size(); ++c)
      if (p.cand[c].point.tooth(1) == t1 && p.cand[c].point.tooth(2) == t2)
        idx.push_back(int(c));
    const int n = int(idx.size());
    Eigen::MatrixXd Wp(n, n);
    Eigen::VectorXd arm(n);
    for (int i = 0; i < n; ++i)
      {
        arm[i] = p.a[idx[std::size_t(i)]];
        for (int j = 0; j < n; ++j)
          Wp(i, j) = p.W(idx[std::size_t(i)], idx[std::size_t(j)]);
      }
    // Minimum over distributions of the pair's torque of lambda^T W lambda / T^2.
    const double kappa = n > 0 ? 1.0 / arm.dot(Wp.ldlt().solve(arm)) : 0.0;
    kappa_[key] = kappa;
    return kappa;
  }

  void SlicedPair::couple(System &s, const std::vector<Sub> &sub) const
  {
    const double l = o_.coupling_length;
    if (!(l > 0))
      return;
    const int N     = o_.slices;
    const double dz = o_.helix.face_width / N;
    // Per tooth pair and slice: sum of weights and of weight x stiffness per unit width of
    // the sub-slices in which the pair has candidates.
    std::map<long, std::pair<Eigen::VectorXd, Eigen::VectorXd>> acc;
    std::set<std::pair<long, int>> seen;
    for (int i = 0; i < s.m; ++i)
      {
        const int j = s.sub[std::size_t(i)];
        if (!seen.insert({s.pair[std::size_t(i)], j}).second)
          continue;
        const Sub &u = sub[std::size_t(j)];
        const auto &pt = u.p->cand[std::size_t(u.keep[std::size_t(i - u.first)])].point;
        const double kappa = pair_compliance(*u.p, pt.tooth(1), pt.tooth(2));
        auto &[w, k] = acc.try_emplace(s.pair[std::size_t(i)], Eigen::VectorXd::Zero(N), Eigen::VectorXd::Zero(N))
                         .first->second;
        if (kappa > 0)
          w[u.slice] += u.weight, k[u.slice] += u.weight / (o_.helix.face_width * kappa);
      }
    for (const auto &[key, wk] : acc)
      {
        const auto &[w, ksum] = wk;
        Eigen::VectorXd K = Eigen::VectorXd::Zero(N);
        std::vector<int> present;
        for (int k = 0; k < N; ++k)
          if (w[k] > 0)
            K[k] = ksum[k] / w[k] * dz, present.push_back(k);
        if (present.empty())
          continue;
        for (int k = 0; k < N; ++k) // the tooth is there where the pair does not touch: nearest stiffness
          if (!(w[k] > 0))
            {
              int best = present.front();
              for (const int p : present)
                if (std::abs(p - k) < std::abs(best - k))
                  best = p;
              K[k] = K[best];
            }
        Eigen::MatrixXd A = K.asDiagonal();
        for (int k = 0; k + 1 < N; ++k)
          {
            const double G = l * l * std::sqrt(K[k] * K[k + 1]) / (dz * dz);
            A(k, k) += G, A(k + 1, k + 1) += G, A(k, k + 1) -= G, A(k + 1, k) -= G;
          }
        Eigen::MatrixXd dC = A.ldlt().solve(Eigen::MatrixXd::Identity(N, N));
        for (int k = 0; k < N; ++k)
          dC(k, k) -= 1.0 / K[k];
        s.dC[key] = std::move(dC);
        s.K[key]  = K;
      }
    std::map<long, std::vector<int>> members;
    for (int i = 0; i < s.m; ++i)
      members[s.pair[std::size_t(i)]].push_back(i);
    for (const auto &[key, idx] : members)
      {
        const auto it = s.dC.find(key);
        if (it == s.dC.end())
          continue;
        const Eigen::MatrixXd &dC = it->second;
        for (const int i : idx)
          for (const int j : idx)
            s.W(i, j) += s.a[i] * s.a[j] *
                         dC(sub[std::size_t(s.sub[std::size_t(i)])].slice, sub[std::size_t(s.sub[std::size_t(j)])].slice);
      }
  }

  HelicalResult SlicedPair::solve(double phi1, double torque) const
  {
    require_greater("Solve/Torques", torque, 0.0, "N m");
    const auto t0  = Clock::now();
    const int N    = o_.slices;
    const double b = o_.helix.face_width;
    const auto zc  = slice_centres(b, N);
    const auto where = [&](const std::string &what) {
      return "helical position phi1 = " + to_string_g(phi1 / units::deg) + " deg, torque " + to_string_g(torque) +
             " N m: " + what;
    };
    const auto clamp_load = [&](double T) { return std::clamp(T, cycle_.torque_lo, cycle_.torque_hi); };
    const auto pair_key = [&](int t1, int t2, long wrap) {
      return long(mod(t1 - wrap, z_[0])) * z_[1] + mod(t2 + wrap, z_[1]);
    };
    std::vector<Sub> sub = subs(phi1);
    const auto prepare = [&](Sub &u, double load) {
      u.p = &cycle_.at(u.g, clamp_load(load));
      u.offset = resolver_.offsets(*u.p).array() + lead_gap(o_.lead, zc[std::size_t(u.slice)], b, o_.alpha_wt);
      u.keep.clear();
      for (std::size_t c = 0; c < u.p->size(); ++c)
        if (u.p->cand[c].point.force > 0 || u.p->cand[c].point.gap < initial_gap)
          u.keep.push_back(int(c));
    };
    for (auto &u : sub)
      prepare(u, torque);

    System s;
    int iterations = 0;
    for (int pass = 0;; ++pass)
      {
        if (pass == 12)
          throw SolverError(where("the scenes and candidate sets of the slices did not settle in 12 passes"));
        // Assemble the coupled problem.
        s   = System();
        s.m = 0;
        for (auto &u : sub)
          u.first = s.m, s.m += int(u.keep.size());
        const int m = s.m;
        s.W = Eigen::MatrixXd::Zero(m, m);
        s.a.resize(m), s.curvature.resize(m), s.q_build.resize(m), s.ghat.resize(m), s.D.resize(m), s.lambda0.resize(m);
        double q = 0;
        for (std::size_t j = 0; j < sub.size(); ++j)
          {
            const Sub &u = sub[j];
            const auto &p = *u.p;
            const int n   = int(u.keep.size());
            for (int r = 0; r < n; ++r)
              {
                const int c = u.keep[std::size_t(r)], i = u.first + r;
                for (int t = 0; t < n; ++t)
                  s.W(i, u.first + t) = p.W(c, u.keep[std::size_t(t)]) / u.weight;
                s.a[i]         = p.a[c];
                s.curvature[i] = p.curvature[c];
                s.q_build[i]   = p.q_build;
                s.ghat[i]      = p.ghat[c] + u.offset[c];
                s.D[i]         = p.D.size() ? p.D[c] / u.weight : 0.0;
                s.lambda0[i]   = p.load_build > 0 ? std::max(0.0, p.cand[std::size_t(c)].point.force) * u.weight *
                                                      torque / p.load_build :
                                                    0.0;
                s.sub.push_back(int(j));
                s.pair.push_back(pair_key(p.cand[std::size_t(c)].point.tooth(1), p.cand[std::size_t(c)].point.tooth(2),
                                          u.wrap));
              }
            q += u.weight * (p.load_build > 0 ? p.q_build * torque / p.load_build : p.q_build);
          }
        couple(s, sub);
        // Newton on the curvature of the rigid gaps, the complementarity problem at each step.
        std::vector<char> prev;
        bool settled = false;
        Eigen::VectorXd lambda0 = s.lambda0;
        for (int it = 0; it < 30 && !settled; ++it)
          {
            const Eigen::VectorXd dq = Eigen::VectorXd::Constant(m, q) - s.q_build;
            s.arm = s.a + s.curvature.cwiseProduct(dq);
            const Eigen::VectorXd gl =
              s.ghat + s.a * q + 0.5 * s.curvature.cwiseProduct(dq.cwiseProduct(dq)) - s.arm * q;
            s.solution = pdas(s.W, s.D, s.arm, gl, torque, lambda0, 400);
            iterations += s.solution.iterations;
            if (!s.solution.ok)
              throw SolverError(where(s.solution.why));
            constexpr double q_floor = 8 * std::numeric_limits<double>::epsilon();
            settled = it > 0 && s.solution.active == prev &&
                      std::abs(s.solution.q - q) <= 1e-10 * std::abs(s.solution.q) + q_floor;
            prev    = s.solution.active;
            lambda0 = s.solution.lambda;
            q       = s.solution.q;
          }
        if (!settled)
          throw SolverError(where("the rotation did not settle in 30 curvature updates"));
        s.q          = q;
        s.iterations = iterations;
        const Eigen::VectorXd &lambda = s.solution.lambda;
        bool changed = false;
        // The scene of each sub-slice at its own load per unit width (as the 2-D section's).
        if (pass < 6)
          for (auto &u : sub)
            {
              double T = 0;
              for (int r = 0; r < int(u.keep.size()); ++r)
                T -= s.arm[u.first + r] * lambda[u.first + r];
              const auto *p = &cycle_.at(u.g, clamp_load(T / u.weight));
              if (T > 0 && p != u.p)
                prepare(u, T / u.weight), changed = true;
            }
        if (changed)
          continue;
        // Candidates left out that would penetrate join the problem.
        std::map<long, Eigen::VectorXd> tau;
        for (int i = 0; i < m; ++i)
          if (s.dC.count(s.pair[std::size_t(i)]))
            {
              auto &t = tau.try_emplace(s.pair[std::size_t(i)], Eigen::VectorXd::Zero(N)).first->second;
              t[sub[std::size_t(s.sub[std::size_t(i)])].slice] -= s.a[i] * lambda[i];
            }
        for (auto &u : sub)
          {
            const auto &p = *u.p;
            std::vector<char> in(p.size(), 0);
            for (const int c : u.keep)
              in[std::size_t(c)] = 1;
            std::vector<int> add;
            for (std::size_t c = 0; c < p.size(); ++c)
              {
                if (in[c])
                  continue;
                const double dq = q - p.q_build;
                double g = p.ghat[Eigen::Index(c)] + u.offset[Eigen::Index(c)] + p.a[Eigen::Index(c)] * q +
                           0.5 * p.curvature[Eigen::Index(c)] * dq * dq;
                for (int r = 0; r < int(u.keep.size()); ++r)
                  g += p.W(Eigen::Index(c), u.keep[std::size_t(r)]) * lambda[u.first + r] / u.weight;
                const long key = pair_key(p.cand[c].point.tooth(1), p.cand[c].point.tooth(2), u.wrap);
                if (const auto it = s.dC.find(key); it != s.dC.end())
                  g -= p.a[Eigen::Index(c)] * it->second.row(u.slice).dot(tau.at(key));
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
        if (!changed)
          break;
      }
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
              throw SolverError(where("stored candidate slave node " + std::to_string(cnd.point.node) + " of body " +
                                      std::to_string(cnd.point.slave_body) +
                                      ", whose gap is not smooth in the rotation, carries load away from the build "
                                      "torque: build the condensed cycle nearer this load"));
            if (!cnd.edge)
              continue;
            double dW = 0;
            for (int t = 0; t < int(u.keep.size()); ++t)
              dW += p.W(c, u.keep[std::size_t(t)]) *
                    (s.solution.lambda[u.first + t] / u.weight - p.cand[std::size_t(u.keep[std::size_t(t)])].point.force);
            const double approach = -(p.a[c] * dq + 0.5 * p.curvature[c] * dq * dq + dW);
            if (approach > 0.5 * p.search_distance)
              throw SolverError(where("the contact of slice " + std::to_string(u.slice + 1) +
                                      " reaches the edge of the stored candidates: build the condensed cycle at a "
                                      "higher torque or with a larger Contact/Search distance"));
          }
      }
    HelicalResult h = evaluate(phi1, torque, sub, s);
    h.iterations    = iterations;
    h.seconds       = since(t0);
    return h;
  }
} // namespace gearfem::helical
