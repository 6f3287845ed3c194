// The evaluation of a solved helical position (helical/slicing.h): each loaded sub-slice as
// its 2-D section at the sub-slice's load per unit face width (post's evaluation, root stress
// from the stored influence coefficients), then the slices, the contact lines and the pair.
#include "helical/slicing.h"
#include "base/number.h"
#include "helical/slicing_detail.h"

#include "base/errors.h"

#include <cmath>
#include <map>

namespace gearfem::helical
{
  namespace
  {
  } // namespace

  void SlicedPair::root_stresses(HelicalResult &h, const std::map<long, Eigen::VectorXd> &tau,
                                 const std::map<long, Eigen::VectorXd> sig[2], const std::vector<Sub> &sub,
                                 const System &s) const
  {
    const int N = o_.slices;
    // The fillet of a section bends under the load its section carries: the contact load plus
    // what the coupling brings from its neighbours, F = tau + K (dC tau) (tau uncoupled), at the
    // stress per unit load of the section's own contact (or of the nearest slice where the pair
    // carries a tenth of its largest load or more: a lightly loaded section's fillet stress comes
    // mostly from the neighbouring tooth's load).
    // The 3-D face (options().face) carries its sections' loads as they are: its correction
    // holds the plane condition too, which moves the deflection and not the stress.
    const bool beam = s.coupled() && !o_.face;
    Eigen::VectorXd tq, Fq;
    if (beam)
      {
        tq = s.pair_torques(sub, s.solution.lambda);
        const Eigen::VectorXd shift = s.dC * tq;
        Fq = tq;
        const int P = s.n_pairs;
        for (int k = 0; k < N; ++k)
          Fq.segment(k * P, P) += s.K[std::size_t(k)] * shift.segment(k * P, P);
      }
    for (const auto &[key, t] : tau)
      {
        Eigen::VectorXd F = t;
        if (beam)
          for (int k = 0; k < N; ++k)
            F[k] = Fq[s.index(k, key)];
        for (int g = 0; g < 2; ++g)
          {
            const auto it = sig[g].find(key);
            if (it == sig[g].end())
              continue;
            if (o_.face && o_.face_root && s.pair_index.count(key))
              {
                // The 3-D fillet: the load the section would carry to reach its stress.
                const int q = s.pair_index.at(key);
                std::vector<double> f(static_cast<std::size_t>(N)), r(static_cast<std::size_t>(N));
                for (int k = 0; k < N; ++k)
                  f[std::size_t(k)] = std::max(0.0, t[k]) / rb1_, r[std::size_t(k)] = s.radius[g](k, q);
                const std::vector<double> e = o_.face_root(g + 1, f, r);
                for (int k = 0; k < N; ++k)
                  F[k] = e[std::size_t(k)] * rb1_;
              }
            const Eigen::VectorXd &sg = it->second;
            const double floor = 0.1 * t.maxCoeff();
            for (int k = 0; k < N; ++k)
              {
                int near = -1;
                for (int d = 0; d < N && near < 0; ++d)
                  for (const int kk : {k - d, k + d})
                    if (near < 0 && kk >= 0 && kk < N && t[kk] >= floor && t[kk] > 0 && sg[kk] > 0)
                      near = kk;
                if (near < 0)
                  continue;
                const double stress = sg[near] / t[near] * std::max(0.0, F[k]);
                double &out = g == 0 ? h.slices[std::size_t(k)].root_stress_pinion : h.slices[std::size_t(k)].root_stress_gear;
                out = std::max(out, stress);
              }
          }
      }
  }

  double SlicedPair::sub_torque(const Sub &u, const System &s) const
  {
    double T = 0;
    for (int r = 0; r < int(u.keep.size()); ++r)
      T -= s.arm[u.first + r] * s.solution.lambda[u.first + r];
    return T;
  }

