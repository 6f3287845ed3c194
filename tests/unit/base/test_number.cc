// base/number.h: the one checked text -> number conversion.
#include "base/errors.h"
#include "base/number.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

using namespace gearfem;

namespace
{
  /// The message of the InputError thrown by f, or "" if none.
  template <typename F>
  std::string error_of(F f)
  {
    try
      {
        f();
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

TEST(Number, AcceptsDecimalNumbers)
{
  EXPECT_DOUBLE_EQ(parse_double("a", "3"), 3.0);
  EXPECT_DOUBLE_EQ(parse_double("a", " -2.5e3 "), -2500.0);
  EXPECT_DOUBLE_EQ(parse_double("a", "+.5"), 0.5);
  EXPECT_DOUBLE_EQ(parse_double("a", "0"), 0.0);
  EXPECT_DOUBLE_EQ(parse_double("a", "1e-300"), 1e-300);
  EXPECT_DOUBLE_EQ(parse_double("a", "1.7e308"), 1.7e308);
  EXPECT_DOUBLE_EQ(parse_double("a", "2.2250738585072014e-308"), std::numeric_limits<double>::min());
  EXPECT_EQ(parse_int("n", " 42"), 42);
  EXPECT_EQ(parse_int("n", "-7"), -7);
}

TEST(Number, RefusesWhatOnlyLooksNumeric)
{
  for (const std::string bad : {"${X}", "", "  ", "1.5x", "x1", "0x10", "0x1p3", "inf", "-inf", "nan",
                                "NaN", "infinity", "1e400", "-1e400", "1e-320", "-4.9e-324", "1,5",
                                "1 2", "e5", "--1", "{1|2}"})
    {
      const std::string m = error_of([&] { parse_double("Gear 1/Face width", bad); });
      ASSERT_FALSE(m.empty()) << "accepted: '" << bad << "'";
      EXPECT_NE(m.find("'Gear 1/Face width'"), std::string::npos) << m;
      EXPECT_NE(m.find(": " + bad + " (allowed: "), std::string::npos) << m;
      EXPECT_NE(m.find("2.22507e-308"), std::string::npos) << m; // the allowed range is stated
    }
  EXPECT_NE(error_of([] { parse_double("E", "1e-320"); }).find("subnormal"), std::string::npos);
  EXPECT_NE(error_of([] { parse_double("E", "1e999"); }).find("overflows"), std::string::npos);
}

TEST(Number, RangeIsStated)
{
  EXPECT_DOUBLE_EQ(parse_double("nu", "0.3", 0, 0.5), 0.3);
  const std::string m = error_of([] { parse_double("Material/Poisson's ratio", "0.7", 0, 0.5); });
  EXPECT_NE(m.find("within [0, 0.5]"), std::string::npos) << m;
}

TEST(Number, Integers)
{
  for (const std::string bad : {"1.0", "1e3", "${X}", "", "99999999999", "-99999999999", "0x10", "3 4"})
    EXPECT_FALSE(error_of([&] { parse_int("Gear 1/Number of teeth", bad); }).empty()) << bad;
  EXPECT_NE(error_of([] { parse_int("z", "4", 5, 10000); }).find("[5, 10000]"), std::string::npos);
}

TEST(Number, Lists)
{
  const auto v = parse_double_list("Solve/Roll angles", " -1, 0 ,, 2.5,");
  ASSERT_EQ(v.size(), 3u);
  EXPECT_DOUBLE_EQ(v[2], 2.5);
  const std::string m = error_of([] { parse_double_list("Solve/Torques", "100, 1e-320, 3"); });
  EXPECT_NE(m.find("'Solve/Torques'"), std::string::npos) << m;
  EXPECT_NE(m.find("item '1e-320'"), std::string::npos) << m;
  EXPECT_EQ(parse_int_list("Mesh/Fine teeth", "0, -1, 2").size(), 3u);
  EXPECT_FALSE(error_of([] { parse_int_list("Mesh/Fine teeth", "0, 1x"); }).empty());
}

TEST(Number, Representable)
{
  EXPECT_TRUE(is_representable(0.0));
  EXPECT_TRUE(is_representable(-1e300));
  EXPECT_FALSE(is_representable(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(is_representable(std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(is_representable(std::numeric_limits<double>::denorm_min()));
}
