// The solve chain as a library call (solve/run.h): the per-torque hook `torque_done`.
// Reference: the plan's own bookkeeping (conservation of the positions: a sweep stopped after
// torque k holds exactly the positions of torques 0..k, and equals the same positions of an
// uninterrupted sweep, since each torque starts cold), and the journal rule (removed unless a
// solver failure leaves something to resume).
#include "common/fixtures.h"
#include "common/solve_input.h"
#include "solve/input.h"
#include "solve/run.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

using namespace gearfem;

namespace
{
  solve::GearContactInput parse(const std::string &text) { return test::parse_solve_input(text); }

  const std::string sector = test::coarse_sector_mesh + R"(
subsection Solve
  set Positions = cycle
  set Number of positions = 3
  set Torques = 100, 200, 300
  set VTU = none
  set Plots = false
end
)";
} // namespace

TEST(SolveRun, TorqueDoneStopsTheSweepAfterATorque)
{
  const auto in    = parse(test::parker_pair(sector));
  auto model       = in.model();
  const auto dir   = std::filesystem::temp_directory_path() / "gearfem_test_solve_run";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  solve::SolveRunOptions opt;
  opt.output_dir = dir;

  // Uninterrupted: the hook sees torques 0 and 1 (not the last), each with the rows so far.
  std::vector<std::size_t> seen, rows;
  opt.torque_done = [&](std::size_t t, const Table &sweep, double seconds) {
    seen.push_back(t);
    rows.push_back(sweep.n_rows());
    EXPECT_GE(seconds, 0.0);
    return true;
  };
  const auto full = solve::run_solve(*model, in, opt);
  EXPECT_FALSE(full.stopped);
  EXPECT_EQ(full.solved, 9u);
  EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(rows, (std::vector<std::size_t>{3, 6}));

  // Stopped after torque 0: its three positions, equal to the uninterrupted run's; no journal.
  seen.clear();
  opt.torque_done = [&](std::size_t t, const Table &, double) {
    seen.push_back(t);
    return false;
  };
  const auto stopped = solve::run_solve(*model, in, opt);
  EXPECT_TRUE(stopped.stopped);
  EXPECT_TRUE(stopped.failure.empty());
  EXPECT_EQ(stopped.solved, 3u);
  EXPECT_EQ(seen, (std::vector<std::size_t>{0}));
  ASSERT_EQ(stopped.results.sweep.n_rows(), 3u);
  const auto T = stopped.results.sweep.column("torque"), ste = stopped.results.sweep.column("STE"),
             ste_full = full.results.sweep.column("STE");
  for (std::size_t i = 0; i < 3; ++i)
    {
      EXPECT_EQ(T[i], 100.0);
      EXPECT_NEAR(ste[i], ste_full[i], 1e-6 * std::abs(ste_full[i])); // solver tolerance
    }
  EXPECT_FALSE(std::filesystem::exists(dir / solve::journal_file));
  std::filesystem::remove_all(dir);
}
