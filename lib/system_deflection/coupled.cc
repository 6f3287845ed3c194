#include "system_deflection/coupled.h"

#include "base/errors.h"
#include "base/units.h"
#include "helical/helix.h"

#include <algorithm>
#include <cmath>

namespace gearfem::system_deflection
{
  namespace
  {
    /// The profile part of `lead` alone at z (the other modifications left out).
    double profile_at(const helical::LeadModification &lead, double z, double b)
    {
      helical::LeadModification only;
      only.profile_z = lead.profile_z, only.profile_gap = lead.profile_gap;
      return helical::lead_gap(only, z, b, 0.3);
    }

    /// `lead` with `extra` [m] added to its profile at the slice centres z.
    helical::LeadModification with_profile(helical::LeadModification lead, const std::vector<double> &z,
                                           const std::vector<double> &extra, double b)
    {
      std::vector<double> g(z.size());
      for (std::size_t k = 0; k < z.size(); ++k)
        g[k] = profile_at(lead, z[k], b) + extra[k];
      lead.profile_z = z, lead.profile_gap = std::move(g);
      return lead;
    }

    double max_abs_diff(const Eigen::VectorXd &a, const Eigen::VectorXd &b) { return (a - b).cwiseAbs().maxCoeff(); }
  } // namespace

  double LeadCorrection::at(double z, double b) const
  {
    const auto p = [&](double s) { return slope * 0.5 * (s + 1) + crowning * (s * s - 1); };
    double lo = std::min(p(-1), p(1));
    if (crowning > 0)
      {
        const double s = -slope / (4 * crowning);
        if (s > -1 && s < 1)
          lo = std::min(lo, p(s));
      }
    return p(std::clamp(2 * z / b, -1.0, 1.0)) - lo;
  }

  CoupledPair::CoupledPair(const helical::SlicedPair &pair, shafts::System system, shafts::MeshLayout mesh,
                           CoupledOptions options)
    : pair_(pair), system_(std::move(system)), mesh_(mesh), options_(options)
  {
    const auto &o  = pair_.options();
    const double b = o.helix.face_width;
    if (std::abs(mesh_.face_width - b) > 1e-9 * b)
      throw InputError("mesh face width", mm_text(mesh_.face_width), "the pair's face width " + mm_text(b));
    if (!(options_.tolerance > 0) || options_.max_iterations < 1)
      throw InputError("coupling tolerance", to_string_g(options_.tolerance), "> 0 with at least one iteration");
    mesh_.validate(system_);
    z_  = helical::slice_centres(b, o.slices);
    dz_.assign(z_.size(), b / double(o.slices));
    const int N = int(z_.size());
    std::vector<std::vector<shafts::PointLoad>> cases;
    for (int j = 0; j < N; ++j)
      {
        std::vector<double> f(std::size_t(N), 0.0);
        f[std::size_t(j)] = 1.0;
        cases.push_back(loads(f));
      }
    const auto sols = shafts::solve_cases(system_, cases);
    std::vector<double> zf;
    for (const double z : z_)
      zf.push_back(z + 0.5 * b);
    A_.resize(N, N);
    for (int j = 0; j < N; ++j)
      {
        const auto d = shafts::mesh_approach(system_, sols[std::size_t(j)], mesh_, zf);
        for (int k = 0; k < N; ++k)
          A_(k, j) = d[std::size_t(k)];
      }
  }

  std::vector<shafts::PointLoad> CoupledPair::loads(const std::vector<double> &force) const
  {
    const double b = mesh_.face_width;
    std::vector<double> zf, w;
    for (std::size_t k = 0; k < z_.size(); ++k)
      zf.push_back(z_[k] + 0.5 * b), w.push_back(force[k] / dz_[k]);
    return shafts::mesh_loads(system_, mesh_, zf, dz_, w);
  }

