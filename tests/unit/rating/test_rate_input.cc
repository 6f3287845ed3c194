// The example input inputs/seed001_23_69_rate.prm parses with the declared sections and
// rates to the AGMA contact stresses of Siasos 2010 (within 1 %).
#include "analytical/parameters.h"
#include "rating/parameters.h"
#include "rating/rating.h"
#include "base/errors.h"
#include "geometry/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

using namespace gearfem;

namespace
{
  std::filesystem::path source_dir()
  {
    const char *s = std::getenv("GEARFEM_SOURCE_DIR");
    return s ? s : GEARFEM_TEST_SOURCE_DIR;
  }

  void declare(dealii::ParameterHandler &prm)
  {
    geometry::declare_geometry_parameters(prm);
    geometry::declare_material_parameters(prm);
    rating::declare_rating_parameters(prm);
    analytical::declare_analytical_parameters(prm);
  }
} // namespace

TEST(RateInput, Seed001ExampleParsesAndRates)
{
  dealii::ParameterHandler prm;
  declare(prm);
  prm.parse_input((source_dir() / "inputs" / "seed001_23_69_rate.prm").string(), "", true, false);
  const geometry::GeometryInput gi = geometry::parse_geometry_parameters(prm);
  const geometry::PairMaterial pm = geometry::parse_material_parameters(prm);
  rating::RatingInput ri = rating::parse_rating_parameters(prm);
  analytical::parse_analytical_parameters(prm);
  ri.E1 = pm.gear1.youngs_modulus, ri.nu1 = pm.gear1.poisson_ratio;
  ri.E2 = pm.gear2.youngs_modulus, ri.nu2 = pm.gear2.poisson_ratio;
  ASSERT_EQ(ri.torques.size(), 4u);
  const rating::RatingReport r = rating::rate(geometry::build_pair(gi), ri);
  const double sH[4] = {827.0, 739.7, 640.6, 523.1}; // Siasos 2010 table 6.2-1
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(r.row("AGMA", "sigma_H").values[i] / sH[i], 1.0, 0.01);
}

TEST(RateInput, BadRatingValuesNameTheParameter)
{
  dealii::ParameterHandler prm;
  declare(prm);
  prm.enter_subsection("Rating");
  prm.set("AGMA dynamic factor", "0.5");
  prm.leave_subsection();
  try
    {
      rating::parse_rating_parameters(prm);
      FAIL() << "no InputError";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("Rating/AGMA dynamic factor"), std::string::npos) << e.what();
    }
  dealii::ParameterHandler prm2;
  declare(prm2);
  prm2.enter_subsection("Analytical");
  prm2.set("Stiffness model", "potential energy");
  prm2.leave_subsection();
  EXPECT_THROW(analytical::parse_analytical_parameters(prm2), InputError);
}
