// A gear tooth in 3-D (three_d/solid_body.h) against its own 2-D section: a z 30, m 3 mm tooth
// of a 3-tooth sector, clamped at the bore and the cuts, under a normal flank load spread
// uniformly over the face near the tip. References (the same section mesh and elements in both):
// - thin faces (b = m/2, m/4): the 3-D deflection tends to the 2-D plane-stress one (sigma_zz -> 0);
// - nu = 0: the body is its section exactly (no coupling across the face);
// - a wide face (b = 10 m): the deflection in the middle is nearer plane strain than plane
//   stress, and the mean over the face lies between the two plane models; the variation along
//   the face is reported;
// - equilibrium: the applied load's resultant is the requested force;
// - the fillet's root stress along a wide face: its middle within 5 % of the plane-strain
//   section's (generalized plane strain), the much lower face ends reported;
// - the VTU file of the body.
#include "base/units.h"
#include "fem/tooth_load.h"
#include "mesh/domain.h"
#include "three_d/solid_body.h"

#include <deal.II/numerics/vector_tools.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using namespace gearfem;

namespace
{
  struct Section
  {
    geometry::ToothProfile tooth;
    mesh::GearMeshParameters mp;
    fem::FlankLoad load;
    mesh::Vec2 x, n; ///< evaluation point (under the patch's middle) and the load's outward normal
  };

  Section section()
  {
    geometry::GearParameters g;
    g.name = "Gear 1", g.teeth = 30, g.face_width = 10e-3;
    g.rack.module = 3e-3, g.rack.pressure_angle = 20 * units::deg;
    Section s{geometry::ToothProfile::generate(g), {}, {}, {}, {}};
    s.mp.model        = mesh::GearMeshParameters::Model::sector;
    s.mp.sector_teeth = 3;
    s.mp.h_contact = s.mp.h_fillet = 0.5e-3;
    s.mp.h_body                    = 3e-3;
    s.load.normal_force = 1000;
    s.load.patch_length = 1.0e-3;
    double r_top = 0;
    for (const int i : s.tooth.flank_segments(geometry::Side::drive))
      for (double t : {s.tooth.segments()[i].t0, s.tooth.segments()[i].t1})
        r_top = std::max(r_top, s.tooth.segments()[i].curve->point(t).norm());
    s.load.load_radius = r_top; // the patch ends at the flank's end: whole faces in both models
    // The load's direction is the flank normal at the patch's top, as fem::solve_flank_load takes
    // it; the deflection is read under the patch's middle.
    s.n = fem::flank_point_and_normal(s.tooth, 0, true, s.load.load_radius).second;
    s.x = fem::flank_point_and_normal(s.tooth, 0, true, s.load.load_radius - 0.5 * s.load.patch_length).first;
    s.x -= 0.05e-3 * s.n; // just inside: straight-sided cells do not hold the exact flank point
    return s;
  }

  /// The 2-D deflection at the load point along the load (-n) [m], plane stress or strain.
  double deflection_2d(const Section &s, double b, fem::PlaneModel model, std::unique_ptr<fem::ElasticBody> *body,
                       double nu = 0.3)
  {
    fem::Elasticity steel;
    steel.thickness = b, steel.model = model, steel.poisson_ratio = nu;
    fem::FeOptions fe;
    fe.degree = 1;
    dealii::Vector<double> u;
    fem::solve_flank_load(s.tooth, s.mp, steel, fe, s.load, body, &u);
    const auto d = (*body)->displacement_at(u, fem::Point2(s.x.x(), s.x.y()));
    return -(d[0] * s.n.x() + d[1] * s.n.y());
  }

  /// The 3-D body of the section `tria` over a face b in `layers`, clamped at the bore and the
  /// cuts, under the section's flank load spread uniformly over the face; its displacement u.
  std::unique_ptr<three_d::SolidBody> loaded_body(const Section &s, const dealii::Triangulation<2> &tria, double b,
                                                  int layers, double nu, dealii::Vector<double> &u,
                                                  double *resultant = nullptr)
  {
    fem::Elasticity steel;
    steel.poisson_ratio = nu;
    auto body = std::make_unique<three_d::SolidBody>(tria, steel, three_d::ExtrusionOptions{b, layers, 1});
    for (const auto id : {mesh::boundary::bore, mesh::boundary::cut_cw, mesh::boundary::cut_ccw})
      body->constrain(dealii::types::boundary_id(id));
    body->assemble_and_factorize();
    const double r_hi = s.load.load_radius, r_lo = r_hi - s.load.patch_length;
    three_d::Tensor3 t;
    t[0] = -s.n.x(), t[1] = -s.n.y();
    auto f = body->traction_load(
      t, {dealii::types::boundary_id(mesh::boundary::tooth_id(0, mesh::boundary::flank_drive))},
      [&](const three_d::Point3 &c) {
        const double r = std::hypot(c[0], c[1]);
        return r >= r_lo - 1e-12 && r <= r_hi + 1e-12;
      });
    f *= s.load.normal_force / body->resultant(f).norm();
    if (resultant)
      *resultant = body->resultant(f).norm();
    u = body->solve(f);
    return body;
  }

