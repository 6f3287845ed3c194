// TwoBodyContact: the solve at one configuration (outer geometric loop over search,
// linearisation and the active-set or penalty Newton solve of contact/ncp.h) and load
// cutting. The search and gaps are in gap.cc, the flexibility cache in flexibility.cc, the
// linearisation in linearise.cc.
#include "contact/two_body.h"
#include "base/progress.h"
#include "contact/ncp.h"

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

    /// The settle test of the geometric iteration, with its state: the last steps of q and
    /// lambda and the active set, and whether that set was unchanged over them.
    struct SettleTest
    {
      std::vector<int> prev_active;
      double prev_dq = 0, prev_dl = 0;
      bool prev_same = false;

      /// Whether iterate `it`, with active set `active`, step dq of the rotation (of size
      /// qs), and relative force step dlrel, is converged to `tolerance`.
      bool settled(const std::vector<int> &active, int it, bool displacement, double dq, double qs, double dlrel,
                   double tolerance)
      {
        // The rotation settles to a relative tolerance, with a floor of 8 ulps of an angle
        // (1.8e-15 rad): at vanishing load q is a few 1e-9 rad and its iterates differ by
        // the round-off of the placed geometry (measured 3-6e-17 rad on the 50/50 m 3 pair;
        // about ulp(centre distance)/radius in general), which no relative test can get
        // below. At ordinary loads (q > 1e-5 rad) tolerance * q is above the floor.
        constexpr double q_floor = 8 * std::numeric_limits<double>::epsilon();
        const double q_tol = tolerance * qs + q_floor, l_tol = std::sqrt(tolerance) * 1e-2;
        const bool same    = it > 0 && active == prev_active;
        bool done          = same && (displacement || dq <= q_tol) && dlrel <= l_tol;
        // On a fixed active set the iteration converges linearly, by a factor rho of about
        // 1e-3 per iteration on gear pairs (the projection points move with the load). The
        // distance of this iterate from the limit is then about rho / (1 - rho) times its
        // step, rho the ratio of the last two steps: when that estimate is within the
        // tolerance the iterate is taken, one confirming search and solve earlier (measured on
        // the demo: steps 6e-6, 4e-9, 3e-12 of q, so the taken iterate is 3e-12 from the one the
        // step test takes).
        const auto distance = [](double step, double prev_step) {
          const double rho = prev_step > 0 ? step / prev_step : 1.0;
          return rho < 0.1 ? rho / (1 - rho) * step : std::numeric_limits<double>::infinity();
        };
        if (!done && same && prev_same && (displacement || distance(dq, prev_dq) <= q_tol) &&
            (dlrel == 0 || distance(dlrel, prev_dl) <= l_tol))
          done = true;
        prev_active = active;
        prev_dq = dq, prev_dl = dlrel, prev_same = same;
        return done;
      }
    };
  } // namespace

  TwoBodyContact::TwoBodyContact(const ContactSurface &s1, const ContactSurface &s2,
                                 const ContactOptions &options, const Drive &drive)
    : s1_(&s1)
    , s2_(&s2)
    , options_(options)
    , drive_(drive)
  {
    options_.validate();
    for (int b = 0; b < 2; ++b)
      {
        const ContactSurface &s = b == 0 ? s1 : s2;
        auto &c                 = cache_[b];
        c.index.assign(s.body().n_dofs(), -1);
        for (const auto &nd : s.nodes())
          for (const unsigned int d : {nd.dof_x, nd.dof_y})
            if (c.index[d] < 0)
              {
                c.index[d] = int(c.dofs.size());
                c.dofs.push_back(d);
              }
        c.node_h.assign(s.nodes().size(), 0.0);
        for (const auto &f : s.faces())
          {
            const auto &pc = s.body().mesh().pieces[f.piece];
            const double L = (pc.curve.point(f.t_hi) - pc.curve.point(f.t_lo)).norm();
            for (const int n : f.nodes)
              c.node_h[n] = std::max(c.node_h[n], L);
          }
        // Faces around each node, and the kinks: a node with one face (surface end) or
        // whose faces' normals differ there (a sharp tip corner).
        c.node_faces.assign(s.nodes().size(), {});
        for (std::size_t f = 0; f < s.faces().size(); ++f)
          for (const int n : s.faces()[f].nodes)
            c.node_faces[n].push_back(int(f));
        c.kink.assign(s.nodes().size(), 0);
        for (std::size_t n = 0; n < s.nodes().size(); ++n)
          {
            const auto &nf = c.node_faces[n];
            if (nf.size() < 2)
              {
                c.kink[n] = 1;
                continue;
              }
            std::vector<Vec2> normals;
            for (const int f : nf)
              {
                const auto &face = s.faces()[f];
                const double t   = face.nodes.front() == int(n) ? face.t_lo : face.t_hi;
                normals.push_back(s.outward_normal(face.piece, t));
              }
            for (const auto &nv : normals)
              if (nv.dot(normals.front()) < std::cos(1e-3))
                c.kink[n] = 1;
          }
        c.flex = std::make_shared<Flexibility>();
        c.flex->reset(c.dofs.size(), 0);
        c.u = Eigen::VectorXd::Zero(c.dofs.size());
        // Until a configuration sets its zone: the whole surface.
        c.node_zone.assign(s.nodes().size(), 1);
        c.zone.resize(c.dofs.size());
        for (std::size_t i = 0; i < c.dofs.size(); ++i)
          c.zone[i] = int(i);
        c.fill_zone = c.zone;
        for (const auto &nd : s.nodes()) // the body frame's origin is its placement centre
          c.r_max = std::max(c.r_max, nd.x.norm());
      }
    // The same factorised body with the same surface on both sides (identical gears): the
    // flexibility columns are the same numbers, so both sides share them.
    if (&s1.body() == &s2.body() && cache_[0].dofs == cache_[1].dofs)
      cache_[1].flex = cache_[0].flex;
  }

  ContactSolution TwoBodyContact::solve(const Scene &scene, Control control, double value,
                                        const ContactSolution *warm)
  {
    // Projection hints live for one configuration: its geometric iterations (and load cuts)
    // start from each other, and the projections do not depend on what was solved before.
    // (The flexibility columns cached from earlier positions do, in their last bits, so a
    // resumed sweep equals an uninterrupted one to the iteration's tolerance, not bit for bit.)
    hints_.clear();
    // The contact zone at the start: the flexibility and the search keep to it.
    const double q0 = control == Control::displacement ? value : (warm ? warm->q : 0.0);
    set_zone(scene, q0, options_.search_distance);
    ContactSolution r = solve_once(scene, control, value, warm);
    if (r.converged)
      return r;
    // Adaptive load cutting: reach the target through intermediate values, each solve
    // warm-started from the previous one.
    std::vector<std::string> history = r.history;
    const double start = warm ? (control == Control::load ? warm->load : warm->q) : 0.0;
    std::function<ContactSolution(const ContactSolution *, double, double, int)> path =
      [&](const ContactSolution *from, double v0, double v1, int depth) -> ContactSolution {
      ContactSolution s = solve_once(scene, control, v1, from);
      if (s.converged || depth >= options_.max_load_cuts)
        {
          s.load_cuts = depth;
          return s;
        }
      history.push_back("load cut: " + to_string_g(v0) + " -> " + to_string_g(0.5 * (v0 + v1)) +
                        " -> " + to_string_g(v1));
      ContactSolution mid = path(from, v0, 0.5 * (v0 + v1), depth + 1);
      if (!mid.converged)
        return mid;
      ContactSolution end = path(&mid, 0.5 * (v0 + v1), v1, depth + 1);
      end.load_cuts       = std::max(end.load_cuts, mid.load_cuts);
      return end;
    };
    if (options_.max_load_cuts > 0)
      {
        ContactSolution s = path(warm, start, 0.5 * (start + value), 1);
        if (s.converged)
          {
            s = path(&s, 0.5 * (start + value), value, 1);
            if (s.converged)
              return s;
          }
        history.insert(history.end(), s.history.begin(), s.history.end());
      }
    std::ostringstream msg;
    msg << "contact did not converge (" << to_string(options_.method) << ", "
        << (control == Control::load ? "load " : "drive ") << to_string_g(value)
        << ") after " << options_.max_load_cuts << " load cuts; residual history:";
    for (const auto &h : history)
      msg << "\n    " << h;
    throw SolverError(msg.str());
  }

  ContactSolution TwoBodyContact::solve_once(const Scene &scene, Control control, double value,
                                             const ContactSolution *warm)
  {
    ContactSolution out;
    double q = control == Control::displacement ? value : (warm ? warm->q : 0.0);
    if (control == Control::load && warm && warm->load > 0 && value > 0)
      q = warm->q * (value / warm->load); // secant start along the previous load path

    // Initial elastic state: from the warm start's forces, else unloaded. `forces`: the
    // nodal forces (universe index, value) of the current elastic state.
    std::vector<std::pair<int, double>> forces[2];
    std::vector<double> lambda_node(s1_->nodes().size() + s2_->nodes().size(), 0.0);
    if (warm)
      {
        const double scale = (control == Control::load && warm->load > 0) ? value / warm->load : 1.0;
        for (const auto &p : warm->points)
          lambda_node[key(p.slave_body, p.node)] = p.force * scale;
        for (int b = 0; b < 2; ++b)
          for (const auto &[d, f] : warm->forces[b])
            forces[b].emplace_back(cache_[b].index[d], f * scale);
      }
    set_displacements(forces, out.t_compliance);
    // The zone must cover every node that can come within the search distance: moved
    // further than its margin, or read outside it (a long face), it is set anew.
    const auto keep_zone = [&](double at) {
      for (int k = 0; k < 30 && !zone_holds(at); ++k)
        {
          set_zone(scene, at, (zone_breach_ || k > 0 ? 2 : 1) * zone_margin_);
          set_displacements(forces, out.t_compliance);
        }
    };

    double prev_q = q;
    SettleTest settle;
    for (int it = 0; it < options_.max_geometry_iterations; ++it)
      {
        keep_zone(q);
        auto t0 = Clock::now();
        const double band =
          options_.candidate_band && 2 * it < options_.max_geometry_iterations ?
            candidate_band(q) :
            std::numeric_limits<double>::infinity();
        SearchResult sr   = search(scene, q, band, &lambda_node);
        out.t_search += since(t0);
        if (zone_breach_)
          {
            keep_zone(q);
            t0 = Clock::now();
            sr = search(scene, q, band, &lambda_node);
            out.t_search += since(t0);
            if (zone_breach_)
              throw SolverError("contact search: a projection reads the elastic state outside the contact zone "
                                "after widening it (margin " + to_string_g(zone_margin_ * 1e3) + " mm)");
          }
        const std::vector<Candidate> &cand = sr.cand;
        const int m = int(cand.size());
        if (m == 0)
          {
            if (control == Control::displacement)
              {
                out.converged = true, out.q = q, out.load = 0;
                out.history.push_back("no candidate slave node within the search distance");
                return out;
              }
            out.history.push_back("iteration " + std::to_string(it) +
                                  ": no slave node within the search distance of the master");
            throw SolverError("no contact found: no slave node lies within the contact search distance (" +
                              to_string_g(options_.search_distance * 1e3) +
                              " mm) of the mating body; check backlash, centre distance and positions");
          }

        t0 = Clock::now();
        const double tc0 = out.t_compliance;
        Linearisation lin = linearise(scene, sr, q, lambda_node, out.t_compliance, false);
        // W's columns are filled as candidates enter the active set: the gaps of the others
        // need only the active columns (lambda is zero off the active set).
        const std::function<void(const std::vector<int> &)> fill = [&](const std::vector<int> &A) {
          fill_delassus(lin, A, out.t_compliance);
        };
        NcpResult ncp = solve_ncp(lin.W, lin.D, lin.a, lin.ghat, control, value, q, lin.lambda0,
                                  options_.max_active_set_iterations, lin.af, &fill);
        out.active_set_iterations += ncp.iterations;
        out.t_solve += since(t0) - (out.t_compliance - tc0); // flexibility columns are not contact solve time
        if (!ncp.ok)
          {
            out.history.push_back("iteration " + std::to_string(it) + ": " + ncp.why);
            if (ncp.why.find("no contact") != std::string::npos ||
                ncp.why.find("singular") != std::string::npos)
              throw SolverError("no contact found: " + ncp.why);
            return out; // not converged: the caller cuts the load
          }

        // New elastic state on the zone.
        for (int b = 0; b < 2; ++b)
          {
            forces[b].clear();
            for (int k = 0; k < m; ++k)
              if (ncp.lambda[k] != 0)
                for (const auto &[i, v] : lin.forces(b)[k])
                  forces[b].emplace_back(i, ncp.lambda[k] * v);
          }
        set_displacements(forces, out.t_compliance);
        std::vector<int> active;
        std::vector<double> lambda_new(lambda_node.size(), 0.0);
        for (int k = 0; k < m; ++k)
          {
            lambda_new[key(cand[k].S, cand[k].node)] = ncp.lambda[k];
            if (ncp.active[k])
              active.push_back(key(cand[k].S, cand[k].node));
          }
        double lmax = 0, dl = 0;
        for (std::size_t i = 0; i < lambda_node.size(); ++i)
          {
            lmax = std::max(lmax, std::abs(lambda_new[i]));
            dl   = std::max(dl, std::abs(lambda_new[i] - lambda_node[i]));
          }
        lambda_node = lambda_new;
        const double dq    = std::abs(ncp.q - prev_q);
        const double qs    = std::max(std::abs(ncp.q), 1e-300);
        const double dlrel = lmax > 0 ? dl / lmax : 0.0;
        q                  = ncp.q;
        std::ostringstream h;
        h << "iteration " << it << ": candidates " << m << ", active " << active.size()
          << ", active-set iterations " << ncp.iterations << ", q " << to_string_g(q)
          << ", |dq|/q " << to_string_g(dq / qs) << ", |dlambda|/lambda " << to_string_g(dlrel)
          << ", complementarity " << to_string_g(ncp.complementarity);
        out.history.push_back(h.str());

        const bool settled = settle.settled(active, it, control == Control::displacement, dq, qs, dlrel,
                                            options_.tolerance);
        prev_q             = q;
        if (!settled)
          continue;

        out.converged           = true;
        out.q                   = q;
        out.load                = -lin.load_arm().dot(ncp.lambda);
        out.tangent             = ncp.tangent;
        out.complementarity     = ncp.complementarity;
        out.n_active            = int(active.size());
        out.geometry_iterations = it + 1;
        fill_solution(out, cand, lin, ncp.lambda, ncp.gap, scene, q);
        return out;
      }
    out.history.push_back("the geometric iteration did not settle in " +
                          std::to_string(options_.max_geometry_iterations) + " iterations");
    return out;
  }
} // namespace gearfem::contact
