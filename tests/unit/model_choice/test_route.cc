// The route of Solve/Target's sweep (model_choice/route.h). References:
// - probe_before_cycle: only for a p-p tolerance with h_contact free;
// - plan_route: its rule in closed form (1.2 x 3.3 x (1 + parts) torque sweeps, parts of the
//   torque range at the scene ratio) and the inputs the condensed cycle cannot serve (VTU
//   fields, --resume, friction: condensed::check_condensable);
// - condensation_error: the same differences computed independently, from a full FE sweep of
//   the same model at the same positions (run_solve), on a 3-tooth sector: at the rows of the
//   largest and smallest STE and the largest root stress of each gear, lowest and highest torque.
#include "model_choice/route.h"
#include "common/fixtures.h"
#include "common/solve_input.h"
#include "condensed/cycle.h"
#include "condensed/resolve.h"
#include "solve/input.h"
#include "solve/run.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <vector>

using namespace gearfem;

namespace
{
  solve::GearContactInput parse(const std::string &text) { return test::parse_solve_input(text); }

  std::string solve_section(const std::string &torques, const std::string &extra = "")
  {
    return "subsection Solve\n  set Torques = " + torques + "\n  set VTU = none\n  set Plots = false\n" + extra +
           "end\n";
  }
} // namespace

TEST(ChoiceRoute, CondensedFromTheTorquesItsBuildCosts)
{
  // 100-340 N m: one part at ratio 4, two scenes per position, 6.6 sweeps: from 8 torques.
  auto plan = model_choice::plan_route(parse(test::parker_pair(solve_section("100, 150, 200, 250, 300, 320, 340"))), false);
  EXPECT_FALSE(plan.condensed);
  EXPECT_NEAR(plan.predicted_build_sweeps, 2 * model_choice::build_sweeps_per_scene, 1e-12);
  EXPECT_NE(plan.why.find("pays from 8 torques"), std::string::npos) << plan.why;
  const std::string eight = "100, 130, 160, 190, 220, 250, 300, 340";
  plan = model_choice::plan_route(parse(test::parker_pair(solve_section(eight))), false);
  EXPECT_TRUE(plan.condensed) << plan.why;
  EXPECT_NEAR(plan.build_torque, std::sqrt(100.0 * 340.0), 1e-9);
  EXPECT_DOUBLE_EQ(plan.lo, 100);
  EXPECT_DOUBLE_EQ(plan.hi, 340);
  // 50-500 N m: two parts, three scenes per position, 9.9 sweeps: eight torques do not pay.
  plan = model_choice::plan_route(parse(test::parker_pair(solve_section("50, 100, 150, 200, 250, 300, 400, 500"))), false);
  EXPECT_FALSE(plan.condensed);
  EXPECT_NEAR(plan.predicted_build_sweeps, 3 * model_choice::build_sweeps_per_scene, 1e-12);
  // Set by hand: the full FE sweep.
  EXPECT_FALSE(
    model_choice::plan_route(parse(test::parker_pair(solve_section(eight, "  set Target route = full FE\n"))), false).condensed);
  // What the cycle cannot serve: fields, a resumed journal, friction.
  EXPECT_FALSE(model_choice::plan_route(parse(test::parker_pair(solve_section(eight, "  set VTU = named\n"))), false).condensed);
  EXPECT_FALSE(model_choice::plan_route(parse(test::parker_pair(solve_section(eight))), true).condensed);
  plan = model_choice::plan_route(
    parse(test::parker_pair(solve_section(eight) + "subsection Contact\n  set Friction coefficient = 0.05\nend\n")),
    false);
  EXPECT_FALSE(plan.condensed);
  EXPECT_NE(plan.why.find("Friction"), std::string::npos) << plan.why;
}

