#pragma once
// Quasi-static load sharing over the mesh cycle (the NTUA tooth-mass thesis: W_i ~ 1/C_i,
// equal deflection; Gkimisis 2019 eqs. 3.10-3.17: Hertz nonlinearity by iteration on the
// load). The tooth-pair compliance is abstract: any model (Weber/Cornell, potential
// energy, FE-calibrated) that gives delta/F of one pair at a contact position and load.
// SI units.
#include "analytical/corner.h"

#include <functional>
#include <vector>

namespace gearfem::analytical
{
  /// What the load-sharing solver needs to know about a pair of gears.
  struct MeshModel
  {
    double g_A = 0, g_E = 0; ///< start and end of contact, distances from T1 along the line of action [m]
    double g_C = 0;          ///< pitch point [m] (roll angle 0)
    double base_pitch = 0;   ///< p_b [m]
    double rb1 = 0;          ///< pinion base radius [m] (roll angle = (g - g_C)/rb1)
    /// Compliance delta/F [m/N] of one tooth pair in contact at g [m] under normal load F [N].
    std::function<double(double g, double F)> pair_compliance;
    /// Optional corner contact (OA/BΓ of Gkimisis 2019, corner.h): the rigid gap [m] and lever arm of
    /// a pair at g outside [g_A, g_E], in compression units with the gear held and the pinion
    /// turned. Empty (the default): only the pairs on A..E carry load. With it,
    /// solve_mesh_position and mesh_cycle also count the corner pairs (the inverse of
    /// load_at_compression), and so do load_at_compression and torque_table.
    std::function<CornerContact(double g)> corner;
  };

  /// Load sharing at one mesh position.
  struct MeshState
  {
    double roll_angle = 0;          ///< pinion roll angle phi1 [rad] (0 at C)
    double load = 0;                ///< total normal load F [N]
    double deflection = 0;          ///< common approach of the pairs along the line of action = loaded STE [m]
    double stiffness = 0;           ///< secant mesh stiffness F/deflection [N/m]
    std::vector<double> g;          ///< contact positions of the pairs in contact [m]
    std::vector<double> pair_load;  ///< load of each pair [N] (sums to `load`)
    std::vector<double> pair_stiffness; ///< secant stiffness of each pair [N/m] (sums to `stiffness`)
    int iterations = 0;             ///< Hertz fixed-point iterations
  };

  /// Pairs in contact at pinion roll angle phi1: g = g_C + rb1 phi1 + j p_b inside [g_A, g_E).
  std::vector<double> contact_positions(const MeshModel &m, double roll_angle);

  /// Equal deflection of all pairs in contact under total normal load F > 0, with the
  /// load-dependent pair compliances updated by fixed-point iteration to rel. tol 1e-12.
  /// With m.corner set, the pairs in corner contact (gap closed by the deflection) share the
  /// load too: the deflection x solves load_at_compression(x) = F (secant, rel. 1e-12);
  /// g and pair_load then list every loaded pair, corner pairs with their g outside A..E
  /// and their load along the line of action.
  /// Throws SolverError when no pair is in contact or the iteration does not converge.
  MeshState solve_mesh_position(const MeshModel &m, double roll_angle, double load);

  /// solve_mesh_position at n equally spaced roll angles over `pitches` angular pitches
  /// starting at the start of contact A.
  std::vector<MeshState> mesh_cycle(const MeshModel &m, double load, int n, int pitches = 1);

  /// Normal load carried at compression x [m] (Gkimisis 2019: F_i = K(w, x_i) x_i): each pair
  /// in contact solves F_i = x/lambda(g_i, F_i). x <= 0 gives 0 (loss of contact).
  /// With m.corner set, the pairs within one base pitch beyond A and E contribute too: a pair
  /// with gap s and lever-arm ratio k (corner.h) has the normal approach k (x - s) when x > s
  /// and carries F_i = k (x - s)/lambda(clamp(g_i, g_A, g_E), F_i) along the normal of the
  /// touched flank, whose moment about O1 is k rb1 F_i. The result is then the load along the
  /// line of action T1/rb1 = sum k_i F_i [N] (k = 1 on the path).
  double load_at_compression(const MeshModel &m, double roll_angle, double x);

  /// Torque table of Gkimisis 2019, T(phi1, x) = rb1 load_at_compression(phi1, x) on a grid [N m];
  /// rows = angles. Corner contact OA/BΓ when m.corner is set.
  std::vector<std::vector<double>> torque_table(const MeshModel &m,
                                                const std::vector<double> &roll_angles,
                                                const std::vector<double> &compressions);
} // namespace gearfem::analytical
