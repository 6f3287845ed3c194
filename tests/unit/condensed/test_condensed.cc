// The condensed mesh cycle (condensed/cycle.h) against full FE solves of the same variants
// on the same factorised model (the independent reference: the full solver searches,
// linearises and iterates on the exact geometry at every load; the condensed route solves
// the stored linearisation). Parker 50/50 m 3 pair, 3-tooth sectors, built at 300 N m.
// Tolerances: STE 0.1 %, load share 0.002, root stress 0.5 % at other torques and tip
// reliefs; at the build torque itself the root stress from the influence coefficients equals
// the stress of the displacement field (same linear map) to round-off.
#include "condensed/cycle.h"
#include "condensed/resolve.h"
#include "condensed/table.h"
#include "common/fixtures.h"
#include "base/errors.h"
#include "post/position.h"
#include "solve/input.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <list>
#include <memory>
#include <string>

using namespace gearfem;

namespace
{
  std::string case_prm(double relief_um, const std::string &torques = "300", const std::string &extra = "")
  {
    std::string s = test::parker_pair(R"(
subsection Mesh
  set Model = sector
  set Sector teeth = 3
  set h_contact = 0.1
  set h_fillet = 0.25
  set h_body = 3
end
subsection Contact
  set Micro-geometry = gap
end
)");
    s += "subsection Solve\n  set Positions = cycle\n  set Number of positions = 5\n  set Torques = " + torques +
         "\n  set VTU = none\n  set Plots = false\nend\n";
    if (relief_um > 0)
      for (const char *g : {"Gear 1", "Gear 2"})
        s += std::string("subsection ") + g + "\n  set Tip relief = linear\n  set Tip relief amount = " +
             std::to_string(relief_um) + "\n  set Tip relief length = 6.7\nend\n";
    return s + extra;
  }

  solve::GearContactInput parse(const std::string &text)
  {
    dealii::ParameterHandler prm;
    solve::declare_gear_contact_input(prm);
    prm.parse_input_from_string(text);
    return solve::parse_gear_contact_input(prm);
  }

  double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

  /// One cycle and its model, built once for the tests of this file.
  struct Built
  {
    solve::GearContactInput in = parse(case_prm(0));
    std::unique_ptr<contact::GearContactModel> model = in.model();
    condensed::CondensedCycle cycle = condensed::cycle_for(*model, in, {300, 100, 900});
  };
  Built &built()
  {
    static Built b;
    return b;
  }
} // namespace

TEST(Condensed, ReSolvesTorquesAndReliefsLikeTheFullSolve)
{
  auto &b = built();
  const post::PostOptions po;
  // The model points to the pair of the variant it was last re-targeted to: keep them alive.
  static std::list<solve::GearContactInput> variants;
  for (const double relief : {0.0, 6.0})
    {
      const auto &variant = variants.emplace_back(parse(case_prm(relief)));
      const condensed::Resolver resolver(b.cycle, variant);
      b.model->set_micro_geometry(*variant.pair);
      for (const double T : {150.0, 300.0, 600.0})
        for (std::size_t k = 0; k < b.cycle.positions.size(); ++k)
          {
            const auto full = b.model->solve(b.cycle.positions[k].second, T);
            const auto fr   = post::evaluate_position(*b.model, full, po);
            const auto c    = resolver.solve(resolver.positions()[k], T, po);
            SCOPED_TRACE("relief " + std::to_string(relief) + " um, T " + std::to_string(T) + ", position " +
                         std::to_string(k));
            EXPECT_LT(rel(c.result.ste, fr.ste), 1e-3);
            EXPECT_LT(rel(c.result.max_root_stress_pinion, fr.max_root_stress_pinion), 5e-3);
            EXPECT_LT(rel(c.result.max_root_stress_gear, fr.max_root_stress_gear), 5e-3);
            ASSERT_EQ(c.result.pairs.size(), fr.pairs.size());
            for (std::size_t i = 0; i < fr.pairs.size(); ++i)
              EXPECT_LT(std::abs(c.result.pairs[i].share - fr.pairs[i].share), 2e-3);
            // Conservation: the moment of the nodal contact forces about the pinion axis
            // carries the torque. The stored force directions are those of the build state,
            // turned by the rotation only through the curvature term: a few 1e-5 off at
            // other loads (exact at the build torque, below).
            EXPECT_LT(rel(c.result.torque_contact, T), 2e-4);
            if (relief == 0 && T == 300.0)
              {
                // The build state: the same linearisation, so the same solution, and the root
                // stress of the influence coefficients is the field's (same linear map).
                EXPECT_LT(rel(c.result.ste, fr.ste), 1e-8);
                EXPECT_LT(rel(c.result.torque_contact, T), 1e-8);
                EXPECT_LT(rel(c.result.max_root_stress_pinion, fr.max_root_stress_pinion), 1e-8);
                EXPECT_LT(rel(c.result.max_root_stress_gear, fr.max_root_stress_gear), 1e-8);
              }
          }
    }
}

