// The input of `gearfem solve` (solve/input.h): checks that need no mesh run when the input
// is parsed, and the model key that decides which designs share one factorised model.
// References: the definition of the key (what changes the meshed FE model and what does
// not) and the contact requirement of a sector (teeth -1, 0, 1 share the mesh cycle).
#include "base/errors.h"
#include "common/fixtures.h"
#include "common/solve_input.h"
#include "mesh/gear_mesh.h"
#include "solve/input.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <string>

using namespace gearfem;

namespace
{
  const std::string sector = R"(
subsection Mesh
  set Model = sector
  set Sector teeth = 3
  set h_contact = 0.2
  set h_fillet = 0.4
  set h_body = 3
end
)";

  solve::GearContactInput parse(const std::string &text) { return test::parse_solve_input(text); }

  std::string key(const std::string &extra) { return solve::model_key(parse(test::parker_pair(sector + extra))); }
} // namespace

TEST(SolveInput, TwoToothSectorRefusedAtParseTime)
{
  // Parsing builds the pair and checks the outline without gmsh; the sector check is
  // among those checks, so `gearfem solve --validate` refuses it (tests/regression:
  // inputs/bad/sector_two_teeth.prm).
  try
    {
      parse(test::parker_pair(sector + "subsection Mesh\n  set Sector teeth = 2\nend\n"));
      FAIL() << "a 2-tooth sector was accepted";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("Mesh/Sector teeth"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(">= 3"), std::string::npos) << e.what();
    }
  EXPECT_NO_THROW(parse(test::parker_pair(sector)));
}

TEST(SolveInput, LoadedFineTeethAreThoseThePositionsLoad)
{
  // Fine teeth = loaded becomes the list of geometry::loaded_teeth for the Solve positions:
  // a pitch from A on Parker (eps_alpha 1.75) loads pairs 0 and 1 and, 0.03 pitch early,
  // pair -1 (pinion tooth k meshes with gear tooth -k); at C alone, pairs -1..1 within the
  // 0.2-pitch margin. A sector (all teeth fine) and a mesh built without Solve positions
  // refuse it with the entry named.
  const std::string loaded = "subsection Mesh\n  subsection Gear 1\n    set Fine teeth = loaded\n  end\n"
                             "  subsection Gear 2\n    set Fine teeth = loaded\n  end\nend\n";
  const auto in = parse(test::parker_pair(loaded));
  EXPECT_EQ(in.mesh[0].fine_teeth, "-1,0,1");
  EXPECT_EQ(in.mesh[1].fine_teeth, "-1,0,1");
  const auto at_c = parse(test::parker_pair(loaded + "subsection Solve\n  set Positions = named\n"
                                                     "  set Named positions = C\nend\n"));
  EXPECT_EQ(at_c.mesh[0].fine_teeth, "-1,0,1");
  try
    {
      parse(test::parker_pair(sector + loaded));
      FAIL() << "a sector took Fine teeth = loaded";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("Mesh/Gear 1/Fine teeth"), std::string::npos) << e.what();
    }
  mesh::GearMeshParameters p;
  p.fine_teeth = "loaded";
  EXPECT_NO_THROW(p.validate());
  EXPECT_THROW(mesh::fine_teeth(p, 50), InputError);
}

TEST(SolveInput, ModelKeySharesWhatTheFactorisationDoesNotDependOn)
{
  const std::string base = key("");
  EXPECT_EQ(base, key("")) << "the key is a function of the input";
  // The sweep and the evaluation do not change the model.
  EXPECT_EQ(base, key("subsection Solve\n  set Torques = 100, 340\n  set Number of positions = 12\nend\n"));
  // A tip relief as a gap leaves the meshed geometry alone; meshed as geometry, it does not.
  const std::string gap = "subsection Contact\n  set Micro-geometry = gap\nend\n";
  const std::string relief =
    "subsection Gear 1\n  set Tip relief = linear\n  set Tip relief amount = 10\n  set Tip relief length = 3\nend\n";
  EXPECT_EQ(key(gap), key(gap + relief));
  EXPECT_NE(key(""), key(relief));
  // Geometry, mesh, material, finite elements and contact options do.
  EXPECT_NE(base, key("subsection Gear 2\n  set Thickness allowance = 0.05\nend\n"));
  EXPECT_NE(base, key("subsection Pair\n  set Centre distance = 150.2\nend\n"));
  EXPECT_NE(base, key("subsection Mesh\n  set h_contact = 0.15\nend\n"));
  EXPECT_NE(base, key("subsection Material\n  subsection Gear 2\n    set Young's modulus = 200\n  end\nend\n"));
  EXPECT_NE(base, key("subsection Finite elements\n  set Degree = 1\nend\n"));
  EXPECT_NE(base, key("subsection Contact\n  set Method = penalty\nend\n"));
}
