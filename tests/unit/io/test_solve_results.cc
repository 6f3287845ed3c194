// The solve-results contract (io/solve_results.h): the writer refuses non-finite values
// and leaves no file behind, and a write/read round trip through results.h5 is
// bit-exact (a conservation check: the reader must return what the writer was given).
#include "io/solve_results.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

using namespace gearfem;

namespace
{
  std::filesystem::path fresh_dir(const std::string &name)
  {
    const auto dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
  }

  io::SolveResults sample()
  {
    io::SolveResults r = io::make_solve_results();
    r.attributes       = {{"geometry_hash", "abc123"}, {"method", "lagrange"}, {"program", "test"}};
    for (int i = 0; i < 3; ++i)
      {
        std::vector<double> row(r.sweep.n_columns());
        for (std::size_t c = 0; c < row.size(); ++c)
          row[c] = (i + 1) * 0.1 + c / 3.0; // not representable in decimal: tests exactness
        r.sweep.add_row(row);
      }
    r.line_of_action.add_row({1, -12.5});
    return r;
  }
} // namespace

TEST(SolveResults, RefuseNonFiniteAndLeaveNoFile)
{
  const auto dir = fresh_dir("gearfem_test_solve_results_bad");
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()})
    {
      io::SolveResults r = sample();
      std::vector<double> row(r.sweep.n_columns(), 1.0);
      row[4] = bad; // STE
      r.sweep.add_row(row);
      try
        {
          io::write_solve_results(r, dir);
          FAIL() << "non-finite value written";
        }
      catch (const std::exception &e)
        {
          EXPECT_NE(std::string(e.what()).find("STE"), std::string::npos) << e.what();
        }
      EXPECT_TRUE(std::filesystem::is_empty(dir)) << "partial file left behind";
    }
  std::filesystem::remove_all(dir);
}

TEST(SolveResults, RoundTripIsBitExact)
{
  const auto dir = fresh_dir("gearfem_test_solve_results_rt");
  const io::SolveResults r = sample();
  io::write_solve_results(r, dir);
  for (const char *f : {"sweep.csv", "pairs.csv", "pressure.csv", "line_of_action.csv", "results.h5"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  const io::SolveResults back = io::read_solve_results(dir / "results.h5", true);
  EXPECT_EQ(back.attributes.at("geometry_hash"), "abc123");
  EXPECT_EQ(back.attributes.at("method"), "lagrange");
  ASSERT_EQ(back.sweep.n_rows(), r.sweep.n_rows());
  ASSERT_EQ(back.sweep.headers(), r.sweep.headers());
  for (std::size_t i = 0; i < r.sweep.n_rows(); ++i)
    for (std::size_t c = 0; c < r.sweep.n_columns(); ++c)
      EXPECT_EQ(back.sweep.row(i)[c], r.sweep.row(i)[c]) << r.sweep.headers()[c];
  EXPECT_EQ(back.pairs.n_rows(), 0u);
  EXPECT_EQ(back.line_of_action.row(0)[1], -12.5);
  // Columns other modules read by header text.
  const auto h = back.sweep.headers();
  for (const char *name : {io::sweep_column::torque, io::sweep_column::roll_angle, io::sweep_column::ste,
                           io::sweep_column::normal_force, io::sweep_column::time})
    EXPECT_NE(std::find(h.begin(), h.end(), name), h.end()) << name;
  std::filesystem::remove_all(dir);
}

TEST(SolveResults, ReaderNamesTheProblem)
{
  const auto dir = fresh_dir("gearfem_test_solve_results_read");
  auto message = [](const std::filesystem::path &f) {
    try
      {
        io::read_solve_results(f);
      }
    catch (const std::exception &e)
      {
        return std::string(e.what());
      }
    return std::string("no error");
  };
  EXPECT_NE(message(dir / "missing.h5").find("file not found"), std::string::npos);
  std::ofstream(dir / "text.h5") << "not hdf5\n";
  EXPECT_NE(message(dir / "text.h5").find("not an HDF5 file"), std::string::npos);
  // A foreign HDF5 file (another format) and one without the STE column.
  Table t;
  t.add_column("torque", "N m");
  t.add_row({1.0});
  io::write_table_file({{"sweep", &t}}, dir / "foreign.h5", {{"format", "other"}});
  EXPECT_NE(message(dir / "foreign.h5").find("format"), std::string::npos);
  io::write_table_file({{"sweep", &t}}, dir / "partial.h5",
                       {{"format", io::solve_results_format}, {"format_version", "1"}, {"geometry_hash", "x"}});
  const std::string m = message(dir / "partial.h5");
  EXPECT_NE(m.find("roll angle [deg]"), std::string::npos) << m;
  std::filesystem::remove_all(dir);
}