TEST(Condensed, FileRoundTripIsExact)
{
  auto &b = built();
  const auto dir = std::filesystem::temp_directory_path() / "gearfem_test_condensed";
  std::filesystem::create_directories(dir);
  condensed::write_cycle(b.cycle, dir / "condensed.h5");
  const auto back    = condensed::read_cycle(dir / "condensed.h5");
  const auto variant = parse(case_prm(6.0, "200"));
  const condensed::Resolver r1(b.cycle, variant), r2(back, variant);
  for (std::size_t k = 0; k < b.cycle.positions.size(); ++k)
    {
      const auto a = r1.solve(k, 200, post::PostOptions()), c = r2.solve(k, 200, post::PostOptions());
      EXPECT_EQ(a.result.ste, c.result.ste);
      EXPECT_EQ(a.result.max_root_stress_pinion, c.result.max_root_stress_pinion);
      EXPECT_EQ(a.result.p_max, c.result.p_max);
    }
  std::filesystem::remove_all(dir);
  EXPECT_THROW(condensed::read_cycle(dir / "missing.h5"), InputError);
}

TEST(Condensed, RefusesWhatItDoesNotHold)
{
  auto &b = built();
  // A torque outside the stored torque range: a named error, not a number.
  const condensed::Resolver r(b.cycle, parse(case_prm(0, "2000")));
  try
    {
      r.solve(0, 2000, post::PostOptions());
      FAIL() << "no error";
    }
  catch (const SolverError &e)
    {
      EXPECT_NE(std::string(e.what()).find("Torque range"), std::string::npos) << e.what();
    }
  // A different mesh, a position the cycle does not hold, a relief meshed as geometry.
  const auto expect_input_error = [&](const std::string &text, const std::string &entry) {
    try
      {
        condensed::Resolver bad(b.cycle, parse(text));
        FAIL() << "no error for " << entry;
      }
    catch (const InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find(entry), std::string::npos) << e.what();
      }
  };
  expect_input_error(case_prm(0, "300", "subsection Mesh\n  set h_contact = 0.12\nend\n"), "--condensed");
  expect_input_error(case_prm(0, "300", "subsection Solve\n  set Number of positions = 7\nend\n"), "Solve");
  expect_input_error(case_prm(6, "300", "subsection Contact\n  set Micro-geometry = geometry\nend\n"),
                     "Contact/Micro-geometry");
}

TEST(Condensed, ContactBeyondTheStoredCandidatesFailsLoudly)
{
  // With a 5 um search distance the cycle stores only the nodes within 5 um of the mating
  // flank at 100 N m; at 40 times the torque the contact spreads beyond them. (Fixed slaves:
  // one scene, built at 100 N m: Scene torque ratio 0.)
  const auto in = parse(case_prm(
    0, "100", "subsection Contact\n  set Search distance = 0.005\n  set Slave selection = fixed\nend\n"));
  auto model    = in.model();
  const auto cycle = condensed::cycle_for(*model, in, {100, 100, 4000}, {0.0, nullptr});
  const condensed::Resolver r(cycle, in);
  EXPECT_NO_THROW(r.solve(2, 100, post::PostOptions()));
  try
    {
      r.solve(2, 4000, post::PostOptions());
      FAIL() << "no error";
    }
  catch (const SolverError &e)
    {
      EXPECT_NE(std::string(e.what()).find("edge of the stored candidates"), std::string::npos) << e.what();
    }
}