  /// The 3-D deflection along the load at the load point, at the given z [m].
  std::vector<double> deflection_3d(const Section &s, const fem::ElasticBody &body2d, double b, int layers,
                                    const std::vector<double> &z, double *resultant = nullptr, double nu = 0.3)
  {
    dealii::Vector<double> u;
    const auto body = loaded_body(s, body2d.triangulation(), b, layers, nu, u, resultant);
    std::vector<double> out;
    for (const double zk : z)
      {
        const auto d = body->displacement_at(u, three_d::Point3(s.x.x(), s.x.y(), zk));
        out.push_back(-(d[0] * s.n.x() + d[1] * s.n.y()));
      }
    return out;
  }
} // namespace

TEST(SolidBody, WithoutPoissonTheBodyIsItsSection)
{
  // nu = 0: no coupling across the face, so the extruded body under a load uniform along z is
  // its 2-D section exactly (the same cells and elements), for any face width and layering.
  const Section s = section();
  std::unique_ptr<fem::ElasticBody> b2;
  const double b  = 6e-3;
  const double d2 = deflection_2d(s, b, fem::PlaneModel::plane_stress, &b2, 0.0);
  const auto d3   = deflection_3d(s, *b2, b, 3, {0.0, 0.5 * b, b}, nullptr, 0.0);
  for (const double v : d3)
    EXPECT_NEAR(v / d2, 1.0, 1e-6);
}

TEST(SolidBody, WritesItsVtu)
{
  // The 3-D body as VTU (the viewer's file): written atomically, with the displacement field.
  const Section s = section();
  std::unique_ptr<fem::ElasticBody> b2;
  deflection_2d(s, 3e-3, fem::PlaneModel::plane_stress, &b2);
  fem::Elasticity steel;
  three_d::SolidBody body(b2->triangulation(), steel, {3e-3, 2, 1});
  body.constrain(dealii::types::boundary_id(mesh::boundary::bore));
  body.assemble_and_factorize();
  three_d::Tensor3 t;
  t[1] = -1e6;
  const auto u = body.solve(body.traction_load(t, {dealii::types::boundary_id(mesh::boundary::tooth_id(0, mesh::boundary::flank_drive))}));
  const auto file = std::filesystem::temp_directory_path() / "gearfem_test_solid_body.vtu";
  std::filesystem::remove(file);
  body.write_vtu(u, file, 1000);
  ASSERT_TRUE(std::filesystem::exists(file));
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<VTKFile"), std::string::npos);
  EXPECT_NE(text.find("NumberOfCells=\"" + std::to_string(body.n_cells()) + "\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"u\""), std::string::npos);
  std::filesystem::remove(file);
}

