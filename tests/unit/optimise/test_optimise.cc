// Optimisers (lib/optimise/optimisers.h): short runs must lower the objective and end
// feasible; an infeasible start and bad settings give named InputErrors (exit status 2).
#include "base/errors.h"
#include "optimise/optimisers.h"
#include "optimise/study.h"

#include <gtest/gtest.h>

using namespace gearfem;
using namespace gearfem::optimise;

namespace
{
  void expect_lowered_and_feasible(DesignKind kind, Method m, double eps_min)
  {
    const Design       d(kind, PairData{});
    EvaluationSettings s;
    s.min_contact_ratio = eps_min;
    s.samples           = 201;
    OptimiserSettings o;
    o.method          = m;
    o.max_evaluations = 300;
    int calls = 0;
    const auto r = optimise::optimise(d, d.default_start(), s, o, [&](int, int, double) { ++calls; });
    EXPECT_LE(r.evaluations, 300);
    EXPECT_GT(calls, 0); // progress is reported
    EXPECT_LT(r.best.objective, 0.9 * r.start.objective) << to_string(m) << " " << r.stop_reason;
    // Re-evaluated independently of the optimiser's record: feasible, every constraint met,
    // and the objective recomputed from the statistics by the thesis formula.
    const Evaluation e = d.evaluate(r.x_best, s);
    ASSERT_TRUE(e.feasible) << e.reason;
    for (double c : e.constraints)
      EXPECT_LE(c, 1e-9);
    EXPECT_DOUBLE_EQ(e.objective, r.best.objective);
    if (kind == DesignKind::case1_rack)
      EXPECT_NEAR(e.objective, 1e-3 * (e.stats.max_abs + e.stats.mean_abs + e.stats.std), 1e-12);
    else
      EXPECT_NEAR(e.objective, 2.5 * e.integral + 1e-3 * e.stats.std + 0.1 / e.contact_ratio, 1e-12);
    // The history is monotone in its best-feasible column and ends at the best.
    for (std::size_t i = 1; i < r.history.size(); ++i)
      EXPECT_LE(r.history[i].best, r.history[i - 1].best);
    EXPECT_DOUBLE_EQ(r.history.back().best, r.best.objective);
  }
} // namespace

TEST(Optimise, SteepestDescentCase1Lowers) { expect_lowered_and_feasible(DesignKind::case1_rack, Method::steepest_descent, 0.85); }
TEST(Optimise, CobylaCase2Lowers) { expect_lowered_and_feasible(DesignKind::case2_flank, Method::cobyla, 1.0); }
TEST(Optimise, SlsqpCase2Lowers) { expect_lowered_and_feasible(DesignKind::case2_flank, Method::slsqp, 1.0); }

TEST(Optimise, InfeasibleStartIsANamedError)
{
  const Design d(DesignKind::case1_rack, PairData{});
  try
    {
      optimise::optimise(d, d.default_start(), EvaluationSettings{}, OptimiserSettings{});
      FAIL() << "no error";
    }
  catch (const InputError &e)
    {
      EXPECT_EQ(e.parameter(), "Optimise/Start point");
      EXPECT_NE(std::string(e.what()).find("contact ratio"), std::string::npos) << e.what();
    }
}

TEST(Optimise, BadSettingsAreNamed)
{
  const Design d(DesignKind::case2_flank, PairData{});
  auto expect_named = [&](OptimiserSettings o, const std::string &name) {
    try
      {
        optimise::optimise(d, d.default_start(), EvaluationSettings{}, o);
        FAIL() << "no error for " << name;
      }
    catch (const InputError &e)
      {
        EXPECT_EQ(e.parameter(), name) << e.what();
      }
  };
  OptimiserSettings o;
  o.max_evaluations = 0;
  expect_named(o, "Optimiser/Max evaluations");
  o = OptimiserSettings{};
  o.bound = -0.1;
  expect_named(o, "Optimiser/Bound");
  o = OptimiserSettings{};
  o.golden_tolerance = 0;
  expect_named(o, "Optimiser/Golden-section tolerance");
  EXPECT_THROW(method_from_string("newton", "Optimiser/Methods"), InputError);
  EXPECT_EQ(method_from_string("isres", "Optimiser/Methods"), Method::isres);
}

// Multistart: the case-1 start (the sinusoid fit, eps = 0.917) is infeasible for eps >= 1;
// the random points of the box supply feasible starts, and the result honours eps >= 1.
TEST(Optimise, MultistartFromAnInfeasibleStart)
{
  const Design       d(DesignKind::case1_rack, PairData{});
  EvaluationSettings s;
  s.min_contact_ratio = 1.0;
  s.samples           = 101;
  OptimiserSettings o;
  o.method          = Method::cobyla;
  o.max_evaluations = 100;
  o.bound           = 0.8;
  o.multistart      = 3;
  const auto r = optimise::optimise(d, d.default_start(), s, o);
  EXPECT_FALSE(r.start.feasible);
  ASSERT_TRUE(r.best.feasible) << r.stop_reason;
  const Evaluation e = d.evaluate(r.x_best, s);
  ASSERT_TRUE(e.feasible) << e.reason;
  EXPECT_GE(e.contact_ratio, 1.0 - 1e-9);
  EXPECT_DOUBLE_EQ(e.objective, r.best.objective);
  for (std::size_t i = 0; i < r.x_best.size(); ++i) // inside the box about the start point
    EXPECT_LE(std::abs(r.x_best[i] - d.default_start()[i]), 0.8 + 1e-12);
  EXPECT_EQ(static_cast<int>(r.history.size()), r.evaluations);
  EXPECT_GE(r.evaluations, 60); // the 20 x 3 random points count
  for (std::size_t i = 1; i < r.history.size(); ++i)
    if (r.history[i - 1].feasible || i > 60)
      EXPECT_LE(r.history[i].best, r.history[i - 1].best);
  EXPECT_DOUBLE_EQ(r.history.back().best, r.best.objective);
  EXPECT_NE(r.stop_reason.find("multistart"), std::string::npos);
}

