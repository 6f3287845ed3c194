#include "rating/parameters.h"

#include "base/errors.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::rating
{
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;
  using dealii::Patterns::Selection;

  void declare_rating_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Rating");
    params::declare_torques(prm, "Pinion torques", "500, 400, 300, 200", "Pinion torques to rate, one report column each.");
    prm.declare_entry("Pinion speed", "0", Double(0),
                      "Pinion speed, for the pitch-line velocity only (the dynamic factors are "
                      "inputs). Units: rpm.");
    prm.declare_entry("AGMA overload factor", "1", Double(0), "K_o (AGMA 2101-D04). Units: none.");
    prm.declare_entry("AGMA dynamic factor", "1.05", Double(0),
                      "K_v (AGMA 2101-D04; 1.05 is the minimum Siasos 2010 uses for wind turbines). Units: none.");
    prm.declare_entry("AGMA size factor", "1", Double(0), "K_s (AGMA 2101-D04). Units: none.");
    prm.declare_entry("AGMA surface condition factor", "1", Double(0), "Z_R (AGMA 2101-D04). Units: none.");
    prm.declare_entry("AGMA rim thickness factor", "1", Double(0),
                      "K_B (AGMA 2101-D04; 1 for backup ratio >= 1.2). Units: none.");
    prm.declare_entry("AGMA gear unit class", "precision",
                      Selection("open|commercial|precision|extra precision"),
                      "Row of the K_Hma table (AGMA 2101-D04 table 3): open gearing, commercial "
                      "enclosed, precision enclosed (Siasos 2010), extra precision enclosed.");
    prm.declare_entry("AGMA load distribution factor", "0", Double(0),
                      "K_H; 0 computes 1 + K_Hma + K_Hpf (AGMA 2101-D04 empirical method, "
                      "K_Hmc = K_Hpm = K_He = 1). Units: none.");
    prm.declare_entry("AGMA tool teeth", "10000", Double(10),
                      "n_o of the AGMA 908 shaper cutter (10000 = hob). Units: none.");
    prm.declare_entry("AGMA tool addendum modification", "0", Double(-2, 2),
                      "x_o of the AGMA 908 tool. Units: multiples of the module.");
    prm.declare_entry("Application factor", "1", Double(0), "K_A (ISO 6336-1). Units: none.");
    prm.declare_entry("ISO dynamic factor", "1.05", Double(0), "K_v (ISO 6336-1, input). Units: none.");
    prm.declare_entry("ISO face load factor", "1", Double(0),
                      "K_Hbeta (ISO 6336-1, input); K_Fbeta = K_Hbeta^N_F. Units: none.");
    prm.declare_entry("ISO accuracy grade", "0", Integer(0, 12),
                      "ISO 1328-1 grade for K_Halpha, K_Falpha (ISO 6336-1 method B); 0 sets them "
                      "to 1. Units: none.");
    prm.declare_entry("Case hardened", "true", Bool(),
                      "Running-in allowance y_alpha = 0.075 f_pb (case hardened) or 160/sigma_Hlim f_pb.");
    prm.declare_entry("Contact fatigue limit", "1500", Double(0),
                      "sigma_Hlim, for y_alpha of through-hardened steel only. Units: MPa.");
    prm.leave_subsection();
  }

  RatingInput parse_rating_parameters(dealii::ParameterHandler &prm)
  {
    RatingInput in;
    prm.enter_subsection("Rating");
    in.torques = params::get_torques(prm, "Pinion torques", "Rating/Pinion torques");
    in.speed = params::get_double(prm, "Pinion speed");
    in.K_o = params::get_double(prm, "AGMA overload factor");
    in.K_v = params::get_double(prm, "AGMA dynamic factor");
    in.K_s = params::get_double(prm, "AGMA size factor");
    in.Z_R = params::get_double(prm, "AGMA surface condition factor");
    in.K_B = params::get_double(prm, "AGMA rim thickness factor");
    in.enclosure = agma::enclosure_from_string(prm.get("AGMA gear unit class"));
    in.K_H = params::get_double(prm, "AGMA load distribution factor");
    in.tool.n_o = params::get_double(prm, "AGMA tool teeth");
    in.tool.x_o = params::get_double(prm, "AGMA tool addendum modification");
    in.K_A = params::get_double(prm, "Application factor");
    in.K_v_iso = params::get_double(prm, "ISO dynamic factor");
    in.K_Hbeta = params::get_double(prm, "ISO face load factor");
    in.accuracy_grade = params::get_integer(prm, "ISO accuracy grade");
    in.case_hardened = params::get_bool(prm, "Case hardened");
    in.sigma_Hlim = params::get_double(prm, "Contact fatigue limit") * 1e6;
    prm.leave_subsection();
    for (auto f : {std::pair<const char *, double>{"AGMA overload factor", in.K_o},
                   {"AGMA dynamic factor", in.K_v}, {"AGMA size factor", in.K_s},
                   {"AGMA surface condition factor", in.Z_R}, {"AGMA rim thickness factor", in.K_B},
                   {"Application factor", in.K_A}, {"ISO dynamic factor", in.K_v_iso},
                   {"ISO face load factor", in.K_Hbeta}})
      require_range(std::string("Rating/") + f.first, f.second, 1.0, 10.0);
    if (in.K_H != 0.0)
      require_range("Rating/AGMA load distribution factor", in.K_H, 1.0, 10.0);
    return in;
  }
} // namespace gearfem::rating