TEST(SolidBody, PlaneLimitsOfALoadedTooth)
{
  const Section s = section();
  const double m = 3e-3;
  std::unique_ptr<fem::ElasticBody> b2;
  // Thin faces, b = m/2 and m/4 in two layers: the 3-D deflection tends to plane stress as the
  // face thins. What is left is the clamp of u_z at the bore and the cuts (the plane model has
  // no u_z), which holds the Poisson contraction there and shrinks with b.
  double gap[2] = {0, 0};
  for (int k = 0; k < 2; ++k)
    {
      const double thin = (k == 0 ? 0.5 : 0.25) * m;
      const double stress = deflection_2d(s, thin, fem::PlaneModel::plane_stress, &b2);
      double R = 0;
      const auto d = deflection_3d(s, *b2, thin, 2, {0.0, 0.5 * thin, thin}, &R);
      EXPECT_NEAR(R, s.load.normal_force, 1e-9 * s.load.normal_force); // the load applied
      const double mean = (d[0] + 2 * d[1] + d[2]) / 4;
      gap[k] = mean / stress - 1;
      std::printf("thin face b = %.2f mm: 3-D %.4f um, 2-D plane stress %.4f um, 3-D / plane stress - 1 = %.2e\n",
                  thin * 1e3, mean * 1e6, stress * 1e6, gap[k]);
    }
  EXPECT_LT(std::abs(gap[0]), 0.01);
  EXPECT_LT(std::abs(gap[1]), std::abs(gap[0]));
  // A wide face, b = 10 m in 20 layers.
  const double wide = 10 * m;
  const double strain = deflection_2d(s, wide, fem::PlaneModel::plane_strain, &b2);
  const double stress = deflection_2d(s, wide, fem::PlaneModel::plane_stress, &b2);
  std::vector<double> z;
  for (int k = 0; k <= 20; ++k)
    z.push_back(wide * k / 20);
  const auto d = deflection_3d(s, *b2, wide, 20, z);
  double mean = 0, peak = 0;
  for (std::size_t k = 0; k + 1 < z.size(); ++k)
    mean += 0.5 * (d[k] + d[k + 1]) / 20; // trapezoidal mean over the face
  for (const double v : d)
    peak = std::max(peak, v);
  const double where = (d[10] - strain) / (stress - strain);
  std::printf("wide face b = %.0f mm: 2-D plane strain %.4f, plane stress %.4f um; 3-D middle %.4f um (%.2f of the "
              "way to plane stress), mean %.4f, face end %.4f, softest %.4f um\n",
              wide * 1e3, strain * 1e6, stress * 1e6, d[10] * 1e6, where, mean * 1e6, d[0] * 1e6, peak * 1e6);
  // The middle is settled (uniform along z there) and nearer plane strain than plane stress: a
  // free-ended body is in generalized plane strain there (eps_zz uniform plus bending, not 0),
  // which is softer than plane strain. Along the face the deflection is largest a few mm inside
  // the free ends and smaller at the ends themselves, where the clamped bore and cuts hold the
  // end faces (reported, not asserted).
  EXPECT_NEAR(d[9], d[10], 2e-3 * d[10]);
  EXPECT_GT(where, 0.0);
  EXPECT_LT(where, 0.5);
  EXPECT_GT(mean, strain);
  EXPECT_LT(mean, stress);
  EXPECT_NEAR(d[0], d[20], 1e-9 * d[0]); // a symmetric face
}

TEST(SolidBody, RootStressAlongTheFace)
{
  // The fillet's peak sigma_1 of the 2-D section (the tension side, at its peak point, read just
  // inside the body) against the 3-D body's along a wide face (b = 10 m). The plane models differ
  // by 3 % here (through the clamped bore and cuts); the face's middle is in generalized plane
  // strain, within 5 % of plane strain and above plane stress. The face ends, much lower, are
  // reported.
  const Section s = section();
  const double b = 30e-3;
  std::unique_ptr<fem::ElasticBody> b2;
  fem::Elasticity steel;
  steel.thickness = b;
  fem::FeOptions fe;
  fe.degree = 1;
  dealii::Vector<double> u2;
  const auto res = fem::solve_flank_load(s.tooth, s.mp, steel, fe, s.load, &b2, &u2);
  const auto xp  = res.fillet_peak.x;
  const double r = xp.norm();
  const fem::Point2 x_in = xp * ((r - 0.05e-3) / r);
  const auto sigma_1_2d  = [&](const fem::ElasticBody &body, const dealii::Vector<double> &u) {
    std::vector<dealii::Tensor<1, 2>> g(2);
    dealii::VectorTools::point_gradient(body.mapping(), body.dof_handler(), u, x_in, g);
    const auto st = body.material().stress(g[0][0], g[1][1], 0.5 * (g[0][1] + g[1][0]));
    return fem::principal_stresses(st[0], st[1], st[2])[0];
  };
  const double s2 = sigma_1_2d(*b2, u2);
  std::unique_ptr<fem::ElasticBody> b2e;
  dealii::Vector<double> u2e;
  fem::Elasticity strain = steel;
  strain.model = fem::PlaneModel::plane_strain;
  fem::solve_flank_load(s.tooth, s.mp, strain, fe, s.load, &b2e, &u2e);
  const double s2e = sigma_1_2d(*b2e, u2e);
  std::vector<double> z;
  for (int k = 0; k <= 20; ++k)
    z.push_back(b * k / 20);
  dealii::Vector<double> u;
  const auto body = loaded_body(s, b2->triangulation(), b, 20, 0.3, u);
  std::vector<double> s3;
  for (const double zk : z)
    {
      const auto sig = body->stress_at(u, three_d::Point3(x_in[0], x_in[1], zk));
      s3.push_back(dealii::eigenvalues(sig)[0]);
    }
  std::printf("root stress (sigma_1 at the 2-D peak, 0.05 mm inside): 2-D plane stress %.3f, plane strain %.3f MPa; "
              "3-D middle %.3f, face end %.3f, largest %.3f MPa\n",
              s2 / 1e6, s2e / 1e6, s3[10] / 1e6, s3[0] / 1e6, *std::max_element(s3.begin(), s3.end()) / 1e6);
  EXPECT_NEAR(s3[10] / s2e, 1.0, 0.05);
  EXPECT_GT(s3[10], s2);
  EXPECT_NEAR(s3[0], s3[20], 1e-6 * s3[0]);
}
