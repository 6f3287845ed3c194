// The `Train` section of `gearfem system` (system_deflection/train.h).
#include "base/errors.h"
#include "base/number.h"
#include "base/units.h"
#include "params/checked.h"
#include "system_deflection/shaft_parameters.h"
#include "system_deflection/train.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

namespace gearfem::system_deflection
{
  namespace
  {
    constexpr int max_stages = 3;
    std::string stage_section(int k) { return "Stage " + std::to_string(k + 1); }
    std::string shaft_section(int k) { return "Shaft " + std::to_string(k + 1); }
  } // namespace

  void declare_train_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    prm.enter_subsection("Train");
    prm.declare_entry("Stages", "2", Integer(),
                      "Stages of the parallel-axis train: stage k's pinion on shaft k, its gear on shaft k + 1 "
                      "(docs/system-deflection.md). Units: none. Allowed: 1 to 3.");
    prm.declare_entry("Torques", "100", Anything(),
                      "Comma-separated input torques on stage 1's pinion; stage k's pinion carries them times "
                      "the ratios before it. Units: N m. Allowed: > 0.");
    prm.declare_entry("Tolerance", "0.001", Double(),
                      "Largest change of any mesh's mismatch along its face at the fixed point. Units: um. "
                      "Allowed: 1e-6 to 1.");
    for (int k = 0; k < max_stages; ++k)
      {
        prm.enter_subsection(stage_section(k));
        prm.declare_entry("Input", "", Anything(),
                          "The stage's `gearfem helical` input file (its pair, mesh, Solve cycle and Helical "
                          "section), relative to this file. Its Solve/Torques are replaced by the train's. "
                          "Units: none.");
        prm.declare_entry("Pinion face start", "0", Double(),
                          "Start of the face (its side at z = -b/2 of the slices) along shaft k. Units: mm. "
                          "Allowed: 0 to the shaft's length - b.");
        prm.declare_entry("Gear face start", "0", Double(),
                          "The same along shaft k + 1. Units: mm. Allowed: 0 to the shaft's length - b.");
        prm.declare_entry("Direction", "0", Double(),
                          "Direction of the gear's axis seen from the pinion's, about +z from +x (stage 1's "
                          "pinion turns counterclockwise and drives). Units: deg. Allowed: -360 to 360.");
        prm.leave_subsection();
      }
    for (int k = 0; k <= max_stages; ++k)
      {
        prm.enter_subsection(shaft_section(k));
        declare_shaft_entries(prm);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  TrainInput parse_train_parameters(dealii::ParameterHandler &prm, const std::filesystem::path &train_file)
  {
    TrainInput t;
    prm.enter_subsection("Train");
    const int n = params::get_integer(prm, "Stages");
    require_range("Train/Stages", double(n), 1.0, double(max_stages), "");
    for (const auto &item : dealii::Utilities::split_string_list(prm.get("Torques"), ','))
      {
        const double T = parse_double("Train/Torques", item, 1e-9, 1e9);
        t.torques.push_back(T);
      }
    if (t.torques.empty())
      throw InputError("Train/Torques", "(none)", "one or more input torques > 0 (N m)");
    const double tol = params::get_double(prm, "Tolerance");
    require_range("Train/Tolerance", tol, 1e-6, 1.0, "um");
    t.options.tolerance = tol * units::um;
    for (int k = 0; k < n; ++k)
      {
        const std::string sec = "Train/" + stage_section(k);
        prm.enter_subsection(stage_section(k));
        TrainStage s;
        const std::string file = dealii::Utilities::trim(prm.get("Input"));
        if (file.empty())
          throw InputError(sec + "/Input", "(empty)", "the stage's gearfem helical input file");
        s.input = train_file.parent_path() / file;
        if (!std::filesystem::is_regular_file(s.input))
          throw InputError(sec + "/Input", s.input.string(), "an existing file (relative to the train's input)");
        const double p0 = params::get_double(prm, "Pinion face start"), g0 = params::get_double(prm, "Gear face start");
        const double dir = params::get_double(prm, "Direction");
        require_range(sec + "/Pinion face start", p0, 0.0, 1e5, "mm");
        require_range(sec + "/Gear face start", g0, 0.0, 1e5, "mm");
        require_range(sec + "/Direction", dir, -360.0, 360.0, "deg");
        s.pinion_face_start = p0 * units::mm, s.gear_face_start = g0 * units::mm, s.direction = dir * units::deg;
        prm.leave_subsection();
        t.stages.push_back(std::move(s));
      }
    for (int k = 0; k <= n; ++k)
      t.system.shafts.push_back(parse_shaft(prm, "Train", shaft_section(k), k, shaft_section(k), t.system.bearings));
    prm.leave_subsection();
    return t;
  }
} // namespace gearfem::system_deflection
