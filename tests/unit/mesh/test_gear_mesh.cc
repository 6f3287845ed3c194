// Gear meshes: every supported tooth shape meshes into valid quads, the physical groups of
// each tooth arrive in deal.II, and refinement follows the exact outline.
#include "base/errors.h"
#include "base/units.h"
#include "mesh/gear_mesh.h"
#include "mesh/triangulation.h"

#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <gtest/gtest.h>

#include <map>

using namespace gearfem;

namespace
{
  geometry::ToothProfile make_tooth(int z, double x = 0.0, double m = 3.0)
  {
    geometry::GearParameters g;
    g.name                = "Gear 1";
    g.teeth               = z;
    g.profile_shift       = x;
    g.face_width          = 20 * units::mm;
    g.rack.module         = m * units::mm;
    g.rack.pressure_angle = 20 * units::deg;
    return geometry::ToothProfile::generate(g);
  }

  std::map<unsigned, int> ids_of(const dealii::Triangulation<2> &tria)
  {
    std::map<unsigned, int> n;
    for (const auto &f : tria.active_face_iterators())
      if (f->at_boundary())
        ++n[f->boundary_id()];
    return n;
  }

  /// The gear meshed by tiles (mesh_gear_tiled); empty with the reason in `why` when refused.
  mesh::MeshData mesh_tiled(const geometry::ToothProfile &tooth, mesh::GearMeshParameters p, std::string &why)
  {
    p.tiled = true;
    mesh::MeshingOptions o;
    o.samples_per_piece = p.spline_samples;
    return mesh::mesh_gear_tiled(tooth, p, o, &why);
  }

  /// Conformity: every cell edge is shared by two cells or is a boundary edge, and every
  /// boundary edge belongs to one cell only (closed cuts, no hanging or doubled vertex).
  void expect_conforming(const mesh::MeshData &m)
  {
    std::map<std::pair<unsigned, unsigned>, int> edges;
    for (const auto &c : m.cells)
      for (const auto &[a, b] : {std::pair{c[0], c[1]}, {c[1], c[3]}, {c[3], c[2]}, {c[2], c[0]}})
        ++edges[{std::min(a, b), std::max(a, b)}];
    std::size_t once = 0;
    for (const auto &[e, n] : edges)
      {
        EXPECT_LE(n, 2);
        once += n == 1;
      }
    EXPECT_EQ(once, m.boundary_edges.size());
    for (const auto &e : m.boundary_edges)
      EXPECT_EQ(edges.at({std::min(e.v0, e.v1), std::max(e.v0, e.v1)}), 1);
  }
} // namespace

// Reference: the exact outline of the geometry module (each boundary vertex must lie on
// its curve to 1e-9 m after two refinements), and the id scheme of meshes/README.md.
TEST(GearMesh, SectorIdsAndExactBoundary)
{
  for (const auto &[z, x] : std::vector<std::pair<int, double>>{{50, 0.0}, {19, 0.0}, {100, 0.0}, {50, 0.5}})
    {
      const auto tooth = make_tooth(z, x);
      mesh::GearMeshParameters p;
      p.model        = mesh::GearMeshParameters::Model::sector;
      p.sector_teeth = 3;
      p.h_contact = p.h_fillet = 0.3e-3;
      p.h_body                 = 2e-3;
      const auto m             = mesh::mesh_gear(tooth, p);
      const auto q             = mesh::quality(m);
      EXPECT_EQ(q.n_inverted, 0u) << "z " << z;
      EXPECT_GT(q.min_angle, 10.0) << "z " << z;
      dealii::Triangulation<2> tria;
      mesh::create_triangulation(m, tria);
      auto ids = ids_of(tria);
      for (int k : {z - 1, 0, 1})
        for (auto c : {mesh::boundary::flank_drive, mesh::boundary::flank_coast,
                       mesh::boundary::fillet_drive, mesh::boundary::fillet_coast,
                       mesh::boundary::tip})
          EXPECT_GT(ids[mesh::boundary::tooth_id(k, c)], 0) << "z " << z << " tooth " << k << " code " << c;
      EXPECT_GT(ids[mesh::boundary::bore], 0);
      EXPECT_GT(ids[mesh::boundary::cut_cw], 0);
      EXPECT_GT(ids[mesh::boundary::cut_ccw], 0);
      tria.refine_global(2);
      EXPECT_LE(mesh::max_boundary_vertex_distance(m, tria), 1e-9) << "z " << z;
    }
}

