// Helical pairs by slicing (helical/helix.h, helical/slicing.h). References:
// - the transverse section of ISO/TR 6336-30:2017 example 1 (m_n 8, z 17/103, beta 15.8 deg,
//   x 0.145/0): d, d_b, d_a, alpha_t, beta_b, eps_alpha, eps_beta from ISO 21771, as the
//   independent validation/helical/iso_reference.py computes them (it reproduces the ISO/TR's
//   published F_t, Z_H, Z_beta, Z_eps and c' to 5e-4);
// - the spur limit: beta = 0 slices are the 2-D section itself (condensed re-solve), coupled
//   or not, to round-off;
// - the Winkler closed form of ISO 6336-1 method C: uncoupled slices under a linear
//   misalignment carry a linear load, K_Hbeta = 1 + f c_gamma / (2 F/b);
// - equilibrium: the slices carry the torque; the loaded slices of a tooth pair are contiguous.
#include "base/errors.h"
#include "base/units.h"
#include "common/fixtures.h"
#include "condensed/cycle.h"
#include "condensed/resolve.h"
#include "geometry/parameters.h"
#include "helical/helix.h"
#include "helical/run.h"
#include "helical/slicing.h"
#include "solve/input.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

using namespace gearfem;

TEST(Helix, TransverseSectionOfIsoTr6336_30Example1)
{
  geometry::GeometryInput n;
  for (auto *g : {&n.gear1, &n.gear2})
    {
      g->rack.module = 8 * units::mm, g->rack.pressure_angle = 20 * units::deg;
      g->rack.addendum = 1.0, g->rack.dedendum = 1.4, g->rack.root_radius = 0.39;
      g->face_width = 100 * units::mm;
    }
  n.gear1.name = "Gear 1", n.gear2.name = "Gear 2";
  n.gear1.teeth = 17, n.gear1.profile_shift = 0.145;
  n.gear2.teeth = 103, n.gear2.profile_shift = 0;
  n.pair.center_distance = 500 * units::mm;
  const double beta = 15.8 * units::deg;
  const auto pair   = geometry::build_pair(helical::transverse_section(n, beta));
  const double mm   = units::mm;
  EXPECT_NEAR(2 * pair.gear(1).parameters().reference_radius() / mm, 141.3401, 1e-4);
  EXPECT_NEAR(2 * pair.base_radius(1) / mm, 132.1986, 1e-4);
  EXPECT_NEAR(2 * pair.base_radius(2) / mm, 800.9678, 1e-4);
  EXPECT_NEAR(2 * pair.gear(1).radii().tip / mm, 159.6601, 1e-3);
  EXPECT_NEAR(2 * pair.gear(2).radii().tip / mm, 872.3548, 1e-3);
  EXPECT_NEAR(pair.working_pressure_angle() / units::deg, 21.06610, 2e-4); // from a = 500 mm
  EXPECT_NEAR(pair.contact_ratio(), 1.54934, 2e-4);
  helical::HelixInput hx;
  hx.beta     = beta;
  const auto &r = pair.gear(1).parameters().rack;
  const auto h  = helical::helix(hx, r.module, r.pressure_angle, pair.base_radius(1), 100 * mm);
  EXPECT_NEAR(h.alpha_t / units::deg, 20.71971, 1e-5);
  EXPECT_NEAR(h.beta_b / units::deg, 14.82453, 1e-5);
  EXPECT_NEAR(h.m_n / mm, 8.0, 1e-12);
  EXPECT_NEAR(h.alpha_n / units::deg, 20.0, 1e-12);
  EXPECT_NEAR(h.overlap_ratio, 1.08337, 1e-5);
  EXPECT_NEAR(h.axial_pitch / mm, 92.3047, 1e-4);
}