  CoupledResult CoupledPair::solve(double phi1, double torque, const helical::LeadModification &lead,
                                   const std::vector<double> &start) const
  {
    const double b = mesh_.face_width;
    const int N    = int(z_.size());
    Eigen::VectorXd g = Eigen::VectorXd::Zero(N);
    if (int(start.size()) == N)
      for (int k = 0; k < N; ++k)
        g[k] = start[std::size_t(k)];
    CoupledResult r;
    r.z = z_;
    Eigen::VectorXd prev_step;
    double omega = 1;
    helical::SlicedPair::Solved solved;
    for (int it = 1;; ++it)
      {
        // The slices' forces only: the post-processing is for the converged mismatch.
        solved = pair_.solve_forces(phi1, torque, with_profile(lead, z_, std::vector<double>(g.data(), g.data() + N), b),
                                    it > 1 ? &solved : nullptr);
        const Eigen::VectorXd F = Eigen::Map<const Eigen::VectorXd>(solved.force.data(), N);
        const Eigen::VectorXd delta = A_ * F;
        const Eigen::VectorXd g_new = Eigen::VectorXd::Constant(N, delta.maxCoeff()) - delta;
        r.residual   = max_abs_diff(g_new, g);
        r.iterations = it;
        r.approach.assign(delta.data(), delta.data() + N);
        r.mean_approach = delta.mean();
        if (r.residual <= options_.tolerance)
          {
            r.helical = pair_.evaluate(solved);
            r.mismatch.assign(g.data(), g.data() + N);
            return r;
          }
        if (it == options_.max_iterations)
          throw SolverError("shaft coupling at phi1 = " + to_string_g(phi1 / units::deg) + " deg, " + to_string_g(torque) +
                            " N m: the mismatch did not settle in " + std::to_string(it) + " iterations (last change " +
                            to_string_g(r.residual / units::um) + " um, tolerance " +
                            to_string_g(options_.tolerance / units::um) + " um)");
        // Aitken's relaxation of the fixed-point step (Irons & Tuck 1969).
        const Eigen::VectorXd step = g_new - g;
        if (prev_step.size() == N)
          {
            const Eigen::VectorXd d = step - prev_step;
            const double dd         = d.squaredNorm();
            if (dd > 0)
              omega = std::clamp(-omega * prev_step.dot(d) / dd, 0.05, 2.0);
          }
        prev_step = step;
        g += omega * step;
      }
  }

  shafts::Solution CoupledPair::shafts_under(const CoupledResult &r) const
  {
    std::vector<double> F;
    for (const auto &s : r.helical.slices)
      F.push_back(s.force);
    return shafts::solve(system_, loads(F));
  }

  LeadCorrection CoupledPair::correction(const std::vector<CoupledResult> &results) const
  {
    if (results.empty())
      throw InputError("lead correction", "no positions", "the coupled results of at least one position");
    const int N    = int(z_.size());
    const double b = mesh_.face_width;
    Eigen::VectorXd g = Eigen::VectorXd::Zero(N);
    for (const auto &r : results)
      for (int k = 0; k < N; ++k)
        g[k] += r.mismatch[std::size_t(k)] / double(results.size());
    LeadCorrection c;
    if (N < 3)
      {
        if (N == 2)
          c.slope = -(g[1] - g[0]) * b / (z_[1] - z_[0]);
        return c;
      }
    // g ~ c0 + c1 s + c2 s^2, s = 2 z / b; the correction cancels c1 s + c2 s^2.
    Eigen::MatrixXd V(N, 3);
    for (int k = 0; k < N; ++k)
      {
        const double s = 2 * z_[std::size_t(k)] / b;
        V(k, 0) = 1, V(k, 1) = s, V(k, 2) = s * s;
      }
    const Eigen::Vector3d p = V.colPivHouseholderQr().solve(g);
    c.slope    = -2 * p[1];
    c.crowning = -p[2];
    return c;
  }

  helical::LeadModification CoupledPair::corrected(helical::LeadModification lead, const LeadCorrection &c) const
  {
    std::vector<double> extra;
    for (const double z : z_)
      extra.push_back(c.at(z, mesh_.face_width));
    return with_profile(std::move(lead), z_, extra, mesh_.face_width);
  }

  DesignedCorrection design_correction(const CoupledPair &pair, const std::vector<double> &phi1, double torque,
                                       const helical::LeadModification &lead, double tolerance)
  {
    if (phi1.empty())
      throw InputError("lead correction", "no positions", "at least one position of the cycle");
    DesignedCorrection d;
    for (int n = 1;; ++n)
      {
        const auto with = pair.corrected(lead, d.correction);
        d.results.clear();
        std::vector<double> start;
        for (const double phi : phi1)
          {
            d.results.push_back(pair.solve(phi, torque, with, start));
            start = d.results.back().mismatch;
          }
        const LeadCorrection next = pair.correction(d.results);
        d.iterations = n;
        d.change     = std::max(std::abs(next.slope - d.correction.slope), std::abs(next.crowning - d.correction.crowning));
        if (d.change <= tolerance)
          return d;
        if (n == 20)
          throw SolverError("lead correction at " + to_string_g(torque) + " N m: slope and crowning did not settle in 20 "
                            "corrections (last change " + to_string_g(d.change / units::um) + " um)");
        d.correction = next;
      }
  }
} // namespace gearfem::system_deflection