// Reference: a full gear has z teeth, each with its four groups, and a bore circle.
TEST(GearMesh, FullGearFineTeeth)
{
  const auto tooth = make_tooth(50);
  mesh::GearMeshParameters p;
  p.h_contact = 0.25e-3;
  p.h_fillet  = 0.25e-3;
  p.h_body    = 4e-3;
  const auto m = mesh::mesh_gear(tooth, p);
  std::cout << "full 50-tooth gear: " << m.cells.size() << " cells, meshed in " << m.mesh_seconds
            << " s" << std::endl;
  dealii::Triangulation<2> tria;
  mesh::create_triangulation(m, tria);
  auto ids = ids_of(tria);
  for (int k = 0; k < 50; ++k)
    EXPECT_GT(ids[mesh::boundary::tooth_id(k, mesh::boundary::flank_drive)], 0) << k;
  // Fine teeth (auto: -2..2) carry many more flank faces than the coarse ones.
  const int fine   = ids[mesh::boundary::tooth_id(0, mesh::boundary::flank_drive)];
  const int coarse = ids[mesh::boundary::tooth_id(25, mesh::boundary::flank_drive)];
  EXPECT_GT(fine, 3 * coarse);
  EXPECT_EQ(mesh::fine_teeth(p, 50), (std::vector<int>{0, 1, 2, 48, 49}));
  // The cell estimate that bounds meshing (and stops the model choice's refinement) against
  // the mesh it estimates: within a factor 2 of the cells gmsh made.
  const double estimate = mesh::estimated_cells(p, tooth);
  std::cout << "estimated " << estimate << " cells" << std::endl;
  EXPECT_GT(estimate, 0.5 * double(m.cells.size()));
  EXPECT_LT(estimate, 2.0 * double(m.cells.size()));
  // Beyond mesh::max_cells the estimate and meshing agree: a named refusal before gmsh runs.
  p.h_contact = p.h_fillet = 5e-6;
  EXPECT_GT(mesh::estimated_cells(p, tooth), mesh::max_cells);
  EXPECT_THROW(mesh::mesh_gear(tooth, p), InputError);
}

// Bad input gets named errors.
TEST(GearMesh, BadInput)
{
  const auto tooth = make_tooth(50);
  mesh::GearMeshParameters p;
  p.model        = mesh::GearMeshParameters::Model::sector;
  p.sector_teeth = 0;
  EXPECT_THROW(mesh::gear_domain(tooth, p), InputError);
  p.sector_teeth = 3;
  p.h_contact    = 5e-3;
  EXPECT_THROW(mesh::gear_domain(tooth, p), InputError); // h_contact > h_body
  p.h_contact = -1;
  EXPECT_THROW(mesh::gear_domain(tooth, p), InputError);
  p.h_contact   = 0.3e-3;
  p.model       = mesh::GearMeshParameters::Model::full_gear;
  p.bore_radius = 80e-3; // root radius is 71.25 mm
  EXPECT_THROW(mesh::gear_domain(tooth, p), InputError);
  p.bore_radius   = 0;
  p.rim_thickness = 75e-3;
  EXPECT_THROW(mesh::gear_domain(tooth, p), InputError);
  p.rim_thickness = 0;
  p.fine_teeth    = "0, a";
  EXPECT_THROW(mesh::gear_domain(tooth, p), InputError);
}

// A fine contact mesh (m/40) with a coarse coast flank (h_coast / h_contact = 3.3) on the
// Parker gear (z 50, m 3, bore 25 mm). Before the coast-corner transition, gmsh's Blossom
// recombination left two triangles at each fine coast tip corner and the mesher fell back
// to subdivision (40 s per gear, angles down to 7 deg). Reference: the quality of the same
// gear at h_coast = 0.15 mm, which meshes without the transition (angles >= 32 deg).
TEST(GearMesh, FineContactCoarseCoastRecombines)
{
  const auto tooth = make_tooth(50);
  mesh::GearMeshParameters p;
  p.h_contact   = 0.075e-3;
  p.h_coast     = 0.25e-3;
  p.bore_radius = 25e-3;
  const auto m  = mesh::mesh_gear(tooth, p);
  const auto q  = mesh::quality(m);
  EXPECT_FALSE(m.subdivided);
  EXPECT_EQ(q.n_inverted, 0u);
  EXPECT_GT(q.min_angle, 25.0);
  std::cout << "Parker gear at h_contact m/40: " << m.cells.size() << " cells, angles "
            << q.min_angle << "-" << q.max_angle << " deg, meshed in " << m.mesh_seconds << " s"
            << std::endl;
}