TEST(Helix, LeadGapShapesAndChecks)
{
  helical::LeadModification m;
  const double b = 40e-3, a = 20 * units::deg;
  m.crowning     = 10e-6;
  EXPECT_NEAR(helical::lead_gap(m, 0, b, a), 0, 1e-18);
  EXPECT_NEAR(helical::lead_gap(m, b / 2, b, a), 10e-6, 1e-15);
  EXPECT_NEAR(helical::lead_gap(m, -b / 4, b, a), 2.5e-6, 1e-15);
  m              = helical::LeadModification();
  m.misalignment = 20e-6; // opens towards +b/2 by f cos(alpha_wt)
  EXPECT_NEAR(helical::lead_gap(m, -b / 2, b, a), 0, 1e-18);
  EXPECT_NEAR(helical::lead_gap(m, b / 2, b, a), 20e-6 * std::cos(a), 1e-15);
  m.misalignment = -20e-6; // opens towards -b/2: zero at the tight end again
  EXPECT_NEAR(helical::lead_gap(m, b / 2, b, a), 0, 1e-18);
  EXPECT_NEAR(helical::lead_gap(m, -b / 2, b, a), 20e-6 * std::cos(a), 1e-15);
  m = helical::LeadModification();
  m.end_relief = 8e-6, m.end_relief_length = 5e-3;
  EXPECT_NEAR(helical::lead_gap(m, 0, b, a), 0, 1e-18);
  EXPECT_NEAR(helical::lead_gap(m, b / 2 - 2.5e-3, b, a), 4e-6, 1e-15);
  // A point-by-point profile: linear between its points, held beyond them.
  m = helical::LeadModification();
  m.profile_z = {-0.01, 0.0, 0.015}, m.profile_gap = {2e-6, 0.0, 6e-6};
  EXPECT_NEAR(helical::lead_gap(m, -0.005, b, a), 1e-6, 1e-18);
  EXPECT_NEAR(helical::lead_gap(m, 0.01, b, a), 4e-6, 1e-18);
  EXPECT_NEAR(helical::lead_gap(m, -b / 2, b, a), 2e-6, 1e-18);
  EXPECT_NEAR(helical::lead_gap(m, b / 2, b, a), 6e-6, 1e-18);
  EXPECT_NO_THROW(helical::check_profile(m, b));
  m.profile_z = {0.0, -0.01, 0.015}; // not increasing
  EXPECT_THROW(helical::check_profile(m, b), InputError);
  m.profile_z = {-0.01, 0.0}; // a gap without a position
  EXPECT_THROW(helical::check_profile(m, b), InputError);
  helical::HelixInput hx;
  hx.slices = 0;
  EXPECT_THROW(helical::check(hx, b), InputError);
  hx        = helical::HelixInput();
  hx.beta   = 50 * units::deg;
  EXPECT_THROW(helical::check(hx, b), InputError);
  hx = helical::HelixInput();
  hx.lead.end_relief = 5e-6; // without a length
  EXPECT_THROW(helical::check(hx, b), InputError);
}

namespace
{
  solve::GearContactInput parse(int positions)
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
)") + "subsection Solve\n  set Positions = cycle\n  set Number of positions = " +
                                std::to_string(positions) +
                                "\n  set Torques = 300\n  set VTU = none\n  set Plots = false\nend\n");
    return solve::parse_gear_contact_input(prm);
  }

  /// The Parker pair's transverse section on a 10-position grid, condensed once.
  struct Built
  {
    solve::GearContactInput in = parse(10);
    helical::SlicingOptions base = helical::slicing_options(in, helical::HelixInput(), post::PostOptions());
    std::unique_ptr<contact::GearContactModel> model = in.model();
    condensed::CondensedCycle cycle = condensed::cycle_for(*model, in, {300, 30, 1200});
  };
  Built &built()
  {
    static Built b;
    return b;
  }

  helical::SlicingOptions options(double beta_deg, int slices, double coupling, double misalignment_um = 0)
  {
    auto &b = built();
    helical::HelixInput hx;
    hx.beta                 = beta_deg * units::deg;
    hx.slices               = slices;
    hx.coupling_length      = coupling;
    hx.lead.misalignment    = misalignment_um * units::um;
    helical::SlicingOptions o = b.base;
    const auto &r             = b.in.pair->gear(1).parameters().rack;
    o.helix = helical::helix(hx, r.module, r.pressure_angle, b.in.pair->base_radius(1), o.helix.face_width);
    o.slices          = slices;
    o.coupling_length = coupling < 0 ? o.helix.m_n : coupling;
    o.lead            = hx.lead;
    return o;
  }
} // namespace

TEST(SlicedPair, SpurLimitIsTheSectionItself)
{
  auto &b = built();
  const condensed::Resolver spur(b.cycle, b.in);
  for (const double l : {0.0, -1.0})
    {
      const helical::SlicedPair pair(b.cycle, b.in, options(0, 4, l));
      for (std::size_t k = 0; k < b.cycle.positions.size(); k += 3)
        {
          const auto h = pair.solve(b.cycle.positions[k].second, 300);
          const auto s = spur.solve(k, 300, post::PostOptions());
          EXPECT_NEAR(h.ste, s.result.ste, 1e-9 * s.result.ste) << "coupling " << l << ", position " << k;
          EXPECT_NEAR(h.root_stress_pinion, s.result.max_root_stress_pinion, 1e-8 * s.result.max_root_stress_pinion);
          EXPECT_NEAR(h.p_max, s.result.p_max, 1e-8 * s.result.p_max);
          EXPECT_NEAR(h.k_h_beta, 1.0, 1e-9);
        }
    }
}

