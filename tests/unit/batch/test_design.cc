// batch/design.h: design tables, full factorial and Latin hypercube. Each test
// states what it checks against: the table text itself, counting, or the defining property
// of the sampling (one sample per stratum and dimension).
#include "base/errors.h"
#include "batch/design.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <string>

using namespace gearfem;
using namespace gearfem::batch;

namespace
{
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
  bool has(const std::string &text, const std::string &part) { return text.find(part) != std::string::npos; }
} // namespace

TEST(DesignTable, ReadsPathsIdsAndQuotedCells)
{
  const std::string text = "# comment line\n"
                           "id, Gear 1/Tip relief amount ,Solve/Torques\n"
                           "\n"
                           "a,5,\"100, 200\"\n"
                           "b , 7.5 ,300\n";
  const DesignSet s = parse_design_table(text, "t.csv");
  ASSERT_EQ(s.paths, (std::vector<std::string>{"Gear 1/Tip relief amount", "Solve/Torques"}));
  ASSERT_EQ(s.designs.size(), 2u);
  EXPECT_EQ(s.designs[0].id, "a");
  EXPECT_EQ(s.designs[0].values, (std::vector<std::string>{"5", "100, 200"}));
  EXPECT_EQ(s.designs[1].id, "b");
  EXPECT_EQ(s.designs[1].values, (std::vector<std::string>{"7.5", "300"}));
  EXPECT_EQ(s.designs[1].origin, "row 5 of t.csv"); // file line, comments and blanks counted
}

TEST(DesignTable, NumbersRowsWithoutIdColumn)
{
  const DesignSet s = parse_design_table("Gear 1/Face width\n10\n20\n30\n", "t.csv");
  ASSERT_EQ(s.designs.size(), 3u);
  EXPECT_EQ(s.designs[0].id, "design_001");
  EXPECT_EQ(s.designs[2].id, "design_003");
  EXPECT_EQ(s.designs[2].values[0], "30");
}

TEST(DesignTable, MalformedTablesNameColumnAndRow)
{
  const std::string short_row = error_of([] { parse_design_table("id,A/x,B/y\na,1,2\nb,1\n", "t.csv"); });
  EXPECT_TRUE(has(short_row, "t.csv, row 3")) << short_row;
  EXPECT_TRUE(has(short_row, "2 cells")) << short_row;
  const std::string empty_cell = error_of([] { parse_design_table("id,A/x,B/y\na,1,\n", "t.csv"); });
  EXPECT_TRUE(has(empty_cell, "column 'B/y', row 2")) << empty_cell;
  const std::string dup = error_of([] { parse_design_table("A/x,A/x\n1,2\n", "t.csv"); });
  EXPECT_TRUE(has(dup, "column 2 'A/x'")) << dup;
  const std::string bad_path = error_of([] { parse_design_table("A//x\n1\n", "t.csv"); });
  EXPECT_TRUE(has(bad_path, "A//x")) << bad_path;
  const std::string bad_id = error_of([] { parse_design_table("id,A/x\na b,1\n", "t.csv"); });
  EXPECT_TRUE(has(bad_id, "column 'id', row 2")) << bad_id;
  const std::string dup_id = error_of([] { parse_design_table("id,A/x\na,1\na,2\n", "t.csv"); });
  EXPECT_TRUE(has(dup_id, "column 'id', row 3")) << dup_id;
  EXPECT_TRUE(has(error_of([] { parse_design_table("", "t.csv"); }), "(empty)"));
  EXPECT_TRUE(has(error_of([] { parse_design_table("A/x\n", "t.csv"); }), "(no rows)"));
  EXPECT_TRUE(has(error_of([] { parse_design_table("A/x\n\"1\n", "t.csv"); }), "quote"));
}

TEST(DesignPaths, SplitsSectionsAndEntry)
{
  const auto [sections, entry] = split_path("Material/Gear 2/Young's modulus");
  EXPECT_EQ(sections, (std::vector<std::string>{"Material", "Gear 2"}));
  EXPECT_EQ(entry, "Young's modulus");
  EXPECT_TRUE(split_path("Contact").first.empty());
  EXPECT_FALSE(error_of([] { split_path("Gear 1/"); }).empty());
}

TEST(Factorial, EveryCombinationOnceFirstPathSlowest)
{
  const auto lists = parse_path_lists("Batch/Factorial", "A/x: 1, 2; B/y: a, b, c");
  const DesignSet s = full_factorial(lists);
  ASSERT_EQ(s.designs.size(), 6u); // 2 x 3
  std::set<std::pair<std::string, std::string>> seen;
  for (const auto &d : s.designs)
    seen.insert({d.values[0], d.values[1]});
  EXPECT_EQ(seen.size(), 6u);
  EXPECT_EQ(s.designs[0].values, (std::vector<std::string>{"1", "a"}));
  EXPECT_EQ(s.designs[1].values, (std::vector<std::string>{"1", "b"}));
  EXPECT_EQ(s.designs[3].values, (std::vector<std::string>{"2", "a"}));
  EXPECT_EQ(s.designs[5].id, "ff_006");
  EXPECT_TRUE(has(error_of([] { parse_path_lists("Batch/Factorial", "A/x 1, 2"); }), "no ':'"));
  EXPECT_TRUE(has(error_of([] { parse_path_lists("Batch/Factorial", "A/x: 1; A/x: 2"); }), "duplicate"));
  EXPECT_TRUE(has(error_of([] { parse_path_lists("Batch/Latin hypercube", "A/x: 1, 2, 3", 2); }), "2 values"));
}

TEST(LatinHypercube, OneSamplePerStratumInEveryDimension)
{
  const std::size_t n = 16;
  const DesignSet s   = latin_hypercube({{"A/x", {0.0, 1.0}}, {"B/y", {-10.0, 30.0}}}, n, 7);
  ASSERT_EQ(s.designs.size(), n);
  const double lo[2] = {0.0, -10.0}, hi[2] = {1.0, 30.0};
  for (int d = 0; d < 2; ++d)
    {
      std::set<int> strata;
      for (const auto &x : s.designs)
        {
          const double v = std::strtod(x.values[d].c_str(), nullptr);
          ASSERT_GE(v, lo[d]);
          ASSERT_LE(v, hi[d]);
          strata.insert(int((v - lo[d]) / (hi[d] - lo[d]) * double(n)));
        }
      EXPECT_EQ(strata.size(), n) << "dimension " << d; // each of the n strata exactly once
    }
  // The same seed gives the same designs; another seed others.
  const DesignSet again = latin_hypercube({{"A/x", {0.0, 1.0}}, {"B/y", {-10.0, 30.0}}}, n, 7);
  const DesignSet other = latin_hypercube({{"A/x", {0.0, 1.0}}, {"B/y", {-10.0, 30.0}}}, n, 8);
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_EQ(s.designs[i].values, again.designs[i].values);
  bool differ = false;
  for (std::size_t i = 0; i < n; ++i)
    differ |= s.designs[i].values != other.designs[i].values;
  EXPECT_TRUE(differ);
  EXPECT_EQ(s.designs[0].id, "lhs_001");
  EXPECT_FALSE(error_of([] { latin_hypercube({{"A/x", {2.0, 1.0}}}, 4, 1); }).empty());
}
