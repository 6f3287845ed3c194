#include "export/parameters.h"

#include "base/errors.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>

#include <set>
#include <sstream>

namespace gearfem::exports
{
  void declare_export_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.enter_subsection("Export");
    prm.declare_entry("Source", "", Anything(),
                      "The file to export: results.h5 of `gearfem solve` (one mesh cycle, or the hunting cycle of a run "
                      "with a Deviations section), or a mesh table (mesh_torque.h5, mesh_stiffness.h5, mesh_ste.h5 of "
                      "`gearfem calibrate`, or the FE-exact table of `gearfem condense`). Relative to the input file.");
    prm.declare_entry("Source kind", "solve results", Selection("solve results|mesh table"), "What Source holds.");
    params::declare_torques(prm, "Torques", "",
                            "pinion torques to export; empty: every torque of a solve result, the load nodes of a "
                            "stiffness or STE table (a torque table needs them)");
    prm.declare_entry("Formats", "all", Anything(),
                      "Comma-separated subset of: ross (ROSS Mesh arrays, ross_mesh.json), spline (spline_ste.csv, "
                      "spline_stiffness.csv), te (te_mesh_cycle.txt, te_revolution.txt), force (force_table.csv, "
                      "torque tables only); all: every format the source supports.");
    prm.declare_entry("Backlash", "-1", Double(),
                      "Clearance b along the line of action for the force table of a one-sided torque table; < 0: "
                      "none (a two-sided table brings its own). Units: um. Allowed: < 0, or 0 to 5000.");
    prm.leave_subsection();
  }

  ExportInput parse_export_parameters(dealii::ParameterHandler &prm)
  {
    ExportInput in;
    prm.enter_subsection("Export");
    in.source      = prm.get("Source");
    in.source_kind = prm.get("Source kind");
    in.torques     = params::get_torques(prm, "Torques", "Export/Torques", true);
    const std::string formats = prm.get("Formats");
    const double b_um = params::get_double(prm, "Backlash");
    prm.leave_subsection();
    if (in.source.empty())
      throw InputError("Export/Source", "(empty)", "a results.h5 or mesh-table file");
    if (b_um >= 0)
      require_range("Export/Backlash", b_um, 0, 5000, "um");
    in.backlash = b_um >= 0 ? b_um * 1e-6 : -1;
    const std::set<std::string> known{"ross", "spline", "te", "force"};
    std::stringstream s(formats);
    std::string item;
    while (std::getline(s, item, ','))
      {
        const auto a = item.find_first_not_of(" \t"), b = item.find_last_not_of(" \t");
        if (a == std::string::npos)
          continue;
        item = item.substr(a, b - a + 1);
        if (item == "all")
          in.formats.push_back(item);
        else if (known.count(item))
          in.formats.push_back(item);
        else
          throw InputError("Export/Formats", item, "all, or a list of ross, spline, te, force");
      }
    if (in.formats.empty())
      throw InputError("Export/Formats", "(empty)", "all, or a list of ross, spline, te, force");
    return in;
  }
} // namespace gearfem::exports
