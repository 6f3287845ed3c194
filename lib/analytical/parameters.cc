#include "analytical/parameters.h"

#include "base/errors.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

namespace gearfem::analytical
{
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;
  using dealii::Patterns::Selection;

  void declare_analytical_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Analytical");
    prm.declare_entry("Stiffness model", "weber cornell", Selection("weber cornell|potential energy"),
                      "Tooth-pair compliance: Weber/Cornell beam + O'Donnell foundation + Weber "
                      "Hertz (load dependent), or potential energy (Yang & Lin 1987, Tian 2004) "
                      "beam + Sainsot foundation + constant Hertz. The plane condition is "
                      "Material/Plane model.");
    prm.declare_entry("ODonnell constant", "cornell", Selection("cornell|seed000"),
                      "First O'Donnell foundation constant: 50/(3 pi) (Cornell 1981, default) or "
                      "50/(2 pi) (Gkimisis 2019 eq. 3.7). See docs/analytical.md.");
    prm.declare_entry("Bore diameter 1", "0", Double(0),
                      "Bore (rim inner) diameter of gear 1, for the Sainsot foundation of the "
                      "potential-energy model. Units: mm. 0: not set (required by that model).");
    prm.declare_entry("Bore diameter 2", "0", Double(0), "The same for gear 2. Units: mm.");
    prm.declare_entry("Mesh positions", "200", Integer(2, 100000),
                      "Positions over one angular pitch for the mesh-cycle output. Units: none.");
    prm.declare_entry("Corner contact", "true", dealii::Patterns::Bool(),
                      "Mesh cycle with the corner contacts OA/BG of Gkimisis 2019: outside A..E a pair "
                      "carries load once the deflection closes the rigid gap of its tip corner "
                      "(the single-pair zone narrows with load). Units: none.");
    prm.declare_entry("Mesh cycle law", "load sharing", Selection("load sharing|seed000 ricker"),
                      "Law of the mesh-cycle output: equal-deflection load sharing on the "
                      "Stiffness model, or the semi-analytical pair stiffness with "
                      "Ricker-wavelet load sharing of Gkimisis 2019 (eqs. 3.18-3.46, its Hertz term "
                      "linearised with the load-sharing mean stiffness; lib/analytical/cycle_table.h).");
    prm.leave_subsection();
  }

  AnalyticalInput parse_analytical_parameters(dealii::ParameterHandler &prm)
  {
    AnalyticalInput a;
    prm.enter_subsection("Analytical");
    a.options.model = stiffness_model_from_string(prm.get("Stiffness model"));
    a.options.odonnell = prm.get("ODonnell constant") == "seed000" ? ODonnellConstant::seed000_50_over_2pi :
                                                                   ODonnellConstant::cornell_50_over_3pi;
    a.bore_radius1 = 0.5e-3 * params::get_double(prm, "Bore diameter 1");
    a.bore_radius2 = 0.5e-3 * params::get_double(prm, "Bore diameter 2");
    a.positions = params::get_integer(prm, "Mesh positions");
    a.corner_contact = params::get_bool(prm, "Corner contact");
    a.law = cycle_law_from_string(prm.get("Mesh cycle law"));
    prm.leave_subsection();
    if (a.options.model == StiffnessModel::potential_energy && (a.bore_radius1 <= 0 || a.bore_radius2 <= 0))
      throw InputError("Analytical/Bore diameter 1, 2", "0 mm", "> 0 mm",
                       "the potential-energy model (Sainsot foundation) needs the bore diameters");
    return a;
  }
} // namespace gearfem::analytical
