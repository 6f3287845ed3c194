#pragma once
// The `Calibration` section of `gearfem calibrate`: the solve results to fit, the model, the
// factors the fit may change, the corner contact and the table grid. Compiled into
// gearfem_calibration_params (deal.II); the light target has no deal.II.
#include "calibration/calibrate.h"

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::calibration
{
  /// The `Calibration` section, checked.
  struct Input
  {
    std::vector<std::string> files; ///< results.h5 of `gearfem solve` (relative to the input file)
    /// condensed.h5 of `gearfem condense` (relative to the input file; "" none): FE samples
    /// at `cycle_torques` re-solved on it, milliseconds per position.
    std::string cycle;
    std::vector<double> cycle_torques; ///< [N m]; empty: 6 torques spread over the cycle's range
    std::string model;              ///< "weber-cornell" | "potential-energy"
    Options options;
  };

  void declare_calibration_parameters(dealii::ParameterHandler &prm);
  /// Read and check the section (InputError naming the entry).
  Input parse_calibration_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::calibration