  HelicalResult SlicedPair::evaluate(double phi1, double torque, const std::vector<Sub> &sub, const System &s,
                                     const LeadModification &lead) const
  {
    const int N     = o_.slices;
    const double b  = o_.helix.face_width, dz = b / N;
    const auto zc   = slice_centres(b, N);
    const auto &lam = s.solution.lambda;
    HelicalResult h;
    h.phi1         = phi1;
    h.torque       = torque;
    h.rotation     = s.q;
    h.ste          = s.q * rb1_;
    h.normal_force = torque / rb1_;
    h.k_mesh       = h.ste > 0 ? h.normal_force / h.ste : 0.0;
    h.k_tangent    = s.solution.tangent / (rb1_ * rb1_);
    h.candidates   = s.m;
    h.slices.resize(std::size_t(N));
    for (int k = 0; k < N; ++k)
      {
        auto &r    = h.slices[std::size_t(k)];
        r.z        = zc[std::size_t(k)];
        r.phi1     = phi1 + o_.helix.roll_per_length * r.z;
        r.lead_gap = lead_gap(lead, r.z, b, o_.alpha_wt);
      }
    std::map<long, std::vector<double>> lines;
    // Per tooth pair and slice: contact torque, and the weighted fillet stresses of the sections.
    std::map<long, Eigen::VectorXd> tau, sig[2];
    for (int i = 0; i < s.m; ++i)
      tau.try_emplace(s.pair[std::size_t(i)], Eigen::VectorXd::Zero(N)).first->second[sub[std::size_t(s.sub[std::size_t(i)])].slice] -=
        s.arm[i] * lam[i];
    for (std::size_t j = 0; j < sub.size(); ++j)
      {
        const Sub &u  = sub[j];
        const auto &p = *u.p;
        const int n   = int(u.keep.size());
        const double T = sub_torque(u, s);
        SliceResult &sr = h.slices[std::size_t(u.slice)];
        sr.force += T / rb1_;
        if (!(T > 0))
          continue;
        // The 2-D section at this sub-slice's load per unit width: forces / weight.
        contact::CondensedSolution cs;
        auto &sol       = cs.solution;
        sol.converged   = true;
        sol.q           = s.q;
        sol.load        = T / u.weight;
        sol.geometry_iterations = 1;
        std::vector<int> at(p.size(), -1);
        for (int r = 0; r < n; ++r)
          at[std::size_t(u.keep[std::size_t(r)])] = u.first + r;
        const double dq       = s.q - p.q_build;
        const contact::Vec2 o1 = p.placement[0].centre;
        std::map<int, double> f[2];
        for (int r = 0; r < n; ++r)
          {
            const int c = u.keep[std::size_t(r)], i = u.first + r;
            contact::ContactPoint pt = p.cand[std::size_t(c)].point;
            pt.force    = lam[i] / u.weight;
            pt.gap      = s.solution.gap[i];
            pt.arm      = s.arm[i];
            pt.pressure = 0;
            for (const auto &[jj, coef] : p.pressure[std::size_t(c)])
              if (at[std::size_t(jj)] >= 0)
                pt.pressure += coef * lam[at[std::size_t(jj)]] / u.weight;
            contact::turn_body1(pt, o1, dq);
            if (s.solution.active[std::size_t(i)])
              ++sol.n_active;
            sol.max_penetration = std::max(sol.max_penetration, -pt.gap);
            sol.points.push_back(pt);
            if (lam[i] != 0)
              for (int bb = 0; bb < 2; ++bb)
                for (const auto &[ui, v] : p.B[bb][std::size_t(c)])
                  f[bb][ui] += lam[i] / u.weight * v;
          }
        for (int bb = 0; bb < 2; ++bb)
          cs.universe_forces[bb].assign(f[bb].begin(), f[bb].end());
        const auto e = resolver_.evaluate(u.g, p, T / u.weight, std::move(cs), o_.post);
        const double w = u.weight * N; // share of the slice
        sr.p_max += w * e.result.p_max;
        for (const auto &tp : e.result.pairs)
          {
            const long key = long(wrap_index(tp.pinion_tooth - u.wrap, z_[0])) * z_[1] + wrap_index(tp.gear_tooth + u.wrap, z_[1]);
            for (int g = 0; g < 2; ++g)
              sig[g].try_emplace(key, Eigen::VectorXd::Zero(N)).first->second[u.slice] +=
                w * (g == 0 ? tp.root_stress_pinion : tp.root_stress_gear);
            auto &line     = lines.try_emplace(key, std::vector<double>(std::size_t(N), 0.0)).first->second;
            line[std::size_t(u.slice)] += tp.force * u.weight / dz;
          }
      }
    root_stresses(h, tau, sig, sub, s);
    const double mean = h.normal_force / b;
    for (auto &sr : h.slices)
      {
        sr.load_per_width      = sr.force / dz;
        h.k_h_beta             = std::max(h.k_h_beta, sr.load_per_width / mean);
        h.p_max                = std::max(h.p_max, sr.p_max);
        h.root_stress_pinion   = std::max(h.root_stress_pinion, sr.root_stress_pinion);
        h.root_stress_gear     = std::max(h.root_stress_gear, sr.root_stress_gear);
      }
    for (auto &[key, w] : lines)
      {
        ContactLine l;
        l.pinion_tooth   = int(key / z_[1]);
        l.gear_tooth     = int(key % z_[1]);
        l.load_per_width = std::move(w);
        h.lines.push_back(std::move(l));
        ++h.n_pairs;
      }
    return h;
  }
} // namespace gearfem::helical
