// TwoBodyContact: the linearised contact problem g = g_hat + a q + W lambda on the current
// candidates (Delassus operator from the flexibility cache), and the solution record.
#include "contact/two_body.h"
#include "geometry/curve.h"

#include "base/errors.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace gearfem::contact
{
  using geometry::rotate;

  namespace
  {

    /// Merge the repeated universe indices of a row of force directions.
    void compress(std::vector<std::pair<int, double>> &row)
    {
      std::sort(row.begin(), row.end());
      std::size_t n = 0;
      for (std::size_t i = 0; i < row.size(); ++i)
        if (n > 0 && row[n - 1].first == row[i].first)
          row[n - 1].second += row[i].second;
        else
          row[n++] = row[i];
      row.resize(n);
    }
  } // namespace

  // Adds the gap of one slave point (its own nodal weights `slave_shape` on the slave face,
  // or the node itself) with weight `coef` to row k: the slave and master force
  // directions, and the arm dg/dq. Body 1 is the driven body, slave or master; its share
  // of the force acts at its nodes (weights N_j), so the arm is the nodal one: then
  // -a^T lambda is exactly the moment of the nodal forces about O1.
  void TwoBodyContact::add_gap_point(Linearisation &L, const Scene &scene, const geometry::Placement P[2], int k,
                                     int S, const GapPoint &gp, const std::vector<int> &slave_nodes,
                                     const std::vector<double> &slave_shape, double coef, double &coef_sum) const
  {
    const double mu    = options_.friction;
    const double v_tol = options_.friction_tolerance * kinematics_.reference_speed;
    // Pair-frame velocity of the driven body's material point x per unit drive rate.
    const auto velocity = [&](const Vec2 &x) {
      if (drive_.kind == Drive::Kind::translation)
        return drive_.direction;
      const Vec2 c = scene.placement[0].centre;
      return Vec2(-(x.y() - c.y()), x.x() - c.x());
    };
    const int M      = 3 - S;
    const auto &ss   = surface(S);
    const auto &ms   = surface(M);
    const Vec2 nS    = rotate(gp.n_pair, -P[S - 1].angle);
    const Vec2 nM    = gp.pr.normal;
    const auto &cS   = cache_[S - 1];
    const auto &cM   = cache_[M - 1];
    // Friction: the force on the slave per unit lambda is n + mu s t (pair frame), s = -sign
    // of the sliding velocity, ramped below v_tol; the master takes the opposite.
    double fs = 0;
    Vec2 fS = nS, fM = nM, f_pair = gp.n_pair;
    // Rigid velocities of the two material points in contact: the slave point and its
    // closest point on the displaced master (they differ by the elastic displacements).
    const Vec2 xs = P[S - 1].apply(gp.x), xm = P[M - 1].apply(gp.pr.point);
    const Vec2 dv = rigid_velocity(scene, S, xs) - rigid_velocity(scene, M, xm);
    L.approach[k] += coef * dv.dot(gp.n_pair);
    coef_sum += coef;
    if (mu > 0)
      {
        const Vec2 t(-gp.n_pair.y(), gp.n_pair.x());
        const double vs = dv.dot(t);
        fs     = -std::clamp(vs / v_tol, -1.0, 1.0);
        f_pair = gp.n_pair + mu * fs * t;
        fS     = rotate(f_pair, -P[S - 1].angle);
        fM     = rotate(f_pair, -P[M - 1].angle);
        L.slip[k] += coef * fs;
      }
    for (std::size_t l = 0; l < slave_nodes.size(); ++l)
      {
        const auto &sn = ss.nodes()[slave_nodes[l]];
        const double v = coef * slave_shape[l];
        L.B[S - 1][k].push_back({cS.index[sn.dof_x], v * nS.x()});
        L.B[S - 1][k].push_back({cS.index[sn.dof_y], v * nS.y()});
        if (S == 1)
          L.a[k] += v * gp.n_pair.dot(velocity(P[0].apply(sn.x)));
        if (mu > 0)
          {
            L.F[S - 1][k].push_back({cS.index[sn.dof_x], v * fS.x()});
            L.F[S - 1][k].push_back({cS.index[sn.dof_y], v * fS.y()});
            if (S == 1)
              L.af[k] += v * f_pair.dot(velocity(P[0].apply(sn.x)));
          }
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
        if (mu > 0)
          {
            L.F[M - 1][k].push_back({cM.index[mn.dof_x], -v * fM.x()});
            L.F[M - 1][k].push_back({cM.index[mn.dof_y], -v * fM.y()});
            if (M == 1)
              L.af[k] -= v * f_pair.dot(velocity(P[0].apply(mn.x)));
          }
      }
  }

  void TwoBodyContact::find_neighbours(Linearisation &L, const std::vector<Candidate> &cand) const
  {
    const int m = int(cand.size());
    std::map<std::pair<int, int>, int> where;
    for (int k = 0; k < m; ++k)
      where[{cand[k].S, cand[k].node}] = k;
    L.neighbours.assign(m, {});
    for (int k = 0; k < m; ++k)
      {
        const auto &cS = cache_[cand[k].S - 1];
        for (const int f : cS.node_faces[cand[k].node])
          for (const int n : surface(cand[k].S).faces()[f].nodes)
            {
              const auto it = where.find({cand[k].S, n});
              if (it != where.end() && it->second != k)
                L.neighbours[k].push_back(it->second);
            }
      }
  }

  TwoBodyContact::Linearisation TwoBodyContact::linearise(const Scene &scene, const SearchResult &sr, double q,
                                                          const std::vector<double> &lambda_node,
                                                          double &t_compliance, bool full)
  {
    const auto &cand = sr.cand;
    const int m      = int(cand.size());
    const geometry::Placement P[2] = {placed(scene, 1, q), placed(scene, 2, q)};
    // Material scale for the penalty: the smaller E.
    const double E = std::min(s1_->body().material().youngs_modulus, s2_->body().material().youngs_modulus);
    const double mu = options_.friction;
    Linearisation L;
    L.B[0].assign(m, {});
    L.B[1].assign(m, {});
    L.a.resize(m), L.ghat.resize(m), L.D.resize(m), L.lambda0.resize(m);
    if (mu > 0)
      {
        L.F[0].assign(m, {});
        L.F[1].assign(m, {});
        L.af = Eigen::VectorXd::Zero(m);
        L.slip = Eigen::VectorXd::Zero(m);
        L.sliding = Eigen::VectorXd::Zero(m);
      }
    std::vector<double> coef_sum(m, 0.0);
    L.approach = Eigen::VectorXd::Zero(m);
    std::vector<int> used[2];
    for (int k = 0; k < m; ++k)
      {
        const auto &c  = cand[k];
        const int S    = c.S;
        const auto &nd = surface(S).nodes()[c.node];
        auto &cS       = cache_[S - 1];
        L.a[k]         = 0;
        if (c.terms.empty())
          add_gap_point(L, scene, P, k, S, c.at, {c.node}, {1.0}, 1.0, coef_sum[k]);
        else
          for (const auto &[i, coef] : c.terms)
            {
              const auto &sm = sr.samples[i];
              add_gap_point(L, scene, P, k, S, sm.gp, surface(S).faces()[sm.slave_face].nodes, sm.slave_shape, coef,
                            coef_sum[k]);
            }
        for (int b = 0; b < 2; ++b)
          {
            compress(L.B[b][k]);
            if (mu > 0)
              compress(L.F[b][k]);
          }
        L.approach[k] /= coef_sum[k] > 0 ? coef_sum[k] : 1.0;
        if (mu > 0)
          {
            L.slip[k] /= coef_sum[k] > 0 ? coef_sum[k] : 1.0;
            L.sliding[k] = sliding_velocity(scene, S, P[S - 1].apply(nd.x), P[2 - S].apply(c.at.pr.point), c.at.n_pair);
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
    prepare_delassus(L, used);
    find_neighbours(L, cand);
    std::vector<int> ks;
    for (int k = 0; k < m; ++k)
      if (full || L.lambda0[k] > 0)
        ks.push_back(k);
    const double t0 = t_compliance;
    fill_delassus(L, ks, t_compliance);
    L.t_flex = t_compliance - t0;
    return L;
  }

  void TwoBodyContact::prepare_delassus(Linearisation &L, std::vector<int> used[2]) const
  {
    const int m = int(L.a.size());
    for (int b = 0; b < 2; ++b)
      {
        std::sort(used[b].begin(), used[b].end());
        used[b].erase(std::unique(used[b].begin(), used[b].end()), used[b].end());
        L.support[b] = used[b];
        std::vector<int> pos(cache_[b].dofs.size(), -1);
        for (std::size_t r = 0; r < used[b].size(); ++r)
          pos[used[b][r]] = int(r);
        const auto local = [&](const std::vector<std::vector<std::pair<int, double>>> &rows) {
          std::vector<std::vector<std::pair<int, double>>> out(rows.size());
          for (std::size_t k = 0; k < rows.size(); ++k)
            for (const auto &[i, v] : rows[k])
              out[k].emplace_back(pos[i], v);
          return out;
        };
        L.Bs[b] = local(L.B[b]);
        L.Fs[b] = L.F[b].empty() ? std::vector<std::vector<std::pair<int, double>>>() : local(L.F[b]);
      }
    L.W = Eigen::MatrixXd::Zero(m, m);
    L.filled.assign(m, 0);
  }

  void TwoBodyContact::fill_delassus(Linearisation &L, const std::vector<int> &ks, double &t_compliance)
  {
    const int m = int(L.a.size());
    std::vector<int> todo;
    for (const int k : ks)
      if (!L.filled[k])
        todo.push_back(k);
    if (todo.empty())
      return;
    // The flexibility columns of the candidates and, when a MUMPS request is needed anyway,
    // of their face neighbours.
    std::vector<int> idx[2];
    bool missing = false;
    for (int b = 0; b < 2; ++b)
      for (const int k : todo)
        for (const auto &[i, v] : L.forces(b)[k])
          {
            idx[b].push_back(i);
            missing = missing || cache_[b].flex->have[i] != 1;
          }
    if (missing && !L.neighbours.empty())
      for (int b = 0; b < 2; ++b)
        for (const int k : todo)
          for (const int j : L.neighbours[k])
            for (const auto &[i, v] : L.forces(b)[j])
              idx[b].push_back(i);
    for (int b = 0; b < 2; ++b)
      ensure_columns(b + 1, idx[b], t_compliance);
    // W = sum_b B_b^T C_b B_b. Column k from s = C_b f_k (f_k: the force directions of
    // candidate k, 2 or 2 (p + 1) entries), on the rows of the support only: O(|support| +
    // nnz(B)) per column instead of a dense product. Without friction W is symmetric and
    // row k is column k. With friction W_f = B^T C B_f: row k is B_k^T C F_l = F_l^T (C B_k)
    // (C symmetric), so the same kind of vector, C B_k, gives the rows of unfilled columns.
    const bool friction = !(L.F[0].empty() && L.F[1].empty());
    Eigen::VectorXd col(m), row(m), s;
    for (const int k : todo)
      {
        col.setZero(), row.setZero();
        for (int b = 0; b < 2; ++b)
          {
            const auto &C   = cache_[b].flex->C;
            const auto &sup = L.support[b];
            const auto gather = [&](const std::vector<std::pair<int, double>> &f) {
              s.setZero(Eigen::Index(sup.size()));
              for (const auto &[i, v] : f)
                {
                  const double *c = C.col(i).data();
                  for (std::size_t r = 0; r < sup.size(); ++r)
                    s[Eigen::Index(r)] += v * c[sup[r]];
                }
            };
            const auto dot = [&](const std::vector<std::pair<int, double>> &f) {
              double v = 0;
              for (const auto &[r, w] : f)
                v += w * s[r];
              return v;
            };
            const auto &fk = L.forces(b)[k];
            if (!fk.empty())
              {
                gather(fk);
                for (int l = 0; l < m; ++l)
                  col[l] += dot(L.Bs[b][l]);
              }
            if (friction && !L.B[b][k].empty())
              {
                gather(L.B[b][k]);
                for (int l = 0; l < m; ++l)
                  if (!L.filled[l])
                    row[l] += dot(L.Fs[b][l].empty() ? L.Bs[b][l] : L.Fs[b][l]);
              }
          }
        L.W.col(k) = col;
        if (!friction)
          L.W.row(k) = col.transpose();
        else
          for (int l = 0; l < m; ++l)
            if (!L.filled[l] && l != k)
              L.W(k, l) = row[l];
        L.filled[k] = 1;
      }
  }

  Vec2 TwoBodyContact::rigid_velocity(const Scene &scene, int body, const Vec2 &x) const
  {
    if (body == 1)
      {
        if (drive_.kind == Drive::Kind::translation)
          return drive_.direction;
        const Vec2 c = scene.placement[0].centre;
        return Vec2(-(x.y() - c.y()), x.x() - c.x());
      }
    const Vec2 c = scene.placement[1].centre;
    return kinematics_.omega2 * Vec2(-(x.y() - c.y()), x.x() - c.x());
  }

  double TwoBodyContact::sliding_velocity(const Scene &scene, int S, const Vec2 &xs, const Vec2 &xm,
                                          const Vec2 &n) const
  {
    const Vec2 t(-n.y(), n.x());
    return (rigid_velocity(scene, S, xs) - rigid_velocity(scene, 3 - S, xm)).dot(t);
  }

  void TwoBodyContact::set_friction(double mu)
  {
    ContactOptions o = options_;
    o.friction       = mu;
    o.validate();
    options_ = o;
  }

  double TwoBodyContact::contact_width() const
  {
    return std::min(s1_->body().material().thickness, s2_->body().material().thickness);
  }

  void TwoBodyContact::fill_solution(ContactSolution &out, const std::vector<Candidate> &cand,
                                     const Linearisation &lin, const Eigen::VectorXd &lambda,
                                     const Eigen::VectorXd &gap, const Scene &scene, double q) const
  {
    const int m = int(cand.size());
    // Pressure recovered on each slave surface from its own nodal forces, over the contact
    // width both bodies share.
    std::vector<double> node_force[2] = {std::vector<double>(s1_->nodes().size(), 0.0),
                                         std::vector<double>(s2_->nodes().size(), 0.0)};
    for (int k = 0; k < m; ++k)
      node_force[cand[k].S - 1][cand[k].node] = lambda[k];
    std::vector<double> node_p[2];
    for (int b = 0; b < 2; ++b)
      node_p[b] = surface(b + 1).recover_pressure(node_force[b], contact_width());
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
        if (lin.slip.size())
          {
            p.friction = options_.friction * lambda[k] * lin.slip[k];
            p.sliding  = lin.sliding[k];
          }
        else
          p.sliding = sliding_velocity(scene, c.S, p.x, p.master_point, p.normal);
        p.approach = lin.approach[k];
        out.max_penetration = std::max(out.max_penetration, -p.gap);
        out.points.push_back(p);
      }
    for (int b = 0; b < 2; ++b)
      {
        std::vector<double> f(cache_[b].dofs.size(), 0.0);
        for (int k = 0; k < m; ++k)
          for (const auto &[i, v] : lin.forces(b)[k])
            f[i] += lambda[k] * v;
        for (std::size_t i = 0; i < f.size(); ++i)
          if (f[i] != 0)
            out.forces[b].emplace_back(cache_[b].dofs[i], f[i]);
      }
  }
} // namespace gearfem::contact
