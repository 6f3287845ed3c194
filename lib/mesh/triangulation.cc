// MeshData -> deal.II Triangulation<2> with boundary ids and exact-curve manifolds.
#include "mesh/triangulation.h"

#include "base/errors.h"

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <set>

namespace gearfem::mesh
{
  namespace
  {
    using dealii::Point;

    /// A plane curve as a one-dimensional chart: pull_back = closest parameter,
    /// push_forward = curve point (deal.II ChartManifold<2, 2, 1>).
    class CurveManifold : public dealii::ChartManifold<2, 2, 1>
    {
    public:
      explicit CurveManifold(const BoundaryPiece &piece)
        : piece_(piece)
      {}
      std::unique_ptr<dealii::Manifold<2, 2>> clone() const override
      {
        return std::make_unique<CurveManifold>(piece_);
      }
      Point<1> pull_back(const Point<2> &x) const override
      {
        return Point<1>(piece_.curve.closest_parameter(Vec2(x[0], x[1]), piece_.t0, piece_.t1));
      }
      Point<2> push_forward(const Point<1> &t) const override
      {
        const Vec2 p = piece_.curve.point(t[0]);
        return Point<2>(p.x(), p.y());
      }
      dealii::DerivativeForm<1, 1, 2> push_forward_gradient(const Point<1> &t) const override
      {
        const Vec2 d = piece_.curve.d1(t[0]);
        dealii::DerivativeForm<1, 1, 2> g;
        g[0][0] = d.x();
        g[1][0] = d.y();
        return g;
      }

    private:
      BoundaryPiece piece_;
    };
  } // namespace

  void create_triangulation(const MeshData &mesh, dealii::Triangulation<2> &tria,
                            InteriorManifold interior)
  {
    std::vector<Point<2>> vertices;
    vertices.reserve(mesh.vertices.size());
    for (const auto &v : mesh.vertices)
      vertices.emplace_back(v.x(), v.y());
    std::vector<dealii::CellData<2>> cells(mesh.cells.size());
    for (std::size_t c = 0; c < mesh.cells.size(); ++c)
      {
        for (unsigned j = 0; j < 4; ++j)
          cells[c].vertices[j] = mesh.cells[c][j];
        cells[c].material_id = 0;
      }
    dealii::SubCellData sub;
    for (const auto &e : mesh.boundary_edges)
      {
        dealii::CellData<1> line;
        line.vertices[0]  = e.v0;
        line.vertices[1]  = e.v1;
        line.boundary_id  = e.boundary_id;
        line.manifold_id  = mesh.pieces[e.piece].straight ?
                              dealii::numbers::flat_manifold_id :
                              first_curve_manifold_id + e.piece;
        sub.boundary_lines.push_back(line);
      }
    dealii::GridTools::delete_unused_vertices(vertices, cells, sub);
    dealii::GridTools::consistently_order_cells(cells);
    tria.create_triangulation(vertices, cells, sub);

    for (std::size_t p = 0; p < mesh.pieces.size(); ++p)
      if (!mesh.pieces[p].straight)
        tria.set_manifold(first_curve_manifold_id + p, CurveManifold(mesh.pieces[p]));

    if (interior == InteriorManifold::none)
      return;
    bool any = false;
    for (const auto &cell : tria.active_cell_iterators())
      {
        bool touches = interior == InteriorManifold::all;
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->manifold_id() != dealii::numbers::flat_manifold_id)
            touches = true;
        if (!touches)
          continue;
        any = true;
        cell->set_manifold_id(transfinite_manifold_id);
        for (const auto f : cell->face_indices())
          if (!cell->face(f)->at_boundary())
            cell->face(f)->set_manifold_id(transfinite_manifold_id);
      }
    if (any)
      {
        dealii::TransfiniteInterpolationManifold<2> tfi;
        tfi.initialize(tria);
        tria.set_manifold(transfinite_manifold_id, tfi);
      }
  }

  double max_boundary_vertex_distance(const MeshData &mesh, const dealii::Triangulation<2> &tria)
  {
    double worst = 0.0;
    for (const auto &face : tria.active_face_iterators())
      {
        if (!face->at_boundary())
          continue;
        const auto mid = face->manifold_id();
        if (mid == dealii::numbers::flat_manifold_id || mid < first_curve_manifold_id)
          continue;
        const auto &piece = mesh.pieces.at(mid - first_curve_manifold_id);
        for (unsigned v = 0; v < 2; ++v)
          {
            const Vec2 x(face->vertex(v)[0], face->vertex(v)[1]);
            const Vec2 p = piece.curve.point(piece.curve.closest_parameter(x, piece.t0, piece.t1));
            worst        = std::max(worst, (p - x).norm());
          }
      }
    return worst;
  }
} // namespace gearfem::mesh
