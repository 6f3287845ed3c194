// TwoBodyContact: the candidate search and the gaps on the exact curves (placement of the
// bodies, slave selection, projection onto the master, segment-to-segment integration,
// micro-geometry as a gap modification).
#include "contact/two_body.h"
#include "geometry/curve.h"

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
  using geometry::rotate;

  namespace
  {
    /// Inverse rigid placement: pair frame -> body frame.
    Vec2 to_body(const geometry::Placement &p, const Vec2 &x)
    {
      return rotate(x - p.centre, -p.angle);
    }
  } // namespace

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
                                     double slave_offset, long long hint_key) const
  {
    const ContactSurface &ms = surface(M);
    const auto &use          = scene.master_pieces[M - 1];
    const geometry::Placement PM = placed(scene, M, q);
    const Vec2 y                 = to_body(PM, xs);
    const auto hint = hint_key >= 0 ? hints_.find(hint_key) : hints_.end();
    // Closest point on the displaced master: project y - u_m(t), fixed point. It starts
    // from the hint, the last search's answer for this point, where there is one (one
    // projection fewer: the undisplaced y is only a start), else from the projection of y.
    const bool from_hint = hint != hints_.end() && hint->second.piece >= 0 && !hint->second.corner;
    const auto start_from_y = [&]() {
      out.pr = hint != hints_.end() ? ms.project_from(y, options_.search_distance, use, hint->second) :
                                      ms.project(y, options_.search_distance, use);
      if (out.pr.piece >= 0)
        out.face = ms.face_at(out.pr.piece, out.pr.t, out.shape);
      return out.pr.piece >= 0;
    };
    if (from_hint)
      out.pr = hint->second, out.face = ms.face_at(out.pr.piece, out.pr.t, out.shape);
    else if (!start_from_y())
      return false;
    thread_local std::vector<double> next_shape;
    for (int k = 0; k < 3; ++k)
      {
        const Vec2 um   = interpolate(M, out.face, out.shape);
        const auto next = ms.project_from(y - um, options_.search_distance, use, out.pr, &next_shape);
        if (next.piece < 0)
          {
            // Out of reach from the hint: start again from y, as without one.
            if (k == 0 && from_hint)
              {
                hints_.erase(hint);
                return project_point(scene, M, xs, q, out, slave_offset, hint_key);
              }
            break;
          }
        const bool same = next.piece == out.pr.piece && std::abs(next.t - out.pr.t) < 1e-12;
        out.pr          = next;
        out.face        = next.face;
        out.shape.swap(next_shape);
        if (same)
          break;
      }
    if (hint_key >= 0)
      hints_[hint_key] = out.pr;
    for (const int n : ms.faces()[out.face].nodes)
      if (!cache_[M - 1].node_zone[n])
        zone_breach_ = true;
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
              for (const int n : ss.faces()[sm.slave_face].nodes)
                if (!cS.node_zone[n])
                  zone_breach_ = true;
              sm.ds = pc.curve.d1(t).norm() * (face.t_hi - face.t_lo) * (face.xi[l + 1] - face.xi[l]) * gw[k];
              sm.gp.x       = pc.curve.point(t);
              const Vec2 us = interpolate(S, sm.slave_face, sm.slave_shape);
              const Vec2 xs = PS.apply(sm.gp.x) + PS.apply_vector(us);
              // Hint key: slave body, face, sub-segment and Gauss point.
              const long long key = ((((long long)(S) << 24) + f) * 64 + (long long)(l)) * 4 + k + (1LL << 40);
              ok = sm.slave_face == f && project_point(scene, M, xs, q, sm.gp, gap_offset(S, sm.gp.x), key) &&
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

  double TwoBodyContact::candidate_band(double q) const
  {
    const double approach = std::abs(q) * (drive_.kind == Drive::Kind::rotation ? cache_[0].r_max : 1.0);
    return std::max(options_.search_distance / 30, 2 * approach);
  }

  TwoBodyContact::SearchResult TwoBodyContact::search(const Scene &scene, double q, double band,
                                                      const std::vector<double> *lambda_node) const
  {
    const geometry::Placement P[2] = {placed(scene, 1, q), placed(scene, 2, q)};
    SearchResult r;
    std::vector<int> face_sample[2] = {std::vector<int>(s1_->faces().size(), -1),
                                       std::vector<int>(s2_->faces().size(), -1)};
    std::vector<Candidate> found;
    double g_min = std::numeric_limits<double>::infinity();
    for (const auto &[S, i] : slaves(scene))
      {
        if (!cache_[S - 1].node_zone[i])
          continue; // beyond the search distance by the zone's margin
        const auto &nd = surface(S).nodes()[i];
        const Vec2 xs = P[S - 1].apply(nd.x) + P[S - 1].apply_vector(displacement(S, i));
        Candidate c;
        c.S = S, c.node = i;
        if (!project_point(scene, 3 - S, xs, q, c.at, gap_offset(S, nd.x), ((long long)(S) << 32) + i))
          continue;
        c.at.x = nd.x;
        c.g    = c.at.g;
        g_min  = std::min(g_min, c.g);
        found.push_back(std::move(c));
      }
    // A node that carries a force, or shares a face with one, stays: its recovered pressure
    // (ContactSurface::recover_pressure spreads a face's force over the face's nodes) is
    // reported whatever its gap.
    const auto loaded = [&](const Candidate &c) {
      if (!lambda_node)
        return false;
      for (const int f : cache_[c.S - 1].node_faces[c.node])
        for (const int n : surface(c.S).faces()[f].nodes)
          if ((*lambda_node)[std::size_t(key(c.S, n))] != 0)
            return true;
      return (*lambda_node)[std::size_t(key(c.S, c.node))] != 0;
    };
    for (auto &c : found)
      {
        if (c.g > g_min + band && !loaded(c))
          continue;
        if (options_.gap == GapRule::integrated)
          integrate_gap(scene, q, c, r.samples, face_sample[c.S - 1]);
        r.cand.push_back(std::move(c));
      }
    return r;
  }
} // namespace gearfem::contact
