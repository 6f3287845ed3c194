// The gear pair on its shafts (system_deflection/coupled.h), on the Parker pair's spur section
// (3-tooth sectors, 10 positions, condensed once) sliced over its 20 mm face. References:
// - the aligned limit: shafts far stiffer than the mesh leave the spur face uniform (K_Hbeta 1);
// - superposition: the influence coefficients reproduce a direct solve of the shafts under the
//   converged slice forces (an independent path through shafts::solve);
// - statics: the pinion shaft's bearings carry the slices' forces;
// - the fixed point: the mismatch the shafts give under the converged forces is the one applied;
// - the lead correction's purpose: K_Hbeta <= 1.05 at its design torque, verified by the coupled
//   solve (ISO 6336-1's aim for a corrected lead), and above 1 away from it.
#include "base/errors.h"
#include "base/units.h"
#include "common/fixtures.h"
#include "condensed/cycle.h"
#include "helical/run.h"
#include "helical/slicing.h"
#include "solve/input.h"
#include "system_deflection/coupled.h"
#include "system_deflection/run.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace gearfem;

namespace
{
  solve::GearContactInput parse()
  {
    dealii::ParameterHandler prm;
    solve::declare_gear_contact_input(prm);
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
  set Number of positions = 10
  set Torques = 300
  set VTU = none
  set Plots = false
end
)"));
    return solve::parse_gear_contact_input(prm);
  }

  struct Built
  {
    solve::GearContactInput in = parse();
    helical::SlicingOptions base = helical::slicing_options(in, helical::HelixInput(), post::PostOptions());
    std::unique_ptr<contact::GearContactModel> model = in.model();
    condensed::CondensedCycle cycle = condensed::cycle_for(*model, in, {300, 30, 1200});
  };
  Built &built()
  {
    static Built b;
    return b;
  }

  helical::SlicingOptions spur(int slices)
  {
    auto o            = built().base;
    o.slices          = slices;
    o.coupling_length = o.helix.m_n;
    return o;
  }

  /// An overhung pinion (bearings at 0 and 60 mm, the face 80-100 mm, shaft d) and a straddled
  /// gear (bearings at 0 and 120 mm, the face 50-70 mm, shaft 70 mm), 150 mm apart.
  void layout(shafts::System &sys, shafts::MeshLayout &mesh, double d)
  {
    shafts::Shaft p, g;
    p.name = "pinion shaft", p.segments = {{0.1, d, 0}};
    g.name = "gear shaft", g.segments = {{0.12, 0.07, 0}}, g.x = 0.15;
    sys.shafts = {p, g};
    const auto bearing = [](int shaft, double z, bool locating) {
      shafts::Bearing b;
      b.name = "b", b.shaft = shaft, b.z = z, b.radial = shafts::rigid;
      b.axial = b.torsional = locating ? shafts::rigid : 0.0;
      return b;
    };
    sys.bearings = {bearing(0, 0, true), bearing(0, 0.06, false), bearing(1, 0, true), bearing(1, 0.12, false)};
    mesh.pinion_shaft = 0, mesh.gear_shaft = 1;
    mesh.pinion_face_start = 0.08, mesh.gear_face_start = 0.05;
    mesh.face_width     = 0.02;
    mesh.alpha_wt       = built().in.pair->working_pressure_angle();
    mesh.pitch_radius_1 = 0.075;
  }
} // namespace

TEST(SystemDeflection, StiffShaftsLeaveTheFaceAligned)
{
  auto &b = built();
  const helical::SlicedPair pair(b.cycle, b.in, spur(9));
  shafts::System sys;
  shafts::MeshLayout mesh;
  layout(sys, mesh, 0.5);
  sys.shafts[1].segments[0].outer_diameter = 0.5;
  const system_deflection::CoupledPair coupled(pair, sys, mesh);
  const auto r = coupled.solve(b.cycle.positions[4].second, 300, helical::LeadModification());
  EXPECT_NEAR(r.helical.k_h_beta, 1.0, 1e-3);
  EXPECT_LE(r.residual, 1e-9);
}

