// solve_condensed: a re-solve of one stored configuration (contact/condensed.h).
#include "contact/condensed.h"
#include "contact/ncp.h"

#include "base/errors.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <map>

namespace gearfem::contact
{
  namespace
  {
    Vec2 rotate_about(const Vec2 &x, const Vec2 &c, double angle)
    {
      const double cs = std::cos(angle), sn = std::sin(angle);
      const Vec2 d    = x - c;
      return c + Vec2(cs * d.x() - sn * d.y(), sn * d.x() + cs * d.y());
    }
  } // namespace

  void turn_body1(ContactPoint &p, const Vec2 &o1, double dq)
  {
    if (p.slave_body == 1)
      p.x = rotate_about(p.x, o1, dq);
    else
      {
        p.master_point = rotate_about(p.master_point, o1, dq);
        p.normal       = rotate_about(p.normal, Vec2::Zero(), dq);
      }
  }

  namespace
  {
    CondensedSolution solve_impl(const CondensedPosition &c, const Eigen::VectorXd &offset,
                                 const Eigen::VectorXd &advance, Control control,
                                 double value, double tolerance, int max_active_set_iterations);
  }

  CondensedSolution solve_condensed(const CondensedPosition &c, const Eigen::VectorXd &offset, double load,
                                    double tolerance, int max_active_set_iterations)
  {
    return solve_impl(c, offset, Eigen::VectorXd(), Control::load, load, tolerance, max_active_set_iterations);
  }

  CondensedSolution solve_condensed(const CondensedPosition &c, const Eigen::VectorXd &offset,
                                    const Eigen::VectorXd &advance, double load, double tolerance,
                                    int max_active_set_iterations)
  {
    return solve_impl(c, offset, advance, Control::load, load, tolerance, max_active_set_iterations);
  }

  CondensedSolution solve_condensed_rotation(const CondensedPosition &c, const Eigen::VectorXd &offset, double q,
                                             int max_active_set_iterations)
  {
    return solve_impl(c, offset, Eigen::VectorXd(), Control::displacement, q, 0.0, max_active_set_iterations);
  }

  CurvatureNewton curvature_newton(
    const Eigen::VectorXd &a, const Eigen::VectorXd &curvature, const Eigen::VectorXd &ghat,
    const Eigen::VectorXd &q_build, const Eigen::VectorXd &advance, double q, Eigen::VectorXd lambda0, bool fixed_q,
    double tolerance, const std::string &what,
    const std::function<NcpResult(const Eigen::VectorXd &, const Eigen::VectorXd &, double, const Eigen::VectorXd &)>
      &step)
  {
    const Eigen::Index m      = a.size();
    const Eigen::VectorXd adv = advance.size() ? advance : Eigen::VectorXd::Zero(m);
    CurvatureNewton out;
    std::vector<char> prev_active;
    bool settled = false;
    for (int it = 0; it < 30 && !settled; ++it)
      {
        // Linearise the curvature term about q: h(q') = h(q) + a(q) (q' - q).
        // A candidate's rigid gap at q + s_k (s: drive advance, zero without deviations).
        const Eigen::VectorXd dq = Eigen::VectorXd::Constant(m, q) - q_build + adv;
        out.arm = a + curvature.cwiseProduct(dq);
        const Eigen::VectorXd gl = ghat + a.cwiseProduct(Eigen::VectorXd::Constant(m, q) + adv) +
                                   0.5 * curvature.cwiseProduct(dq.cwiseProduct(dq)) - out.arm * q;
        out.ncp = step(out.arm, gl, q, lambda0);
        out.iterations += out.ncp.iterations;
        if (!out.ncp.ok)
          throw SolverError(what + out.ncp.why);
        constexpr double q_floor = 8 * std::numeric_limits<double>::epsilon();
        settled = fixed_q || (it > 0 && out.ncp.active == prev_active &&
                              std::abs(out.ncp.q - q) <= tolerance * std::abs(out.ncp.q) + q_floor);
        prev_active = out.ncp.active;
        lambda0     = out.ncp.lambda;
        q           = out.ncp.q;
      }
    if (!settled)
      throw SolverError(what + "the rotation did not settle in 30 curvature updates");
    out.q = q;
    return out;
  }