TEST(SlicedPair, HelicalSlicesCarryTheTorqueAlongContiguousContactLines)
{
  auto &b = built();
  const helical::SlicedPair pair(b.cycle, b.in, options(20, 21, -1));
  const double rb1 = b.in.pair->base_radius(1);
  double lo = 1e9, hi = -1e9;
  for (const auto &[name, phi] : b.cycle.positions)
    {
      const auto h = pair.solve(phi, 300);
      double F     = 0;
      for (const auto &s : h.slices)
        F += s.force;
      EXPECT_NEAR(F, 300 / rb1, 1e-9 * 300 / rb1); // equilibrium of the torque
      for (const auto &l : h.lines)
        {
          // The loaded extent of the line: slices above 1 % of its peak load.
          const double peak = *std::max_element(l.load_per_width.begin(), l.load_per_width.end());
          int first = -1, last = -1, n = 0;
          for (int k = 0; k < int(l.load_per_width.size()); ++k)
            if (l.load_per_width[std::size_t(k)] > 0.01 * peak)
              last = k, first = first < 0 ? k : first, ++n;
          std::string w;
          for (const double v : l.load_per_width)
            w += " " + std::to_string(int(v * 1e-3));
          EXPECT_EQ(n, last - first + 1) << "tooth pair " << l.pinion_tooth << "/" << l.gear_tooth << ", N/mm:" << w;
        }
      lo = std::min(lo, h.ste), hi = std::max(hi, h.ste);
      EXPECT_GE(h.k_h_beta, 1.0);
    }
  // The spur section's STE varies by a third over the cycle; 20 deg of helix (eps_beta 0.72)
  // smooths it.
  double slo = 1e9, shi = -1e9;
  const condensed::Resolver spur(b.cycle, b.in);
  for (std::size_t k = 0; k < b.cycle.positions.size(); ++k)
    {
      const auto s = spur.solve(k, 300, post::PostOptions());
      slo = std::min(slo, s.result.ste), shi = std::max(shi, s.result.ste);
    }
  EXPECT_LT(hi - lo, 0.5 * (shi - slo));
  // A torque beyond the cycle's range is a named error, not a number.
  EXPECT_THROW(pair.solve(b.cycle.positions[0].second, 5000), SolverError);
  EXPECT_THROW(pair.solve(b.cycle.positions[0].second, 10), SolverError);
}

TEST(SlicedPair, HandMirrorsTheFace)
{
  // An aligned pair of the other hand is the same pair seen from the other face: the same STE,
  // the load of slice k that of slice N-1-k (mirror symmetry of the slicing and the coupling).
  auto &b  = built();
  auto o   = options(20, 21, -1);
  auto ol  = o;
  ol.helix.roll_per_length = -o.helix.roll_per_length;
  const helical::SlicedPair right(b.cycle, b.in, o), left(b.cycle, b.in, ol);
  for (std::size_t k = 0; k < b.cycle.positions.size(); k += 4)
    {
      const double phi = b.cycle.positions[k].second;
      const auto r = right.solve(phi, 300), l = left.solve(phi, 300);
      EXPECT_NEAR(l.ste, r.ste, 1e-9 * r.ste);
      const std::size_t N = r.slices.size();
      for (std::size_t i = 0; i < N; ++i)
        EXPECT_NEAR(l.slices[i].load_per_width, r.slices[N - 1 - i].load_per_width, 1e-6 * r.normal_force / 0.02);
    }
}

TEST(SlicedPair, LeadProfileIsAGapOffsetLikeTheParametricOnes)
{
  // A profile that samples the linear opening of a misalignment at the slice centres gives the
  // misaligned pair's solution (the slices see the gap at their centres only).
  auto &b = built();
  const double f = 10e-6;
  const auto o   = options(0, 7, -1, f / units::um);
  const helical::SlicedPair tilted(b.cycle, b.in, o);
  const helical::SlicedPair aligned(b.cycle, b.in, options(0, 7, -1));
  helical::LeadModification profile;
  const double bw = o.helix.face_width;
  for (const double z : helical::slice_centres(bw, 7))
    profile.profile_z.push_back(z), profile.profile_gap.push_back(helical::lead_gap(o.lead, z, bw, o.alpha_wt));
  const double phi = b.cycle.positions[3].second;
  const auto h1 = tilted.solve(phi, 300), h2 = aligned.solve(phi, 300, profile);
  EXPECT_NEAR(h2.ste, h1.ste, 1e-12 * h1.ste);
  EXPECT_NEAR(h2.k_h_beta, h1.k_h_beta, 1e-12);
  for (std::size_t k = 0; k < h1.slices.size(); ++k)
    EXPECT_NEAR(h2.slices[k].force, h1.slices[k].force, 1e-9 * h1.normal_force);
}

