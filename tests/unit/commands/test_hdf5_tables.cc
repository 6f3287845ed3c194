// write_hdf5_tables (the solve-results writer) refuses a non-finite value, names the
// table and column, and leaves no file behind (issue 13: no NaN or inf reaches an output
// file); a finite table is written and its dataset read back with the HDF5 C API.
#include "commands/hdf5_tables.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <limits>
#include <vector>

using namespace gearfem;

TEST(Hdf5Tables, RefuseNonFiniteAndLeaveNoFile)
{
  const auto dir = std::filesystem::temp_directory_path() / "gearfem_test_hdf5_tables";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()})
    {
      Table t;
      t.add_column("roll angle", "deg");
      t.add_column("STE", "um");
      t.add_row({0.0, 5.0});
      t.add_row({1.0, bad});
      try
        {
          commands::write_hdf5_tables({{"sweep", t}}, dir / "results.h5", {{"format", "test"}});
          FAIL() << "non-finite value written";
        }
      catch (const std::exception &e)
        {
          EXPECT_NE(std::string(e.what()).find("STE"), std::string::npos) << e.what();
        }
      EXPECT_TRUE(std::filesystem::is_empty(dir)) << "partial file left behind";
    }
  Table ok;
  ok.add_column("STE", "um");
  ok.add_row({5.0});
  ok.add_row({6.5});
  commands::write_hdf5_tables({{"sweep", ok}}, dir / "results.h5", {{"format", "test"}});
  const hid_t f = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t d = H5Dopen2(f, "/sweep/STE [um]", H5P_DEFAULT);
  ASSERT_GE(d, 0);
  std::vector<double> v(2, 0.0);
  EXPECT_GE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0);
  EXPECT_EQ(v[0], 5.0);
  EXPECT_EQ(v[1], 6.5);
  H5Dclose(d);
  H5Fclose(f);
  std::filesystem::remove_all(dir);
}
