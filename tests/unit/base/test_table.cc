// base/table.h: the CSV writer refuses non-finite values (nothing partial is left), and the
// reader converts every cell with the checked conversion; the cells have the digits an ostream
// writes.
#include "base/errors.h"
#include "base/table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

using namespace gearfem;

TEST(Table, RefusesNonFiniteAndLeavesNoFile)
{
  const auto dir = std::filesystem::temp_directory_path() / "gearfem_test_table";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()})
    {
      Table t;
      t.add_column("x", "mm");
      t.add_column("STE", "um");
      t.add_row({1.0, 2.0});
      t.add_row({2.0, bad});
      try
        {
          t.write_csv(dir / "t.csv");
          FAIL() << "non-finite value written";
        }
      catch (const std::exception &e)
        {
          EXPECT_NE(std::string(e.what()).find("STE"), std::string::npos) << e.what();
        }
      EXPECT_TRUE(std::filesystem::is_empty(dir)) << "partial file left behind";
    }
  Table ok;
  ok.add_column("x", "mm");
  ok.add_row({1.5});
  ok.write_csv(dir / "ok.csv");
  std::vector<std::string> h;
  const auto rows = read_csv_numbers(dir / "ok.csv", &h);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_DOUBLE_EQ(rows[0][0], 1.5);
  EXPECT_EQ(h[0], "x [mm]");
  std::ofstream(dir / "bad.csv") << "x [mm],y\n1,2\n3,nan\n";
  try
    {
      read_csv_numbers(dir / "bad.csv");
      FAIL() << "nan read";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("line 3, column 2"), std::string::npos) << e.what();
    }
  std::filesystem::remove_all(dir);
}

// The writer formats with std::to_chars; the reference here is an ostream with
// setprecision(significant), the formatting the CSV files had before, and printf's %.<n>g.
TEST(Table, CsvCellsAreTheOstreamsSignificantDigits)
{
  const auto dir = std::filesystem::temp_directory_path() / "gearfem_test_table_format";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::vector<double> values = {0.0, -0.0, 1.0, -1.0, 200.0, 0.1, 1.0 / 3.0, -2.5e-7, 6.02214076e23,
                                1e-300, 4.9e-324, 1.7976931348623157e308, 123456789012.0, 1e10, 1e-5,
                                99999.999995, 0.000123456789012345};
  unsigned long long state = 36;
  for (int i = 0; i < 2000; ++i)
    {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      const double mantissa = double(state >> 11) / double(1ull << 53) - 0.5;
      values.push_back(mantissa * std::pow(10.0, int(state % 41) - 20));
    }
  for (const int significant : {6, 10, 17})
    {
      Table t;
      t.add_column("a", "");
      t.add_column("b", "um");
      std::ostringstream expected;
      expected << "a,b [um]\n" << std::setprecision(significant);
      for (std::size_t i = 0; i + 1 < values.size(); i += 2)
        {
          t.add_row({values[i], values[i + 1]});
          expected << values[i] << "," << values[i + 1] << "\n";
          char c[64];
          std::snprintf(c, sizeof(c), "%.*g", significant, values[i]);
          std::ostringstream one;
          one << std::setprecision(significant) << values[i];
          ASSERT_EQ(one.str(), c);
        }
      t.write_csv(dir / "t.csv", significant);
      std::ifstream in(dir / "t.csv");
      std::stringstream got;
      got << in.rdbuf();
      EXPECT_EQ(got.str(), expected.str()) << "significant " << significant;
    }
  std::filesystem::remove_all(dir);
}