  namespace
  {
  CondensedSolution solve_impl(const CondensedPosition &c, const Eigen::VectorXd &offset,
                               const Eigen::VectorXd &advance, Control control, double value, double tolerance,
                               int max_active_set_iterations)
  {
    const double load = value;
    const auto t0 = std::chrono::steady_clock::now();
    const int m   = int(c.size());
    if (m == 0)
      throw SolverError("no contact found: the stored configuration has no candidate slave node");
    if (offset.size() != 0 && offset.size() != m)
      throw SolverError("condensed re-solve: " + std::to_string(offset.size()) + " gap offsets for " +
                        std::to_string(m) + " candidates");
    if (advance.size() != 0 && advance.size() != m)
      throw SolverError("condensed re-solve: " + std::to_string(advance.size()) + " drive advances for " +
                        std::to_string(m) + " candidates");
    const Eigen::VectorXd o = offset.size() ? offset : Eigen::VectorXd::Zero(m);
    const Eigen::VectorXd adv = advance.size() ? advance : Eigen::VectorXd::Zero(m);
    // Secant start along the build solve's load path (or the given rotation).
    double q = control == Control::displacement ? value :
                                                  (c.load_build > 0 ? c.q_build * load / c.load_build : c.q_build);
    // Start the active set from the build solve's contact forces, scaled to the load: a
    // re-solve near the build (another torque, a modification of a few um) then settles in
    // one or two active-set iterations instead of growing the set from one node.
    Eigen::VectorXd lambda0 = Eigen::VectorXd::Zero(m);
    if (control == Control::load && c.load_build > 0)
      for (int k = 0; k < m; ++k)
        lambda0[k] = std::max(0.0, c.cand[k].point.force) * load / c.load_build;
    const CurvatureNewton cn = curvature_newton(
      c.a, c.curvature, c.ghat + o, Eigen::VectorXd::Constant(m, c.q_build), adv, q, lambda0,
      control == Control::displacement, tolerance, "condensed re-solve: ",
      [&](const Eigen::VectorXd &arm_, const Eigen::VectorXd &ghat_, double q_, const Eigen::VectorXd &lambda0_) {
        return solve_ncp(c.W, c.D, arm_, ghat_, control, value, q_, lambda0_, max_active_set_iterations);
      });
    const NcpResult &ncp       = cn.ncp;
    const Eigen::VectorXd &arm = cn.arm;
    const int iterations       = cn.iterations;
    q                          = cn.q;
    // The approach of each edge candidate beyond its build state (unmodified geometry).
    Eigen::VectorXd lambda_b(m);
    for (int k = 0; k < m; ++k)
      lambda_b[k] = c.cand[k].point.force;
    const double dq = q - c.q_build;
    const Eigen::VectorXd dqs = Eigen::VectorXd::Constant(m, dq) + adv;
    const Eigen::VectorXd dlambda = ncp.lambda - lambda_b;
    // Only the edge candidates' approach is checked: their rows of W, not the whole product
    // (which had become the largest single cost of a re-solve).
    const auto approach = [&](int k) {
      return -(c.a[k] * dqs[k] + 0.5 * c.curvature[k] * dqs[k] * dqs[k] + c.W.row(k).dot(dlambda));
    };
    for (int k = 0; k < m; ++k)
      if (!c.cand[k].smooth && ncp.lambda[k] > 0 && std::abs(dqs[k]) > 1e-3 * std::abs(c.q_build)) // its own rigid state q + s_k
        throw SolverError("condensed re-solve: stored candidate slave node " + std::to_string(c.cand[k].point.node) +
                          " of body " + std::to_string(c.cand[k].point.slave_body) +
                          ", whose gap is not smooth in the rotation (its closest point jumps), carries load away "
                          "from the build torque: build the condensed cycle nearer this load");
    for (int k = 0; k < m; ++k)
      if (c.cand[k].edge && approach(k) > 0.5 * c.search_distance)
        throw SolverError("condensed re-solve: the contact reaches the edge of the stored candidates (slave node " +
                          std::to_string(c.cand[k].point.node) + " of body " +
                          std::to_string(c.cand[k].point.slave_body) + " approaches the mating flank by " +
                          to_string_g(approach(k) * 1e6) + " um more than at the build, over half the search distance " +
                          to_string_g(c.search_distance * 1e6) +
                          " um): the condensed cycle does not cover this load or modification; build it at a "
                          "higher torque or with a larger Contact/Search distance");
    // A banded cycle stores only the candidates within its search distance of contact at the
    // build: a rigid closure beyond half of it could bring a tooth pair that has no stored
    // candidate (which the edge check above cannot see) into contact.
    for (int k = 0; k < m; ++k)
      if (-c.a[k] * dqs[k] > 0.5 * c.search_distance)
        throw SolverError("condensed re-solve: the rigid approach of slave node " + std::to_string(c.cand[k].point.node) +
                          " of body " + std::to_string(c.cand[k].point.slave_body) + " (" +
                          to_string_g(-c.a[k] * dqs[k] * 1e6) + " um) is over half the search distance of the stored "
                          "candidates (" + to_string_g(c.search_distance * 1e6) +
                          " um): the condensed cycle does not cover this load or modification; build it at a higher "
                          "torque or with a larger Contact/Search distance");

    CondensedSolution out;
    ContactSolution &s = out.solution;
    s.converged             = true;
    s.q                     = q;
    s.load                  = -arm.dot(ncp.lambda);
    s.tangent               = ncp.tangent;
    s.complementarity       = ncp.complementarity;
    s.active_set_iterations = iterations;
    s.geometry_iterations   = 1;
    const Vec2 o1           = c.placement[0].centre;
    for (int k = 0; k < m; ++k)
      {
        ContactPoint p = c.cand[k].point;
        p.force        = ncp.lambda[k];
        p.gap          = ncp.gap[k];
        p.arm          = arm[k];
        p.pressure     = 0;
        for (const auto &[j, coef] : c.pressure[k])
          p.pressure += coef * ncp.lambda[j];
        // Body 1 turns with q: its points follow the rotation from the build state.
        turn_body1(p, o1, q - c.q_build);
        s.max_penetration = std::max(s.max_penetration, -p.gap);
        if (ncp.active[k])
          ++s.n_active;
        s.points.push_back(p);
      }
    for (int b = 0; b < 2; ++b)
      {
        std::map<int, double> f;
        for (int k = 0; k < m; ++k)
          if (ncp.lambda[k] != 0)
            for (const auto &[i, v] : c.B[b][k])
              f[i] += ncp.lambda[k] * v;
        out.universe_forces[b].assign(f.begin(), f.end());
      }
    s.t_solve = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }
  } // namespace
} // namespace gearfem::contact
