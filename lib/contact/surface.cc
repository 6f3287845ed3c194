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
    /// Distance from q to the segment [a, b].
    double segment_distance(const Vec2 &q, const Vec2 &a, const Vec2 &b)
    {
      const Vec2 ab   = b - a;
      const double l2 = ab.squaredNorm();
      const double s  = l2 > 0 ? std::clamp((q - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
      return (q - a - s * ab).norm();
    }
    /// Index along one axis of the grid cell of coordinate x (origin o, cell size h, n
    /// cells), clamped into the grid.
    int grid_cell(double x, double o, double h, int n)
    {
      return std::clamp(int(std::floor((x - o) / h)), 0, n - 1);
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

    index_pieces();
  }

  void ContactSurface::index_pieces()
  {
    const auto &mesh = body_->mesh();
    piece_box_.assign(mesh.pieces.size(), {Vec2(0, 0), Vec2(0, 0)});
    piece_samples_.assign(mesh.pieces.size(), {});
    piece_sag_.assign(mesh.pieces.size(), 0.0);
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
        // The samples of closest_parameter (the same parameters, so the same answer), and
        // the largest distance of the curve from their chords at a quarter, the middle and
        // three quarters of each, doubled: the curves are smooth at this spacing.
        const int m     = mesh::ParametricCurve::closest_samples;
        const double a  = std::min(pc.t0, pc.t1), b = std::max(pc.t0, pc.t1);
        auto &samples   = piece_samples_[p];
        samples.resize(m + 1);
        for (int i = 0; i <= m; ++i)
          samples[i] = pc.curve.point(a + (b - a) * i / m);
        double sag = 0;
        for (int i = 0; i < m; ++i)
          for (const double f : {0.25, 0.5, 0.75})
            sag = std::max(sag, segment_distance(pc.curve.point(a + (b - a) * (i + f) / m), samples[i], samples[i + 1]));
        piece_sag_[p] = 2 * sag + 1e-12 + 1e-9 * (b - a) * pc.curve.d1(0.5 * (a + b)).norm();
      }
    // The grid: about as many cells as surface pieces, square.
    Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
    int n = 0;
    for (std::size_t p = 0; p < mesh.pieces.size(); ++p)
      if (surface_piece_[p])
        lo = lo.cwiseMin(piece_box_[p][0]), hi = hi.cwiseMax(piece_box_[p][1]), ++n;
    const Vec2 span = (hi - lo).cwiseMax(Vec2(1e-9, 1e-9));
    grid_.cell      = std::sqrt(span.x() * span.y() / std::max(n, 1));
    grid_.origin    = lo;
    grid_.nx        = std::max(1, int(std::ceil(span.x() / grid_.cell)));
    grid_.ny        = std::max(1, int(std::ceil(span.y() / grid_.cell)));
    grid_.pieces.assign(std::size_t(grid_.nx) * grid_.ny, {});
    for (std::size_t p = 0; p < mesh.pieces.size(); ++p)
      {
        if (!surface_piece_[p])
          continue;
        const auto index       = [&](double x, double o, int m) { return grid_cell(x, o, grid_.cell, m); };
        const auto &[blo, bhi] = piece_box_[p];
        for (int j = index(blo.y(), lo.y(), grid_.ny); j <= index(bhi.y(), lo.y(), grid_.ny); ++j)
          for (int i = index(blo.x(), lo.x(), grid_.nx); i <= index(bhi.x(), lo.x(), grid_.nx); ++i)
            grid_.pieces[std::size_t(j) * grid_.nx + i].push_back(int(p));
      }
  }

  void ContactSurface::pieces_near(const Vec2 &q, double reach, std::vector<int> &out) const
  {
    out.clear();
    const auto cell = [&](double x, double o, int n) { return grid_cell(x, o, grid_.cell, n); };
    const Vec2 lo = q - Vec2(reach, reach), hi = q + Vec2(reach, reach);
    const Vec2 glo = grid_.origin, ghi = grid_.origin + grid_.cell * Vec2(grid_.nx, grid_.ny);
    if (grid_.nx == 0 || hi.x() < glo.x() || hi.y() < glo.y() || lo.x() > ghi.x() || lo.y() > ghi.y())
      return;
    const int i0 = cell(lo.x(), glo.x(), grid_.nx), i1 = cell(hi.x(), glo.x(), grid_.nx);
    const int j0 = cell(lo.y(), glo.y(), grid_.ny), j1 = cell(hi.y(), glo.y(), grid_.ny);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        {
          const auto &c = grid_.pieces[std::size_t(j) * grid_.nx + i];
          out.insert(out.end(), c.begin(), c.end());
        }
    if (i0 != i1 || j0 != j1)
      {
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
      }
  }

  double ContactSurface::distance_lower_bound(const Vec2 &q, double reach) const
  {
    thread_local std::vector<int> near;
    pieces_near(q, reach, near);
    double d = 2 * reach + 1;
    for (const int p : near)
      if (box_distance(q, piece_box_[p][0], piece_box_[p][1]) <= reach)
        d = std::min(d, distance_bound(p, q));
    return d;
  }

  double ContactSurface::distance_bound(int p, const Vec2 &q) const
  {
    const auto &samples = piece_samples_[p];
    double d            = 1e300;
    for (std::size_t i = 0; i + 1 < samples.size(); ++i)
      d = std::min(d, segment_distance(q, samples[i], samples[i + 1]));
    return d - piece_sag_[p];
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
                                          const Projection &hint, std::vector<double> *shape) const
  {
    const auto full = [&]() {
      Projection p = project(q, max_distance, use_piece);
      if (shape && p.piece >= 0)
        face_at(p.piece, p.t, *shape);
      return p;
    };
    if (hint.piece < 0 || hint.corner)
      return full();
    const auto &pc  = body_->mesh().pieces[hint.piece];
    const double lo = std::min(pc.t0, pc.t1), hi = std::max(pc.t0, pc.t1);
    bool ok         = false;
    Vec2 x, tau;
    const double t  = pc.curve.closest_parameter_from(q, lo, hi, hint.t, ok, x, tau);
    if (!ok)
      return full();
    Projection p;
    p.piece = hint.piece, p.t = t, p.point = x;
    if ((q - p.point).norm() > max_distance)
      return Projection();
    thread_local std::vector<double> own;
    p.face = face_at(p.piece, p.t, shape ? *shape : own);
    if (pc.t1 < pc.t0)
      tau = -tau;
    tau.normalize();
    p.normal          = Vec2(tau.y(), -tau.x()); // as outward_normal, from Newton's tangent
    p.signed_distance = (q - p.point).dot(p.normal);
    return p;
  }

  Projection ContactSurface::project(const Vec2 &q, double max_distance,
                                     const std::vector<bool> &use_piece) const
  {
    const auto &pieces = body_->mesh().pieces;
    // Distances within `tie` are equal; the choice among the pieces nearest to q is made
    // in piece order below, and only those pieces take part in it.
    const auto tie = [](double d) { return 1e-12 + 1e-9 * d; };
    // Pieces in reach by their lower bound; the exact distance first on the one with the
    // least bound: every piece whose bound exceeds that distance by more than a few ties is
    // farther than the nearest and cannot take part in the choice (nor change it).
    thread_local std::vector<std::pair<int, double>> reach; // per call; kept to spare the allocation
    reach.clear();
    int first = -1;
    thread_local std::vector<int> near;
    pieces_near(q, max_distance, near);
    for (const int p : near)
      {
        if (!use_piece.empty() && !use_piece[p])
          continue;
        if (box_distance(q, piece_box_[p][0], piece_box_[p][1]) > max_distance)
          continue;
        const double lb = distance_bound(p, q);
        if (lb > max_distance + 10 * tie(max_distance))
          continue;
        if (first < 0 || lb < reach[first].second)
          first = int(reach.size());
        reach.emplace_back(p, lb);
      }
    const auto closest = [&](int p, double &t, Vec2 &x) {
      const auto &pc  = pieces[p];
      const double lo = std::min(pc.t0, pc.t1), hi = std::max(pc.t0, pc.t1);
      t               = pc.curve.closest_parameter(q, lo, hi, piece_samples_[p]);
      x               = pc.curve.point(t);
      return (q - x).norm();
    };
    double t_first = 0, d_first = 1e300;
    Vec2 x_first;
    if (first >= 0)
      d_first = closest(reach[first].first, t_first, x_first);
    Projection best;
    double best_d = 1e300;
    bool best_interior = false;
    for (std::size_t r = 0; r < reach.size(); ++r)
      {
        const int p = reach[r].first;
        if (reach[r].second > d_first + 10 * tie(d_first))
          continue;
        double t = t_first, d = d_first;
        Vec2 x   = x_first;
        if (int(r) != first)
          d = closest(p, t, x);
        const auto &pc  = pieces[p];
        const double lo = std::min(pc.t0, pc.t1), hi = std::max(pc.t0, pc.t1);
        const double eps = 1e-9 * (hi - lo);
        const bool interior = t > lo + eps && t < hi - eps;
        // Prefer an interior projection at (numerically) equal distance.
        if (d < best_d - tie(d) || (std::abs(d - best_d) <= tie(d) && interior && !best_interior))
          {
            best_d = d, best_interior = interior;
            best.piece = p, best.t = t, best.point = x;
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
    pieces_near(best.point, scale, near);
    for (const int p : near)
      {
        if (found)
          break;
        if (p == best.piece)
          continue;
        for (const double t : {pieces[p].t0, pieces[p].t1})
          if ((pieces[p].curve.point(t) - best.point).norm() < scale)
            {
              n_other = outward_normal(p, t);
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
