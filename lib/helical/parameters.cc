#include "helical/parameters.h"

#include "condensed/parameters.h"
#include "helical/run.h"
#include "post/parameters.h"
#include "solve/input.h"

#include "base/errors.h"
#include "base/units.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::helical
{
  void declare_helical_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    prm.enter_subsection("Helical");
    prm.declare_entry("Helix angle", "0", Double(),
                      "beta at the reference circle. 0 gives the spur pair as the limit. Units: deg. Allowed: 0 to < 45.");
    prm.declare_entry("Hand", "right", Selection("right|left"),
                      "Hand of gear 1 (gear 2 has the other). It sets which end of the face enters mesh first, "
                      "which matters with a misalignment. Units: none.");
    prm.declare_entry("Rack section", "normal", Selection("normal|transverse"),
                      "Section the Rack and Gear entries describe. normal (ISO 21771, as ratings and tool makers "
                      "give a helical gear): Rack/Module is m_n, Rack/Pressure angle alpha_n, the profile shift and "
                      "the rack coefficients in m_n; gearfem converts them to the transverse section it meshes "
                      "(docs/helical.md). transverse: the entries are the transverse section itself. Units: none.");
    prm.declare_entry("Slices", "21", Integer(),
                      "Slices over the face width, each a transverse section of width b/N. Units: none. "
                      "Allowed: 1 to 201.");
    prm.declare_entry("Coupling", "bending", Selection("bending|shear"),
                      "How the slices of one tooth pair are joined across the face (docs/helical.md). bending: a "
                      "beam along the face on the sections' foundation with free ends (a uniform load and a rigid "
                      "tilt cost nothing). shear: a Pasternak layer, whose free ends carry an edge force under a "
                      "misalignment. Units: none.");
    prm.declare_entry("Coupling length", "-1", Double(),
                      "Length l of the coupling: a point load on the face spreads over an effective width 2 l "
                      "(docs/helical.md). Units: mm. Allowed: -1 (one normal module), 0 (uncoupled slices), or "
                      "> 0 up to the face width.");
    prm.declare_entry("Model", "slices", Selection("slices|3-D FE"),
                      "What joins the sections across the face (docs/three_d.md). slices: the beam of the Coupling "
                      "entries. 3-D FE: a coarse 3-D finite-element body of each gear (a sector extruded along the "
                      "helix) gives the far field across the face, and the exact 2-D sections the contact (the "
                      "combined method); slower to set up, no coupling length to choose. Units: none.");
    prm.declare_entry("3-D element size", "0", Double(),
                      "Element size of the coarse section of the 3-D bodies. Units: mm. Allowed: 0 (m_n/3) or > 0 "
                      "up to 2 m_n.");
    prm.declare_entry("3-D degree", "2", Integer(), "Polynomial degree of the 3-D elements. Units: none. Allowed: 1, 2.");
    prm.declare_entry("3-D layers per slice", "1", Integer(),
                      "Hexahedra across the width of one slice. Units: none. Allowed: 1 to 400/Slices.");
    prm.declare_entry("3-D flank points", "7", Integer(),
                      "Radii over each drive flank at which the 3-D face is tabulated (linear between). Units: none. "
                      "Allowed: 2 to 50.");
    prm.declare_entry("3-D sector teeth", "3", Integer(),
                      "Teeth of each gear's 3-D sector (clamped at its bore and cuts; the middle tooth is loaded). "
                      "Units: none. Allowed: odd, 1 to 9.");
    prm.declare_entry("Crowning", "0", Double(),
                      "Lead crowning C_beta, removed at each end of the face (parabolic), both gears together. "
                      "Units: um. Allowed: 0 to 1000.");
    prm.declare_entry("End relief", "0", Double(),
                      "Linear end relief C_I at both ends, both gears together. Units: um. Allowed: 0 to 1000.");
    prm.declare_entry("End relief length", "0", Double(),
                      "Length b_I of each end relief from its end. Units: mm. Allowed: 0 to b/2 (> 0 with an end "
                      "relief).");
    prm.declare_entry("Helix slope deviation", "0", Double(),
                      "f_Hbeta over the face width, along the line of action; > 0 opens the gap towards the far end "
                      "of the face. Units: um. Allowed: -1000 to 1000.");
    prm.declare_entry("Misalignment", "0", Double(),
                      "f_Sigma_beta: inclination of the axes out of their plane, over the face width (scale a "
                      "bearing-span value by b/L). It tilts the contact by f cos(alpha_wt). Units: um. "
                      "Allowed: -1000 to 1000.");
    prm.declare_entry("Axis deviation", "0", Double(),
                      "f_Sigma_delta: deviation of the axes in their plane, over the face width. It tilts the "
                      "contact by f sin(alpha_wt); the change of each slice's centre distance and working pressure "
                      "angle with it is not represented. Units: um. Allowed: -1000 to 1000.");
    prm.leave_subsection();
  }

  HelixInput parse_helical_parameters(dealii::ParameterHandler &prm)
  {
    HelixInput h;
    prm.enter_subsection("Helical");
    h.beta            = params::get_double(prm, "Helix angle") * units::deg;
    h.hand            = prm.get("Hand") == "left" ? -1 : 1;
    h.normal_section  = prm.get("Rack section") == "normal";
    h.slices          = params::get_integer(prm, "Slices");
    h.coupling        = prm.get("Coupling") == "shear" ? Coupling::shear : Coupling::bending;
    const double l    = params::get_double(prm, "Coupling length");
    h.coupling_length = l < 0 ? l : l * units::mm;
    h.model             = prm.get("Model") == "3-D FE" ? FaceModel::solid : FaceModel::slices;
    h.solid.element_size = params::get_double(prm, "3-D element size") * units::mm;
    const long degree    = params::get_integer(prm, "3-D degree");
    if (degree != 1 && degree != 2)
      throw InputError("Helical/3-D degree", std::to_string(degree), "1 or 2");
    h.solid.degree           = unsigned(degree);
    h.solid.layers_per_slice = int(params::get_integer(prm, "3-D layers per slice"));
    h.solid.flank_points     = int(params::get_integer(prm, "3-D flank points"));
    h.solid.sector_teeth     = int(params::get_integer(prm, "3-D sector teeth"));
    auto &m             = h.lead;
    m.crowning          = params::get_double(prm, "Crowning") * units::um;
    m.end_relief        = params::get_double(prm, "End relief") * units::um;
    m.end_relief_length = params::get_double(prm, "End relief length") * units::mm;
    m.slope             = params::get_double(prm, "Helix slope deviation") * units::um;
    m.misalignment      = params::get_double(prm, "Misalignment") * units::um;
    m.deviation         = params::get_double(prm, "Axis deviation") * units::um;
    prm.leave_subsection();
    if (l < 0 && l != -1)
      throw InputError("Helical/Coupling length", to_string_g(l) + " mm", "-1, 0, or > 0 up to the face width");
    return h;
  }
} // namespace gearfem::helical

namespace gearfem::helical
{
  void declare_request(dealii::ParameterHandler &prm)
  {
    solve::declare_gear_contact_input(prm);
    post::declare_post_parameters(prm);
    condensed::declare_condense_parameters(prm);
    declare_helical_parameters(prm);
  }

  Request parse_request(dealii::ParameterHandler &prm)
  {
    Request r;
    r.helix = parse_helical_parameters(prm);
    const double beta = r.helix.beta;
    r.section = r.helix.normal_section ?
                  solve::parse_gear_contact_input(
                    prm, [&](const geometry::GeometryInput &g) { return transverse_section(g, beta); }) :
                  solve::parse_gear_contact_input(prm);
    const post::PostOptions post = post::parse_post_parameters(prm);
    const auto cp                = condensed::parse_condense_parameters(prm);
    r.run.build_torque = cp.build_torque;
    r.run.torque_lo    = cp.torque_lo;
    r.run.torque_hi    = cp.torque_hi;
    r.run.scene_ratio  = cp.scene_ratio;
    // The checks and the helix, before any meshing; the positions become the grid.
    r.slicing = slicing_options(r.section, r.helix, post);
    return r;
  }
} // namespace gearfem::helical