// The root lands between the coarse teeth of a full gear are one edge much shorter than the
// fillets beside them (FZG type C gear, z 24, m 4.5, x 0.1715: 0.64 mm against h 1.8 mm).
// gmsh's Blossom recombination left triangle pairs there, its retries failed alike, and the
// mesher fell back to subdivision (20 s, angles down to 11 deg). The mesh graded to those
// pieces recombines. Reference: the quality of the gears that recombine at once (angles
// >= 29 deg above), and the root circle r_f = m (z/2 - 1.25 + x) for the root-land vertices.
TEST(GearMesh, ShortRootLandsRecombine)
{
  const double m_n = 4.5, x = 0.1715;
  const int z      = 24;
  const auto tooth = make_tooth(z, x, m_n);
  mesh::GearMeshParameters p;
  p.h_contact  = 0.3e-3;
  const auto m = mesh::mesh_gear(tooth, p);
  const auto q = mesh::quality(m);
  EXPECT_FALSE(m.subdivided);
  EXPECT_EQ(q.n_inverted, 0u);
  EXPECT_GT(q.min_angle, 30.0);
  EXPECT_LT(q.max_angle, 150.0);
  const double r_f = m_n * (z / 2.0 - 1.25 + x) * units::mm;
  int on_root      = 0;
  for (const auto &e : m.boundary_edges)
    {
      const unsigned code = mesh::boundary::code_of(e.boundary_id);
      if (code == mesh::boundary::root_drive || code == mesh::boundary::root_coast)
        for (unsigned v : {e.v0, e.v1})
          {
            EXPECT_NEAR(m.vertices[v].norm(), r_f, 1e-9);
            ++on_root;
          }
    }
  EXPECT_GE(on_root, 4 * z);
  std::cout << "FZG C gear 2 at h_contact 0.3 mm: " << m.cells.size() << " cells, angles " << q.min_angle << "-"
            << q.max_angle << " deg, meshed in " << m.mesh_seconds << " s" << std::endl;
}

