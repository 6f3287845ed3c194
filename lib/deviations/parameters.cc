// `Deviations` section.
#include "deviations/parameters.h"

#include "base/errors.h"
#include "base/number.h"
#include "base/units.h"
#include "geometry/pair.h"
#include "params/checked.h"
#include "deviations/hunting.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <cmath>

namespace gearfem::deviations
{
  namespace
  {
    constexpr double um = 1e-6, mm = 1e-3;

    void declare_gear(dealii::ParameterHandler &prm, int i)
    {
      prm.enter_subsection("Gear " + std::to_string(i));
      prm.declare_entry("Single pitch deviations", "", dealii::Patterns::Anything(),
                        "f_pt of every tooth: tooth k's entry is the deviation of the pitch from tooth k - 1 to "
                        "tooth k on the loaded flanks (teeth counter-clockwise in the body frame, tooth 0 meshes at "
                        "the pitch point at roll angle 0), positive when longer (ISO 1328-1); the list must sum to "
                        "zero. Empty: none. Units: um. Allowed: z values, each within +-1000 um.");
      prm.declare_entry("Profile slope deviation", "", dealii::Patterns::Anything(),
                        "f_Ha: positive for plus material towards the tip over the evaluation range (the active "
                        "profile of the pair). One value for every tooth or one per tooth; empty: none. Units: um. "
                        "Allowed: within +-1000 um.");
      prm.declare_entry("Profile form", "none", dealii::Patterns::Selection("none|parabolic|table"),
                        "Form deviation f_fa of the profile about its mean line: parabolic (Profile form "
                        "amplitude: f_fa (1/3 - 4 u^2), u from -1/2 at the start to 1/2 at the end of the "
                        "evaluation range; > 0 plus material mid-profile) or a measured trace (Profile form table).");
      prm.declare_entry("Profile form amplitude", "0", dealii::Patterns::Anything(),
                        "f_fa of the parabolic form, one value or one per tooth. Units: um. Allowed: within "
                        "+-1000 um.");
      prm.declare_entry("Profile form table", "", dealii::Patterns::Anything(),
                        "Measured trace of every tooth: comma-separated 'roll length : deviation' pairs, roll length "
                        "from the start of the evaluation range (mm, ascending), deviation (um, plus material "
                        "positive); linear between points, constant beyond.");
      prm.declare_entry("Flank offset", "0", dealii::Patterns::Double(),
                        "A common normal offset of every loaded flank, plus material positive (a thicker tooth "
                        "on the loaded side). Units: um. Allowed: within +-1000 um.");
      prm.declare_entry("Runout", "0", dealii::Patterns::Double(),
                        "Radial runout F_r (ISO 1328-1: probe in every tooth space), modelled as the eccentricity "
                        "e = F_r / 2 of the gear's centre from its axis. Units: um. Allowed: 0 .. 2000 um.");
      prm.declare_entry("Runout phase", "0", dealii::Patterns::Double(),
                        "Direction of the eccentricity in the body frame, from the body x axis counter-clockwise "
                        "(tooth 0's axis is at 90 deg). Units: deg.");
      prm.leave_subsection();
    }

    std::vector<double> micrometres(const dealii::ParameterHandler &prm, const std::string &entry,
                                    const std::string &path)
    {
      std::vector<double> v;
      try
        {
          v = params::get_doubles(prm, entry);
        }
      catch (const InputError &)
        {
          throw InputError(path, prm.get(entry), "a comma-separated list of numbers (um)");
        }
      for (double &x : v)
        {
          if (!std::isfinite(x) || std::abs(x) > 1000)
            throw InputError(path, to_string_g(x) + " um", "within +-1000 um");
          x *= um;
        }
      return v;
    }

