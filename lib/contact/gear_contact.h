#pragma once
// Loaded static contact of a spur pair: the two gear bodies (full gears or sectors) meshed
// once in their body frames and factorised once; for each mesh position the pinion is
// placed at roll angle phi1 and gear 2 at its unloaded conjugate angle (geometry module),
// gear 2's bore is clamped and the pinion turns rigidly by delta_theta about its centre
// (kinematic rotation, never a large displacement). Torque targeting solves for
// delta_theta. Results per position: STE, secant and tangent mesh stiffness, load sharing,
// contact pressure, root stress, and equilibrium checks. SI units inside.
#include "contact/two_body.h"
#include "fem/elastic_body.h"
#include "geometry/pair.h"
#include "mesh/gear_mesh.h"

#include <deal.II/lac/vector.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace gearfem::contact
{
  /// One loaded tooth pair at one position.
  struct ToothPairResult
  {
    int pinion_tooth = 0, gear_tooth = 0;
    double force = 0;         ///< normal load of the pair [N]
    double share = 0;         ///< force / sum of forces
    int active_nodes = 0;     ///< slave nodes in contact
    double p_max = 0;         ///< peak recovered contact pressure [Pa]
    double half_width = 0;    ///< from the ellipse fit [m]; 0 when unresolved
    bool resolved = false;    ///< at least 5 nodes across the patch and a valid ellipse fit
    double p_hertz = 0;       ///< Hertz p0 on the local involute radii of curvature [Pa]
    double a_hertz = 0;       ///< Hertz half-width [m]
    double radius_pinion = 0; ///< radius of the peak-pressure point on the pinion [m]
    double radius_gear = 0;   ///< the same on the gear [m]
    /// The loaded patch reaches a tip edge of either gear: its tip corner, tip rounding or
    /// tip land (extended or corner contact). Its pressure is not Hertzian: at a sharp
    /// corner it is singular and grows under refinement. false: flank-to-flank contact.
    bool edge = false;
    int slave_body = 1;       ///< body that carried the slave nodes of this pair
    double root_stress_pinion = 0, root_stress_gear = 0; ///< peak fillet sigma_1 [Pa]
    double root_radius_pinion = 0, root_radius_gear = 0; ///< where [m]
    std::vector<std::array<double, 3>> profile; ///< (s [m] along the pinion flank from the peak, radius [m], p [Pa])
  };

  struct PositionResult
  {
    std::string name;           ///< A, B, C, D, E or ""
    double phi1 = 0;            ///< pinion roll angle [rad] (0 at C)
    double torque = 0;          ///< target pinion torque T1 [N m]
    double rotation = 0;        ///< delta_theta [rad]
    double ste = 0;             ///< delta_theta r_b1 [m]
    double normal_force = 0;    ///< F_n = T1 / r_b1 [N]
    double k_secant = 0;        ///< F_n / STE [N/m]
    double k_tangent = 0;       ///< dF_n / dSTE [N/m] (consistent tangent)
    double torque_contact = 0;  ///< moment of the contact forces about O1 [N m]
    double torque_reaction = 0; ///< reaction moment at the pinion bore [N m]
    double torque_gear = 0;     ///< |moment of the contact forces on gear 2 about O2| [N m]
    int n_pairs = 0;            ///< tooth pairs carrying load
    double p_max = 0;           ///< peak pressure over the flank-to-flank (Hertzian) pairs [Pa]
    double p_max_edge = 0;      ///< peak pressure over the edge/corner pairs [Pa] (mesh-dependent)
    std::vector<ToothPairResult> pairs;
    ContactSolution solution;
    double max_root_stress_pinion = 0, max_root_stress_gear = 0; ///< [Pa]
    double t_search = 0, t_compliance = 0, t_solve = 0, t_post = 0, t_total = 0; ///< [s]
    dealii::Vector<double> u[2]; ///< body-frame displacements (kept only when asked)
  };

  /// The bodies and solver of one pair.
  class GearContactModel
  {
  public:
    /// Mesh both gears (mesh parameters per gear), build and factorise the bodies (bore
    /// clamped; sector cut edges clamped), and the contact surfaces: drive flank, tip
    /// rounding and tip of the fine teeth (slave side), plus the drive fillet (master
    /// side, for tip-to-fillet corner contact under heavy load).
    GearContactModel(const geometry::GearPair &pair, const mesh::GearMeshParameters mesh[2],
                     const fem::Elasticity material[2], const fem::FeOptions &fe,
                     const ContactOptions &options);
    ~GearContactModel();

    /// Solve position phi1 [rad] at pinion torque T1 [N m] (> 0), warm-started from
    /// `warm` (may be null). `keep_displacements` keeps u for VTU output.
    PositionResult solve(double phi1, double torque, const PositionResult *warm = nullptr,
                         bool keep_displacements = false);
    /// Rotation-controlled: the pinion turns by delta_theta [rad] (>= 0); T1 is the result.
    PositionResult solve_rotation(double phi1, double delta_theta, const PositionResult *warm = nullptr,
                                  bool keep_displacements = false);

    /// Write the deformed pair (pair frame) with stresses and contact traction to a VTU.
    void write_vtu(const PositionResult &r, const std::filesystem::path &file, double scale = 1.0) const;

    const geometry::GearPair &pair() const { return *pair_; }
    const fem::ElasticBody &body(int i) const { return *bodies_[i - 1]; }
    const TwoBodyContact &solver() const { return *solver_; }
    unsigned int n_dofs() const { return bodies_[0]->n_dofs() + bodies_[1]->n_dofs(); }
    double setup_seconds() const { return t_setup_; }
    double mesh_seconds() const { return t_mesh_; }
    /// Fine teeth (body-frame indices) of gear i.
    const std::vector<int> &fine_teeth(int i) const { return fine_[i - 1]; }

    /// The scene at pinion position phi1: rigid placements and, with per-zone slaves, the
    /// slave nodes of each tooth pair. `normal_force` [N] sizes the Hertz patch that decides
    /// whether a tip corner is within reach.
    Scene scene(double phi1, double normal_force) const;
    /// Path position of tooth `tooth` of gear `body` at pinion position phi1: the pinion
    /// position at which tooth 0 of the pinion stands where this tooth stands now [rad]
    /// (0 at C; the teeth of a meshing pair share it).
    double tooth_roll(int body, int tooth, double phi1) const;
    /// Which body carries the slave nodes of the tooth pair at path position psi (see
    /// ContactOptions::per_zone_slaves).
    int zone_slave(double psi, double normal_force) const;

    /// A loaded patch with fewer nodes is not resolved (its pressure peak is not reported
    /// as resolved, and the ellipse fit is not attempted).
    static constexpr int min_patch_nodes = 5;

  private:
    PositionResult finish(double phi1, double torque, ContactSolution &&s, bool keep);
    /// The contact point touches a tip edge (corner, tip rounding or tip land) of either gear.
    bool at_tip_edge(const ContactPoint &p, const geometry::Placement &P1, const geometry::Placement &P2) const;
    /// Peak pressure, profile, ellipse fit and Hertz comparison of one loaded pair.
    void pressure_and_hertz(ToothPairResult &tp, const ContactSolution &sol, const geometry::Placement &P1,
                            const geometry::Placement &P2) const;
    const geometry::GearPair *pair_;
    std::unique_ptr<fem::ElasticBody> bodies_[2];
    std::unique_ptr<ContactSurface> surfaces_[2];
    std::unique_ptr<TwoBodyContact> solver_;
    std::vector<int> fine_[2];
    std::vector<bool> slave_capable_[2]; ///< surface nodes on a drive flank, tip rounding or tip
    int tooth0_[2] = {0, 0};             ///< tooth of each gear at C when phi1 = 0
    double sense_[2] = {1, -1};          ///< sign of d(body angle)/d(phi1)
    double h_reach_ = 0;                 ///< contact element size of the coarser flank [m]
    ContactOptions options_;
    double t_setup_ = 0, t_mesh_ = 0;
  };

  /// Pinion roll angles [rad]: `n` equally spaced over `pitches` angular pitches starting at
  /// `start` (end excluded).
  std::vector<double> cycle_positions(const geometry::GearPair &pair, int n, double pitches,
                                      double start);
} // namespace gearfem::contact
