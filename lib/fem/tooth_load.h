#pragma once
// A gear body under a concentrated flank load (tip loading of ISO 6336-3 method B): mesh,
// assemble, solve, and extract the fillet stress. Used by the single-tooth root-stress
// validation and by the fem benchmark. SI units.
#include "fem/elastic_body.h"
#include "geometry/profile.h"
#include "mesh/gear_mesh.h"

#include <memory>

namespace gearfem::fem
{
  /// The load: normal force F_n along the flank normal at radius `load_radius`,
  /// distributed uniformly over the flank patch [load_radius - patch_length, load_radius].
  struct FlankLoad
  {
    double normal_force = 0;   ///< F_n [N] (ISO: F_t / cos alpha_n)
    double load_radius  = 0;   ///< [m]; 0: tip radius (flank end)
    double patch_length = 0.15e-3; ///< radial extent of the loaded patch [m]
    int tooth           = 0;   ///< loaded tooth index
    bool drive_side     = true; ///< drive flank (x < 0 on tooth 0) or coast flank
  };

  /// Result of one load case.
  struct FlankLoadResult
  {
    StressPeak fillet_peak;      ///< max sigma_1 along the tension-side fillet of the loaded tooth
    StressPeak opposite_peak;    ///< the same on the compression-side fillet
    std::vector<BoundaryStressSample> fillet_profile; ///< sigma along the tension-side fillet
    Tensor2 applied_resultant;   ///< sum of the applied nodal forces [N]
    double reaction_moment = 0;  ///< about the gear centre [N m]
    double applied_moment  = 0;  ///< about the gear centre [N m]
    std::size_t n_cells = 0, n_dofs = 0;
    double t_mesh = 0, t_setup = 0, t_assemble = 0, t_factorize = 0, t_solve = 0; ///< [s]
    SolverKind solver = SolverKind::automatic;
  };

  /// Outward unit normal and point of the flank of `tooth` at radius r (exact curve).
  std::pair<mesh::Vec2, mesh::Vec2> flank_point_and_normal(const geometry::ToothProfile &tooth,
                                                           int tooth_index, bool drive_side,
                                                           double r);

  /// Mesh the gear body, clamp the bore (and the cut edges of a sector), apply the flank
  /// load, solve, and extract the fillet stresses. If `body_out` is not null it receives
  /// the body, and `u_out` the displacement (for VTU output).
  FlankLoadResult solve_flank_load(const geometry::ToothProfile &tooth,
                                   const mesh::GearMeshParameters &mesh_parameters,
                                   const Elasticity &material, const FeOptions &fe,
                                   const FlankLoad &load,
                                   std::unique_ptr<ElasticBody> *body_out = nullptr,
                                   dealii::Vector<double> *u_out = nullptr);
} // namespace gearfem::fem
