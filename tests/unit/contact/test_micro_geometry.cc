// Micro-geometry as a gap modification (Contact/Micro-geometry = gap): the unmodified gears
// meshed, each tip relief an initial separation along the normal. Reference: the exact
// route (the relieved profiles meshed), an independent discretisation of the same physics,
// at the design load (340 N m) with a long and a short linear relief on both gears; the
// tolerances are those of the MPI-batch issue (STE 0.5 %, root stress 1 %). The Parker-pair
// figures over whole cycles are validation/micro_geometry.
#include "contact/gear_contact.h"
#include "contact/parameters.h"
#include "post/position.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace gearfem;
using namespace gearfem::contact;

namespace
{
  std::string case_prm(const char *route, double length_mm)
  {
    std::string s = R"(
subsection Rack
  set Module = 3
  set Pressure angle = 20
end
subsection Pair
  set Centre distance = 150
end
subsection Mesh
  set Model = sector
  set Sector teeth = 3
  set h_contact = 0.1
  set h_fillet = 0.25
  set h_body = 3
end
)";
    for (const char *g : {"Gear 1", "Gear 2"})
      s += std::string("subsection ") + g + "\n  set Number of teeth = 50\n  set Face width = 20\n" +
           "  set Tip relief = linear\n  set Tip relief amount = 6\n  set Tip relief length = " +
           std::to_string(length_mm) + "\nend\n";
    s += std::string("subsection Contact\n  set Micro-geometry = ") + route + "\nend\n";
    return s;
  }

  GearContactInput parse(const std::string &text)
  {
    dealii::ParameterHandler prm;
    declare_gear_contact_input(prm);
    prm.parse_input_from_string(text);
    return parse_gear_contact_input(prm);
  }
} // namespace

TEST(MicroGeometry, GapRouteMatchesRemeshedReliefAtDesignLoad)
{
  const double T = 340;
  for (const double length : {6.7, 3.35})
    {
      const auto exact = parse(case_prm("geometry", length));
      const auto gap   = parse(case_prm("gap", length));
      ASSERT_EQ(exact.unmodified_pair, nullptr);
      ASSERT_NE(gap.unmodified_pair, nullptr);
      auto m_exact = exact.model();
      auto m_gap   = gap.model();
      // The start of contact (the gear's relieved tip on the pinion root), the highest
      // point of single contact (the end of the long relief) and the pitch point.
      const double phiA = exact.pair->point("A").roll_angle, phiB = exact.pair->point("B").roll_angle;
      for (const double phi : {phiA + 0.1 * (phiB - phiA), phiB, 0.0})
        {
          const auto se = m_exact->solve(phi, T), sg = m_gap->solve(phi, T);
          ASSERT_TRUE(se.solution.converged && sg.solution.converged);
          const auto re = post::evaluate_position(*m_exact, se), rg = post::evaluate_position(*m_gap, sg);
          std::cout << "relief length " << length << " mm, phi " << phi * 180 / M_PI << " deg: STE "
                    << re.ste * 1e6 << " / " << rg.ste * 1e6 << " um, root stress pinion "
                    << re.max_root_stress_pinion * 1e-6 << " / " << rg.max_root_stress_pinion * 1e-6 << " MPa\n";
          EXPECT_NEAR(rg.ste / re.ste, 1.0, 5e-3) << "length " << length << ", phi " << phi;
          EXPECT_NEAR(rg.max_root_stress_pinion / re.max_root_stress_pinion, 1.0, 1e-2)
            << "pinion, length " << length << ", phi " << phi;
          EXPECT_NEAR(rg.max_root_stress_gear / re.max_root_stress_gear, 1.0, 1e-2)
            << "gear, length " << length << ", phi " << phi;
        }
    }
}

// Without a relief the gap route is the geometry route: the same mesh, no modification.
TEST(MicroGeometry, NoReliefNoUnmodifiedPair)
{
  std::string text = case_prm("gap", 3.0);
  for (std::size_t p = text.find("linear"); p != std::string::npos; p = text.find("linear"))
    text.replace(p, 6, "none");
  for (std::size_t p = text.find("amount = 6"); p != std::string::npos; p = text.find("amount = 6"))
    text.replace(p, 10, "amount = 0");
  const auto in = parse(text);
  EXPECT_EQ(in.unmodified_pair, nullptr);
}
