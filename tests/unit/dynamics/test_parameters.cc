// The `Dynamics` parameter section: every example input parses and builds its model;
// bad values give InputError naming the parameter.
#include "base/errors.h"
#include "base/units.h"
#include "dynamics/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace gearfem::dynamics;

namespace
{
  std::filesystem::path source_dir()
  {
    const char *s = std::getenv("GEARFEM_SOURCE_DIR");
    return s ? s : GEARFEM_TEST_SOURCE_DIR;
  }

  DynamicsCase parse_text(const std::string &text)
  {
    dealii::ParameterHandler prm;
    declare_parameters(prm);
    std::istringstream in(text);
    prm.parse_input(in, "test.prm", "", true);
    return parse_parameters(prm);
  }
} // namespace

// Lethe practice: every example input is parsed in CI, so examples cannot rot.
TEST(DynamicsParameters, ExampleInputsParseAndBuild)
{
  int n = 0;
  for (const auto &e : std::filesystem::directory_iterator(source_dir() / "inputs"))
    {
      const std::string name = e.path().filename().string();
      if (name.rfind("dynamics_", 0) != 0 || e.path().extension() != ".prm")
        continue;
      dealii::ParameterHandler prm;
      declare_parameters(prm);
      prm.enter_subsection("Output");
      prm.declare_entry("Directory", "", dealii::Patterns::Anything());
      prm.leave_subsection();
      prm.parse_input(e.path().string(), "", false, true);
      const DynamicsCase c = parse_parameters(prm, e.path().parent_path().string());
      if (c.law == LawKind::external)
        {
          ++n; // built by the command from lib/analytical (checked by its CLI run)
          continue;
        }
      std::vector<std::string> notes;
      const auto model = build_model(c, &notes);
      EXPECT_GT(model->mesh_period_time(), 0.0) << name;
      ++n;
    }
  EXPECT_GE(n, 2);
}

// Unit conversion at the boundary: rpm -> rad/s, mm -> m, N/(mm um) -> N/m^2.
TEST(DynamicsParameters, UnitsAreConverted)
{
  const DynamicsCase c = parse_text("subsection Dynamics\n subsection Operating\n"
                                    "  set Pinion speed = 600\n end\n subsection Pair\n"
                                    "  set Module = 3\n set Face width = 20\n end\nend\n");
  EXPECT_NEAR(c.speed, 600 * 2 * gearfem::units::pi / 60, 1e-12);
  EXPECT_NEAR(c.module, 3e-3, 1e-15);
  EXPECT_NEAR(c.face_width, 0.02, 1e-15);
  EXPECT_NEAR(c.single_pair_stiffness, 14e9, 1e-3);
}

// Bad input: step/tolerance <= 0, speed range min >= max, zeta < 0 -> InputError naming it.
TEST(DynamicsParameters, BadInput)
{
  auto expect_error = [](const std::string &text, const std::string &name) {
    try
      {
        parse_text(text);
        ADD_FAILURE() << "no error for " << name;
      }
    catch (const gearfem::InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      }
  };
  expect_error("subsection Dynamics\n subsection Integrator\n set Steps per period = 0\n end\nend\n",
               "Steps per period");
  expect_error("subsection Dynamics\n subsection Integrator\n set Method = DOPRI5\n"
               " set Relative tolerance = -1\n end\nend\n",
               "Relative tolerance");
  expect_error("subsection Dynamics\n set Analysis = sweep\n subsection Analysis\n"
               " set Sweep minimum speed = 900\n set Sweep maximum speed = 900\n end\nend\n",
               "Sweep minimum speed");
  expect_error("subsection Dynamics\n subsection Operating\n set Damping ratio = -0.01\n end\nend\n",
               "Damping ratio");
  expect_error("subsection Dynamics\n subsection Mesh force\n set Law = STE\n"
               " set STE file = /nonexistent.csv\n end\nend\n",
               "STE file");
}

// Law = STE reads the sweep.csv of `gearfem solve` directly: the rows at the case's input
// torque give STE(theta), and kbar = mean F_n / mean STE (the FE mean mesh stiffness; here
// computed by hand from the rows written below). Another torque is refused, naming the
// torques the file has.
TEST(DynamicsParameters, SteFromFeSweep)
{
  const auto dir = std::filesystem::temp_directory_path() / "gearfem_ste_sweep_test";
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "sweep.csv");
    f << "torque [N m],position [-],roll angle [deg],STE [um],F_n [N],p_max [MPa]\n";
    // z1 = 50: one mesh period is 7.2 deg; four positions at 100 N m, two at 200 N m.
    f << "100,0,-6,4.0,1400,300\n100,1,-4,3.0,1400,300\n100,2,-2,3.5,1400,300\n100,3,0,4.5,1400,300\n";
    f << "200,0,-6,8.0,2800,400\n200,1,-4,6.0,2800,400\n";
  }
  const std::string head = "subsection Dynamics\n subsection Pair\n set Pinion teeth = 50\n"
                           " set Gear teeth = 50\n set Module = 3\n set Face width = 20\n end\n"
                           " subsection Mesh force\n set Law = STE\n set STE file = " +
                           (dir / "sweep.csv").string() + "\n end\n subsection Operating\n";
  const DynamicsCase c = parse_text(head + " set Input torque = 100\n end\nend\n");
  ASSERT_EQ(c.ste_theta.size(), 4u);
  EXPECT_NEAR(c.ste_theta[1], -4 * gearfem::units::deg, 1e-15);
  EXPECT_NEAR(c.ste_values[3], 4.5e-6, 1e-18);
  EXPECT_NEAR(c.ste_stiffness, 1400 / 3.75e-6, 1e-6 * 1400 / 3.75e-6); // mean F / mean STE
  std::vector<std::string> notes;
  const auto model = build_model(c, &notes);
  EXPECT_NEAR(model->law().mean_stiffness(), 1400 / 3.75e-6, 1.0);
  try
    {
      parse_text(head + " set Input torque = 150\n end\nend\n");
      ADD_FAILURE() << "no error for a torque the file does not have";
    }
  catch (const gearfem::InputError &e)
    {
      const std::string w = e.what();
      EXPECT_NE(w.find("STE file"), std::string::npos) << w;
      EXPECT_NE(w.find("100 200"), std::string::npos) << w;
    }
  std::filesystem::remove_all(dir);
}
