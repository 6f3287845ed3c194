#pragma once
// `gearfem helical` on the pair's shafts (`System/Coupling = shafts`, docs/system-deflection.md):
// the helical sweep with every position solved on the shafts (coupled.h), the lead correction
// designed at a torque when asked, and the tables of the shafts: the mismatch along the face per
// position, the coupling's iterations and residual, and per torque the shafts' deflection lines
// and bearing reactions under the cycle's mean slice forces.
#include "helical/run.h"
#include "system_deflection/coupled.h"

#include <filesystem>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::system_deflection
{
  /// The `System` section: shaft 0 carries the pinion (gear 1), shaft 1 the gear (gear 2), whose
  /// axis is placed at the centre distance along +x.
  struct SystemInput
  {
    bool coupled = false; ///< false: the helical run is not coupled (the section is ignored)
    shafts::System system;
    /// Face starts on the shafts and the drive sense; the face width, pressure angle, helix and
    /// pitch radius are the pair's (completed by run_coupled).
    shafts::MeshLayout mesh;
    CoupledOptions options;
    double correction_torque = 0; ///< > 0: design the lead correction at this torque [N m]
    int correction_positions = 8; ///< positions of the cycle the correction is designed over
  };

  void declare_system_parameters(dealii::ParameterHandler &prm);
  /// InputError naming the `System` entry of the first bad value (a segment, a bearing, a face
  /// off its shaft).
  SystemInput parse_system_parameters(dealii::ParameterHandler &prm);

  /// ISO 6336-1:2006 method C beside the coupled solution at one torque: K_Hbeta from the
  /// mismatch the shafts give plus the lead correction when there is one (F_beta_y the largest
  /// span of that sum over the face in the cycle, no running-in allowance; the input's other
  /// lead modifications left out) with method B's c_gamma_beta of the pair, F_m/b = F_t/b.
  struct MethodC
  {
    double torque = 0;        ///< pinion torque [N m]
    double f_beta_y = 0;      ///< [m]
    double c_gamma_beta = 0;  ///< [N/(mm um)] (0: method B does not cover the pair)
    double line_load = 0;     ///< F_t / b [N/mm]
    double k_h_beta = 0;      ///< method C (0 when c_gamma_beta is 0)
    double k_h_beta_coupled = 0; ///< the coupled solution's, largest over the cycle
  };
  /// Per torque of `summary`, from the coupled results of the sweep.
  std::vector<MethodC> method_c(const solve::GearContactInput &section, const helical::SlicingOptions &o,
                                const std::vector<CoupledResult> &coupled,
                                const std::vector<helical::TorqueSummary> &summary,
                                const LeadCorrection *correction = nullptr);

  struct TorqueShafts
  {
    double torque = 0;
    shafts::Solution solution; ///< under the cycle's mean slice forces
  };

  struct CoupledRun
  {
    helical::HelicalRun helical;
    std::vector<CoupledResult> coupled; ///< parallel to helical.results
    bool corrected = false;
    DesignedCorrection design;          ///< when corrected
    double design_seconds = 0;
    std::vector<TorqueShafts> shafts;   ///< per torque
    std::vector<MethodC> iso;           ///< per torque
    shafts::System system;              ///< as solved (the gear axis placed)
    shafts::MeshLayout mesh;            ///< as solved
  };

  /// The pair's mesh layout on `sys` completed from the slicing (face width, alpha_wt, helix,
  /// pitch radius) and the gear shaft placed at the centre distance.
  void complete(SystemInput &sys, const solve::GearContactInput &section, const helical::SlicingOptions &o);

  /// The helical run of `section` with every position on the shafts of `sys` (completed here).
  CoupledRun run_coupled(const solve::GearContactInput &section, const helical::SlicingOptions &o,
                         helical::RunOptions ro, SystemInput sys);

  /// The `gearfem helical` job: on the shafts of `sys` when it is coupled (run_coupled), else the
  /// slicing alone on rigid, aligned axes (helical::run_helical; `coupled` empty). The one route
  /// decision of the CLI and the Python module.
  CoupledRun run_job(const solve::GearContactInput &section, const helical::SlicingOptions &o, helical::RunOptions ro,
                     const SystemInput &sys);

  /// The tables of a job: write_coupled when it ran on the shafts, else helical::write_helical.
  void write_job(const CoupledRun &run, bool coupled, const std::filesystem::path &dir, const std::string &input_name);

  /// The helical tables (helical::write_helical) and coupling.csv, misalignment.csv,
  /// shafts.csv, bearings.csv and system.json, each written atomically into `dir`.
  void write_coupled(const CoupledRun &run, const std::filesystem::path &dir, const std::string &input_name);
} // namespace gearfem::system_deflection
