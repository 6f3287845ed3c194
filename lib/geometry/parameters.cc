// ParameterHandler bindings of the geometry sections. The Patterns are deliberately wide;
// the design checks (geometry/rack.cc, profile.cc, pair.cc) give the named errors with the
// allowed ranges, so that every bad value is reported the same way ("Gear 1/Number of
// teeth: 4 (allowed: [5, 10000])").
#include "geometry/parameters.h"

#include "base/errors.h"
#include "base/number.h"
#include "params/checked.h"
#include "base/units.h"
#include "geometry/limits.h"

#include <deal.II/base/parameter_handler.h>

#include <sstream>

namespace gearfem::geometry
{
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  namespace
  {
    void declare_gear(dealii::ParameterHandler &prm, const std::string &name, int teeth)
    {
      prm.enter_subsection(name);
      declare_teeth_entry(prm, "Number of teeth", teeth, "z");
      prm.declare_entry("Profile shift coefficient", "0", Double(-5, 5),
                        "x (ISO 21771). Units: multiples of the module.");
      prm.declare_entry("Tip shortening coefficient", "0", Double(),
                        "k*: the tip circle is lowered by k* m. Units: multiples of the module. "
                        "Allowed: 0 to 1.");
      prm.declare_entry("Thickness allowance", "0", Double(),
                        "Reduction of the circular tooth thickness on the reference circle "
                        "(backlash allowance); shifts both flanks inwards. Units: mm.");
      declare_face_width_entry(prm, "Face width", 20);
      prm.declare_entry("Tip relief", "none", Selection("none|linear|parabolic"),
                        "Profile modification near the tip: amount grows linearly or "
                        "parabolically in roll angle from the start of relief to the tip.");
      prm.declare_entry("Tip relief amount", "0", Double(),
                        "C_a: relief at the tip, normal to the flank. Units: um.");
      prm.declare_entry("Tip relief length", "0", Double(),
                        "Length of relief along the line of action from the tip down. Units: mm.");
      prm.declare_entry("Tip relief roll angle", "0", Double(),
                        "Length of relief as a roll angle (used instead of the length if > 0). "
                        "Units: deg.");
      prm.leave_subsection();
    }

    GearParameters parse_gear(dealii::ParameterHandler &prm, const std::string &name,
                              const RackParameters &rack)
    {
      GearParameters g;
      g.name = name;
      g.rack = rack;
      prm.enter_subsection(name);
      g.teeth               = params::get_integer(prm, "Number of teeth");
      g.profile_shift       = params::get_double(prm, "Profile shift coefficient");
      g.tip_shortening      = params::get_double(prm, "Tip shortening coefficient");
      g.thickness_allowance = params::get_double(prm, "Thickness allowance") * units::mm;
      g.face_width          = params::get_double(prm, "Face width") * units::mm;
      const std::string k   = prm.get("Tip relief");
      g.relief.kind = k == "linear"    ? TipRelief::Kind::linear :
                      k == "parabolic" ? TipRelief::Kind::parabolic :
                                         TipRelief::Kind::none;
      g.relief.amount     = params::get_double(prm, "Tip relief amount") * units::um;
      g.relief.length     = params::get_double(prm, "Tip relief length") * units::mm;
      g.relief.roll_angle = params::get_double(prm, "Tip relief roll angle") * units::deg;
      prm.leave_subsection();
      limits::check_face_width(name + "/Face width", g.face_width);
      if (g.thickness_allowance < 0)
        throw InputError(name + "/Thickness allowance", to_string_g(g.thickness_allowance / units::mm) + " mm",
                         ">= 0 mm", "a negative allowance gives negative backlash");
      if (g.relief.amount < 0)
        throw InputError(name + "/Tip relief amount", to_string_g(g.relief.amount / units::um) + " um",
                         ">= 0 um");
      return g;
    }

    std::vector<Vec2> parse_points(const std::string &text)
    {
      // "u1, v1; u2, v2; ..." (module units)
      std::vector<Vec2> pts;
      std::stringstream all(text);
      std::string       item;
      while (std::getline(all, item, ';'))
        {
          if (item.find_first_not_of(" \t") == std::string::npos)
            continue;
          const auto uv = split_trimmed(item, ',');
          if (uv.size() != 2)
            throw InputError("Rack/Control points", "'" + item + "'",
                             "a list 'u1, v1; u2, v2; ...' of numbers (module units)");
          pts.emplace_back(parse_double("Rack/Control points", uv[0]),
                           parse_double("Rack/Control points", uv[1]));
        }
      return pts;
    }
  } // namespace

