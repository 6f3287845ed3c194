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