// Tooth placement offsets (a pitch deviation built into the geometry). Reference: tooth k's
// outline is tooth 0's turned by 2 pi k / z + delta_k (counter-clockwise for delta_k > 0), and
// neighbouring teeth meet on the root circle at the mean of their offsets.
TEST(GearMesh, ToothAnglesTurnTheTeethAndCloseTheOutline)
{
  const int z      = 20;
  const auto tooth = make_tooth(z);
  mesh::GearMeshParameters p;
  p.h_contact = p.h_fillet = 0.5e-3;
  p.h_body                 = 3e-3;
  p.fine_teeth             = "3";
  p.tooth_angles.assign(z, 0.0);
  p.tooth_angles[3] = 3e-4, p.tooth_angles[4] = -2e-4;
  const double pi = units::pi;
  ASSERT_GT(mesh::max_tooth_angle_step(tooth), 5e-4);
  const mesh::Domain d = mesh::gear_domain(tooth, p);
  const auto &pieces   = d.loops.at(0).pieces;
  for (std::size_t i = 0; i < pieces.size(); ++i)
    EXPECT_LT((pieces[i].end() - pieces[(i + 1) % pieces.size()].start()).norm(), 1e-12) << "piece " << i;
  // The drive flank of tooth 3 at mid-parameter: the nominal flank turned by 6 pi / z + delta_3.
  const auto &segs = tooth.segments();
  for (std::size_t s = 0; s < segs.size(); ++s)
    if (segs[s].type == geometry::SegmentType::flank && segs[s].side == geometry::Side::drive)
      {
        const mesh::Vec2 q = segs[s].point(0.5);
        const double a     = 2 * pi * 3 / z + 3e-4;
        const mesh::Vec2 expected(std::cos(a) * q.x() - std::sin(a) * q.y(), std::sin(a) * q.x() + std::cos(a) * q.y());
        double nearest = 1; // the flank may be split into pieces (tip-corner grading)
        for (const auto &pc : pieces)
          if (pc.boundary_id == mesh::boundary::tooth_id(3, mesh::boundary::flank_drive))
            {
              const double t = pc.curve.closest_parameter(expected, std::min(pc.t0, pc.t1), std::max(pc.t0, pc.t1));
              nearest        = std::min(nearest, (pc.curve.point(t) - expected).norm());
            }
        EXPECT_LT(nearest, 1e-10);
      }
  // Root lands: tooth 3 starts at the mean of delta_2 = 0 and delta_3, and ends at the mean of
  // delta_3 and delta_4, on the root circle.
  const double rf = tooth.radii().root;
  for (const auto &pc : pieces)
    if (pc.tooth == 3 && pc.segment == 0)
      {
        EXPECT_NEAR(std::atan2(pc.start().y(), pc.start().x()), pi / 2 - pi / z + 2 * pi * 3 / z + 1.5e-4, 1e-12);
        EXPECT_NEAR(pc.start().norm(), rf, 1e-12);
      }
    else if (pc.tooth == 3 && pc.segment == int(segs.size()) - 1)
      {
        EXPECT_NEAR(std::atan2(pc.end().y(), pc.end().x()), pi / 2 + pi / z + 2 * pi * 3 / z + 0.5e-4, 1e-12);
        EXPECT_NEAR(pc.end().norm(), rf, 1e-12);
      }
  // Meshed: valid quads, and every vertex of tooth 3's drive flank lies on the turned flank,
  // 3e-4 rad x r (about 9 um) away from the nominal one.
  const auto m = mesh::mesh_gear(tooth, p);
  EXPECT_EQ(mesh::quality(m).n_inverted, 0u);
  dealii::Triangulation<2> tria;
  mesh::create_triangulation(m, tria);
  EXPECT_LE(mesh::max_boundary_vertex_distance(m, tria), 1e-9);
  double worst_turned = 0, least_nominal = 1;
  int n = 0;
  for (std::size_t s = 0; s < segs.size(); ++s)
    if (segs[s].type == geometry::SegmentType::flank && segs[s].side == geometry::Side::drive)
      {
        const auto turned  = mesh::ParametricCurve::from(segs[s].curve, 2 * pi * 3 / z + 3e-4);
        const auto nominal = mesh::ParametricCurve::from(segs[s].curve, 2 * pi * 3 / z);
        const double lo = std::min(segs[s].t0, segs[s].t1), hi = std::max(segs[s].t0, segs[s].t1);
        for (const auto &f : tria.active_face_iterators())
          if (f->at_boundary() && f->boundary_id() == mesh::boundary::tooth_id(3, mesh::boundary::flank_drive))
            for (unsigned v = 0; v < 2; ++v)
              {
                const mesh::Vec2 x(f->vertex(v)[0], f->vertex(v)[1]);
                worst_turned  = std::max(worst_turned, (turned.point(turned.closest_parameter(x, lo, hi)) - x).norm());
                least_nominal = std::min(least_nominal, (nominal.point(nominal.closest_parameter(x, lo, hi)) - x).norm());
                ++n;
              }
      }
  EXPECT_GT(n, 10);
  EXPECT_LT(worst_turned, 1e-9);
  EXPECT_GT(least_nominal, 0.5 * 3e-4 * tooth.radii().base);
  // Refused: a wrong count, and a step between neighbours beyond half a root land.
  p.tooth_angles.resize(z - 1);
  EXPECT_THROW(mesh::gear_domain(tooth, p), InputError);
  p.tooth_angles.assign(z, 0.0);
  p.tooth_angles[5] = 1.01 * mesh::max_tooth_angle_step(tooth);
  EXPECT_THROW(mesh::gear_domain(tooth, p), InputError);
}

// The tiles of validation/model_choice's random 1 gear (z 28, m 2.5, x 0.06) at h_contact
// m/30 and h_fillet m/12: gmsh places the graded nodes of a cut in the two tiles meeting on it
// up to 4e-11 m apart, which a tolerance of 1e-9 of the tip radius refused, sending the gear to
// the whole-gear mesher (5.9 s instead of 0.5 s). Reference: the tiles join (not refused), and
// the joined mesh is conforming with no inverted cell, as TiledTeethJoinIntoTheWholeGear checks.
TEST(GearMesh, TilesJoinDespiteGmshRoundingOnTheCuts)
{
  const auto tooth = make_tooth(28, 0.06, 2.5);
  mesh::GearMeshParameters p;
  p.h_contact = 2.5e-3 / 30;
  p.h_fillet  = 2.5e-3 / 12;
  std::string why;
  const auto tiled = mesh_tiled(tooth, p, why);
  ASSERT_FALSE(tiled.cells.empty()) << why;
  EXPECT_EQ(mesh::quality(tiled).n_inverted, 0u);
  expect_conforming(tiled);
}

