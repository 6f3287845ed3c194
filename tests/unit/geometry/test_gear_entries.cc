// One declaration of the gear-geometry entries: the same pair (Siasos 2010's 23/69, m 4,
// alpha 20 deg, h_a* 1, b 70 mm) parsed by the input sections of `profile`/`rate`/`solve`
// (Rack, Gear i), `dynamics` (Dynamics/Pair), `optimise` (Optimise) and `gearbox`
// (Stage 1, a parallel stage) gives the same numbers, and the same out-of-range value gives
// the same allowed range in every command's error, naming that command's own entry.
// Reference: geometry/limits.h (the one statement of the ranges); the values are SI
// conversions of the same input.
#include "base/errors.h"
#include "base/units.h"
#include "dynamics/parameters.h"
#include "gearbox/parameters.h"
#include "geometry/parameters.h"
#include "optimise/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <functional>
#include <sstream>
#include <string>

using namespace gearfem;

namespace
{
  /// The parsed pair: z1, z2, m, alpha, h_a*, b (SI).
  struct Pair
  {
    int z1 = 0, z2 = 0;
    double m = 0, alpha = 0, ha = 0, b = 0;
  };

  /// The entries of the pair, with `name = value` overriding one of them (by the generic
  /// name: teeth1, module, alpha, addendum).
  struct Values
  {
    std::string z1 = "23", z2 = "69", m = "4", alpha = "20", ha = "1.0", b = "70";
  };

  Pair parse(dealii::ParameterHandler &prm, const std::string &text,
             const std::function<void(dealii::ParameterHandler &)> &declare,
             const std::function<Pair(dealii::ParameterHandler &)> &read)
  {
    declare(prm);
    prm.parse_input_from_string(text);
    return read(prm);
  }

  Pair profile(const Values &v)
  {
    dealii::ParameterHandler prm;
    const std::string text = "subsection Rack\n  set Module = " + v.m + "\n  set Pressure angle = " + v.alpha +
                             "\n  set Addendum coefficient = " + v.ha + "\nend\nsubsection Gear 1\n  set Number of teeth = " +
                             v.z1 + "\n  set Face width = " + v.b + "\nend\nsubsection Gear 2\n  set Number of teeth = " +
                             v.z2 + "\n  set Face width = " + v.b + "\nend\n";
    return parse(prm, text, geometry::declare_geometry_parameters, [](dealii::ParameterHandler &p) {
      const auto gi   = geometry::parse_geometry_parameters(p);
      const auto pair = geometry::build_pair(gi); // the checks of the generated geometry
      return Pair{pair.gear(1).teeth(), pair.gear(2).teeth(), gi.gear1.rack.module, gi.gear1.rack.pressure_angle,
                  gi.gear1.rack.addendum, gi.gear1.face_width};
    });
  }

  Pair dynamics(const Values &v)
  {
    dealii::ParameterHandler prm;
    const std::string text = "subsection Dynamics\n  subsection Pair\n    set Pinion teeth = " + v.z1 +
                             "\n    set Gear teeth = " + v.z2 + "\n    set Module = " + v.m +
                             "\n    set Pressure angle = " + v.alpha + "\n    set Addendum coefficient = " + v.ha +
                             "\n    set Face width = " + v.b + "\n  end\nend\n";
    return parse(prm, text, dynamics::declare_parameters, [](dealii::ParameterHandler &p) {
      const auto c = dynamics::parse_parameters(p);
      return Pair{c.z1, c.z2, c.module, c.alpha, c.addendum, c.face_width};
    });
  }

  Pair optimise(const Values &v)
  {
    dealii::ParameterHandler prm;
    const std::string text = "subsection Optimise\n  set Case = case 2\n  set Pinion teeth = " + v.z1 +
                             "\n  set Gear teeth = " + v.z2 + "\n  set Module = " + v.m + "\n  set Pressure angle = " +
                             v.alpha + "\n  set Addendum coefficient = " + v.ha + "\n  set Face width = " + v.b +
                             "\nend\n";
    return parse(prm, text, optimise::declare_study_parameters, [](dealii::ParameterHandler &p) {
      const auto s = optimise::parse_study_parameters(p);
      return Pair{s.pair.z1, s.pair.z2, s.pair.module, s.pair.pressure_angle, s.pair.addendum, s.face_width};
    });
  }