    geometry::GearDeviations parse_gear(dealii::ParameterHandler &prm, int i)
    {
      const std::string s = "Deviations/Gear " + std::to_string(i) + "/";
      geometry::GearDeviations g;
      prm.enter_subsection("Gear " + std::to_string(i));
      g.f_pt = micrometres(prm, "Single pitch deviations", s + "Single pitch deviations");
      g.f_Ha = micrometres(prm, "Profile slope deviation", s + "Profile slope deviation");
      const std::string form = prm.get("Profile form");
      if (form == "parabolic")
        for (const double a : micrometres(prm, "Profile form amplitude", s + "Profile form amplitude"))
          g.form.push_back({geometry::ProfileForm::Kind::parabolic, a, {}});
      else if (form == "table")
        {
          geometry::ProfileForm f;
          f.kind = geometry::ProfileForm::Kind::table;
          for (const auto &item : dealii::Utilities::split_string_list(prm.get("Profile form table"), ','))
            {
              const auto kv = dealii::Utilities::split_string_list(item, ':');
              if (kv.size() != 2)
                throw InputError(s + "Profile form table", item, "'roll length [mm] : deviation [um]' pairs");
              const double l = parse_double(s + "Profile form table", kv[0], 0.0, 1e3);
              const double d = parse_double(s + "Profile form table", kv[1], -1000.0, 1000.0);
              if (!f.trace.empty() && l * mm <= f.trace.back().first)
                throw InputError(s + "Profile form table", item,
                                 "'roll length [mm] : deviation [um]' pairs, roll lengths >= 0 ascending, "
                                 "deviations within +-1000 um");
              f.trace.emplace_back(l * mm, d * um);
            }
          if (f.trace.size() < 2)
            throw InputError(s + "Profile form table", std::to_string(f.trace.size()) + " points", ">= 2 points");
          g.form.push_back(f);
        }
      g.flank_offset = params::get_double(prm, "Flank offset") * um;
      const double Fr = params::get_double(prm, "Runout");
      if (!(Fr >= 0 && Fr <= 2000))
        throw InputError(s + "Runout", to_string_g(Fr) + " um", "0 .. 2000 um");
      g.eccentricity       = 0.5 * Fr * um;
      g.eccentricity_phase = params::get_double(prm, "Runout phase") * units::deg;
      if (std::abs(g.flank_offset) > 1000 * um)
        throw InputError(s + "Flank offset", to_string_g(g.flank_offset / um) + " um", "within +-1000 um");
      prm.leave_subsection();
      return g;
    }
  } // namespace