// A full gear meshed by tiles (Mesh/Tiled teeth). References: the same gear meshed whole
// (the same boundary ids on the same teeth, the same area of the polygonal cells to the
// chord error of the outline, 3e-3), the exact outline (every boundary vertex on its piece's
// curve), and conformity (every cell edge is shared by two cells or is a boundary edge: the
// cuts between the tiles are closed, no hanging or doubled vertex).
TEST(GearMesh, TiledTeethJoinIntoTheWholeGear)
{
  const int z      = 20;
  const auto tooth = make_tooth(z);
  mesh::GearMeshParameters p;
  p.h_contact      = 0.15e-3;
  p.h_fillet       = 0.25e-3;
  const auto whole = mesh::mesh_gear(tooth, p);
  std::string why;
  const auto tiled = mesh_tiled(tooth, p, why);
  ASSERT_FALSE(tiled.cells.empty()) << why;
  const auto q     = mesh::quality(tiled);
  EXPECT_FALSE(tiled.subdivided);
  EXPECT_EQ(q.n_inverted, 0u);
  EXPECT_GT(q.min_angle, 25.0); // the whole gear: 27.5-158.5 deg on the Parker gear
  EXPECT_LT(q.max_angle, 155.0);

  expect_conforming(tiled);

  auto area = [](const mesh::MeshData &m) {
    double a = 0;
    for (const auto &c : m.cells)
      {
        const auto &p0 = m.vertices[c[0]], &p1 = m.vertices[c[1]], &p2 = m.vertices[c[3]], &p3 = m.vertices[c[2]];
        a += 0.5 * ((p2 - p0).x() * (p3 - p1).y() - (p2 - p0).y() * (p3 - p1).x());
      }
    return a;
  };
  // The bore's chords differ (3 mm edges on a 13 mm radius lose 0.18 % of the area).
  EXPECT_NEAR(area(tiled) / area(whole), 1.0, 3e-3);

  std::map<unsigned, int> ids_whole, ids_tiled;
  for (const auto &e : whole.boundary_edges)
    ++ids_whole[e.boundary_id];
  for (const auto &e : tiled.boundary_edges)
    {
      ++ids_tiled[e.boundary_id];
      const auto &piece = tiled.pieces.at(std::size_t(e.piece));
      EXPECT_EQ(piece.boundary_id, e.boundary_id);
      if (e.boundary_id >= 1000)
        EXPECT_EQ(piece.tooth, mesh::boundary::tooth_of(e.boundary_id));
      for (const unsigned v : {e.v0, e.v1})
        {
          const auto x = tiled.vertices[v];
          EXPECT_LT((piece.curve.point(piece.curve.closest_parameter(x, piece.t0, piece.t1)) - x).norm(), 1e-9);
        }
    }
  ASSERT_EQ(ids_tiled.size(), ids_whole.size());
  for (const auto &[id, n] : ids_whole)
    EXPECT_GT(ids_tiled[id], 0) << "boundary id " << id;

  // Into deal.II as the whole gear is.
  dealii::Triangulation<2> tria;
  mesh::create_triangulation(tiled, tria);
  EXPECT_EQ(tria.n_active_cells(), tiled.cells.size());
  std::cout << "z 20 m 3 gear: tiled " << tiled.cells.size() << " cells, angles " << q.min_angle << "-" << q.max_angle
            << " deg, " << tiled.mesh_seconds << " s; whole " << whole.cells.size() << " cells, " << whole.mesh_seconds
            << " s" << std::endl;
}

// A coarse tooth's tile whose first quad recombination leaves triangles is meshed again a
// little finer, not graded to its short half root lands. The 41-tooth pinion of
// validation/model_choice's random 1 (m 2.5, x +0.5) at the choice's companion sizes: at
// h_tooth 2 mm gmsh's Blossom left four triangles in the coarse tile, whose graded remesh had
// 91 cells instead of about 35 (4223 cells in the gear against 2088 at h_tooth 1.8 mm).
// Reference: monotonicity in the size asked for: a coarser outline on the unloaded teeth
// must not give more cells than a finer one; and the joined mesh is conforming with no
// inverted cell.
TEST(GearMesh, ACoarseTileThatFailsToRecombineIsNotGraded)
{
  const auto tooth = make_tooth(41, 0.5, 2.5);
  mesh::GearMeshParameters p;
  p.h_contact  = 2.5e-3 / 22.5;
  p.h_fillet   = 2.5e-3 / 6;
  p.h_body     = 3.75e-3;
  p.fine_teeth = "0";
  std::map<double, std::size_t> cells;
  for (const double h : {1.8e-3, 2.0e-3})
    {
      p.h_tooth = h;
      std::string why;
      const auto tiled = mesh_tiled(tooth, p, why);
      ASSERT_FALSE(tiled.cells.empty()) << why;
      EXPECT_EQ(mesh::quality(tiled).n_inverted, 0u);
      expect_conforming(tiled);
      cells[h] = tiled.cells.size();
    }
  std::cout << "z 41 m 2.5 x +0.5 pinion: " << cells[1.8e-3] << " cells at h_tooth 1.8 mm, " << cells[2.0e-3]
            << " at 2 mm" << std::endl;
  EXPECT_LE(cells[2.0e-3], cells[1.8e-3]);
}