TEST(ChoiceRoute, ProbeTheFirstTorqueOnlyWhereAFinerLevelCouldFollow)
{
  // The first torque is swept in full before a cycle is built only for a p-p tolerance that a
  // finer h_contact may still meet.
  model_choice::TargetOutcome o;
  o.target = model_choice::parse_target("mean STE 1, p-p STE 1, root stress 3");
  EXPECT_TRUE(model_choice::probe_before_cycle(o, {}));
  model_choice::FixedSettings set_h{};
  set_h.h_contact = true;
  EXPECT_FALSE(model_choice::probe_before_cycle(o, set_h));
  o.target = model_choice::parse_target("mean STE 1, root stress 3");
  EXPECT_FALSE(model_choice::probe_before_cycle(o, {}));
}

TEST(ChoiceRoute, CondensationErrorEqualsTheFullSweepsDifferences)
{
  const auto in = parse(test::parker_pair(test::coarse_sector_mesh + solve_section("100, 200, 400") + "subsection Solve\n  set Positions = cycle\n  set Number of positions = 6\nend\n"));
  auto model     = in.model();
  const auto dir = std::filesystem::temp_directory_path() / "gearfem_test_choice_route";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "full");
  std::filesystem::create_directories(dir / "cycle");
  solve::SolveRunOptions opt;
  opt.output_dir  = dir / "full";
  const auto full = solve::run_solve(*model, in, opt);
  const auto cycle = condensed::cycle_for(*model, in, {200, 100, 400});
  opt.output_dir   = dir / "cycle";
  const auto cond  = condensed::run_condensed(cycle, in, opt);
  ASSERT_TRUE(cond.failure.empty());
  const auto e = model_choice::condensation_error(*model, in, cond.results.sweep, opt.post);

  // The same quantities from the full sweep: rows correspond one to one (torque-major).
  const auto &a = full.results.sweep, &b = cond.results.sweep;
  const auto Ta = a.column("torque"), sa = a.column("STE"), sb = b.column("STE"), ra = a.column("root stress pinion"),
             rb = b.column("root stress pinion"), ga = a.column("root stress gear"), gb = b.column("root stress gear");
  ASSERT_EQ(Ta.size(), b.n_rows());
  double mean = 0, pp = 0, root = 0;
  for (const double T : {100.0, 400.0})
    {
      std::vector<std::size_t> rows;
      for (std::size_t i = 0; i < Ta.size(); ++i)
        if (Ta[i] == T)
          rows.push_back(i);
      const auto arg = [&](const std::vector<double> &v, bool largest) {
        std::size_t k = rows.front();
        for (const std::size_t i : rows)
          k = (largest ? v[i] > v[k] : v[i] < v[k]) ? i : k;
        return k;
      };
      const std::size_t hi = arg(sb, true), lo = arg(sb, false), p = arg(rb, true), g = arg(gb, true);
      double sum = 0;
      for (const std::size_t i : rows)
        sum += sb[i];
      const double d_hi = sb[hi] - sa[hi], d_lo = sb[lo] - sa[lo];
      mean = std::max(mean, std::max(std::abs(d_hi), std::abs(d_lo)) / (sum / double(rows.size())));
      pp   = std::max(pp, std::abs(d_hi - d_lo) / (sb[hi] - sb[lo]));
      root = std::max({root, std::abs(rb[p] - ra[p]) / rb[p], std::abs(gb[g] - ga[g]) / gb[g]});
    }
  // Equal to the solver's tolerance (relative 1e-8 of the STE and the stress).
  EXPECT_NEAR(e[0], mean, 1e-7);
  EXPECT_NEAR(e[1], pp, 1e-6);
  EXPECT_NEAR(e[2], root, 1e-7);
  std::cout << "condensation error: mean " << e[0] << ", p-p " << e[1] << ", root " << e[2] << std::endl;
  EXPECT_GT(e[0] + e[1] + e[2], 0); // 100 and 400 N m are not the build torque: not exact
  // And small: the torques within a factor 2 of the build (docs/model-choice.md: within 0.3 %).
  for (int q = 0; q < 3; ++q)
    {
      EXPECT_TRUE(std::isfinite(e[q]));
      EXPECT_LT(e[q], 3e-3) << q;
    }
  std::filesystem::remove_all(dir);
}
