#pragma once
// A gear mesh between two parallel shafts of a shafts::System (light layer): the line load of
// the mesh along the face onto both shafts, and back from the shafts' deflection the approach
// of the flanks along the line of action at each face position, whose variation over the face
// is the misalignment the contact sees (ISO 6336-1 f_sh and its kin, from the load path).
//
// Frame: the pinion's axis P and the gear's axis Q (external pair), e = (Q - P) / |Q - P|, t =
// z x e. With the pinion turning about +z (drive_sense +1) and driving, the normal force on the
// gear lies in the transverse plane along n = cos(alpha_wt) t + sin(alpha_wt) e (it pushes the
// gear away and turns it about -z), plus the axial component tan(beta_b) per unit transverse
// force of a helical pair (the helicoid's normal at the base cylinder); the pinion takes the
// opposite force. It acts at the pitch point of each face position (the standard's choice for
// the shaft load, ISO 6336-1 annex E). The approach at a face position is
//   delta(z) = (u_p + theta_p x r_p - u_g - theta_g x r_g) . n,
// r the pitch point from each axis: the shafts' bending, their torsion (r_b theta_z) and the
// bearings' give-way, positive where the flanks are pushed into each other.
#include "shafts/shaft.h"

#include <Eigen/Dense>

#include <vector>

namespace gearfem::shafts
{
  struct MeshLayout
  {
    int pinion_shaft = 0, gear_shaft = 1;
    /// Axial position of the face's start (the side of z = 0 of the slices) on each shaft [m
    /// from the shaft's start]; the face runs towards +z over face_width on both.
    double pinion_face_start = 0, gear_face_start = 0;
    double face_width = 0;      ///< [m]
    double alpha_wt = 0;        ///< working transverse pressure angle [rad]
    double beta_b = 0;          ///< base helix angle [rad], signed (> 0: axial force on the gear along +z)
    double pitch_radius_1 = 0;  ///< operating pitch radius of the pinion [m]
    int drive_sense = 1;        ///< +1: the pinion turns about +z and drives; -1 the reverse
    /// InputError naming the entry for shafts that are not in the system, a face off its
    /// shaft, coincident axes or a pitch radius that does not fit the centre distance.
    void validate(const System &system) const;
  };

  /// The unit normal force direction on the gear (system frame, transverse part only).
  Eigen::Vector3d line_of_action(const System &system, const MeshLayout &mesh);

  /// Point loads on both shafts for the transverse normal line load `w` [N/m] at face
  /// positions `z` [m from the face start] (slice centres, each of width `dz` [m]): slice k puts
  /// F_k = w_k dz_k along n (and tan(beta_b) F_k axially) on the gear at its pitch point and the
  /// opposite on the pinion, each as a force and its moment at the shaft node.
  std::vector<PointLoad> mesh_loads(const System &system, const MeshLayout &mesh, const std::vector<double> &z,
                                    const std::vector<double> &dz, const std::vector<double> &w);

  /// The approach of the flanks along the line of action [m] at face positions `z` (as in
  /// mesh_loads) from the shafts' solution.
  std::vector<double> mesh_approach(const System &system, const Solution &solution, const MeshLayout &mesh,
                                    const std::vector<double> &z);
  /// The gear's axis relative to the pinion's at face positions `z` (as in mesh_loads), from
  /// the shafts' solution [m]: its component along e (the centre distance's change; its
  /// variation along the face is the in-plane axis deviation, ISO 1328's f_Sigma_delta) and
  /// along t (perpendicular to the plane of the axes; its variation is f_Sigma_beta).
  std::vector<Eigen::Vector2d> mesh_axes_offset(const System &system, const Solution &solution,
                                                const MeshLayout &mesh, const std::vector<double> &z);
} // namespace gearfem::shafts