TEST(SlicedPair, ForcesFirstThenEvaluateIsTheSolveAndAWarmStartLandsOnTheSameSolution)
{
  // solve() is evaluate(solve_forces()); a solve started from another lead's solution (the shaft
  // coupling's previous iterate) ends at the cold solve's answer: the complementarity problem's
  // solution is unique, only its start differs.
  auto &b = built();
  const auto o = options(15, 9, -1);
  const helical::SlicedPair pair(b.cycle, b.in, o);
  const double phi = b.cycle.positions[4].second;
  helical::LeadModification tilt, tilt2;
  const double bw = o.helix.face_width;
  for (const double z : helical::slice_centres(bw, 9))
    {
      tilt.profile_z.push_back(z), tilt.profile_gap.push_back(8e-6 * (z / bw + 0.5));
      tilt2.profile_z.push_back(z), tilt2.profile_gap.push_back(9e-6 * (z / bw + 0.5));
    }
  const auto full  = pair.solve(phi, 300, tilt2);
  const auto cold  = pair.solve_forces(phi, 300, tilt2);
  const auto first = pair.solve_forces(phi, 300, tilt);
  const auto warm  = pair.solve_forces(phi, 300, tilt2, &first);
  const auto ev    = pair.evaluate(warm);
  ASSERT_EQ(cold.force.size(), full.slices.size());
  double total = 0;
  for (std::size_t k = 0; k < full.slices.size(); ++k)
    {
      EXPECT_NEAR(cold.force[k], full.slices[k].force, 1e-12 * full.normal_force);
      EXPECT_NEAR(warm.force[k], cold.force[k], 1e-9 * full.normal_force);
      EXPECT_NEAR(ev.slices[k].force, warm.force[k], 1e-12 * full.normal_force);
      total += warm.force[k];
    }
  EXPECT_NEAR(total, full.normal_force, 1e-9 * full.normal_force); // equilibrium: T1 / r_b1
  EXPECT_NEAR(ev.ste, full.ste, 1e-9 * full.ste);
  EXPECT_NEAR(ev.k_h_beta, full.k_h_beta, 1e-9);
  EXPECT_NEAR(ev.p_max, full.p_max, 1e-8 * full.p_max);
  EXPECT_NEAR(ev.root_stress_pinion, full.root_stress_pinion, 1e-8 * full.root_stress_pinion);
}

TEST(SlicedPair, UncoupledMisalignedSpurFollowsWinkler)
{
  auto &b = built();
  // Uncoupled slices of the spur section under a 10 um mesh misalignment: each slice is a
  // spring of the section's stiffness per unit width, so the load is linear in z where all
  // slices touch and K_Hbeta = 1 + f c / (2 F/b) (ISO 6336-1 method C), c the stiffness per
  // unit width of the aligned section at the mean load (tangent: the load moves along the
  // springs), taken at the centre of the end slice, (1 - 1/N) of the way to the end.
  const double f = 10e-6 / std::cos(b.in.pair->working_pressure_angle()); // f cos(alpha_wt) = 10 um
  const helical::SlicedPair aligned(b.cycle, b.in, options(0, 11, 0));
  const helical::SlicedPair tilted(b.cycle, b.in, options(0, 11, 0, f / units::um));
  const double phi = b.cycle.positions[5].second;
  const auto h0    = aligned.solve(phi, 300);
  const auto h     = tilted.solve(phi, 300);
  const double bw  = b.base.helix.face_width;
  const double c   = h0.k_tangent / bw, Fb = h.normal_force / bw;
  const double N   = double(h.slices.size());
  // 4 % of K - 1: Hertz stiffens the springs with the load, which loads the tight end more.
  EXPECT_NEAR(h.k_h_beta, 1 + 10e-6 * c / (2 * Fb) * (1 - 1 / N), 0.04 * (h.k_h_beta - 1));
  for (std::size_t k = 1; k + 1 < h.slices.size(); ++k)
    {
      const double d2 = h.slices[k - 1].load_per_width - 2 * h.slices[k].load_per_width + h.slices[k + 1].load_per_width;
      EXPECT_LT(std::abs(d2), 0.02 * Fb) << "slice " << k;
    }
  EXPECT_GT(h.slices.front().load_per_width, h.slices.back().load_per_width); // the tight end at -b/2
  // The bending coupling (a beam along the face, free ends) costs nothing for a rigid tilt:
  // with the whole face in contact it leaves the Winkler distribution (to the Hertzian part of
  // the approach, which is not linear in z); the shear layer's free ends load the tight end.
  const helical::SlicedPair beam(b.cycle, b.in, options(0, 11, -1, f / units::um));
  const auto hb = beam.solve(phi, 300);
  EXPECT_NEAR(hb.k_h_beta, h.k_h_beta, 0.01 * (h.k_h_beta - 1));
  auto o      = options(0, 11, -1, f / units::um);
  o.coupling  = helical::Coupling::shear;
  const auto hs = helical::SlicedPair(b.cycle, b.in, o).solve(phi, 300);
  EXPECT_GT(hs.k_h_beta, h.k_h_beta + 0.05 * (h.k_h_beta - 1));
}
