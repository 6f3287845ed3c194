// Optimisers (lib/optimise/optimisers.h): short runs must lower the objective and end
// feasible; an infeasible start and bad settings give named InputErrors (exit status 2).
#include "base/errors.h"
#include "optimise/optimisers.h"

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
