// TwoBodyContact: candidate search, linearised gaps, flexibility cache, active-set and
// penalty Newton solvers, outer geometric loop and load cutting.
#include "contact/two_body.h"
#include "contact/ncp.h"

#include "base/errors.h"

#include <algorithm>
#include <limits>
#include <chrono>
#include <cmath>
#include <functional>
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
    Vec2 rotate(const Vec2 &v, double angle)
    {
      const double c = std::cos(angle), s = std::sin(angle);
      return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
    }
    /// Inverse rigid placement: pair frame -> body frame.
    Vec2 to_body(const geometry::Placement &p, const Vec2 &x)
    {
      return rotate(x - p.centre, -p.angle);
    }

  } // namespace

  Method method_from_string(const std::string &s)
  {
    if (s == "penalty")
      return Method::penalty;
    if (s == "lagrange")
      return Method::lagrange;
    throw InputError("Contact/Method", s, "penalty | lagrange");
  }
  const char *to_string(Method m) { return m == Method::penalty ? "penalty" : "lagrange"; }

  GapRule gap_rule_from_string(const std::string &s)
  {
    if (s == "node")
      return GapRule::node;
    if (s == "integrated")
      return GapRule::integrated;
    throw InputError("Contact/Gap", s, "node | integrated");
  }
  const char *to_string(GapRule g) { return g == GapRule::node ? "node" : "integrated"; }

  void ContactOptions::validate() const
  {
    require_greater("Contact/Penalty factor", penalty_factor, 0.0, "-");
    require_greater("Contact/Search distance", search_distance, 0.0, "m");
    if (!(tolerance > 0 && tolerance < 1e-2))
      throw InputError("Contact/Tolerance", to_string_g(tolerance), "(0, 1e-2)");
    if (max_active_set_iterations < 1)
      throw InputError("Contact/Max active-set iterations", std::to_string(max_active_set_iterations), ">= 1");
    if (max_geometry_iterations < 1)
      throw InputError("Contact/Max geometry iterations", std::to_string(max_geometry_iterations), ">= 1");
    if (max_load_cuts < 0)
      throw InputError("Contact/Max load cuts", std::to_string(max_load_cuts), ">= 0");
    if (slave != 1 && slave != 2)
      throw InputError("Contact/Slave body", std::to_string(slave), "1 | 2");
  }

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
        c.C = Eigen::MatrixXd::Zero(c.dofs.size(), c.dofs.size());
        c.have.assign(c.dofs.size(), 0);
        c.u = Eigen::VectorXd::Zero(c.dofs.size());
      }
  }

  std::size_t TwoBodyContact::cached_columns(int body) const
  {
    const auto &h = cache_[body - 1].have;
    return std::size_t(std::count(h.begin(), h.end(), 1));
  }

  geometry::Placement TwoBodyContact::placed(const Scene &scene, int body, double q) const
  {
    geometry::Placement p = scene.placement[body - 1];
    if (body == 1)
      {
        if (drive_.kind == Drive::Kind::rotation)
          p.angle += q;
        else
          p.centre += q * drive_.direction;
      }
    return p;
  }

  void TwoBodyContact::ensure_columns(int body, const std::vector<int> &idx, double &seconds)
  {
    auto &c = cache_[body - 1];
    std::vector<int> missing;
    for (const int i : idx)
      if (!c.have[i])
        {
          missing.push_back(i);
          c.have[i] = 2; // queued
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
          c.C(i, missing[j]) = X[j * n + i];
        c.have[missing[j]] = 1;
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

  ContactSolution TwoBodyContact::solve(const Scene &scene, Control control, double value,
                                        const ContactSolution *warm)
  {
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

  std::vector<std::pair<int, int>> TwoBodyContact::slaves(const Scene &scene) const
  {
    std::vector<std::pair<int, int>> r;
    const bool masks = !scene.slave_nodes[0].empty() || !scene.slave_nodes[1].empty();
    for (int b = 1; b <= 2; ++b)
      {
        if (!masks && b != options_.slave)
          continue;
        const auto &mask = scene.slave_nodes[b - 1];
        for (std::size_t i = 0; i < surface(b).nodes().size(); ++i)
          if (!masks || (i < mask.size() && mask[i]))
            r.emplace_back(b, int(i));
      }
    return r;
  }

  void TwoBodyContact::set_gap_modification(int body, GapModification f)
  {
    if (body != 1 && body != 2)
      throw InputError("gap modification body", std::to_string(body), "1 | 2");
    gap_mod_[body - 1] = std::move(f);
  }

  bool TwoBodyContact::project_point(const Scene &scene, int M, const Vec2 &xs, double q, GapPoint &out,
                                     double slave_offset) const
  {
    const ContactSurface &ms = surface(M);
    const auto &use          = scene.master_pieces[M - 1];
    const geometry::Placement PM = placed(scene, M, q);
    const Vec2 y                 = to_body(PM, xs);
    out.pr = ms.project(y, options_.search_distance, use);
    if (out.pr.piece < 0)
      return false;
    // Closest point on the displaced master: project y - u_m(t), fixed point.
    for (int k = 0; k < 3; ++k)
      {
        out.face        = ms.face_at(out.pr.piece, out.pr.t, out.shape);
        const Vec2 um   = interpolate(M, out.face, out.shape);
        const auto next = ms.project(y - um, options_.search_distance, use);
        if (next.piece < 0)
          break;
        const bool same = next.piece == out.pr.piece && std::abs(next.t - out.pr.t) < 1e-12;
        out.pr          = next;
        if (same)
          break;
      }
    out.face      = ms.face_at(out.pr.piece, out.pr.t, out.shape);
    const Vec2 um = interpolate(M, out.face, out.shape);
    out.g         = (y - out.pr.point - um).dot(out.pr.normal) + slave_offset + gap_offset(M, out.pr.point);
    if (std::abs(out.g) > options_.search_distance)
      return false;
    out.n_pair = PM.apply_vector(out.pr.normal);
    return true;
  }

  bool TwoBodyContact::integrate_gap(const Scene &scene, double q, Candidate &c,
                                     std::vector<FaceSample> &samples, std::vector<int> &face_sample) const
  {
    const int S = c.S, M = 3 - S;
    const ContactSurface &ss = surface(S);
    const auto &cS           = cache_[S - 1];
    if (cS.kink[c.node])
      return false; // a corner is a point contact: nodal gap
    const geometry::Placement PS = placed(scene, S, q);
    // Gauss samples of each face around the node (once per face and search): 2 points on
    // each sub-segment between consecutive face nodes, where the hats are linear (hat times
    // a quadratic gap is cubic: 2-point Gauss is exact; 4 points gave the same STE to
    // 1e-4 at twice the projections).
    constexpr int ng = 2;
    constexpr double gx[ng] = {0.2113248654051871, 0.7886751345948129}, gw[ng] = {0.5, 0.5};
    for (const int f : cS.node_faces[c.node])
      {
        if (face_sample[f] != -1)
          continue;
        const auto &face = ss.faces()[f];
        const auto &pc   = ss.body().mesh().pieces[face.piece];
        const int first  = int(samples.size());
        bool ok          = true;
        for (std::size_t l = 0; l + 1 < face.nodes.size() && ok; ++l)
          for (int k = 0; k < ng && ok; ++k)
            {
              FaceSample sm;
              sm.sub         = int(l);
              sm.eta         = gx[k];
              const double x = face.xi[l] + sm.eta * (face.xi[l + 1] - face.xi[l]);
              const double t = face.t_lo + x * (face.t_hi - face.t_lo);
              sm.slave_face  = ss.face_at(face.piece, t, sm.slave_shape);
              sm.ds = pc.curve.d1(t).norm() * (face.t_hi - face.t_lo) * (face.xi[l + 1] - face.xi[l]) * gw[k];
              sm.gp.x       = pc.curve.point(t);
              const Vec2 us = interpolate(S, sm.slave_face, sm.slave_shape);
              const Vec2 xs = PS.apply(sm.gp.x) + PS.apply_vector(us);
              ok = sm.slave_face == f && project_point(scene, M, xs, q, sm.gp, gap_offset(S, sm.gp.x)) &&
                   !sm.gp.pr.corner;
              samples.push_back(std::move(sm));
            }
        face_sample[f] = ok ? first : -2;
      }
    c.terms.clear();
    double g = 0, w = 0;
    for (const int f : cS.node_faces[c.node])
      {
        if (face_sample[f] < 0)
          {
            c.terms.clear();
            return false; // a sample with no smooth master point: nodal gap
          }
        const auto &face = ss.faces()[f];
        const int j = int(std::find(face.nodes.begin(), face.nodes.end(), c.node) - face.nodes.begin());
        const int n = ng * (int(face.nodes.size()) - 1);
        for (int i = face_sample[f]; i < face_sample[f] + n; ++i)
          {
            const auto &sm   = samples[i];
            const double phi = sm.sub == j ? 1 - sm.eta : (sm.sub == j - 1 ? sm.eta : 0.0);
            if (phi == 0)
              continue;
            c.terms.emplace_back(i, phi * sm.ds);
            w += phi * sm.ds;
            g += phi * sm.ds * sm.gp.g;
          }
      }
    if (!(w > 0))
      {
        c.terms.clear();
        return false;
      }
    for (auto &t : c.terms)
      t.second /= w;
    g /= w;
    c.g = g;
    return true;
  }

  TwoBodyContact::SearchResult TwoBodyContact::search(const Scene &scene, double q) const
  {
    const geometry::Placement P[2] = {placed(scene, 1, q), placed(scene, 2, q)};
    SearchResult r;
    std::vector<int> face_sample[2] = {std::vector<int>(s1_->faces().size(), -1),
                                       std::vector<int>(s2_->faces().size(), -1)};
    for (const auto &[S, i] : slaves(scene))
      {
        const auto &nd = surface(S).nodes()[i];
        const Vec2 xs = P[S - 1].apply(nd.x) + P[S - 1].apply_vector(displacement(S, i));
        Candidate c;
        c.S = S, c.node = i;
        if (!project_point(scene, 3 - S, xs, q, c.at, gap_offset(S, nd.x)))
          continue;
        c.at.x = nd.x;
        c.g    = c.at.g;
        if (options_.gap == GapRule::integrated)
          integrate_gap(scene, q, c, r.samples, face_sample[S - 1]);
        r.cand.push_back(std::move(c));
      }
    return r;
  }

  TwoBodyContact::Linearisation TwoBodyContact::linearise(const Scene &scene, const SearchResult &sr, double q,
                                                          const std::vector<double> &lambda_node,
                                                          double &t_compliance)
  {
    const auto &cand = sr.cand;
    const int m      = int(cand.size());
    const geometry::Placement P[2] = {placed(scene, 1, q), placed(scene, 2, q)};
    // Material scale for the penalty: the smaller E.
    const double E = std::min(s1_->body().material().youngs_modulus, s2_->body().material().youngs_modulus);
    const auto velocity = [&](const Vec2 &x) {
      if (drive_.kind == Drive::Kind::translation)
        return drive_.direction;
      const Vec2 c = scene.placement[0].centre;
      return Vec2(-(x.y() - c.y()), x.x() - c.x());
    };
    Linearisation L;
    L.B[0].assign(m, {});
    L.B[1].assign(m, {});
    L.a.resize(m), L.ghat.resize(m), L.D.resize(m), L.lambda0.resize(m);
    std::vector<int> used[2];
    // Adds the gap of one slave point (its own nodal weights `slave_shape` on the slave face,
    // or the node itself) with weight `coef` to row k: the slave and master force
    // directions, and the arm dg/dq. Body 1 is the driven body, slave or master; its share
    // of the force acts at its nodes (weights N_j), so the arm is the nodal one: then
    // -a^T lambda is exactly the moment of the nodal forces about O1.
    const auto add_point = [&](int k, int S, const GapPoint &gp, const std::vector<int> &slave_nodes,
                               const std::vector<double> &slave_shape, double coef) {
      const int M      = 3 - S;
      const auto &ss   = surface(S);
      const auto &ms   = surface(M);
      const Vec2 nS    = rotate(gp.n_pair, -P[S - 1].angle);
      const Vec2 nM    = gp.pr.normal;
      const auto &cS   = cache_[S - 1];
      const auto &cM   = cache_[M - 1];
      for (std::size_t l = 0; l < slave_nodes.size(); ++l)
        {
          const auto &sn = ss.nodes()[slave_nodes[l]];
          const double v = coef * slave_shape[l];
          L.B[S - 1][k].push_back({cS.index[sn.dof_x], v * nS.x()});
          L.B[S - 1][k].push_back({cS.index[sn.dof_y], v * nS.y()});
          if (S == 1)
            L.a[k] += v * gp.n_pair.dot(velocity(P[0].apply(sn.x)));
        }
      const auto &face = ms.faces()[gp.face];
      for (std::size_t j = 0; j < face.nodes.size(); ++j)
        {
          const auto &mn = ms.nodes()[face.nodes[j]];
          const double v = coef * gp.shape[j];
          L.B[M - 1][k].push_back({cM.index[mn.dof_x], -v * nM.x()});
          L.B[M - 1][k].push_back({cM.index[mn.dof_y], -v * nM.y()});
          if (M == 1)
            L.a[k] -= v * gp.n_pair.dot(velocity(P[0].apply(mn.x)));
        }
    };
    for (int k = 0; k < m; ++k)
      {
        const auto &c  = cand[k];
        const int S    = c.S;
        const auto &nd = surface(S).nodes()[c.node];
        auto &cS       = cache_[S - 1];
        L.a[k]         = 0;
        if (c.terms.empty())
          add_point(k, S, c.at, {c.node}, {1.0}, 1.0);
        else
          for (const auto &[i, coef] : c.terms)
            {
              const auto &sm = sr.samples[i];
              add_point(k, S, sm.gp, surface(S).faces()[sm.slave_face].nodes, sm.slave_shape, coef);
            }
        for (int b = 0; b < 2; ++b)
          {
            auto &row = L.B[b][k];
            std::sort(row.begin(), row.end());
            std::size_t n = 0;
            for (std::size_t i = 0; i < row.size(); ++i)
              if (n > 0 && row[n - 1].first == row[i].first)
                row[n - 1].second += row[i].second;
              else
                row[n++] = row[i];
            row.resize(n);
          }
        double btu = 0;
        for (int b = 0; b < 2; ++b)
          for (const auto &[i, v] : L.B[b][k])
            btu += v * cache_[b].u[i];
        L.ghat[k] = c.g - L.a[k] * q - btu;
        if (options_.method == Method::penalty)
          {
            const double thickness = surface(S).body().material().thickness;
            L.D[k] = cS.node_h[c.node] / (options_.penalty_factor * E * thickness * nd.weight);
          }
        else
          L.D[k] = 0.0;
        L.lambda0[k] = lambda_node[key(S, c.node)];
        for (int b = 0; b < 2; ++b)
          for (const auto &[i, v] : L.B[b][k])
            used[b].push_back(i);
      }
    for (int b = 0; b < 2; ++b)
      {
        std::sort(used[b].begin(), used[b].end());
        used[b].erase(std::unique(used[b].begin(), used[b].end()), used[b].end());
      }
    const double t0 = t_compliance;
    for (int b = 1; b <= 2; ++b)
      ensure_columns(b, used[b - 1], t_compliance);
    L.t_flex = t_compliance - t0;

    // W = sum_b B_b^T C_b B_b. B has 2 (slave) or 2 (p + 1) (master face) entries per
    // column, so W is built from the columns C_b B_b (contiguous columns of the cache):
    // O(u m) instead of the O(u^2 m) of a dense product. Symmetrised (C is symmetric to
    // round-off).
    L.W = Eigen::MatrixXd::Zero(m, m);
    Eigen::VectorXd t;
    for (int b = 0; b < 2; ++b)
      for (int k = 0; k < m; ++k)
        {
          if (L.B[b][k].empty())
            continue;
          t.setZero(cache_[b].C.rows());
          for (const auto &[i, v] : L.B[b][k])
            t.noalias() += v * cache_[b].C.col(i);
          for (int l = 0; l < m; ++l)
            for (const auto &[j, w] : L.B[b][l])
              L.W(l, k) += w * t[j];
        }
    L.W = 0.5 * (L.W + L.W.transpose()).eval();
    return L;
  }

  void TwoBodyContact::fill_solution(ContactSolution &out, const std::vector<Candidate> &cand,
                                     const Linearisation &lin, const Eigen::VectorXd &lambda,
                                     const Eigen::VectorXd &gap, const Scene &scene, double q) const
  {
    const int m = int(cand.size());
    // Pressure recovered on each slave surface from its own nodal forces.
    std::vector<double> node_force[2] = {std::vector<double>(s1_->nodes().size(), 0.0),
                                         std::vector<double>(s2_->nodes().size(), 0.0)};
    for (int k = 0; k < m; ++k)
      node_force[cand[k].S - 1][cand[k].node] = lambda[k];
    std::vector<double> node_p[2];
    for (int b = 0; b < 2; ++b)
      node_p[b] = surface(b + 1).recover_pressure(node_force[b], surface(b + 1).body().material().thickness);
    out.max_penetration = 0;
    for (int k = 0; k < m; ++k)
      {
        const auto &c  = cand[k];
        const int M    = 3 - c.S;
        const auto &nd = surface(c.S).nodes()[c.node];
        const auto &mp = surface(M).body().mesh().pieces[c.at.pr.piece];
        ContactPoint p;
        p.slave_body    = c.S;
        p.node          = c.node;
        p.slave_tooth   = nd.tooth;
        p.master_piece  = c.at.pr.piece;
        p.master_tooth  = mp.tooth;
        p.master_t      = c.at.pr.t;
        p.slave_code    = mesh::boundary::code_of(nd.boundary_id);
        p.master_code   = mesh::boundary::code_of(mp.boundary_id);
        p.master_corner = c.at.pr.corner;
        p.master_point  = placed(scene, M, q).apply(c.at.pr.point);
        p.x             = placed(scene, c.S, q).apply(nd.x);
        p.normal        = c.at.n_pair;
        p.gap           = gap[k];
        p.force         = lambda[k];
        p.weight        = nd.weight;
        p.pressure      = node_p[c.S - 1][c.node];
        p.arm           = lin.a[k];
        out.max_penetration = std::max(out.max_penetration, -p.gap);
        out.points.push_back(p);
      }
    for (int b = 0; b < 2; ++b)
      {
        std::vector<double> f(cache_[b].dofs.size(), 0.0);
        for (int k = 0; k < m; ++k)
          for (const auto &[i, v] : lin.B[b][k])
            f[i] += lambda[k] * v;
        for (std::size_t i = 0; i < f.size(); ++i)
          if (f[i] != 0)
            out.forces[b].emplace_back(cache_[b].dofs[i], f[i]);
      }
  }

  ContactSolution TwoBodyContact::solve_once(const Scene &scene, Control control, double value,
                                             const ContactSolution *warm)
  {
    ContactSolution out;
    double q = control == Control::displacement ? value : (warm ? warm->q : 0.0);
    if (control == Control::load && warm && warm->load > 0 && value > 0)
      q = warm->q * (value / warm->load); // secant start along the previous load path

    // Initial elastic state: from the warm start's forces, else unloaded.
    for (auto &c : cache_)
      c.u.setZero();
    std::vector<double> lambda_node(s1_->nodes().size() + s2_->nodes().size(), 0.0);
    if (warm)
      {
        const double scale = (control == Control::load && warm->load > 0) ? value / warm->load : 1.0;
        for (const auto &p : warm->points)
          lambda_node[key(p.slave_body, p.node)] = p.force * scale;
        for (int b = 1; b <= 2; ++b)
          {
            auto &c = cache_[b - 1];
            std::vector<int> idx;
            for (const auto &[d, f] : warm->forces[b - 1])
              idx.push_back(c.index[d]);
            ensure_columns(b, idx, out.t_compliance);
            for (const auto &[d, f] : warm->forces[b - 1])
              c.u += (f * scale) * c.C.col(c.index[d]);
          }
      }

    std::vector<int> prev_active;
    double prev_q = q;
    for (int it = 0; it < options_.max_geometry_iterations; ++it)
      {
        auto t0 = Clock::now();
        const SearchResult sr = search(scene, q);
        const std::vector<Candidate> &cand = sr.cand;
        out.t_search += since(t0);
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
        const Linearisation lin = linearise(scene, sr, q, lambda_node, out.t_compliance);
        NcpResult ncp = solve_ncp(lin.W, lin.D, lin.a, lin.ghat, control, value, q, lin.lambda0,
                                  options_.max_active_set_iterations);
        out.active_set_iterations += ncp.iterations;
        out.t_solve += since(t0) - lin.t_flex; // flexibility columns are not contact solve time
        if (!ncp.ok)
          {
            out.history.push_back("iteration " + std::to_string(it) + ": " + ncp.why);
            if (ncp.why.find("no contact") != std::string::npos ||
                ncp.why.find("singular") != std::string::npos)
              throw SolverError("no contact found: " + ncp.why);
            return out; // not converged: the caller cuts the load
          }

        // New elastic state on the universes.
        for (int b = 0; b < 2; ++b)
          {
            auto &c = cache_[b];
            c.u.setZero();
            for (int k = 0; k < m; ++k)
              if (ncp.lambda[k] != 0)
                for (const auto &[i, v] : lin.B[b][k])
                  c.u += (ncp.lambda[k] * v) * c.C.col(i);
          }
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

        // The rotation settles to a relative tolerance, with a floor of 8 ulps of an angle
        // (1.8e-15 rad): at vanishing load q is a few 1e-9 rad and its iterates differ by
        // the round-off of the placed geometry (measured 3-6e-17 rad on the 50/50 m 3 pair;
        // about ulp(centre distance)/radius in general), which no relative test can get
        // below. At ordinary loads (q > 1e-5 rad) tolerance * q is above the floor.
        constexpr double q_floor = 8 * std::numeric_limits<double>::epsilon();
        const bool settled = it > 0 && active == prev_active &&
                             (control == Control::displacement || dq <= options_.tolerance * qs + q_floor) &&
                             dlrel <= std::sqrt(options_.tolerance) * 1e-2;
        prev_active = active;
        prev_q      = q;
        if (!settled)
          continue;

        out.converged           = true;
        out.q                   = q;
        out.load                = -lin.a.dot(ncp.lambda);
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