  Pair gearbox(const Values &v)
  {
    dealii::ParameterHandler prm;
    const std::string text =
      "subsection Gearbox\n  set Number of stages = 1\nend\nsubsection Stage 1\n  set Type = parallel\n"
      "  set Output member = gear 2\n  set Sun profile shift = 0\n  set Planet profile shift = 0\n  set Sun teeth = " +
      v.z1 + "\n  set Planet teeth = " + v.z2 + "\n  set Module = " + v.m + "\n  set Pressure angle = " + v.alpha +
      "\n  set Addendum coefficient = " + v.ha + "\n  set Face width = " + v.b + "\nend\n";
    return parse(prm, text, gearbox::declare_gearbox_parameters, [](dealii::ParameterHandler &p) {
      const auto st = gearbox::parse_gearbox_parameters(p);
      const auto &s = st.input.stages.at(0);
      return Pair{s.z_sun, s.z_planet, s.module, s.pressure_angle, s.addendum, s.face_width};
    });
  }

  const std::vector<std::pair<std::string, std::function<Pair(const Values &)>>> commands = {
    {"profile", profile}, {"dynamics", dynamics}, {"optimise", optimise}, {"gearbox", gearbox}};

  /// Every command refuses `v` with an InputError naming an entry that ends in `entry` and
  /// stating `range`.
  void expect_same_error(const Values &v, const std::string &entry, const std::string &range)
  {
    for (const auto &[name, f] : commands)
      try
        {
          f(v);
          ADD_FAILURE() << name << " accepted the value of " << entry;
        }
      catch (const InputError &e)
        {
          const std::string what = e.what();
          EXPECT_NE(what.find(entry + "'"), std::string::npos) << name << ": " << what;
          EXPECT_NE(what.find(range), std::string::npos) << name << ": " << what;
        }
  }
} // namespace

TEST(GearEntries, SamePairSameNumbersInEveryCommand)
{
  const Values v;
  for (const auto &[name, f] : commands)
    {
      SCOPED_TRACE(name);
      const Pair p = f(v);
      EXPECT_EQ(p.z1, 23);
      EXPECT_EQ(p.z2, 69);
      EXPECT_DOUBLE_EQ(p.m, 4e-3);
      EXPECT_DOUBLE_EQ(p.alpha, 20 * units::deg);
      EXPECT_DOUBLE_EQ(p.ha, 1.0);
      EXPECT_DOUBLE_EQ(p.b, 70e-3);
    }
}

TEST(GearEntries, SameErrorsInEveryCommand)
{
  Values v;
  v.alpha = "40";
  expect_same_error(v, "Pressure angle", "40 deg (allowed: [10, 35] deg)");
  v       = Values();
  v.z1    = "4";
  expect_same_error(v, "teeth", "4 (allowed: [5, 10000])");
  v       = Values();
  v.ha    = "1.6";
  expect_same_error(v, "Addendum coefficient", "1.6 (allowed: [0.5, 1.5])");
  v       = Values();
  v.m     = "0";
  expect_same_error(v, "Module", "0 mm (allowed: > 0 mm)");
  v       = Values();
  v.b     = "-1";
  expect_same_error(v, "Face width", "-1 mm (allowed: > 0 mm)");
}

TEST(GearEntries, SameDescriptionsInEveryCommand)
{
  // The parameter texts that --print-parameters shows state the same ranges.
  auto doc = [](const std::function<void(dealii::ParameterHandler &)> &declare, const std::string &path) {
    dealii::ParameterHandler prm;
    declare(prm);
    std::ostringstream s;
    prm.print_parameters(s, dealii::ParameterHandler::OutputStyle::PRM);
    const std::string t = s.str();
    return t.find(path) != std::string::npos ? t : std::string();
  };
  for (const auto &d : {doc(geometry::declare_geometry_parameters, "Pressure angle"),
                        doc(dynamics::declare_parameters, "Pressure angle"),
                        doc(optimise::declare_study_parameters, "Pressure angle"),
                        doc(gearbox::declare_gearbox_parameters, "Pressure angle")})
    {
      EXPECT_NE(d.find("Allowed: 10 to 35."), std::string::npos);
      EXPECT_NE(d.find("Allowed: 5 to 10000."), std::string::npos);
    }
}
