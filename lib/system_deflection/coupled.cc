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

    double max_abs_diff(const Eigen::VectorXd &a, const Eigen::VectorXd &b) { return (a - b).cwiseAbs().maxCoeff(); }
  } // namespace

  helical::LeadModification with_profile(helical::LeadModification lead, const std::vector<double> &z,
                                         const std::vector<double> &extra, double b)
  {
    std::vector<double> g(z.size());
    for (std::size_t k = 0; k < z.size(); ++k)
      g[k] = profile_at(lead, z[k], b) + extra[k];
    lead.profile_z = z, lead.profile_gap = std::move(g);
    return lead;
  }

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

  CoupledTrain::CoupledTrain(std::vector<TrainMesh> meshes, shafts::System system, CoupledOptions options)
    : meshes_(std::move(meshes)), system_(std::move(system)), options_(options)
  {
    if (meshes_.empty())
      throw InputError("gear train meshes", "none", "at least one mesh");
    if (!(options_.tolerance > 0) || options_.max_iterations < 1)
      throw InputError("coupling tolerance", to_string_g(options_.tolerance), "> 0 with at least one iteration");
    int N = 0;
    for (auto &m : meshes_)
      {
        const auto &o  = m.pair->options();
        const double b = o.helix.face_width;
        if (std::abs(m.mesh.face_width - b) > 1e-9 * b)
          throw InputError("mesh face width", mm_text(m.mesh.face_width), "the pair's face width " + mm_text(b));
        m.mesh.validate(system_);
        z_.push_back(helical::slice_centres(b, o.slices));
        dz_.emplace_back(z_.back().size(), b / double(o.slices));
        first_.push_back(N);
        N += int(z_.back().size());
      }
    // One load case per slice of every mesh: the influence of its unit force on every slice.
    std::vector<std::vector<shafts::PointLoad>> cases;
    for (std::size_t m = 0; m < meshes_.size(); ++m)
      for (std::size_t j = 0; j < z_[m].size(); ++j)
        {
          std::vector<std::vector<double>> f(meshes_.size());
          for (std::size_t q = 0; q < meshes_.size(); ++q)
            f[q].assign(z_[q].size(), 0.0);
          f[m][j] = 1.0;
          cases.push_back(loads(f));
        }
    const auto sols = shafts::solve_cases(system_, cases);
    A_.resize(N, N), Ae_.resize(N, N), At_.resize(N, N);
    for (int c = 0; c < N; ++c)
      for (std::size_t m = 0; m < meshes_.size(); ++m)
        {
          std::vector<double> zf;
          for (const double z : z_[m])
            zf.push_back(z + 0.5 * meshes_[m].mesh.face_width);
          const auto d = shafts::mesh_approach(system_, sols[std::size_t(c)], meshes_[m].mesh, zf);
          const auto o = shafts::mesh_axes_offset(system_, sols[std::size_t(c)], meshes_[m].mesh, zf);
          for (std::size_t k = 0; k < d.size(); ++k)
            A_(first_[m] + int(k), c) = d[k], Ae_(first_[m] + int(k), c) = o[k][0], At_(first_[m] + int(k), c) = o[k][1];
        }
  }

  std::vector<shafts::PointLoad> CoupledTrain::loads(const std::vector<std::vector<double>> &force) const
  {
    std::vector<shafts::PointLoad> out;
    for (std::size_t m = 0; m < meshes_.size(); ++m)
      {
        const double b = meshes_[m].mesh.face_width;
        std::vector<double> zf, w;
        for (std::size_t k = 0; k < z_[m].size(); ++k)
          zf.push_back(z_[m][k] + 0.5 * b), w.push_back(force[m][k] / dz_[m][k]);
        const auto l = shafts::mesh_loads(system_, meshes_[m].mesh, zf, dz_[m], w);
        out.insert(out.end(), l.begin(), l.end());
      }
    return out;
  }

  std::vector<CoupledResult> CoupledTrain::solve(const std::vector<double> &phi1, const std::vector<double> &torque,
                                                 const std::vector<helical::LeadModification> &lead,
                                                 const std::vector<std::vector<double>> &start) const
  {
    const std::size_t M = meshes_.size();
    if (phi1.size() != M || torque.size() != M || lead.size() != M)
      throw InputError("gear train positions", std::to_string(phi1.size()), "one roll angle, torque and lead per mesh");
    const int N = int(A_.rows());
    Eigen::VectorXd g = Eigen::VectorXd::Zero(N);
    if (start.size() == M)
      for (std::size_t m = 0; m < M; ++m)
        if (start[m].size() == z_[m].size())
          for (std::size_t k = 0; k < z_[m].size(); ++k)
            g[first_[m] + int(k)] = start[m][k];
    std::vector<CoupledResult> r(M);
    std::vector<helical::SlicedPair::Solved> solved(M);
    Eigen::VectorXd prev_step;
    double omega = 1;
    for (int it = 1;; ++it)
      {
        // The slices' forces only: the post-processing is for the converged mismatch.
        Eigen::VectorXd F(N);
        for (std::size_t m = 0; m < M; ++m)
          {
            const int n  = int(z_[m].size());
            const auto gm = std::vector<double>(g.data() + first_[m], g.data() + first_[m] + n);
            solved[m] = meshes_[m].pair->solve_forces(
              phi1[m], torque[m], with_profile(lead[m], z_[m], gm, meshes_[m].mesh.face_width),
              it > 1 ? &solved[m] : nullptr);
            F.segment(first_[m], n) = Eigen::Map<const Eigen::VectorXd>(solved[m].force.data(), n);
          }
        const Eigen::VectorXd delta = A_ * F;
        Eigen::VectorXd g_new(N);
        for (std::size_t m = 0; m < M; ++m)
          {
            const int n = int(z_[m].size());
            const auto d = delta.segment(first_[m], n);
            g_new.segment(first_[m], n) = Eigen::VectorXd::Constant(n, d.maxCoeff()) - d;
          }
        const double residual = max_abs_diff(g_new, g);
        for (std::size_t m = 0; m < M; ++m)
          {
            const int n = int(z_[m].size());
            r[m].z = z_[m], r[m].iterations = it, r[m].residual = residual;
            r[m].approach.assign(delta.data() + first_[m], delta.data() + first_[m] + n);
            r[m].mean_approach = delta.segment(first_[m], n).mean();
          }
        if (residual <= options_.tolerance)
          {
            const Eigen::VectorXd oe = Ae_ * F, ot = At_ * F;
            for (std::size_t m = 0; m < M; ++m)
              {
                const int n = int(z_[m].size());
                r[m].axes_e.assign(oe.data() + first_[m], oe.data() + first_[m] + n);
                r[m].axes_t.assign(ot.data() + first_[m], ot.data() + first_[m] + n);
                r[m].helical = meshes_[m].pair->evaluate(solved[m]);
                r[m].mismatch.assign(g.data() + first_[m], g.data() + first_[m] + int(z_[m].size()));
              }
            return r;
          }
        if (it == options_.max_iterations)
          throw SolverError("shaft coupling at phi1 = " + to_string_g(phi1[0] / units::deg) + " deg, " +
                            to_string_g(torque[0]) + " N m: the mismatch did not settle in " + std::to_string(it) +
                            " iterations (last change " + to_string_g(residual / units::um) + " um, tolerance " +
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

  shafts::Solution CoupledTrain::shafts_under(const std::vector<CoupledResult> &r) const
  {
    if (r.size() != meshes_.size())
      throw InputError("gear train results", std::to_string(r.size()), "one per mesh");
    std::vector<std::vector<double>> F(r.size());
    for (std::size_t m = 0; m < r.size(); ++m)
      for (const auto &s : r[m].helical.slices)
        F[m].push_back(s.force);
    return shafts::solve(system_, loads(F));
  }

  CoupledPair::CoupledPair(const helical::SlicedPair &pair, shafts::System system, shafts::MeshLayout mesh,
                           CoupledOptions options)
    : train_({TrainMesh{&pair, mesh}}, std::move(system), options)
  {}

  CoupledResult CoupledPair::solve(double phi1, double torque, const helical::LeadModification &lead,
                                   const std::vector<double> &start) const
  {
    return train_.solve({phi1}, {torque}, {lead}, start.empty() ? std::vector<std::vector<double>>{} :
                                                                  std::vector<std::vector<double>>{start})
      .front();
  }

  LeadCorrection fit_correction(const std::vector<double> &z, const std::vector<double> &g, double b)
  {
    const int N = int(z.size());
    LeadCorrection c;
    if (N < 3)
      {
        if (N == 2)
          c.slope = -(g[1] - g[0]) * b / (z[1] - z[0]);
        return c;
      }
    // g ~ c0 + c1 s + c2 s^2, s = 2 z / b; the correction cancels c1 s + c2 s^2.
    Eigen::MatrixXd V(N, 3);
    Eigen::VectorXd y(N);
    for (int k = 0; k < N; ++k)
      {
        const double s = 2 * z[std::size_t(k)] / b;
        V(k, 0) = 1, V(k, 1) = s, V(k, 2) = s * s, y[k] = g[std::size_t(k)];
      }
    const Eigen::Vector3d p = V.colPivHouseholderQr().solve(y);
    c.slope    = -2 * p[1];
    c.crowning = -p[2];
    return c;
  }

  LeadCorrection CoupledPair::correction(const std::vector<CoupledResult> &results) const
  {
    if (results.empty())
      throw InputError("lead correction", "no positions", "the coupled results of at least one position");
    const auto &z = train_.slice_centres(0);
    std::vector<double> g(z.size(), 0.0);
    for (const auto &r : results)
      for (std::size_t k = 0; k < z.size(); ++k)
        g[k] += r.mismatch[k] / double(results.size());
    return fit_correction(z, g, mesh().face_width);
  }

  helical::LeadModification CoupledPair::corrected(helical::LeadModification lead, const LeadCorrection &c) const
  {
    const auto &z = train_.slice_centres(0);
    std::vector<double> extra;
    for (const double zk : z)
      extra.push_back(c.at(zk, mesh().face_width));
    return with_profile(std::move(lead), z, extra, mesh().face_width);
  }

  DesignedCorrection design_correction(const CoupledPair &pair, const std::vector<double> &phi1, double torque,
                                       const helical::LeadModification &lead, double tolerance)
  {
    if (phi1.empty())
      throw InputError("lead correction", "no positions", "at least one position of the cycle");
    DesignedCorrection d;
    // The fixed point c = correction(c), Aitken-relaxed like the coupling itself; each position
    // starts from its own mismatch of the previous correction.
    std::vector<std::vector<double>> warm(phi1.size());
    Eigen::Vector2d prev_step(0, 0);
    double omega = 1;
    for (int n = 1;; ++n)
      {
        const auto with = pair.corrected(lead, d.correction);
        d.results.clear();
        for (std::size_t p = 0; p < phi1.size(); ++p)
          {
            const auto &start = !warm[p].empty() ? warm[p] : (p > 0 ? warm[p - 1] : warm[p]);
            d.results.push_back(pair.solve(phi1[p], torque, with, start));
            warm[p] = d.results.back().mismatch;
          }
        const LeadCorrection next = pair.correction(d.results);
        d.iterations = n;
        const Eigen::Vector2d step(next.slope - d.correction.slope, next.crowning - d.correction.crowning);
        d.change = step.cwiseAbs().maxCoeff();
        if (d.change <= tolerance)
          return d;
        if (n == 20)
          throw SolverError("lead correction at " + to_string_g(torque) + " N m: slope and crowning did not settle in 20 "
                            "corrections (last change " + to_string_g(d.change / units::um) + " um)");
        if (n > 1)
          {
            const Eigen::Vector2d dd = step - prev_step;
            if (dd.squaredNorm() > 0)
              omega = std::clamp(-omega * prev_step.dot(dd) / dd.squaredNorm(), 0.05, 2.0);
          }
        prev_step = step;
        d.correction.slope += omega * step[0];
        d.correction.crowning += omega * step[1];
      }
  }
} // namespace gearfem::system_deflection
