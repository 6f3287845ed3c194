// Mesh module on domains with known geometry (annulus, rectangle): all-quad gmsh meshes,
// boundary ids through the import path and the .msh file, exact-curve manifolds.
#include "base/errors.h"
#include "mesh/domain.h"
#include "mesh/triangulation.h"

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>

using namespace gearfem;

namespace
{
  std::map<unsigned, int> count_boundary_ids(const dealii::Triangulation<2> &tria)
  {
    std::map<unsigned, int> n;
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary())
        ++n[face->boundary_id()];
    return n;
  }
} // namespace

// Reference: the annulus boundary is the pair of circles r = 10 mm and r = 20 mm exactly.
TEST(MeshDomain, AnnulusIdsManifoldsAndRefinement)
{
  const double a = 0.010, b = 0.020;
  const mesh::MeshData m = mesh::mesh_domain(mesh::annulus_domain(a, b, 0.002));
  const auto q           = mesh::quality(m);
  EXPECT_GT(q.n_cells, 50u);
  EXPECT_EQ(q.n_inverted, 0u);
  EXPECT_GT(q.min_angle, 20.0);
  EXPECT_LT(q.max_angle, 160.0);
  // gmsh vertices snapped onto the exact circles.
  for (const auto &e : m.boundary_edges)
    for (unsigned v : {e.v0, e.v1})
      {
        const double r = m.vertices[v].norm();
        EXPECT_NEAR(r, e.boundary_id == mesh::boundary::bore ? a : b, 1e-12);
      }

  dealii::Triangulation<2> tria;
  mesh::create_triangulation(m, tria);
  auto ids = count_boundary_ids(tria);
  ASSERT_EQ(ids.size(), 2u); // exactly bore (1) and outer (4) arrive
  EXPECT_GT(ids[mesh::boundary::bore], 10);
  EXPECT_GT(ids[mesh::boundary::outer], 10);

  // Requirement: after 2 global refinements the boundary vertices lie on the exact
  // curve to <= 1e-9 m (here: the circles, by their radius).
  tria.refine_global(2);
  double worst = 0;
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary())
      for (unsigned v = 0; v < 2; ++v)
        worst = std::max(worst, std::abs(face->vertex(v).norm() -
                                         (face->boundary_id() == mesh::boundary::bore ? a : b)));
  EXPECT_LE(worst, 1e-9);
  EXPECT_LE(mesh::max_boundary_vertex_distance(m, tria), 1e-9);
  // Ids survive refinement (4x the faces).
  auto ids2 = count_boundary_ids(tria);
  EXPECT_EQ(ids2[mesh::boundary::bore], 4 * ids[mesh::boundary::bore]);
}

// Reference: the physical groups written to the .msh file (format 4.1) must come back
// through deal.II's native stream reader with the same ids (PITFALLS.md: the file-name
// overload lost them in 9.4.1).
TEST(MeshDomain, MshFileKeepsPhysicalGroups)
{
  mesh::MeshingOptions opt;
  opt.msh_file = std::filesystem::temp_directory_path() / "gearfem_test_annulus.msh";
  const auto m = mesh::mesh_domain(mesh::annulus_domain(0.01, 0.02, 0.003), opt);
  ASSERT_TRUE(std::filesystem::exists(opt.msh_file));
  std::ifstream in(opt.msh_file);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "$MeshFormat");
  in.seekg(0);
  dealii::Triangulation<2> tria;
  dealii::GridIn<2> gi;
  gi.attach_triangulation(tria);
  gi.read_msh(in);
  EXPECT_EQ(tria.n_active_cells(), m.cells.size());
  auto ids = count_boundary_ids(tria);
  EXPECT_GT(ids[1], 0);
  EXPECT_GT(ids[4], 0);
  std::filesystem::remove(opt.msh_file);
}

// Reference: a rectangle has four straight sides with the documented ids 11..14 and area L H.
TEST(MeshDomain, RectangleAllQuadsAndArea)
{
  const double L = 0.1, H = 0.01;
  const auto m = mesh::mesh_domain(mesh::rectangle_domain(L, H, 0.002));
  double area  = 0;
  for (const auto &c : m.cells)
    {
      const auto &p0 = m.vertices[c[0]], &p1 = m.vertices[c[1]], &p2 = m.vertices[c[3]],
                 &p3 = m.vertices[c[2]];
      area += 0.5 * ((p2 - p0).x() * (p3 - p1).y() - (p2 - p0).y() * (p3 - p1).x());
    }
  EXPECT_NEAR(area, L * H, 1e-12 * L * H * 100);
  dealii::Triangulation<2> tria;
  mesh::create_triangulation(m, tria);
  auto ids = count_boundary_ids(tria);
  for (unsigned id : {11u, 12u, 13u, 14u})
    EXPECT_GT(ids[id], 0) << "id " << id;
}

