// ContactSurface: boundary nodes and faces of one body, closest-point projection onto the
// exact curves, face interpolation.
#include "contact/surface.h"

#include "base/errors.h"

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace gearfem::contact
{
  namespace
  {
    double lagrange(const std::vector<double> &xi, std::size_t j, double x)
    {
      double v = 1.0;
      for (std::size_t k = 0; k < xi.size(); ++k)
        if (k != j)
          v *= (x - xi[k]) / (xi[j] - xi[k]);
      return v;
    }
    double box_distance(const Vec2 &q, const Vec2 &lo, const Vec2 &hi)
    {
      const double dx = std::max({lo.x() - q.x(), 0.0, q.x() - hi.x()});
      const double dy = std::max({lo.y() - q.y(), 0.0, q.y() - hi.y()});
      return std::hypot(dx, dy);
    }
  } // namespace

  ContactSurface::ContactSurface(const fem::ElasticBody &body, const std::set<unsigned int> &ids)
    : body_(&body)
    , ids_(ids)
  {
    const auto &mesh   = body.mesh();
    const auto &fe     = body.fe();
    const auto &points = body.dof_points();
    piece_faces_.assign(mesh.pieces.size(), {});
    surface_piece_.assign(mesh.pieces.size(), false);
    std::unordered_map<unsigned int, int> node_of_dof;
    std::vector<dealii::types::global_dof_index> fd(fe.dofs_per_face);

    for (const auto &cell : body.dof_handler().active_cell_iterators())
      for (const auto f : cell->face_indices())
        {
          if (!cell->at_boundary(f) || ids.count(cell->face(f)->boundary_id()) == 0)
            continue;
          const unsigned int id = cell->face(f)->boundary_id();
          cell->face(f)->get_dof_indices(fd);
          // Support nodes of the face: x DoF and the y DoF at the same point.
          std::vector<std::pair<unsigned int, unsigned int>> face_nodes;
          for (unsigned int i = 0; i < fd.size(); ++i)
            {
              if (fe.face_system_to_component_index(i).first != 0)
                continue;
              unsigned int dy = fd[i];
              for (unsigned int j = 0; j < fd.size(); ++j)
                if (fe.face_system_to_component_index(j).first == 1 &&
                    points[fd[j]].distance(points[fd[i]]) < 1e-14)
                  dy = fd[j];
              face_nodes.emplace_back(fd[i], dy);
            }
          // The piece of the face: the piece with this id closest to the face's centre.
          Vec2 centre(0, 0);
          for (const auto &fn : face_nodes)
            centre += Vec2(points[fn.first][0], points[fn.first][1]);
          centre /= double(face_nodes.size());
          int piece = -1;
          double best = 1e300;
          for (std::size_t p = 0; p < mesh.pieces.size(); ++p)
            {
              const auto &pc = mesh.pieces[p];
              if (pc.boundary_id != id)
                continue;
              const double lo = std::min(pc.t0, pc.t1), hi = std::max(pc.t0, pc.t1);
              const double t  = pc.curve.closest_parameter(centre, lo, hi);
              const double d  = (pc.curve.point(t) - centre).norm();
              if (d < best)
                best = d, piece = int(p);
            }
          if (piece < 0)
            throw SolverError("contact surface: boundary id " + std::to_string(id) +
                              " has faces but no exact curve piece");
          const auto &pc  = mesh.pieces[piece];
          const double lo = std::min(pc.t0, pc.t1), hi = std::max(pc.t0, pc.t1);
          surface_piece_[piece] = true;

          SurfaceFace face;
          face.piece = piece;
          std::vector<std::pair<double, int>> by_t;
          for (const auto &fn : face_nodes)
            {
              const Vec2 x(points[fn.first][0], points[fn.first][1]);
              const double t = pc.curve.closest_parameter(x, lo, hi);
              auto it        = node_of_dof.find(fn.first);
              int node;
              if (it == node_of_dof.end())
                {
                  SurfaceNode nd;
                  nd.x = x, nd.dof_x = fn.first, nd.dof_y = fn.second, nd.piece = piece, nd.t = t;
                  nd.boundary_id = id, nd.tooth = pc.tooth, nd.segment = pc.segment;
                  node = int(nodes_.size());
                  nodes_.push_back(nd);
                  node_of_dof.emplace(fn.first, node);
                }
              else
                node = it->second;
              by_t.emplace_back(t, node);
            }
          std::sort(by_t.begin(), by_t.end());
          face.t_lo = by_t.front().first, face.t_hi = by_t.back().first;
          if (!(face.t_hi > face.t_lo))
            throw SolverError("contact surface: degenerate face on boundary id " + std::to_string(id));
          for (const auto &[t, node] : by_t)
            {
              face.nodes.push_back(node);
              face.xi.push_back((t - face.t_lo) / (face.t_hi - face.t_lo));
            }
          // Consistent nodal weights: integral of N_j |X'(t)| dt, 4-point Gauss.
          const double *gx = gauss4_x, *gw = gauss4_w;
          face.w.assign(face.nodes.size(), 0.0);
          for (int k = 0; k < 4; ++k)
            {
              const double t  = face.t_lo + gx[k] * (face.t_hi - face.t_lo);
              const double ds = pc.curve.d1(t).norm() * (face.t_hi - face.t_lo) * gw[k];
              face.length += ds;
              for (std::size_t j = 0; j < face.nodes.size(); ++j)
                face.w[j] += lagrange(face.xi, j, gx[k]) * ds;
            }
          for (std::size_t j = 0; j < face.nodes.size(); ++j)
            nodes_[face.nodes[j]].weight += face.w[j];
          piece_faces_[piece].push_back(int(faces_.size()));
          faces_.push_back(std::move(face));
        }
    if (faces_.empty())
      throw InputError("contact surface", "boundary ids of the body",
                       "ids with at least one boundary face");
    for (auto &pf : piece_faces_)
      std::sort(pf.begin(), pf.end(), [&](int a, int b) { return faces_[a].t_lo < faces_[b].t_lo; });

    piece_box_.assign(mesh.pieces.size(), {Vec2(0, 0), Vec2(0, 0)});
    for (std::size_t p = 0; p < mesh.pieces.size(); ++p)
      {
        if (!surface_piece_[p])
          continue;
        const auto &pc = mesh.pieces[p];
        Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
        const int n = 64;
        for (int k = 0; k <= n; ++k)
          {
            const Vec2 x = pc.curve.point(pc.t0 + (pc.t1 - pc.t0) * k / n);
            lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
          }
        const double pad = 0.02 * (hi - lo).norm() + 1e-9; // chord sag between samples
        piece_box_[p] = {lo - Vec2(pad, pad), hi + Vec2(pad, pad)};
      }
  }

  Vec2 ContactSurface::outward_normal(int piece, double t) const
  {
    const auto &pc  = body_->mesh().pieces[piece];
    Vec2 tau        = pc.curve.d1(t);
    if (pc.t1 < pc.t0)
      tau = -tau;
    tau.normalize();
    return Vec2(tau.y(), -tau.x());
  }

  Projection ContactSurface::project_from(const Vec2 &q, double max_distance, const std::vector<bool> &use_piece,
                                          const Projection &hint) const
  {
    if (hint.piece < 0 || hint.corner)
      return project(q, max_distance, use_piece);
    const auto &pc  = body_->mesh().pieces[hint.piece];
    const double lo = std::min(pc.t0, pc.t1), hi = std::max(pc.t0, pc.t1);
    bool ok         = false;
    const double t  = pc.curve.closest_parameter_from(q, lo, hi, hint.t, ok);
    if (!ok)
      return project(q, max_distance, use_piece);
    Projection p;
    p.piece = hint.piece, p.t = t, p.point = pc.curve.point(t);
    if ((q - p.point).norm() > max_distance)
      return Projection();
    std::vector<double> shape;
    p.face            = face_at(p.piece, p.t, shape);
    p.normal          = outward_normal(p.piece, p.t);
    p.signed_distance = (q - p.point).dot(p.normal);
    return p;
  }

  Projection ContactSurface::project(const Vec2 &q, double max_distance,
                                     const std::vector<bool> &use_piece) const
  {
    const auto &pieces = body_->mesh().pieces;
    Projection best;
    double best_d = 1e300;
    bool best_interior = false;
    for (std::size_t p = 0; p < pieces.size(); ++p)
      {
        if (!surface_piece_[p] || (!use_piece.empty() && !use_piece[p]))
          continue;
        if (box_distance(q, piece_box_[p][0], piece_box_[p][1]) > max_distance)
          continue;
        const auto &pc  = pieces[p];
        const double lo = std::min(pc.t0, pc.t1), hi = std::max(pc.t0, pc.t1);
        const double t  = pc.curve.closest_parameter(q, lo, hi);
        const Vec2 x    = pc.curve.point(t);
        const double d  = (q - x).norm();
        const double eps = 1e-9 * (hi - lo);
        const bool interior = t > lo + eps && t < hi - eps;
        // Prefer an interior projection at (numerically) equal distance.
        const double tie = 1e-12 + 1e-9 * d;
        if (d < best_d - tie || (std::abs(d - best_d) <= tie && interior && !best_interior))
          {
            best_d = d, best_interior = interior;
            best.piece = int(p), best.t = t, best.point = x;
          }
      }
    if (best.piece < 0 || best_d > max_distance)
      return Projection();
    std::vector<double> shape;
    best.face   = face_at(best.piece, best.t, shape);
    best.normal = outward_normal(best.piece, best.t);
    if (best_interior)
      {
        best.signed_distance = (q - best.point).dot(best.normal);
        return best;
      }
    // At a piece end: look for the neighbouring surface piece that starts or ends there.
    const double scale = 1e-9 * std::max(1e-3, best.point.norm());
    Vec2 n_other       = best.normal;
    bool found         = false;
    for (std::size_t p = 0; p < pieces.size() && !found; ++p)
      {
        if (!surface_piece_[p] || int(p) == best.piece)
          continue;
        for (const double t : {pieces[p].t0, pieces[p].t1})
          if ((pieces[p].curve.point(t) - best.point).norm() < scale)
            {
              n_other = outward_normal(int(p), t);
              found   = true;
              break;
            }
      }
    const double turn = std::acos(std::clamp(n_other.dot(best.normal), -1.0, 1.0));
    if (!found || turn < 1e-3)
      {
        best.signed_distance = (q - best.point).dot(best.normal);
        best.corner          = !found;
        return best;
      }
    best.corner = true;
    if (best_d < 1e-14)
      {
        best.normal          = (best.normal + n_other).normalized();
        best.signed_distance = 0;
        return best;
      }
    const Vec2 dir = (q - best.point) / best_d;
    if (dir.dot(best.normal) < 0 && dir.dot(n_other) < 0)
      best.normal = -dir, best.signed_distance = -best_d; // inside, at a convex corner
    else
      best.normal = dir, best.signed_distance = best_d;   // outside: point-to-point normal
    return best;
  }

  int ContactSurface::face_at(int piece, double t, std::vector<double> &shape) const
  {
    const auto &pf = piece_faces_.at(piece);
    if (pf.empty())
      throw SolverError("contact surface: piece " + std::to_string(piece) + " has no faces");
    auto it = std::upper_bound(pf.begin(), pf.end(), t,
                               [&](double v, int f) { return v < faces_[f].t_lo; });
    const int f = it == pf.begin() ? pf.front() : *(it - 1);
    const auto &face = faces_[f];
    const double xi  = std::clamp((t - face.t_lo) / (face.t_hi - face.t_lo), 0.0, 1.0);
    shape.resize(face.nodes.size());
    for (std::size_t j = 0; j < face.nodes.size(); ++j)
      shape[j] = lagrange(face.xi, j, xi);
    return f;
  }

  std::vector<double> ContactSurface::recover_pressure(const std::vector<double> &force, double b) const
  {
    std::vector<double> p(nodes_.size(), 0.0);
    for (const auto &f : faces_)
      {
        double pf = 0;
        for (std::size_t j = 0; j < f.nodes.size(); ++j)
          {
            const auto &nd = nodes_[f.nodes[j]];
            if (nd.weight > 0)
              pf += force[f.nodes[j]] * f.w[j] / nd.weight;
          }
        pf /= b * f.length;
        for (std::size_t j = 0; j < f.nodes.size(); ++j)
          {
            const auto &nd = nodes_[f.nodes[j]];
            if (nd.weight > 0)
              p[f.nodes[j]] += pf * f.w[j] / nd.weight;
          }
      }
    return p;
  }

  std::vector<int> ContactSurface::nodes_on_piece(int piece) const
  {
    std::vector<int> out;
    for (std::size_t i = 0; i < nodes_.size(); ++i)
      if (nodes_[i].piece == piece)
        out.push_back(int(i));
    std::sort(out.begin(), out.end(), [&](int a, int b) { return nodes_[a].t < nodes_[b].t; });
    return out;
  }
} // namespace gearfem::contact
