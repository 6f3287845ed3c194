#include "gearbox/fe/parameters.h"

#include "base/number.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::gearbox::fe
{
  void declare_fe_stress_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    prm.enter_subsection("FE stresses");
    prm.declare_entry("Stages", "", Anything(),
                      "Stages (1-based, comma-separated) whose meshes (sun-planet and planet-ring, or the pair of a "
                      "parallel stage) are solved by FE when Gearbox/Stress source = FE; empty: all. The "
                      "planet-ring mesh is solved as a pinion in a ring (docs/internal-gears.md). Allowed: 1 to the "
                      "number of stages.");
    prm.declare_entry("Sector teeth", "3", Anything(), "Teeth of each sector model. Units: none. Allowed: 3 to 7.");
    prm.declare_entry("h_contact", "0", Anything(),
                      "Element size on the drive flanks; 0: m_n/30. Units: mm. Allowed: 0 to 5.");
    prm.declare_entry("h_fillet", "0", Anything(),
                      "Element size on the fillets; 0: m_n/14. Units: mm. Allowed: 0 to 5.");
    prm.declare_entry("h_body", "0", Anything(), "Element size inside the bodies; 0: m_n. Units: mm. Allowed: 0 to 50.");
    prm.declare_entry("Positions", "12", Anything(),
                      "Roll angles over one mesh cycle, from A. Units: none. Allowed: 4 to 200.");
    prm.declare_entry("Torque points", "3", Anything(),
                      "Gearbox-input torques solved, evenly from the smallest to the largest bin; the "
                      "bins in between are interpolated (sigma_H/sqrt(T), sigma_F/T linear in T); 0: "
                      "every bin. Units: none. Allowed: 0 to 50.");
    prm.leave_subsection();
  }

  FeStressOptions parse_fe_stress_parameters(dealii::ParameterHandler &prm, std::size_t n_stages)
  {
    FeStressOptions o;
    const std::string p = "FE stresses/";
    prm.enter_subsection("FE stresses");
    o.stages = parse_int_list(p + "Stages", prm.get("Stages"));
    o.sector_teeth = parse_int(p + "Sector teeth", prm.get("Sector teeth"), 3, 7);
    o.h_contact = parse_double(p + "h_contact", prm.get("h_contact"), 0.0, 5.0) * 1e-3;
    o.h_fillet = parse_double(p + "h_fillet", prm.get("h_fillet"), 0.0, 5.0) * 1e-3;
    o.h_body = parse_double(p + "h_body", prm.get("h_body"), 0.0, 50.0) * 1e-3;
    o.positions = parse_int(p + "Positions", prm.get("Positions"), 4, 200);
    o.torque_points = parse_int(p + "Torque points", prm.get("Torque points"), 0, 50);
    prm.leave_subsection();
    validate(o, n_stages);
    return o;
  }
} // namespace gearfem::gearbox::fe
