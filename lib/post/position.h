#pragma once
// Post-processing of one converged contact state (contact::ContactState) of a
// GearContactModel: STE, secant and tangent mesh stiffness, the equilibrium checks (moment
// of the contact forces, bore reaction, gear-2 moment), load sharing by tooth pair, the
// recovered contact pressure with its ellipse fit and the Hertz comparison on the local
// involute radii, edge (tip corner) classification, and the peak root stress of the loaded
// teeth; and the VTU of the deformed pair. The thresholds are the `Post` parameters
// (post/parameters.h). SI units inside.
#include "contact/gear_contact.h"

#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <filesystem>
#include <functional>
#include <vector>

namespace gearfem::post
{
  /// Thresholds of the evaluation (`Post` section, docs/output-format.md).
  struct PostOptions
  {
    /// A loaded patch with fewer slave nodes in contact is not resolved: its pressure peak
    /// is not reported as resolved and the ellipse fit is not attempted. >= 3 (the fit has
    /// three parameters).
    int min_patch_nodes = 5;
    /// A tooth pair counts as loaded (n_pairs, column `pairs in contact` of sweep.csv) when its share
    /// of the total normal load exceeds this. [-], in [0, 1).
    double loaded_share = 1e-6;
    /// Unresolved Hertzian pairs with a larger load share are counted and warned about
    /// (summary, `solve` warning); smaller ones carry too little load to matter. [-], in [0, 1).
    double unresolved_share = 0.05;
    /// A contact node (slave node or master point) within this distance of the tip-form
    /// circle of its gear counts as touching the tip edge (edge contact), in units of the
    /// module m_n of the pinion [-], >= 0. The default only absorbs round-off.
    double tip_edge_band = 1e-9;
    /// Pinion speed [rad/s] of the mesh power loss (the `Contact/Pinion speed` of the run).
    double pinion_speed = 1000.0 * 3.14159265358979323846 / 30.0;
  };

  /// Throws InputError naming the `Post` entry ("Post/Min patch nodes", ...) of the first
  /// value out of range.
  void validate(const PostOptions &options);

  /// One loaded tooth pair at one position.
  struct ToothPairResult
  {
    int pinion_tooth = 0, gear_tooth = 0;
    double force = 0;         ///< normal load of the pair [N]
    double share = 0;         ///< force / sum of forces
    int active_nodes = 0;     ///< slave nodes in contact
    double p_max = 0;         ///< peak recovered contact pressure [Pa]
    double half_width = 0;    ///< from the ellipse fit [m]; 0 when unresolved
    bool resolved = false;    ///< at least min_patch_nodes across the patch and a valid ellipse fit
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
    /// Friction force of the pair on the pinion flank along its profile, positive towards
    /// the pinion tip [N]; it reverses at the pitch point (0 when frictionless).
    double friction = 0;
    double power_loss = 0;    ///< sum of |friction force| |sliding speed| of the pair [W]
    std::vector<std::array<double, 3>> profile; ///< (s [m] along the pinion flank from the peak, radius [m], p [Pa])
  };

  /// The evaluated results of one position.
  struct PositionResult
  {
    double phi1 = 0;            ///< pinion roll angle [rad] (0 at C)
    double torque = 0;          ///< pinion torque T1 [N m] (target, or result of rotation control)
    double rotation = 0;        ///< delta_theta [rad]
    double ste = 0;             ///< delta_theta r_b1 [m]
    double normal_force = 0;    ///< F_n = T1 / r_b1 [N]
    double k_secant = 0;        ///< F_n / STE [N/m]
    double k_tangent = 0;       ///< dF_n / dSTE [N/m] (consistent tangent)
    double torque_contact = 0;  ///< moment of the contact forces about O1 [N m]
    double torque_reaction = 0; ///< reaction moment at the pinion bore [N m]
    double torque_gear = 0;     ///< |moment of the contact forces on gear 2 about O2| [N m]
    int n_pairs = 0;            ///< tooth pairs with a load share above PostOptions::loaded_share
    double p_max = 0;           ///< peak pressure over the flank-to-flank (Hertzian) pairs [Pa]
    double p_max_edge = 0;      ///< peak pressure over the edge/corner pairs [Pa] (mesh-dependent)
    std::vector<ToothPairResult> pairs;
    double max_root_stress_pinion = 0, max_root_stress_gear = 0; ///< [Pa]
    double friction_force = 0;  ///< sum of |friction force| over the contact points [N]
    double power_loss = 0;      ///< mesh power loss sum mu lambda |v_s| at PostOptions::pinion_speed [W]
    /// Power of the normal contact forces at non-conjugate contact, sum lambda n . (v_1 - v_2)
    /// at PostOptions::pinion_speed [W] (tip-corner contact, contact off the line of action):
    /// T1 omega1 - T2 omega2 = power_loss + normal_power; its mean over a mesh cycle is 0.
    double normal_power = 0;
    double t_post = 0;           ///< wall time of the evaluation [s] (set by Evaluator)
    dealii::Vector<double> u[2]; ///< body-frame displacements (kept only when asked)
  };

  /// The evaluation that needs no finite-element field, shared by the full and the condensed
  /// routes: STE, secant and tangent stiffness, load sharing, pressure with the ellipse fit
  /// and Hertz, edge flags, n_pairs and the peak pressures of state `s` with the rigid
  /// placements `P` (GearContactModel::placements at its rotation). `root_stress` (may be
  /// empty) fills the root stresses of each loaded pair; the equilibrium moments are left 0.
  PositionResult evaluate_contact(const geometry::MeshingPair &pair, const fem::Elasticity material[2],
                                  const contact::ContactState &s, const std::array<geometry::Placement, 2> &P,
                                  const PostOptions &options,
                                  const std::function<void(ToothPairResult &)> &root_stress);

  /// Evaluate the converged state `s` of `model`. `keep_displacements` keeps u for VTU output.
  PositionResult evaluate_position(const contact::GearContactModel &model, const contact::ContactState &s,
                                   const PostOptions &options = PostOptions(), bool keep_displacements = false);

  /// Write the deformed pair of state `s` (pair frame) with stresses and the contact traction
  /// to a VTU; `r` must have been evaluated with keep_displacements.
  void write_vtu(const contact::GearContactModel &model, const contact::ContactState &s, const PositionResult &r,
                 const std::filesystem::path &file, double scale = 1.0);

  /// evaluate_position timed in section "post" of its own TimerOutput (t_post of each result);
  /// callers time their output in section "output" of the same timer.
  class Evaluator
  {
  public:
    Evaluator(const contact::GearContactModel &model, const PostOptions &options);
    PositionResult operator()(const contact::ContactState &s, bool keep_displacements = false);
    const contact::GearContactModel &model() const { return model_; }
    const PostOptions &options() const { return options_; }
    dealii::TimerOutput &timer() { return timer_; }
    const dealii::TimerOutput &timer() const { return timer_; }

  private:
    const contact::GearContactModel &model_;
    PostOptions options_;
    dealii::TimerOutput timer_;
  };
} // namespace gearfem::post
