#pragma once
// A parallel-axis gear train on its shafts (`gearfem system`, docs/system-deflection.md).
// Stage k's pinion sits on shaft k and its gear on shaft k + 1 (the stages counted from the
// input). Each stage is a helical (or spur) pair sliced over its face on the condensed cycle of
// its transverse section, and all meshes are coupled through the shafts at once
// (CoupledTrain), so a stage's misalignment includes what its neighbours' loads do to the
// shared shafts. Stage k's pinion torque is the input torque times the ratios before it (no
// losses). Its roll angle follows stage 1's through the same ratios, from each stage's own first
// grid position (the stages' relative phase is that of their grids' starts).
#include "helical/run.h"
#include "system_deflection/coupled.h"
#include "system_deflection/run.h"

#include <filesystem>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::system_deflection
{
  struct TrainStage
  {
    std::filesystem::path input;  ///< the stage's `gearfem helical` input file
    helical::Request request;     ///< read from it (its Solve/Torques are the train's)
    double pinion_face_start = 0, gear_face_start = 0; ///< on shafts k and k + 1 [m]
    double direction = 0;         ///< direction of the gear's axis from the pinion's, about +z [rad]
  };

  struct TrainInput
  {
    std::vector<TrainStage> stages;
    shafts::System system;        ///< stages + 1 shafts (placed by run_train) and their bearings
    CoupledOptions options;
    std::vector<double> torques;  ///< input torques on stage 1's pinion [N m]
  };

  /// The `Train` section and its `Stage k` and `Shaft k` subsections; the stages' input files
  /// are named there, relative to the train's file, and read by the caller.
  void declare_train_parameters(dealii::ParameterHandler &prm);
  /// InputError naming the entry of the first bad value. Stage requests are left empty.
  TrainInput parse_train_parameters(dealii::ParameterHandler &prm, const std::filesystem::path &train_file);

  struct TrainRun
  {
    std::vector<helical::HelicalRun> stages;          ///< per stage: its results and summary
    std::vector<std::vector<CoupledResult>> coupled;  ///< per stage, parallel to stages[k].results
    std::vector<TorqueShafts> shafts;                 ///< per input torque, under the mean slice forces
    std::vector<std::vector<MethodC>> iso;            ///< per stage and torque
    std::vector<double> ratio;                        ///< per stage: its pinion torque / the input torque
    shafts::System system;                            ///< as solved (the shafts placed)
    std::vector<shafts::MeshLayout> meshes;           ///< per stage, as solved
    std::string failure;                              ///< empty: every position solved
    double sweep_seconds = 0;
  };

  /// Build every stage's cycle (with the Condense options of its own input) and sweep the
  /// input torques over stage 1's grid with all meshes on the shafts; progress to `out` (null:
  /// quiet). A position that fails ends the sweep with `failure` set; what was solved is kept.
  TrainRun run_train(TrainInput input, std::ostream *out = nullptr);

  /// stage_<k>/ with each stage's helical tables, and coupling.csv, misalignment.csv (a stage
  /// column), shafts.csv, bearings.csv and system.json, each written atomically into `dir`.
  void write_train(const TrainRun &run, const std::filesystem::path &dir, const std::string &input_name);
} // namespace gearfem::system_deflection