TEST(SystemDeflection, OverhungPinionConvergesToTheFixedPointAndBalances)
{
  auto &b = built();
  const helical::SlicedPair pair(b.cycle, b.in, spur(9));
  shafts::System sys;
  shafts::MeshLayout mesh;
  layout(sys, mesh, 0.035);
  const system_deflection::CoupledPair coupled(pair, sys, mesh);
  const double phi = b.cycle.positions[4].second;
  const auto r     = coupled.solve(phi, 300, helical::LeadModification());
  EXPECT_LE(r.residual, 1e-9);
  EXPECT_GE(r.iterations, 2);
  // The free end of the overhang gives way most: the load moves to the bearing side (z < 0 is
  // the face start, nearer the bearings).
  EXPECT_GT(r.helical.k_h_beta, 1.05);
  EXPECT_GT(r.helical.slices.front().load_per_width, r.helical.slices.back().load_per_width);
  // Superposition: a direct solve of the shafts under the converged forces.
  const auto s = coupled.shafts_under(r);
  std::vector<double> zf;
  for (const double z : r.z)
    zf.push_back(z + 0.01);
  const auto direct = shafts::mesh_approach(sys, s, mesh, zf);
  double scale = 0, worst = 0;
  for (std::size_t k = 0; k < zf.size(); ++k)
    scale = std::max(scale, std::abs(r.approach[k]));
  for (std::size_t k = 0; k < zf.size(); ++k)
    worst = std::max(worst, std::abs(direct[k] - r.approach[k]));
  EXPECT_LE(worst, 1e-10 * scale);
  // The fixed point: the mismatch under the converged forces is the one applied.
  for (std::size_t k = 0; k < zf.size(); ++k)
    EXPECT_NEAR(r.mismatch[k], *std::max_element(direct.begin(), direct.end()) - direct[k], 2e-9);
  // Statics: the pinion shaft's bearings carry the slices' forces (T1 / r_b1 in all).
  Eigen::Vector3d R = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < 2; ++i)
    R += s.reactions[i].force;
  EXPECT_NEAR(R.norm(), 300 / b.in.pair->base_radius(1), 1e-9 * 300 / b.in.pair->base_radius(1));
}

TEST(SystemDeflection, LeadCorrectionMakesTheLoadUniformAtItsTorque)
{
  auto &b = built();
  const helical::SlicedPair pair(b.cycle, b.in, spur(9));
  shafts::System sys;
  shafts::MeshLayout mesh;
  layout(sys, mesh, 0.035);
  const system_deflection::CoupledPair coupled(pair, sys, mesh);
  const std::vector<double> phis = {b.cycle.positions[2].second, b.cycle.positions[5].second,
                                    b.cycle.positions[8].second};
  const auto d = system_deflection::design_correction(coupled, phis, 300, helical::LeadModification());
  double worst = 0;
  for (const auto &r : d.results)
    worst = std::max(worst, r.helical.k_h_beta);
  EXPECT_LE(worst, 1.05);
  EXPECT_GT(std::abs(d.correction.slope) + std::abs(d.correction.crowning), 1e-6); // not a null correction
  // Away from the design torque the shafts bend by more (2T) or less (T/2) than corrected for.
  const auto lead = coupled.corrected(helical::LeadModification(), d.correction);
  for (const double T : {150.0, 600.0})
    EXPECT_GT(coupled.solve(phis[1], T, lead).helical.k_h_beta, 1.0 + 1e-3) << T << " N m";
}

TEST(SystemDeflection, BadLayoutsAreNamed)
{
  auto &b = built();
  const helical::SlicedPair pair(b.cycle, b.in, spur(5));
  shafts::System sys;
  shafts::MeshLayout mesh;
  layout(sys, mesh, 0.035);
  mesh.face_width = 0.03; // not the pair's
  EXPECT_THROW(system_deflection::CoupledPair(pair, sys, mesh), InputError);
  layout(sys, mesh, 0.035);
  mesh.pinion_face_start = 0.09; // the face runs off the shaft's end
  EXPECT_THROW(system_deflection::CoupledPair(pair, sys, mesh), InputError);
}

