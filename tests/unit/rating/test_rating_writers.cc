// The rating report writers (markdown and CSV) refuse a non-finite value, name its row, and
// leave no file behind (no NaN or inf reaches an output file). Reference: the
// writers' contract itself; a finite report is written and read back.
#include "rating/rating.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

using namespace gearfem::analytical;
using namespace gearfem::rating;

namespace
{
  RatingReport report(double value)
  {
    RatingReport r;
    r.torques = {100.0, 200.0};
    r.rows.push_back({"ISO 6336", "contact stress", "sigma_H", "6336-2 5.1", "MPa", {500.0, 700.0}});
    r.rows.push_back({"ISO 6336", "root stress", "sigma_F1", "6336-3 5.1", "MPa", {100.0, value}});
    return r;
  }
} // namespace

TEST(RatingWriters, RefuseNonFiniteAndLeaveNoFile)
{
  const auto dir = std::filesystem::temp_directory_path() / "gearfem_test_rating_writers";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
      const RatingReport r = report(bad);
      for (int kind = 0; kind < 2; ++kind)
        {
          try
            {
              if (kind == 0)
                r.write_csv(dir / "rating.csv");
              else
                r.write_markdown(dir / "rating.md", "test");
              FAIL() << "non-finite value written";
            }
          catch (const std::exception &e)
            {
              EXPECT_NE(std::string(e.what()).find("root stress"), std::string::npos) << e.what();
            }
          EXPECT_TRUE(std::filesystem::is_empty(dir)) << "partial file left behind";
        }
    }
  report(150.0).write_csv(dir / "rating.csv");
  std::ifstream in(dir / "rating.csv");
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_NE(s.str().find(",150"), std::string::npos) << s.str();
  std::filesystem::remove_all(dir);
}
