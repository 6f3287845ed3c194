// The 3-D face of a gear pair (three_d/face_compliance.h, system_deflection/solid_face.h) against
// exact limits, on the Parker 50/50 m 3 pair's transverse section (a 3-tooth sector):
// - nu = 0: nothing couples the face, so a strip load uniform along the face deflects the 3-D
//   body exactly as its 2-D section (the same straight cells and elements): the rows of the
//   solid table sum to the section table; reciprocity makes the table symmetric;
// - nu = 0 through the whole route: the aligned spur pair, whose slices carry equal loads, is its
//   uncoupled sections exactly;
// - a thin face (b = m/2): the 3-D body tends to plane stress, the sections' model, so the
//   route's STE tends to the uncoupled sections';
// - a face 6.7 m wide is stiffer than its plane-stress sections (nearer plane strain).
#include "base/units.h"
#include "common/fixtures.h"
#include "condensed/cycle.h"
#include "helical/run.h"
#include "helical/slicing.h"
#include "solve/input.h"
#include "system_deflection/solid_face.h"
#include "three_d/face_compliance.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <memory>

using namespace gearfem;

namespace
{
  solve::GearContactInput parse(double face_width_mm)
  {
    dealii::ParameterHandler prm;
    solve::declare_gear_contact_input(prm);
    const std::string b = std::to_string(face_width_mm);
    prm.parse_input_from_string(test::parker_pair(R"(
subsection Mesh
  set Model = sector
  set Sector teeth = 3
  set h_contact = 0.1
  set h_fillet = 0.25
  set h_body = 3
end
subsection Solve
  set Positions = cycle
  set Number of positions = 6
  set Torques = 300
  set VTU = none
  set Plots = false
end
)") + "subsection Gear 1\n  set Face width = " + b + "\nend\nsubsection Gear 2\n  set Face width = " + b + "\nend\n");
    return solve::parse_gear_contact_input(prm);
  }

  /// A pair's section condensed over its grid, the slicing options with the 3-D face settings.
  struct Built
  {
    /// The 3-D settings: 1.5 mm cells of degree p, N slices.
    Built(double b_mm, double torque, unsigned p = 1, int N = 5)
      : in(parse(b_mm)), o(make_options(in, p, N)), model(in.model()),
        cycle(condensed::cycle_for(*model, in, {torque, torque / 8, 4 * torque}))
    {
    }
    static helical::SlicingOptions make_options(solve::GearContactInput &in, unsigned p, int N)
    {
      helical::HelixInput hx;
      hx.slices          = N;
      hx.coupling_length = 0;
      hx.model           = helical::FaceModel::solid;
      hx.solid.element_size = 1.5e-3, hx.solid.flank_points = 4, hx.solid.degree = p;
      return helical::slicing_options(in, hx, post::PostOptions());
    }
    solve::GearContactInput in;
    helical::SlicingOptions o;
    std::unique_ptr<contact::GearContactModel> model;
    condensed::CondensedCycle cycle;
  };

  Built &wide()
  {
    static Built b(20, 300);
    return b;
  }

  three_d::FaceOptions face_options(const helical::SlicingOptions &o)
  {
    three_d::FaceOptions f;
    f.face_width = o.helix.face_width, f.slices = o.slices, f.degree = o.solid.degree, f.radii = o.solid.flank_points;
    return f;
  }
} // namespace

TEST(FaceCompliance, WithoutPoissonAUniformStripLoadIsTheSection)
{
  Built &b = wide();
  fem::Elasticity steel = b.in.material[0];
  steel.poisson_ratio   = 0;
  const three_d::FaceCompliance face(b.in.pair->gear(1), system_deflection::solid_mesh(b.in, b.o, 1), steel,
                                     face_options(b.o));
  const auto &r = face.radii();
  std::printf("3-D body: %u cells, %u DoFs, %.2f s\n", face.n_cells(), face.n_dofs(), face.seconds());
  for (const double rr : {r[1], 0.5 * (r[1] + r[2])})
    for (int i = 0; i < b.o.slices; ++i)
      {
        double sum = 0;
        for (int j = 0; j < b.o.slices; ++j)
          sum += face.solid(i, rr, j, rr);
        EXPECT_NEAR(sum / face.section(rr, rr), 1.0, 1e-8) << "slice " << i << ", r " << rr;
      }
  // Reciprocity (Maxwell-Betti): the table is symmetric in load and reading.
  EXPECT_NEAR(face.solid(0, r[0], 3, r[2]), face.solid(3, r[2], 0, r[0]), 1e-12 * face.solid(0, r[0], 0, r[0]));
  EXPECT_GT(face.solid(2, r[2], 2, r[2]), face.solid(2, r[2], 0, r[2])); // a strip deflects most under itself
}

TEST(SolidFace, WithoutPoissonTheAlignedSpurPairIsItsSections)
{
  Built &b = wide();
  std::shared_ptr<const three_d::FaceCompliance> f[2];
  for (int i = 0; i < 2; ++i)
    {
      fem::Elasticity steel = b.in.material[i];
      steel.poisson_ratio   = 0;
      f[i] = std::make_shared<const three_d::FaceCompliance>(b.in.pair->gear(i + 1),
                                                             system_deflection::solid_mesh(b.in, b.o, i + 1), steel,
                                                             face_options(b.o));
    }
  helical::SlicingOptions solid = b.o;
  solid.face = [f](const std::vector<double> &r1, const std::vector<double> &r2) {
    return Eigen::MatrixXd(f[0]->correction(r1) + f[1]->correction(r2));
  };
  solid.face_root = [f](int g, const std::vector<double> &force, const std::vector<double> &r) {
    return f[g - 1]->section_load(force, r);
  };
  helical::SlicingOptions plain = b.o;
  plain.model = helical::FaceModel::slices;
  const helical::SlicedPair with(b.cycle, b.in, solid), without(b.cycle, b.in, plain);
  for (const auto &[name, phi] : b.cycle.positions)
    {
      const auto h = with.solve(phi, 300), s = without.solve(phi, 300);
      EXPECT_NEAR(h.ste, s.ste, 1e-9 * s.ste) << name;
      EXPECT_NEAR(h.root_stress_pinion, s.root_stress_pinion, 1e-8 * s.root_stress_pinion) << name;
      EXPECT_NEAR(h.root_stress_gear, s.root_stress_gear, 1e-8 * s.root_stress_gear) << name;
      EXPECT_NEAR(h.k_h_beta, 1.0, 1e-8) << name;
    }
}

TEST(SolidFace, AThinFaceIsPlaneStressAndAWideOneStiffer)
{
  // b = m/2: the 3-D STE within 1 % of the plane-stress sections', and the largest root stress
  // within 2 % (quadratic cells); b = 20 mm = 6.7 m: a lower STE (the middle of a wide face is
  // nearer plane strain).
  for (const double b_mm : {1.5, 20.0})
    {
      const double T = 300 * b_mm / 20;
      std::unique_ptr<Built> thin;
      if (b_mm < 2)
        thin = std::make_unique<Built>(b_mm, T, 2, 3); // the fillet stress needs p = 2 (p = 1: +3 %)
      Built &b = thin ? *thin : wide();
      helical::SlicingOptions plain = b.o;
      plain.model = helical::FaceModel::slices;
      const auto solid = system_deflection::with_solid_face(b.in, b.o);
      const helical::SlicedPair with(b.cycle, b.in, solid), without(b.cycle, b.in, plain);
      double mean3 = 0, mean2 = 0, root3 = 0, root2 = 0;
      for (const auto &[name, phi] : b.cycle.positions)
        {
          const auto h = with.solve(phi, T), s = without.solve(phi, T);
          mean3 += h.ste, mean2 += s.ste;
          root3 = std::max(root3, h.root_stress_pinion), root2 = std::max(root2, s.root_stress_pinion);
        }
      const double ratio = mean3 / mean2;
      std::printf("b = %g mm: mean STE 3-D / plane-stress sections = %.4f, largest root stress %.4f\n", b_mm, ratio,
                  root3 / root2);
      if (b_mm < 2)
        {
          EXPECT_NEAR(ratio, 1.0, 0.01);
          EXPECT_NEAR(root3 / root2, 1.0, 0.02);
        }
      else
        EXPECT_LT(ratio, 0.99);
    }
}