TEST(SystemDeflection, TrainOfTwoPairsOnSeparateShaftsIsEachPairAlone)
{
  // Two copies of the overhung layout in one system (shafts 0-1 and 2-3, apart): the train's
  // joint fixed point and influence matrix must decouple into each pair's own solution, at its
  // own position and torque (independence of the blocks).
  auto &b = built();
  const helical::SlicedPair pair(b.cycle, b.in, spur(7));
  shafts::System one, two;
  shafts::MeshLayout m1, m2;
  layout(one, m1, 0.035);
  layout(two, m2, 0.045); // a stiffer pinion shaft: a different mismatch
  shafts::System both = one;
  for (auto sh : two.shafts)
    sh.y = 0.5, both.shafts.push_back(sh);
  for (auto br : two.bearings)
    br.shaft += 2, both.bearings.push_back(br);
  const shafts::MeshLayout m2_alone = m2;
  m2.pinion_shaft = 2, m2.gear_shaft = 3;
  const system_deflection::CoupledTrain train({{&pair, m1}, {&pair, m2}}, both);
  const double p1 = b.cycle.positions[3].second, p2 = b.cycle.positions[7].second;
  const auto r = train.solve({p1, p2}, {300, 200}, {helical::LeadModification(), helical::LeadModification()});
  ASSERT_EQ(r.size(), 2u);
  const system_deflection::CoupledPair alone1(pair, one, m1), alone2(pair, two, m2_alone);
  const auto a1 = alone1.solve(p1, 300, helical::LeadModification());
  const auto a2 = alone2.solve(p2, 200, helical::LeadModification());
  // The influence of one pair's slices on the other's approach is zero.
  const auto &A = train.influence();
  EXPECT_EQ(A.block(0, 7, 7, 7).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(A.block(7, 0, 7, 7).cwiseAbs().maxCoeff(), 0.0);
  for (std::size_t k = 0; k < 7; ++k)
    {
      // Both at their fixed points to the tolerance (1e-9 m): the joint iteration stops later.
      EXPECT_NEAR(r[0].mismatch[k], a1.mismatch[k], 3e-9) << k;
      EXPECT_NEAR(r[1].mismatch[k], a2.mismatch[k], 3e-9) << k;
      EXPECT_NEAR(r[0].helical.slices[k].force, a1.helical.slices[k].force, 1e-3 * a1.helical.normal_force) << k;
      EXPECT_NEAR(r[1].helical.slices[k].force, a2.helical.slices[k].force, 1e-3 * a2.helical.normal_force) << k;
    }
  EXPECT_EQ(r[0].iterations, r[1].iterations); // one fixed point for the train
  // Statics of the train's shafts: each pinion shaft's bearings carry its own pair's force.
  const auto s = train.shafts_under(r);
  for (const auto &[first, T] : {std::pair<std::size_t, double>{0, 300.0}, {4, 200.0}})
    {
      const Eigen::Vector3d R = s.reactions[first].force + s.reactions[first + 1].force;
      EXPECT_NEAR(R.norm(), T / b.in.pair->base_radius(1), 1e-9 * T / b.in.pair->base_radius(1));
    }
}

TEST(SystemDeflection, HousingStiffnessActsInSeriesWithTheBearing)
{
  // Bearings z:radial:axial:tilting:torsional:housing radial:housing axial: the seat's springs in
  // series, 1/k = 1/k_bearing + 1/k_housing (a rigid side leaves the other).
  dealii::ParameterHandler prm;
  system_deflection::declare_system_parameters(prm);
  prm.parse_input_from_string(R"(
subsection System
  set Coupling = shafts
  subsection Pinion shaft
    set Segments = 100:40
    set Bearings = 0:rigid:rigid:0:rigid:500:rigid, 100:1000:0:0:0:1000:250
  end
  subsection Gear shaft
    set Segments = 100:60
    set Bearings = 0:rigid:rigid:0:0, 100:rigid:0:0:rigid
  end
end
)");
  const auto s = system_deflection::parse_system_parameters(prm);
  ASSERT_EQ(s.system.bearings.size(), 4u);
  const auto &b = s.system.bearings;
  EXPECT_DOUBLE_EQ(b[0].radial, 500e6);         // rigid bearing on a 500 N/um seat
  EXPECT_EQ(b[0].axial, shafts::rigid);          // rigid on rigid
  EXPECT_DOUBLE_EQ(b[1].radial, 500e6);         // 1000 and 1000 N/um in series
  EXPECT_EQ(b[1].axial, 0.0);                    // a floating bearing stays free
  EXPECT_EQ(b[0].name, "pinion bearing 1");
  EXPECT_EQ(b[2].name, "gear bearing 1");        // numbered per shaft
  prm.parse_input_from_string(R"(
subsection System
  subsection Pinion shaft
    set Bearings = 0:rigid:rigid:0:rigid:0:rigid, 100:rigid:0:0:0
  end
end
)");
  EXPECT_THROW(system_deflection::parse_system_parameters(prm), InputError);
}
