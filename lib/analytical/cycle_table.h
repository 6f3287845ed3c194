#pragma once
// The analytical mesh cycle as a table (`gearfem rate`'s mesh_cycle.csv): for each pinion
// torque, n positions over one angular pitch from the start of contact A, with the pairs
// in contact, the loaded STE, the secant mesh stiffness and the load of each pair. Two laws:
//  - load_sharing: the equal-deflection load sharing of mesh_cycle.h on the pair compliance
//    (Weber/Cornell or potential energy, with or without the corner contacts OA/BΓ);
//  - ricker: the semi-analytical pair stiffness of Gkimisis 2019 with Ricker-wavelet load
//    sharing (ricker_load_sharing.h); its Hertz term is linearised with the mean stiffness of the
//    load-sharing cycle at the same torque (eq. 3.30), and the STE at a position solves
//    load(phi1, x) = F (TOMS 748).
// The evaluation is timed, so that the speed-against-error study can put each
// analytical rung next to the FE. SI units.
#include "analytical/tooth.h"
#include "base/units.h"
#include "base/table.h"

#include <vector>

namespace gearfem::analytical
{
  enum class CycleLaw
  {
    load_sharing,  ///< mesh_cycle.h on the pair compliance
    ricker ///< RickerSemiAnalytical::load with Ricker load sharing
  };
  CycleLaw cycle_law_from_string(const std::string &s); ///< "load sharing" | "seed000 ricker"

  /// What both laws need: the two teeth, materials, face width and line of action.
  struct CycleInput
  {
    InvoluteTooth pinion, gear;
    Material m1, m2;
    double face_width = 0; ///< [m]
    PairLine line;
    PairModelOptions options;
    bool corner_contact = true; ///< corner contacts OA/BΓ in the load-sharing cycle
    double ricker_widening = 2.0 * units::pi / 180.0 / 1e-3; ///< c_x [rad/m]
  };

  struct CycleTable
  {
    /// Columns: pinion torque [N m], roll angle [deg], pairs in contact, loaded STE [um],
    /// mesh stiffness [N/um], load pair 1..3 [N] (in the order of g, A side first).
    Table table;
    std::vector<double> torques;                           ///< [N m]
    std::vector<double> k_min, k_max, k_mean;              ///< per torque [N/m]
    double seconds = 0; ///< wall time of the evaluation (all torques, table filling excluded)
  };

  /// The mesh cycle at every torque (> 0) with `positions` (>= 2) positions over one pitch.
  /// Throws SolverError when a position does not converge.
  CycleTable mesh_cycle_table(const CycleInput &in, CycleLaw law, const std::vector<double> &torques,
                              int positions);
} // namespace gearfem::analytical
