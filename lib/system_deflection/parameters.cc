// The `System` section (system_deflection/run.h).
#include "base/errors.h"
#include "base/number.h"
#include "base/units.h"
#include "params/checked.h"
#include "system_deflection/run.h"
#include "system_deflection/shaft_parameters.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <algorithm>

namespace gearfem::system_deflection
{
  namespace
  {
    const char *const shaft_sections[2] = {"Pinion shaft", "Gear shaft"};

    std::vector<std::vector<std::string>> items(const std::string &text)
    {
      std::vector<std::vector<std::string>> out;
      for (const auto &item : dealii::Utilities::split_string_list(text, ','))
        {
          if (dealii::Utilities::trim(item).empty())
            continue;
          std::vector<std::string> f;
          for (const auto &x : dealii::Utilities::split_string_list(item, ':'))
            f.push_back(dealii::Utilities::trim(x));
          out.push_back(f);
        }
      return out;
    }

    /// A stiffness field: `rigid`, or a number >= 0 in `unit` scaled by `scale` to SI.
    double stiffness(const std::string &entry, const std::string &text, double scale)
    {
      if (text == "rigid")
        return shafts::rigid;
      return parse_double(entry, text, 0.0, 1e9) * scale;
    }

  } // namespace

  shafts::Shaft parse_shaft(dealii::ParameterHandler &prm, const std::string &parent, const std::string &section, int i,
                            const std::string &bearing_prefix, std::vector<shafts::Bearing> &bearings)
    {
      const std::string sec = parent + "/" + section;
      prm.enter_subsection(section);
      shafts::Shaft s;
      s.name                    = section;
      s.material.youngs_modulus = params::get_double(prm, "Young's modulus") * 1e6;
      s.material.poisson_ratio  = params::get_double(prm, "Poisson's ratio");
      const std::string seg_entry = sec + "/Segments", brg_entry = sec + "/Bearings";
      for (const auto &f : items(prm.get("Segments")))
        {
          if (f.size() < 2 || f.size() > 3)
            throw InputError(seg_entry, prm.get("Segments"),
                             "comma-separated segments length:outer diameter[:bore] in mm");
          shafts::Segment g;
          g.length         = parse_double(seg_entry, f[0], 1e-3, 1e5) * units::mm;
          g.outer_diameter = parse_double(seg_entry, f[1], 1e-3, 1e5) * units::mm;
          g.inner_diameter = f.size() == 3 ? parse_double(seg_entry, f[2], 0.0, 1e5) * units::mm : 0.0;
          if (!(g.inner_diameter < g.outer_diameter))
            throw InputError(seg_entry, f[2] + " mm bore", "below the outer diameter " + f[1] + " mm");
          s.segments.push_back(g);
        }
      if (s.segments.empty())
        throw InputError(seg_entry, "(none)", "at least one segment length:outer diameter[:bore] in mm");
      for (const auto &f : items(prm.get("Bearings")))
        {
          if (f.size() != 5 && f.size() != 7)
            throw InputError(brg_entry, prm.get("Bearings"),
                             "comma-separated bearings z:radial:axial:tilting:torsional[:housing radial:housing axial] "
                             "(mm, N/um, N/um, N m/mrad, N m/rad, N/um, N/um; rigid or a number >= 0)");
          shafts::Bearing b;
          b.name      = bearing_prefix + " bearing " +
                   std::to_string(1 + std::count_if(bearings.begin(), bearings.end(),
                                                    [&](const shafts::Bearing &o) { return o.shaft == i; }));
          b.shaft     = i;
          b.z         = parse_double(brg_entry, f[0], 0.0, 1e5) * units::mm;
          b.radial    = stiffness(brg_entry, f[1], 1e6);
          b.axial     = stiffness(brg_entry, f[2], 1e6);
          b.tilting   = stiffness(brg_entry, f[3], 1e3);
          b.torsional = stiffness(brg_entry, f[4], 1.0);
          if (f.size() == 7)
            {
              // The housing's seat in series with the bearing (diagonal: radial and axial).
              const auto series = [](double k, double h) { return k == shafts::rigid ? h : h == shafts::rigid ? k : k * h / (k + h); };
              const double hr = stiffness(brg_entry, f[5], 1e6), ha = stiffness(brg_entry, f[6], 1e6);
              if (!(hr > 0) || !(ha > 0))
                throw InputError(brg_entry, f[5] + ":" + f[6], "housing stiffnesses > 0 N/um (or rigid)");
              b.radial = series(b.radial, hr), b.axial = b.axial > 0 ? series(b.axial, ha) : 0.0;
            }
          bearings.push_back(b);
        }
      prm.leave_subsection();
      s.validate();
      for (const auto &b : bearings)
        if (b.shaft == i && b.z > s.length() * (1 + 1e-12))
          throw InputError(brg_entry, to_string_g(b.z / units::mm) + " mm", "0 to the shaft's length " + mm_text(s.length()));
      return s;
    }