TEST(Condensed, SceneSplitBoundsTheLoadRatioAndKeepsADegenerateRange)
{
  // Scene torque ratio 4 over 30-900 N m built at 300: cuts at 150 and 600 (and 37.5), so every
  // scene is solved within a factor 2 of each torque it serves; a range of one torque (the
  // single-torque optimiser: lo = hi = build) keeps one scene per position.
  auto in    = parse(case_prm(0, "300", "subsection Solve\n  set Number of positions = 2\nend\n"));
  auto model = in.model();
  const auto split = condensed::cycle_for(*model, in, {300, 30, 900});
  for (const auto &scenes : split.cycle)
    {
      ASSERT_GE(scenes.size(), 4u);
      for (const auto &p : scenes)
        for (const double T : {p.load_lo, p.load_hi})
          {
            const double ratio = T / p.load_build;
            EXPECT_LE(std::max(ratio, 1 / ratio), 2.0 * (1 + 1e-9)) << p.load_lo << " " << p.load_hi;
          }
    }
  const auto one = condensed::cycle_for(*model, in, {300, 300, 300});
  for (const auto &scenes : one.cycle)
    {
      ASSERT_EQ(scenes.size(), 1u);
      EXPECT_DOUBLE_EQ(scenes.front().load_build, 300);
    }
  EXPECT_NO_THROW(one.at(0, 300));
}

TEST(Condensed, SceneRatioRuleOfEachUse)
{
  // auto (< 0): a factor-2 bound for the cycles of variants and given torques, no split for the
  // transverse section of helical slices; a set ratio is taken as it is (docs/helical.md).
  EXPECT_EQ(condensed::scene_ratio(condensed::CycleUse::variants, -1), 4.0);
  EXPECT_EQ(condensed::scene_ratio(condensed::CycleUse::given_torques, -1), 4.0);
  EXPECT_EQ(condensed::scene_ratio(condensed::CycleUse::slices, -1), 0.0);
  EXPECT_EQ(condensed::scene_ratio(condensed::CycleUse::slices, 4), 4.0);
  EXPECT_EQ(condensed::scene_ratio(condensed::CycleUse::variants, 0), 0.0);
}

TEST(Condensed, TorqueTableMatchesRotationControlledFullSolves)
{
  // Independent reference: the full FE under rotation control (GearContactModel::
  // solve_rotation) at table nodes; the table is contact solves on the cycle.
  auto in          = parse(case_prm(0, "300", "subsection Solve\n  set Number of positions = 8\nend\n"));
  auto model       = in.model();
  const auto cycle = condensed::cycle_for(*model, in, {300, 30, 900});
  condensed::TableOptions o;
  o.n_delta  = 6;
  o.backlash = 50e-6;
  const io::MeshTable t = condensed::torque_table(cycle, *in.pair, o);
  ASSERT_TRUE(t.two_sided());
  ASSERT_EQ(t.theta.size(), 8u);
  const double rb1 = in.pair->base_radius(1);
  const long j0    = io::node_at(t.second, 0.0);
  ASSERT_GE(j0, 0);
  for (std::size_t i = 0; i < t.theta.size(); i += 3)
    for (std::size_t j = std::size_t(j0) + 2; j < t.second.size(); j += 2)
      {
        const auto full = model->solve_rotation(t.theta[i], t.second[j] / rb1);
        EXPECT_LT(rel(t.value(i, j), full.solution.load), 2e-3) << "theta " << t.theta[i] << ", delta " << t.second[j];
      }
  // The contract of a two-sided table: 0 on [-b, 0], reverse side <= 0, drive side >= 0.
  for (std::size_t i = 0; i < t.theta.size(); ++i)
    for (std::size_t j = 0; j < t.second.size(); ++j)
      {
        const double d = t.second[j], v = t.value(i, j);
        if (d >= -o.backlash && d <= 0)
          EXPECT_EQ(v, 0.0);
        else
          EXPECT_TRUE(d > 0 ? v > 0 : v < 0) << d << " " << v;
      }
  // Not one pitch of positions: refused with the entry named.
  auto few = parse(case_prm(0, "300", "subsection Solve\n  set Pitches = 0.5\n  set Number of positions = 8\nend\n"));
  auto m2  = few.model();
  const auto c2 = condensed::cycle_for(*m2, few, {300, 30, 900});
  EXPECT_THROW(condensed::torque_table(c2, *few.pair, o), InputError);
}
