// The `Post` section: defaults equal the thresholds the evaluation had before they became
// parameters (5 nodes, share 1e-6, unresolved share 0.05, tip edge band 1e-9 m_n), and each
// value out of range is an InputError naming its entry (exit status 2 in the CLI).
#include "base/errors.h"
#include "post/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <string>

using namespace gearfem;

namespace
{
  post::PostOptions parse(const std::string &text)
  {
    dealii::ParameterHandler prm;
    post::declare_post_parameters(prm);
    prm.parse_input_from_string(text);
    return post::parse_post_parameters(prm);
  }

  /// The entry named by the InputError that parsing `text` throws ("" if none is thrown).
  std::string rejected_entry(const std::string &text)
  {
    try
      {
        (void)parse(text);
      }
    catch (const InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find(e.parameter()), std::string::npos) << e.what();
        return e.parameter();
      }
    return "";
  }
} // namespace

TEST(PostParameters, DefaultsAreThePreviousThresholds)
{
  const auto o = parse("");
  EXPECT_EQ(o.min_patch_nodes, 5);
  EXPECT_EQ(o.loaded_share, 1e-6);
  EXPECT_EQ(o.unresolved_share, 0.05);
  EXPECT_EQ(o.tip_edge_band, 1e-9);
}

TEST(PostParameters, ValuesAreRead)
{
  const auto o = parse("subsection Post\n set Min patch nodes = 8\n set Loaded pair share = 0.01\n"
                       " set Unresolved share = 0.1\n set Tip edge band = 0.02\nend\n");
  EXPECT_EQ(o.min_patch_nodes, 8);
  EXPECT_EQ(o.loaded_share, 0.01);
  EXPECT_EQ(o.unresolved_share, 0.1);
  EXPECT_EQ(o.tip_edge_band, 0.02);
}

TEST(PostParameters, BadValuesNameTheEntry)
{
  EXPECT_EQ(rejected_entry("subsection Post\n set Min patch nodes = 2\nend\n"), "Post/Min patch nodes");
  EXPECT_EQ(rejected_entry("subsection Post\n set Min patch nodes = ${N}\nend\n"), "Post/Min patch nodes");
  EXPECT_EQ(rejected_entry("subsection Post\n set Loaded pair share = 1\nend\n"), "Post/Loaded pair share");
  EXPECT_EQ(rejected_entry("subsection Post\n set Unresolved share = -0.1\nend\n"), "Post/Unresolved share");
  EXPECT_EQ(rejected_entry("subsection Post\n set Tip edge band = 0.6\nend\n"), "Post/Tip edge band");
  EXPECT_EQ(rejected_entry("subsection Post\n set Tip edge band = 1e-320\nend\n"), "Post/Tip edge band");
}
