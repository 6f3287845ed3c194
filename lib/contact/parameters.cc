// The `Contact` section.
#include "contact/parameters.h"

#include "base/errors.h"
#include "base/number.h"
#include "base/units.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>

namespace gearfem::contact
{
  void declare_contact_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.enter_subsection("Contact");
    prm.declare_entry("Method", "lagrange", Selection("lagrange|penalty"),
                      "Contact enforcement: Lagrange multipliers (primal-dual active set) or "
                      "penalty (Newton, consistent tangent). Units: none.");
    prm.declare_entry("Penalty factor", "100", Double(),
                      "Penalty pressure per unit penetration = factor * E / h (E the smaller "
                      "Young's modulus, h the local face length). Units: none. Allowed: > 0.");
    prm.declare_entry("Search distance", "0.3", Double(),
                      "Slave nodes within this normal distance of the mating flank are contact "
                      "candidates. Units: mm. Allowed: > 0.");
    prm.declare_entry("Tolerance", "1e-9", Double(),
                      "Relative tolerance on rotation, contact forces and torque. Units: none. "
                      "Allowed: (0, 1e-2).");
    prm.declare_entry("Max active-set iterations", "60", Integer(), "Units: none. Allowed: >= 1.");
    prm.declare_entry("Max geometry iterations", "25", Integer(),
                      "Re-linearisations of the gap on the exact geometry. Units: none. Allowed: >= 1.");
    prm.declare_entry("Max load cuts", "4", Integer(),
                      "Load-step halvings after a non-converged solve. Units: none. Allowed: >= 0.");
    prm.declare_entry("Slave body", "auto", Selection("auto|1|2"),
                      "Body carrying the slave nodes of flank-to-flank contacts: auto = the softer "
                      "gear (the pinion when equal). With `Slave selection = per zone` a tooth "
                      "pair whose contact has a tip corner within reach takes the corner's owner "
                      "as its slave instead. Units: none.");
    prm.declare_entry("Slave selection", "per zone", Selection("per zone|fixed"),
                      "per zone: in each tooth pair whose contact lies within reach of a tip "
                      "corner (2 Hertz half-widths + 3 contact elements along the flank, or "
                      "outside the path A-E) the gear owning that corner carries the slave nodes, "
                      "so that the corner is a node checked against the smooth mating flank "
                      "(docs/contact.md); `Slave body` elsewhere. fixed: every node of `Slave "
                      "body` (single-pass node-to-segment, for comparison). Units: none.");
    prm.declare_entry("Gap", "integrated", Selection("integrated|node"),
                      "How the gap of a slave node is measured. integrated: segment-to-segment "
                      "(mortar-type), the gap weighted by the node's shape function over its slave "
                      "faces, so that a contact patch of a few nodes sees the curved gap between "
                      "them (slave-independent and smooth STE on coarse contact meshes); sharp "
                      "slave corners keep the nodal gap (point contact). node: node-to-segment "
                      "collocation at the slave nodes (docs/contact.md). Units: none.");
    prm.declare_entry("Micro-geometry", "geometry", Selection("geometry|gap"),
                      "How tip reliefs (Gear i/Tip relief) enter the contact. geometry: the relieved "
                      "profiles are meshed (exact). gap: the unmodified gears are meshed and each "
                      "relief is an initial separation along the normal, as LTCA codes do; designs "
                      "that differ only in micro-geometry then share one mesh and factorisation "
                      "(docs/contact.md). Units: none.");
    prm.declare_entry("Friction coefficient", "0", Double(),
                      "Coulomb friction coefficient mu of Friction law = constant: the tangential force "
                      "mu lambda at each contact point opposes the rigid-body sliding of the flanks "
                      "(docs/friction.md). 0: frictionless. Units: none. Allowed: [0, 1].");
    prm.declare_entry("Friction sliding tolerance", "1e-4", Double(),
                      "Below this sliding speed, as a fraction of the pitch-line speed, the friction "
                      "force ramps linearly through zero instead of reversing (near the pitch point; "
                      "docs/friction.md measures its effect). Units: none. Allowed: (0, 0.1].");
    prm.declare_entry("Friction law", "constant", Selection("constant|ISO/TR 14179-2|AGMA 925"),
                      "The mean friction coefficient of the mesh. constant: Friction coefficient. "
                      "ISO/TR 14179-2: Schlenk's law of ISO/TR 14179-2:2001 from the load per face width, "
                      "the sum velocity and radius of curvature at the pitch point, Oil viscosity and the "
                      "roughness (evaluated per torque). AGMA 925: 0.06 C_R of AGMA 925-A03 from the "
                      "roughness (the gearbox's scuffing coefficient). Units: none.");
    prm.declare_entry("Pinion speed", "1000", Double(),
                      "Pinion speed for the mesh power loss and the speeds of the friction law. "
                      "Units: rpm. Allowed: > 0.");
    prm.declare_entry("Oil viscosity", "0", Double(),
                      "Dynamic viscosity of the oil at its operating temperature (ISO/TR 14179-2; 0: not "
                      "given). Units: mPa s. Allowed: [0.1, 1e5] when the law needs it.");
    prm.declare_entry("Roughness gear 1", "0", Double(),
                      "Arithmetic mean roughness Ra of the pinion flanks (0: not given). Units: um.");
    prm.declare_entry("Roughness gear 2", "0", Double(),
                      "Arithmetic mean roughness Ra of the gear flanks (0: not given). Units: um.");
    prm.declare_entry("Lubricant factor", "1", Double(),
                      "X_L of ISO/TR 14179-2 (1 for mineral oil). Units: none.");
    prm.leave_subsection();
  }

  ContactOptions parse_contact_parameters(dealii::ParameterHandler &prm, double E1, double E2)
  {
    ContactOptions o;
    prm.enter_subsection("Contact");
    o.method                    = method_from_string(prm.get("Method"));
    o.penalty_factor            = params::get_double(prm, "Penalty factor");
    o.search_distance           = params::get_double(prm, "Search distance") * 1e-3;
    o.tolerance                 = params::get_double(prm, "Tolerance");
    o.max_active_set_iterations = params::get_integer(prm, "Max active-set iterations");
    o.max_geometry_iterations   = params::get_integer(prm, "Max geometry iterations");
    o.max_load_cuts             = params::get_integer(prm, "Max load cuts");
    const std::string slave     = prm.get("Slave body");
    o.slave = slave == "auto" ? (E2 < E1 ? 2 : 1) : std::stoi(slave);
    o.per_zone_slaves           = prm.get("Slave selection") == "per zone";
    o.gap                       = gap_rule_from_string(prm.get("Gap"));
    o.micro_geometry_as_gap     = prm.get("Micro-geometry") == "gap";
    o.friction                  = params::get_double(prm, "Friction coefficient");
    o.friction_tolerance        = params::get_double(prm, "Friction sliding tolerance");
    prm.leave_subsection();
    o.validate();
    return o;
  }
} // namespace gearfem::contact