  void declare_tolerance_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Tolerance");
    prm.declare_entry("Samples", "100", dealii::Patterns::Integer(),
                      "Monte Carlo samples: draws of both gears within Deviations/Accuracy grade (sample i uses the "
                      "i-th draw of Deviations/Seed), each solved over the cycle of Deviations/Pitches. Allowed: "
                      "1 .. 1000000.");
    prm.declare_entry("Condensed cycle", "", dealii::Patterns::Anything(),
                      "A condensed cycle of this design (gearfem condense) to solve the samples on; empty: the "
                      "study builds it once and keeps it as condensed.h5 in the output folder (a resumed study "
                      "reads it back).");
    prm.leave_subsection();
  }

  ToleranceParameters parse_tolerance_parameters(dealii::ParameterHandler &prm)
  {
    ToleranceParameters p;
    prm.enter_subsection("Tolerance");
    p.samples    = params::get_integer(prm, "Samples");
    p.cycle_file = dealii::Utilities::trim(prm.get("Condensed cycle"));
    prm.leave_subsection();
    if (p.samples < 1 || p.samples > 1000000)
      throw InputError("Tolerance/Samples", std::to_string(p.samples), "1 .. 1000000");
    return p;
  }

  void declare_deviation_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Deviations");
    prm.declare_entry("Model", "condensed", dealii::Patterns::Selection("condensed|geometry"),
                      "condensed: the hunting cycle on a condensed cycle, every deviation as a gap and drive-advance "
                      "offset of the contact candidates. geometry: the single pitch deviations built into the mesh "
                      "(tooth k turned by F_p,k / r_ref about the gear centre, F_p about the teeth's mean) and the "
                      "full-FE sweep over the positions of the Solve section; no other deviation kind, no accuracy "
                      "grade, Pitches unused (docs/deviations.md).");
    prm.declare_entry("Pitches", "hunting", dealii::Patterns::Anything(),
                      "Length of the cycle solved with the deviations: 'hunting' (lcm(z1, z2) pitches, after which "
                      "every tooth pair recurs) or a number of pinion pitches (z1 per pinion revolution). Runs only "
                      "when a deviation is given or drawn. Allowed: hunting, or 1 .. 100000.");
    prm.declare_entry("Accuracy grade", "0", dealii::Patterns::Integer(),
                      "Draw the deviations of both gears at random within the ISO 1328-1:2013 tolerances of this "
                      "flank tolerance class (f_pT, F_pT, f_HaT, f_faT, F_rT from the standard's formulas for each "
                      "gear's module, reference diameter and face width; docs/deviations.md). The given deviations "
                      "are then ignored. Allowed: 0 (no draw) or 1 .. 11.");
    prm.declare_entry("Distribution", "uniform", dealii::Patterns::Selection("uniform|truncated normal"),
                      "Distribution of a draw: uniform within +-tolerance, or normal with sigma = tolerance / 3 "
                      "truncated at +-tolerance.");
    prm.declare_entry("Seed", "1", dealii::Patterns::Integer(),
                      "Seed of the draw: the same seed gives the same gears on every machine. Allowed: >= 1.");
    declare_gear(prm, 1);
    declare_gear(prm, 2);
    prm.leave_subsection();
  }

  DeviationParameters parse_deviation_parameters(dealii::ParameterHandler &prm)
  {
    DeviationParameters p;
    prm.enter_subsection("Deviations");
    p.model = prm.get("Model") == "geometry" ? DeviationParameters::Model::geometry :
                                               DeviationParameters::Model::condensed;
    const std::string pitches = dealii::Utilities::trim(prm.get("Pitches"));
    if (pitches != "hunting")
      {
        if (pitches.empty() || pitches.find_first_not_of("0123456789") != std::string::npos)
          throw InputError("Deviations/Pitches", pitches, "hunting, or 1 .. 100000");
        p.pitches = parse_int("Deviations/Pitches", pitches, 1, 100000);
      }
    p.grade = params::get_integer(prm, "Accuracy grade");
    if (p.grade < 0 || p.grade > 11)
      throw InputError("Deviations/Accuracy grade", std::to_string(p.grade), "0 (no draw) or 1 .. 11");
    p.distribution = geometry::distribution_from_string(prm.get("Distribution"), "Deviations/Distribution");
    const int seed = params::get_integer(prm, "Seed");
    if (seed < 1)
      throw InputError("Deviations/Seed", std::to_string(seed), ">= 1");
    p.seed = std::uint64_t(seed);
    p.gear[0] = parse_gear(prm, 1);
    p.gear[1] = parse_gear(prm, 2);
    prm.leave_subsection();
    return p;
  }

  geometry::PairDeviations resolve_deviations(const DeviationParameters &p, const geometry::GearPair &pair,
                                              std::uint64_t sample)
  {
    if (p.grade == 0)
      return pair_deviations(pair, p.gear[0], p.gear[1]);
    geometry::GearDeviations g[2];
    for (int b = 0; b < 2; ++b)
      {
        const auto &gear = pair.gear(b + 1);
        const double m   = gear.parameters().rack.module;
        const auto t = geometry::iso1328_tolerances(p.grade, m, m * gear.teeth(), gear.parameters().face_width, true,
                                                    "Deviations/Accuracy grade");
        g[b] = geometry::draw_deviations(t, gear.teeth(), p.distribution, p.seed, 2 * sample + std::uint64_t(b));
      }
    return pair_deviations(pair, g[0], g[1]);
  }
} // namespace gearfem::deviations
