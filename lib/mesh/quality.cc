// Mesh quality: the angle, edge and aspect report, where an inverted cell lies, and the
// untangling of inverted cells by Laplacian smoothing of their free vertices.
#include "mesh/domain.h"
#include "base/units.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>

namespace gearfem::mesh
{
  QualityReport quality(const MeshData &mesh)
  {
    QualityReport r;
    r.n_cells    = mesh.cells.size();
    std::vector<char> used(mesh.vertices.size(), 0);
    for (const auto &c : mesh.cells)
      for (unsigned v : c)
        used[v] = 1;
    r.n_vertices = std::count(used.begin(), used.end(), 1);
    r.min_angle = 360, r.max_angle = 0, r.min_edge = 1e300, r.max_edge = 0;
    const double rad2deg = 180.0 / units::pi;
    for (const auto &c : mesh.cells)
      {
        const Vec2 p[4] = {mesh.vertices[c[0]], mesh.vertices[c[1]], mesh.vertices[c[3]],
                           mesh.vertices[c[2]]}; // counter-clockwise
        double lmin = 1e300, lmax = 0;
        bool inverted = false;
        for (int i = 0; i < 4; ++i)
          {
            const Vec2 a = p[(i + 1) % 4] - p[i], b = p[(i + 3) % 4] - p[i];
            const double cross = a.x() * b.y() - a.y() * b.x();
            if (cross <= 0)
              inverted = true;
            const double ang = std::atan2(std::abs(cross), a.dot(b)) * rad2deg;
            r.min_angle      = std::min(r.min_angle, inverted ? 0.0 : ang);
            r.max_angle      = std::max(r.max_angle, inverted ? 180.0 : ang);
            lmin             = std::min(lmin, a.norm());
            lmax             = std::max(lmax, a.norm());
          }
        r.n_inverted += inverted;
        r.max_aspect_ratio = std::max(r.max_aspect_ratio, lmax / lmin);
        r.min_edge         = std::min(r.min_edge, lmin);
        r.max_edge         = std::max(r.max_edge, lmax);
      }
    return r;
  }

  namespace
  {
    /// The corners of a cell counter-clockwise (gmsh/deal.II lexicographic order 0, 1, 3, 2).
    std::array<unsigned int, 4> ccw(const std::array<unsigned int, 4> &c) { return {c[0], c[1], c[3], c[2]}; }

    bool is_inverted(const MeshData &m, const std::array<unsigned int, 4> &c)
    {
      const auto q = ccw(c);
      for (int i = 0; i < 4; ++i)
        {
          const Vec2 a = m.vertices[q[(i + 1) % 4]] - m.vertices[q[i]], b = m.vertices[q[(i + 3) % 4]] - m.vertices[q[i]];
          if (a.x() * b.y() - a.y() * b.x() <= 0)
            return true;
        }
      return false;
    }
  } // namespace

  /// Where the first inverted cell is, and how many of its vertices lie on the boundary
  /// (those the untangling may not move), for the error message.
  std::string inverted_cell_location(const MeshData &m)
  {
    std::vector<char> on_boundary(m.vertices.size(), 0);
    for (const auto &e : m.boundary_edges)
      on_boundary[e.v0] = on_boundary[e.v1] = 1;
    for (const auto &c : m.cells)
      if (is_inverted(m, c))
        {
          Vec2 centre(0, 0);
          int  fixed = 0;
          for (unsigned v : c)
            centre += 0.25 * m.vertices[v], fixed += on_boundary[v];
          return " (the first at (" + to_string_g(centre.x() * 1e3) + ", " + to_string_g(centre.y() * 1e3) +
                 ") mm, radius " + to_string_g(centre.norm() * 1e3) + " mm, " + std::to_string(fixed) +
                 " of its 4 vertices on the boundary)";
        }
    return "";
  }


  int untangle_inverted_cells(MeshData &mesh, int sweeps)
  {
    auto inverted = [&] {
      std::vector<std::size_t> bad;
      for (std::size_t k = 0; k < mesh.cells.size(); ++k)
        if (is_inverted(mesh, mesh.cells[k]))
          bad.push_back(k);
      return bad;
    };
    std::vector<std::size_t> bad = inverted();
    if (bad.empty())
      return 0;
    std::vector<char> fixed(mesh.vertices.size(), 0);
    for (const auto &e : mesh.boundary_edges)
      fixed[e.v0] = fixed[e.v1] = 1;
    std::vector<std::vector<unsigned int>> nb(mesh.vertices.size()), cells_of(mesh.vertices.size());
    for (std::size_t k = 0; k < mesh.cells.size(); ++k)
      {
        const auto q = ccw(mesh.cells[k]);
        for (int i = 0; i < 4; ++i)
          {
            nb[q[i]].push_back(q[(i + 1) % 4]), nb[q[i]].push_back(q[(i + 3) % 4]);
            cells_of[q[i]].push_back(static_cast<unsigned int>(k));
          }
      }
    // The free vertices to smooth: those of the inverted cells, grown by one ring of cells
    // every 10 sweeps that did not untangle them.
    std::vector<char> active(mesh.vertices.size(), 0);
    for (const std::size_t k : bad)
      for (unsigned v : mesh.cells[k])
        active[v] = !fixed[v];
    for (int s = 0; s < sweeps && !bad.empty(); ++s)
      {
        if (s > 0 && s % 10 == 0)
          {
            std::vector<char> grown = active;
            for (std::size_t v = 0; v < active.size(); ++v)
              if (active[v])
                for (unsigned k : cells_of[v])
                  for (unsigned w : mesh.cells[k])
                    grown[w] = !fixed[w];
            active.swap(grown);
          }
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
          if (active[v] && !nb[v].empty())
            {
              Vec2 sum(0, 0);
              for (unsigned w : nb[v])
                sum += mesh.vertices[w];
              mesh.vertices[v] = sum / double(nb[v].size());
            }
        bad = inverted();
      }
    return static_cast<int>(bad.size());
  }
} // namespace gearfem::mesh