  void declare_shaft_entries(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    prm.declare_entry("Segments", "", Anything(),
                      "The stepped shaft from its start: comma-separated segments length:outer diameter[:bore]. "
                      "The part under the face is the gear body (its root diameter, or the rim's bore for a "
                      "gear on a hub). Units: mm. Allowed: lengths and diameters > 0, bore below the outer "
                      "diameter.");
    prm.declare_entry("Bearings", "", Anything(),
                      "Comma-separated bearings z:radial:axial:tilting:torsional[:housing radial:housing axial]: "
                      "the position from the shaft's start and the spring of each (rigid, or a number; 0 leaves "
                      "it free). The torsional spring at the input (pinion) or output (gear) coupling holds the "
                      "torque. The optional housing stiffnesses of the seat act in series with the bearing's "
                      "radial and axial springs (rigid housing when left out). Units: mm, N/um, N/um, N m/mrad, "
                      "N m/rad, N/um, N/um.");
    prm.declare_entry("Young's modulus", "206000", Double(), "Units: MPa. Allowed: > 0.");
    prm.declare_entry("Poisson's ratio", "0.3", Double(), "Units: none. Allowed: -1 to 0.5.");
  }

  void declare_system_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    prm.enter_subsection("System");
    prm.declare_entry("Coupling", "none", Selection("none|shafts"),
                      "none: the helical pair on rigid, aligned axes (the Helical section's misalignment only). "
                      "shafts: every position solved on the pinion and gear shafts below, the mesh load on the "
                      "shafts and their deflection's mismatch along the face iterated to a fixed point "
                      "(docs/system-deflection.md). Units: none.");
    prm.declare_entry("Pinion face start", "0", Double(),
                      "Position of the start of the face (its side at z = -b/2 of the slices) along the pinion "
                      "shaft, from the shaft's start. Units: mm. Allowed: 0 to the shaft's length - b.");
    prm.declare_entry("Gear face start", "0", Double(),
                      "The same along the gear shaft. Units: mm. Allowed: 0 to the shaft's length - b.");
    prm.declare_entry("Pinion rotation", "counterclockwise", Selection("counterclockwise|clockwise"),
                      "Sense of the driving pinion's rotation about the shafts' +z axis (the gear shaft lies at the "
                      "centre distance along +x). Units: none.");
    prm.declare_entry("Tolerance", "0.001", Double(),
                      "Largest change of the mismatch along the face at the fixed point. Units: um. Allowed: 1e-6 "
                      "to 1.");
    prm.declare_entry("Correction torque", "0", Double(),
                      "> 0: design the lead correction (helix slope and crowning) that makes the load uniform at "
                      "this pinion torque on the shafts, and run the sweep with it. Units: N m. Allowed: 0 (none) "
                      "or > 0 within the cycle's torque range.");
    prm.declare_entry("Correction positions", "8", Integer(),
                      "Positions of the cycle (evenly taken) the correction is designed over. Units: none. "
                      "Allowed: 1 to 200.");
    for (const char *s : shaft_sections)
      {
        prm.enter_subsection(s);
        declare_shaft_entries(prm);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  SystemInput parse_system_parameters(dealii::ParameterHandler &prm)
  {
    SystemInput s;
    prm.enter_subsection("System");
    s.coupled = prm.get("Coupling") == "shafts";
    const double p0 = params::get_double(prm, "Pinion face start"), g0 = params::get_double(prm, "Gear face start");
    s.mesh.drive_sense = prm.get("Pinion rotation") == "clockwise" ? -1 : 1;
    const double tol   = params::get_double(prm, "Tolerance");
    s.correction_torque    = params::get_double(prm, "Correction torque");
    s.correction_positions = params::get_integer(prm, "Correction positions");
    if (s.coupled)
      for (int i = 0; i < 2; ++i)
        s.system.shafts.push_back(
          parse_shaft(prm, "System", shaft_sections[i], i, i == 0 ? "pinion" : "gear", s.system.bearings));
    prm.leave_subsection();
    require_range("System/Pinion face start", p0, 0.0, 1e5, "mm");
    require_range("System/Gear face start", g0, 0.0, 1e5, "mm");
    require_range("System/Tolerance", tol, 1e-6, 1.0, "um");
    if (!(s.correction_torque >= 0 && s.correction_torque < 1e9))
      throw InputError("System/Correction torque", to_string_g(s.correction_torque) + " N m", "0 (none) or > 0");
    if (s.correction_positions < 1 || s.correction_positions > 200)
      throw InputError("System/Correction positions", std::to_string(s.correction_positions), "1 to 200");
    s.mesh.pinion_face_start = p0 * units::mm, s.mesh.gear_face_start = g0 * units::mm;
    s.options.tolerance      = tol * units::um;
    return s;
  }
} // namespace gearfem::system_deflection
