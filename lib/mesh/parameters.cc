// The `Mesh` section. Patterns are wide on purpose: GearMeshParameters::validate() gives
// the named errors with the allowed ranges.
#include "mesh/parameters.h"

#include "base/units.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::mesh
{
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  void declare_mesh_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Model", "full gear", Selection("full gear|sector"),
                      "Full gear (all z teeth, bore) or a sector of N teeth with a rim below the "
                      "root circle and radial cut edges (the 3-tooth model of Siasos 2010).",
                      true /* has_to_be_set: tells a set entry from a default (model_choice/parameters.h) */);
    prm.declare_entry("Sector teeth", "3", Integer(),
                      "N, teeth of a sector model. Units: none. Allowed: >= 1 (>= 3 for a contact "
                      "model: solve, batch, optimise, gearbox).");
    prm.declare_entry("h_contact", "0", Double(),
                      "Element size on the drive flanks (and tip) of the fine teeth; 0: m_n/30 "
                      "(0.1 mm at m 3: six nodes across a Hertz patch, STE ripple below 0.1 %, "
                      "see docs/contact.md). Units: mm. Allowed: >= 0 and <= h_body.",
                      true /* has_to_be_set: tells a set entry from a default (model_choice/parameters.h) */);
    prm.declare_entry("h_coast", "0", Double(),
                      "Element size on the coast flanks (and coast tip rounding) of the fine "
                      "teeth, which carry no load in a drive-side analysis; 0: h_fillet. Units: mm. "
                      "Allowed: >= 0, <= h_body.");
    prm.declare_entry("h_corner", "0", Double(),
                      "Element size at the sharp drive tip corners of the fine teeth (the last "
                      "2 h_contact of the drive flank and of the tip land), where a tip corner "
                      "pressing into the mating flank has a singular pressure; 0: h_contact/4 "
                      "(STE converged to 0.5 % between h_contact 0.1 and 0.05 mm at the corner "
                      "positions, docs/contact.md); >= h_contact: no grading. Units: mm. "
                      "Allowed: 0 or >= h_contact/50.",
                      true /* has_to_be_set: tells a set entry from a default (model_choice/parameters.h) */);
    prm.declare_entry("h_fillet", "0.25", Double(),
                      "Element size on the fillets and root of the fine teeth. Units: mm. "
                      "Allowed: > 0 and <= h_body.",
                      true /* has_to_be_set: tells a set entry from a default (model_choice/parameters.h) */);
    prm.declare_entry("h_body", "3", Double(), "Largest element size inside the body. Units: mm. Allowed: > 0.",
                      true /* has_to_be_set: tells a set entry from a default (model_choice/parameters.h) */);
    prm.declare_entry("h_tooth", "0", Double(),
                      "Element size on the outline of the other teeth; 0: min(h_body, 0.4 m). Units: mm.",
                      true /* has_to_be_set: tells a set entry from a default (model_choice/parameters.h) */);
    prm.declare_entry("Growth ratio", "1.2", Double(),
                      "Bound on the size ratio of neighbouring elements away from the fine "
                      "boundaries. Units: none. Allowed: > 1.");
    prm.declare_entry("Global refinements", "0", Integer(0, 6),
                      "Uniform refinements of the gmsh mesh after import (new boundary points on "
                      "the exact curves). Units: none.");
    prm.declare_entry("Spline samples", "24", Integer(4, 400),
                      "Points per outline segment of the gmsh spline geometry (the mesh is snapped "
                      "to the exact curves afterwards). Units: none.");
    prm.declare_entry("Tiled teeth", "false", Bool(),
                      "Full gears: mesh one tooth of each size (fine and coarse) with gmsh and "
                      "turn copies into place, instead of meshing the whole gear (the coarse teeth "
                      "are the same at every position; gmsh's time falls by about z/2). The teeth "
                      "join on radial cuts with one fixed node distribution; where the tiles do not "
                      "join, the whole gear is meshed as usual. Solve/Target tiles unless this "
                      "entry is set. Units: none.",
                      true /* has_to_be_set: tells a set entry from a default (model_choice/parameters.h) */);
    for (const char *g : {"Gear 1", "Gear 2"})
      {
        prm.enter_subsection(g);
        prm.declare_entry("Bore radius", "0", Double(),
                          "Radius of the clamped inner circle; 0: half the root radius. Units: mm. "
                          "Allowed: 0 < r < root radius.");
        prm.declare_entry("Rim thickness", "0", Double(),
                          "If > 0, the inner circle is a fixed rim boundary this far below the root "
                          "circle (replaces the bore); 0: bore for a full gear, 2.75 m for a sector. "
                          "Units: mm.");
        prm.declare_entry("Fine teeth", "auto", Anything(),
                          "Teeth meshed with h_contact/h_fillet: auto (full gear: teeth -2..2, those "
                          "in contact over a mesh cycle plus one on each side; with Solve/Target, "
                          "the teeth the positions load; sector: all), loaded (full gears of an "
                          "external pair: the teeth the Solve positions load, with 0.2 pitch "
                          "beyond A and E; 12-16 % less CPU than auto for a pitch from A) or a "
                          "comma-separated list of tooth indices (negative allowed, modulo z).");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  GearMeshParameters parse_mesh_parameters(dealii::ParameterHandler &prm, int gear)
  {
    GearMeshParameters p;
    prm.enter_subsection("Mesh");
    p.model = prm.get("Model") == "sector" ? GearMeshParameters::Model::sector :
                                             GearMeshParameters::Model::full_gear;
    p.sector_teeth   = params::get_integer(prm, "Sector teeth");
    p.h_contact      = params::get_double(prm, "h_contact") * units::mm;
    p.h_fillet       = params::get_double(prm, "h_fillet") * units::mm;
    p.h_coast        = params::get_double(prm, "h_coast") * units::mm;
    p.h_corner       = params::get_double(prm, "h_corner") * units::mm;
    p.h_body         = params::get_double(prm, "h_body") * units::mm;
    p.h_tooth        = params::get_double(prm, "h_tooth") * units::mm;
    p.growth         = params::get_double(prm, "Growth ratio");
    p.refinements    = params::get_integer(prm, "Global refinements");
    p.spline_samples = params::get_integer(prm, "Spline samples");
    p.tiled          = prm.get_bool("Tiled teeth");
    prm.enter_subsection(gear == 2 ? "Gear 2" : "Gear 1");
    p.bore_radius   = params::get_double(prm, "Bore radius") * units::mm;
    p.rim_thickness = params::get_double(prm, "Rim thickness") * units::mm;
    p.fine_teeth    = prm.get("Fine teeth");
    prm.leave_subsection();
    prm.leave_subsection();
    p.validate();
    return p;
  }
} // namespace gearfem::mesh