TEST(Optimise, MultistartWithoutAFeasiblePointIsNamed)
{
  const Design       d(DesignKind::case1_rack, PairData{});
  EvaluationSettings s;
  s.min_contact_ratio = 4.0; // no rack of the box has it
  s.samples           = 51;
  OptimiserSettings o;
  o.method     = Method::cobyla;
  o.multistart = 1;
  try
    {
      optimise::optimise(d, d.default_start(), s, o);
      FAIL() << "no error";
    }
  catch (const InputError &e)
    {
      EXPECT_EQ(e.parameter(), "Optimiser/Multistart") << e.what();
    }
  o.multistart = -1;
  EXPECT_THROW(optimise::optimise(d, d.default_start(), s, o), InputError);
}

// Case 2's objective weights: each term alone, and the thesis' weights by default.
TEST(Optimise, Case2ObjectiveWeights)
{
  const Design       d(DesignKind::case2_flank, PairData{});
  EvaluationSettings s;
  s.samples         = 201;
  const Evaluation e = d.evaluate(d.default_start(), s);
  ASSERT_TRUE(e.feasible) << e.reason;
  EXPECT_NEAR(e.objective, 2.5 * e.integral + 1e-3 * e.stats.std + 0.1 / e.contact_ratio, 1e-12);
  s.weights = {0, 1, 0};
  EXPECT_NEAR(d.evaluate(d.default_start(), s).objective, 1e-3 * e.stats.std, 1e-15);
  s.weights = {1, 0, 0};
  EXPECT_NEAR(d.evaluate(d.default_start(), s).objective, e.integral, 1e-15);
  s.weights = {0, 0, 1};
  EXPECT_NEAR(d.evaluate(d.default_start(), s).objective, 1 / e.contact_ratio, 1e-15);
}

// Fixing P0 instead of P4: the same start curve (the involute fit), the other 8 coordinates.
TEST(Optimise, Case2FixedRootEndHasTheSameStartCurve)
{
  const Design tip(DesignKind::case2_flank, PairData{}), root(DesignKind::case2_flank, PairData{}, FixedEnd::root);
  const auto   pt = tip.control_points(tip.default_start()), pr = root.control_points(root.default_start());
  ASSERT_EQ(pt.size(), 5u);
  ASSERT_EQ(pr.size(), 5u);
  for (int i = 0; i < 5; ++i)
    EXPECT_LT((pt[i] - pr[i]).norm(), 1e-14) << i;
  EXPECT_EQ(root.free_names().front(), "x1");
  EvaluationSettings s;
  s.samples = 201;
  EXPECT_DOUBLE_EQ(tip.evaluate(tip.default_start(), s).objective, root.evaluate(root.default_start(), s).objective);
  // A change of the first free coordinate moves P1 for the root-fixed design, P0 otherwise.
  auto x = root.default_start();
  x[0] += 0.01;
  EXPECT_LT((root.control_points(x)[0] - pr[0]).norm(), 1e-14);
  EXPECT_NEAR((root.control_points(x)[1] - pr[1]).norm(), 0.01, 1e-14);
}

// Study checks of the new entries: case 1 has no weights and no choice of fixed end; a
// multistart study accepts an infeasible start point (the centre of its box).
TEST(Optimise, StudyChecksWeightsFixedEndAndMultistart)
{
  auto expect_named = [](const Study &s, const std::string &name) {
    try
      {
        check_study(s);
        FAIL() << "no error for " << name;
      }
    catch (const InputError &e)
      {
        EXPECT_EQ(e.parameter(), name) << e.what();
      }
  };
  Study s;
  s.kind = DesignKind::case1_rack;
  s.runs.push_back(OptimiserSettings{});
  s.eval.min_contact_ratio = 1.0; // the case-1 start has eps 0.917
  expect_named(s, "Optimise/Start point");
  s.runs.back().multistart = 2;
  EXPECT_NO_THROW(check_study(s));
  s.eval.weights = {2.5, 10, 0.1};
  expect_named(s, "Optimise/Objective weights");
  s.eval.weights = EvaluationSettings{}.weights;
  s.fixed_end    = FixedEnd::root;
  expect_named(s, "Optimise/Fixed end");
  Study t; // case 2
  t.runs.push_back(OptimiserSettings{});
  t.eval.weights = {0, 0, 0};
  expect_named(t, "Optimise/Objective weights");
  t.eval.weights = {-1, 1, 0};
  expect_named(t, "Optimise/Objective weights");
  t.eval.weights = {0, 1, 0};
  t.fixed_end    = FixedEnd::root;
  EXPECT_NO_THROW(check_study(t));
}
