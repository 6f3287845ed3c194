// base/table.h: the CSV writer refuses non-finite values (nothing partial is left), and the
// reader converts every cell with the checked conversion.
#include "base/errors.h"
#include "base/table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

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