  void declare_teeth_entry(dealii::ParameterHandler &prm, const std::string &name, int default_teeth,
                           const std::string &what)
  {
    prm.declare_entry(name, std::to_string(default_teeth), Integer(),
                      what + ". Units: none. Allowed: " + std::to_string(limits::min_teeth) + " to " +
                        std::to_string(limits::max_teeth) + ".");
  }

  void declare_module_entry(dealii::ParameterHandler &prm, const std::string &name, double default_mm)
  {
    prm.declare_entry(name, to_string_g(default_mm), Double(), "m (normal module). Units: mm. Allowed: > 0.");
  }

  void declare_pressure_angle_entry(dealii::ParameterHandler &prm, const std::string &name)
  {
    prm.declare_entry(name, "20", Double(),
                      "alpha: pressure angle of the basic rack. Units: deg. Allowed: " +
                        to_string_g(limits::min_pressure_angle_deg) + " to " +
                        to_string_g(limits::max_pressure_angle_deg) + ".");
  }

  void declare_addendum_entry(dealii::ParameterHandler &prm, const std::string &name, const std::string &what)
  {
    prm.declare_entry(name, "1.0", Double(),
                      what + ". Units: multiples of the module. Allowed: " + to_string_g(limits::min_addendum) +
                        " to " + to_string_g(limits::max_addendum) + ".");
  }

  void declare_face_width_entry(dealii::ParameterHandler &prm, const std::string &name, double default_mm,
                                const std::string &what)
  {
    prm.declare_entry(name, to_string_g(default_mm), Double(), what + ". Units: mm. Allowed: > 0.");
  }