// Bad input gets a named InputError.
TEST(MeshDomain, BadInput)
{
  EXPECT_THROW(mesh::annulus_domain(0.02, 0.01, 0.001), InputError);
  auto d   = mesh::annulus_domain(0.01, 0.02, 0.001);
  d.h_body = 0;
  EXPECT_THROW(mesh::mesh_domain(d), InputError);
  d.h_body = 0.001;
  d.growth = 1.0;
  EXPECT_THROW(mesh::mesh_domain(d), InputError);
}

TEST(MeshDomain, UntangleInvertedCells)
{
  // A 3 x 3 grid of unit quads on [0, 3]^2 (lexicographic corners 0, 1, 3, 2 as gmsh gives
  // them) with one interior vertex pushed across its neighbours, as a snap of a coarse
  // boundary vertex onto a curve can do: Laplacian smoothing of the free vertices must
  // untangle it (the closed form: a regular grid is its own Laplacian fixed point, so the
  // vertex returns to (1, 1)) and must not move a boundary vertex.
  mesh::MeshData m;
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i)
      m.vertices.emplace_back(i, j);
  auto id = [](int i, int j) { return static_cast<unsigned>(j * 4 + i); };
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      m.cells.push_back({id(i, j), id(i + 1, j), id(i, j + 1), id(i + 1, j + 1)});
  for (int i = 0; i < 3; ++i)
    for (auto [a, b] : {std::pair{id(i, 0), id(i + 1, 0)}, std::pair{id(i, 3), id(i + 1, 3)},
                        std::pair{id(0, i), id(0, i + 1)}, std::pair{id(3, i), id(3, i + 1)}})
      m.boundary_edges.push_back({a, b, 1});
  const auto before = m.vertices;
  EXPECT_EQ(mesh::untangle_inverted_cells(m), 0); // nothing inverted: untouched
  EXPECT_EQ(m.vertices, before);
  m.vertices[id(1, 1)] = mesh::Vec2(2.4, 2.3); // beyond the vertices (2, 1), (1, 2) and (2, 2)
  ASSERT_GT(mesh::quality(m).n_inverted, 0);
  EXPECT_EQ(mesh::untangle_inverted_cells(m), 0);
  EXPECT_EQ(mesh::quality(m).n_inverted, 0);
  for (int k = 0; k < 16; ++k)
    if (k != int(id(1, 1)) && k != int(id(2, 1)) && k != int(id(1, 2)) && k != int(id(2, 2)))
      EXPECT_EQ(m.vertices[k], before[k]) << "boundary vertex " << k << " moved";
  EXPECT_LT((m.vertices[id(1, 1)] - mesh::Vec2(1, 1)).norm(), 0.05);
}

// Reference (closed form): the point of a circle of radius r about c closest to q is
// c + r (q - c)/|q - c|, at the parameter atan2 of q - c. The contact search projects from a
// previous answer (closest_parameter_from): Newton first, the bracket t0 -/+ (hi - lo)/32
// checked only where Newton does not converge inside it.
TEST(MeshDomain, ClosestParameterFromAHint)
{
  const mesh::Vec2 c(0.01, -0.02);
  const double r  = 0.05;
  const auto circ = mesh::ParametricCurve::circle(c, r);
  const double lo = 0.2, hi = 2.8, dt = (hi - lo) / mesh::ParametricCurve::closest_samples;
  for (const double angle : {0.9, 1.4, 2.1})
    for (const double off : {0.0, 1e-3, -3e-3}) // inside, outside the circle
      {
        const mesh::Vec2 q = c + (r + off) * mesh::Vec2(std::cos(angle), std::sin(angle));
        bool ok            = false;
        mesh::Vec2 x, x1;
        const double t = circ.closest_parameter_from(q, lo, hi, angle + 0.4 * dt, ok, x, x1);
        ASSERT_TRUE(ok) << angle;
        EXPECT_NEAR(t, angle, 1e-13);
        EXPECT_NEAR(t, circ.closest_parameter(q, lo, hi), 1e-13); // the sampled search
        // The point and tangent Newton ended on are the curve's at t.
        EXPECT_LT((x - circ.point(t)).norm(), 1e-15);
        EXPECT_LT((x1 - circ.d1(t)).norm(), 1e-15);
        // The short form gives the same parameter.
        bool ok2 = false;
        EXPECT_EQ(circ.closest_parameter_from(q, lo, hi, angle + 0.4 * dt, ok2), t);
        EXPECT_TRUE(ok2);
      }
  // The minimum outside the hint's bracket, and a bracket reaching a piece end: not ok (the
  // caller then searches the whole surface).
  const mesh::Vec2 q = c + r * mesh::Vec2(std::cos(1.4), std::sin(1.4));
  bool ok            = true;
  circ.closest_parameter_from(q, lo, hi, 1.4 + 3 * dt, ok);
  EXPECT_FALSE(ok);
  ok = true;
  circ.closest_parameter_from(c + r * mesh::Vec2(std::cos(0.21), std::sin(0.21)), lo, hi, 0.21, ok);
  EXPECT_FALSE(ok);
}
