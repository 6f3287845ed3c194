#pragma once
// The accuracy a run asks for (`Solve/Target`): relative tolerances on the mean STE, the
// peak-to-peak STE, the peak root stress and the peak contact pressure, or a named preset.
// gearfem then chooses the FE model (model_choice/choose.h) and proves the choice on the run
// (model_choice/to_target.h). No deal.II.
#include <array>
#include <string>

namespace gearfem::model_choice
{
  /// The quantities a target can name, in this order everywhere.
  enum class Quantity
  {
    mean_ste,
    pp_ste,
    root_stress,
    p_max
  };
  inline constexpr int n_quantities = 4;

  struct AccuracyTarget
  {
    /// Relative tolerance per quantity (0.01 = 1 %); 0: not asked.
    std::array<double, n_quantities> tolerance{};
    std::string preset; ///< the preset it came from, or empty
    bool active() const;
    bool asks(Quantity q) const { return tolerance[static_cast<int>(q)] > 0; }
    double operator[](Quantity q) const { return tolerance[static_cast<int>(q)]; }
    /// "mean STE", "p-p STE", "root stress", "p_max" (the words of `Solve/Target`).
    static const std::array<const char *, n_quantities> &names();
    /// "mean_ste", "pp_ste", "root_stress", "p_max" (run.json keys).
    static const std::array<const char *, n_quantities> &keys();
  };

  /// The presets and what they ask:
  ///   dynamics tables:       mean STE 1 %, p-p STE 2 %   (the STE curve a table is built from)
  ///   rating check:          root stress 3 %, p_max 5 %
  ///   micro-geometry design: mean STE 2 %, p-p STE 1 %, p_max 10 %
  /// Text forms: "none", a preset name, or a comma-separated list of "<quantity> <percent>"
  /// with an optional "%" (e.g. "mean STE 1, p-p STE 2 %, root stress 3"). Each tolerance in
  /// 0.01 to 50 %. Throws InputError naming `entry`, the value and the allowed forms.
  AccuracyTarget parse_target(const std::string &text, const std::string &entry = "Solve/Target");
  /// "mean STE 1 %, root stress 3 %" (and the preset's name in front when it came from one).
  std::string to_string(const AccuracyTarget &t);
} // namespace gearfem::model_choice