  void declare_geometry_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Rack");
    declare_module_entry(prm, "Module", 3);
    declare_pressure_angle_entry(prm);
    declare_addendum_entry(prm, "Addendum coefficient", "h_aP*: sets the tip circle r_a = r + (h_aP* + x - k*) m");
    prm.declare_entry("Dedendum coefficient", "1.25", Double(),
                      "h_fP*: the cutter addendum, sets the root circle r_f = r + (x - h_fP*) m. "
                      "Units: module.");
    prm.declare_entry("Root radius coefficient", "0.25", Double(),
                      "rho_fP*: cutter tip radius; generates the trochoidal root fillet. Units: module.");
    prm.declare_entry("Tip radius coefficient", "0", Double(),
                      "rho_aP*: tooth tip rounding (cutter root radius), 0 = sharp. Units: module.");
    prm.declare_entry("Profile type", "standard", Selection("standard|bspline rack|bspline flank"),
                      "standard: straight-flank rack (involute). bspline rack: gear 1's rack flank "
                      "from control points (Koronaios 2021 case 1). bspline flank: gear 1's flank from "
                      "control points, rack recovered by involutisation (Koronaios 2021 case 2). Gear 2 "
                      "is generated from the complementary rack.");
    prm.declare_entry("Control points", "", dealii::Patterns::Anything(),
                      "B-spline control points 'a1, b1; a2, b2; ...'. Units: module. bspline rack: "
                      "(u, v) rack coordinates (u from the middle of the tooth, v outwards from "
                      "the pitch line), tooth tip to root. bspline flank: (x, y) of gear 1's "
                      "x > 0 flank in the gear frame (tooth axis +y), root to tip.");
    prm.declare_entry("Spline degree", "4", Integer(1, 10), "p. Units: none.");
    prm.leave_subsection();
    declare_gear(prm, "Gear 1", 20);
    declare_gear(prm, "Gear 2", 40);
    prm.enter_subsection("Pair");
    prm.declare_entry("Centre distance", "0", Double(),
                      "a. 0 = zero-backlash centre distance from the profile shifts "
                      "(inv a_w = inv a + 2 tan a (x1 + x2)/(z1 + z2)). Units: mm.");
    prm.leave_subsection();
  }

  void declare_material_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Plane model", "plane stress", Selection("plane stress|plane strain"),
                      "2-D elasticity model (plane stress is the default; plane strain for "
                      "comparison with ISO and Hertz plane-strain formulas).");
    for (const std::string g : {"Gear 1", "Gear 2"})
      {
        prm.enter_subsection(g);
        prm.declare_entry("Young's modulus", "207", Double(), "E. Units: GPa. Allowed: 0.1 to 1500.");
        prm.declare_entry("Poisson ratio", "0.3", Double(), "nu. Units: none. Allowed: 0 to 0.5.");
        prm.declare_entry("Density", "7850", Double(), "rho. Units: kg/m^3. Allowed: > 0.");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  GeometryInput parse_geometry_parameters(dealii::ParameterHandler &prm)
  {
    RackParameters rack;
    prm.enter_subsection("Rack");
    rack.module         = params::get_double(prm, "Module") * units::mm;
    rack.pressure_angle = params::get_double(prm, "Pressure angle") * units::deg;
    rack.addendum       = params::get_double(prm, "Addendum coefficient");
    rack.dedendum       = params::get_double(prm, "Dedendum coefficient");
    rack.root_radius    = params::get_double(prm, "Root radius coefficient");
    rack.tip_radius     = params::get_double(prm, "Tip radius coefficient");
    const std::string k = prm.get("Profile type");
    rack.kind = k == "bspline rack"  ? RackParameters::Kind::bspline_rack :
                k == "bspline flank" ? RackParameters::Kind::bspline_flank :
                                       RackParameters::Kind::standard;
    rack.control_points = parse_points(prm.get("Control points"));
    rack.spline_degree  = params::get_integer(prm, "Spline degree");
    prm.leave_subsection();
    require_greater("Rack/Module", rack.module / units::mm, 0.0, "mm");
    require_range("Rack/Pressure angle", rack.pressure_angle / units::deg, 10.0, 35.0, "deg");
    if (rack.kind != RackParameters::Kind::standard && rack.control_points.empty())
      throw InputError("Rack/Control points", "(empty)", "at least degree + 1 points",
                       "Profile type = " + k + " needs control points");

    GeometryInput in;
    in.gear1 = parse_gear(prm, "Gear 1", rack);
    in.gear2 = parse_gear(prm, "Gear 2", rack);
    prm.enter_subsection("Pair");
    in.pair.center_distance = params::get_double(prm, "Centre distance") * units::mm;
    prm.leave_subsection();
    if (in.pair.center_distance < 0)
      throw InputError("Pair/Centre distance", to_string_g(in.pair.center_distance / units::mm) + " mm",
                       "> 0 mm, or 0 for the value from the profile shifts");
    return in;
  }

  PairMaterial parse_material_parameters(dealii::ParameterHandler &prm)
  {
    PairMaterial pm;
    prm.enter_subsection("Material");
    pm.plane_strain = prm.get("Plane model") == "plane strain";
    for (int i : {1, 2})
      {
        const std::string g = "Gear " + std::to_string(i);
        Material         &m = i == 1 ? pm.gear1 : pm.gear2;
        prm.enter_subsection(g);
        m.youngs_modulus = params::get_double(prm, "Young's modulus") * units::GPa;
        m.poisson_ratio  = params::get_double(prm, "Poisson ratio");
        m.density        = params::get_double(prm, "Density");
        prm.leave_subsection();
        limits::check_youngs_modulus("Material/" + g + "/Young's modulus", m.youngs_modulus);
        if (!(m.poisson_ratio >= 0.0 && m.poisson_ratio < 0.5))
          throw InputError("Material/" + g + "/Poisson ratio", to_string_g(m.poisson_ratio), "[0, 0.5)");
        require_greater("Material/" + g + "/Density", m.density, 0.0, "kg/m^3");
      }
    prm.leave_subsection();
    return pm;
  }

  GearPair build_pair(const GeometryInput &in)
  {
    ToothProfile g1 = ToothProfile::generate(in.gear1);
    ToothProfile g2 = ToothProfile::generate_mate(in.gear2, g1);
    return GearPair(std::move(g1), std::move(g2), in.pair);
  }
} // namespace gearfem::geometry
