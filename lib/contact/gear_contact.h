#pragma once
// Loaded static contact of a spur pair, external (GearPair) or a pinion inside a ring
// (InternalGearPair, whose ring body is clamped on its outer support and cut edges
// instead of a bore): the two gear bodies (full gears or sectors) meshed
// once in their body frames and factorised once; for each mesh position the pinion is
// placed at roll angle phi1 and gear 2 at its unloaded conjugate angle (geometry module),
// gear 2's bore is clamped and the pinion turns rigidly by delta_theta about its centre
// (kinematic rotation, never a large displacement). Torque targeting solves for
// delta_theta. The model does contact only: it returns the converged contact state of each
// position (ContactState); lib/post evaluates it (STE, stiffness, load sharing, pressure,
// root stress, VTU). SI units inside. Phases are timed with deal.II TimerOutput sections
// "mesh", "assemble and factorise", "contact surfaces" (set-up) and "contact" (per position).
#include "contact/two_body.h"
#include "fem/elastic_body.h"
#include "geometry/internal_pair.h"
#include "geometry/pair.h"
#include "mesh/gear_mesh.h"
#include "mesh/ring_domain.h"

#include <deal.II/base/timer.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace gearfem::contact
{
  /// The converged contact state of one position: what GearContactModel::solve returns, what
  /// a warm start and a checkpoint read (the ContactSolution), and what post-processing
  /// (post::evaluate_position) turns into STE, stiffness, load sharing, pressure and root
  /// stress.
  struct ContactState
  {
    double phi1   = 0; ///< pinion roll angle [rad] (0 at C)
    double torque = 0; ///< pinion torque T1 [N m]: the target (torque control) or the result
    /// q = delta_theta [rad], load = T1 [N m], tangent dT1/d(delta_theta) [N m/rad], the
    /// contact points, the nodal contact forces of both bodies, iterations and the wall
    /// times of search, flexibility and solve.
    ContactSolution solution;
    double t_contact = 0; ///< wall time of the contact solve of this position [s]
    double rotation() const { return solution.q; } ///< delta_theta [rad]
  };

  /// One gear of a pair, ready for contact: its factorised elastic body (bore clamped;
  /// sector cut edges clamped), the fine teeth that carry contact surfaces, and the contact
  /// element size of its flanks.
  struct GearBody
  {
    /// Shared: the two gears of a pair whose bodies are identical use one factorised body.
    std::shared_ptr<fem::ElasticBody> body;
    std::vector<int> fine_teeth; ///< body-frame tooth indices
    double contact_size = 0;     ///< element size on the drive flanks after refinement [m]
  };
  /// The mesh requirements of a contact model that need no mesh (InputError naming the
  /// entry): a sector has at least 3 teeth, so that teeth -1, 0 and 1 share the mesh cycle.
  /// Checked when the input is parsed (solve/input.h) and again before a body is meshed.
  void check_contact_mesh(const mesh::GearMeshParameters &mesh);

  /// True when gears 1 and 2 of `pair` have the same body: the same generated outline (tooth
  /// count, face width and every outline point), the same mesh parameters and the same
  /// material. Such a pair (a 1:1 pair of identical gears) is meshed and factorised once.
  bool identical_bodies(const geometry::GearPair &pair, const mesh::GearMeshParameters mesh[2],
                        const fem::Elasticity material[2]);

  /// Mesh gear i (1 or 2) of `pair`, build, constrain, assemble and factorise its body.
  /// With a timer, the phases are its sections "mesh" and "assemble and factorise".
  GearBody build_gear_body(const geometry::GearPair &pair, int i, const mesh::GearMeshParameters &mesh,
                           const fem::Elasticity &material, const fem::FeOptions &fe,
                           dealii::TimerOutput *timer = nullptr);
  /// Mesh the ring of an internal pair, build, constrain (its outer support, boundary::bore,
  /// and a sector's cut edges), assemble and factorise it.
  GearBody build_ring_body(const geometry::InternalToothProfile &ring, const mesh::RingMeshParameters &mesh,
                           const fem::Elasticity &material, const fem::FeOptions &fe,
                           dealii::TimerOutput *timer = nullptr);

  /// The drive (tension-side) fillet of one fine tooth as observed by the flexibility cache:
  /// the samples of fem::ElasticBody::boundary_stress, rows first_row + 3 i + (xx, yy, xy).
  struct FilletObservation
  {
    int tooth = 0;          ///< tooth index in [0, z)
    int first_row = 0;      ///< first row of TwoBodyContact::observed(body)
    std::vector<Vec2> x;    ///< sample points, body frame [m]
    std::vector<double> arc; ///< arc length along the fillet [m]
  };

  /// The bodies and solver of one pair.
  class GearContactModel
  {
  public:
    /// The contact model of two prepared gear bodies (build_gear_body): the contact
    /// surfaces (drive flank, tip rounding and tip of the fine teeth on the slave side, plus
    /// the drive fillet on the master side, for tip-to-fillet corner contact under heavy
    /// load) and the two-body solver.
    /// With `options.micro_geometry_as_gap`, the tip reliefs of `pair` are applied as
    /// initial separations (TwoBodyContact::set_gap_modification), so the bodies must be
    /// meshed from the unmodified gears (unmodified_pair).
    GearContactModel(const geometry::GearPair &pair, std::array<GearBody, 2> bodies,
                     const ContactOptions &options);
    /// Build both bodies (mesh parameters per gear) in this model's timer, then as above.
    /// `mesh_pair` (may be null: `pair`) is the pair whose gears are meshed: the unmodified
    /// pair when `options.micro_geometry_as_gap`.
    GearContactModel(const geometry::GearPair &pair, const mesh::GearMeshParameters mesh[2],
                     const fem::Elasticity material[2], const fem::FeOptions &fe,
                     const ContactOptions &options, const geometry::GearPair *mesh_pair = nullptr);
    /// An internal pair: the pinion meshed with `pinion_mesh`, the ring with `ring_mesh`.
    /// A pinion tip relief needs `options.micro_geometry_as_gap` and `mesh_pair` (the pair
    /// with the unmodified pinion, which is meshed) as above.
    GearContactModel(const geometry::InternalGearPair &pair, const mesh::GearMeshParameters &pinion_mesh,
                     const mesh::RingMeshParameters &ring_mesh, const fem::Elasticity material[2],
                     const fem::FeOptions &fe, const ContactOptions &options,
                     const geometry::InternalGearPair *mesh_pair = nullptr);
    ~GearContactModel();

    /// Re-target the model to `pair`, a design that differs from the current one only in
    /// micro-geometry (tip relief): its reliefs become the gap modifications, and the bodies,
    /// their factorisations and the cached flexibility columns are kept. Requires
    /// `options.micro_geometry_as_gap` and the same macro-geometry (teeth, module, pressure
    /// angle, shifts, tip radii and centre distance; InputError otherwise). `pair` must
    /// outlive the model or the next call. The solution of a position does not depend on
    /// what was solved before, so the results equal those of a model built for `pair`.
    void set_micro_geometry(const geometry::GearPair &pair);

    /// Solve position phi1 [rad] at pinion torque T1 [N m] (> 0), warm-started from the
    /// converged solution `warm` of a neighbouring position (may be null).
    ContactState solve(double phi1, double torque, const ContactSolution *warm = nullptr);
    /// Rotation-controlled: the pinion turns by delta_theta [rad] (>= 0); T1 is the result.
    ContactState solve_rotation(double phi1, double delta_theta, const ContactSolution *warm = nullptr);

    /// Rigid placements (pair frame) of the pinion turned by `rotation` [rad] from its
    /// conjugate position at phi1, and of gear 2 at phi1.
    std::array<geometry::Placement, 2> placements(double phi1, double rotation) const;

    /// The pair's kinematics and flank facts (external or internal).
    const geometry::MeshingPair &pair() const { return *pair_; }
    /// The external pair (InputError for an internal pair: what needs it is external-only).
    const geometry::GearPair &gear_pair() const;
    const fem::ElasticBody &body(int i) const { return *bodies_[i - 1]; }
    const TwoBodyContact &solver() const { return *solver_; }
    /// The solver itself, for what goes beyond a solve (observed functionals, condensing).
    TwoBodyContact &contact_solver() { return *solver_; }
    /// Contact surface of gear i (its nodes are those of ContactPoint::node).
    const ContactSurface &surface(int i) const { return *surfaces_[i - 1]; }
    unsigned int n_dofs() const { return bodies_[0]->n_dofs() + bodies_[1]->n_dofs(); }
    /// Wall time of the set-up (mesh, assemble and factorise, contact surfaces) [s].
    double setup_seconds() const;
    /// Wall time of meshing both gears [s].
    double mesh_seconds() const;
    /// The phase timer: set-up sections and the cumulative "contact" section.
    const dealii::TimerOutput &timer() const { return timer_; }
    /// Fine teeth (body-frame indices) of gear i.
    const std::vector<int> &fine_teeth(int i) const { return fine_[i - 1]; }

    /// Observe, on every flexibility column the solver computes, the drive-fillet stresses of
    /// the fine teeth and the bore reaction moment of both gears (unit-load solves of the
    /// influence coefficients: TwoBodyContact::observe). Then a position's root stresses and
    /// reaction moment are linear maps of its nodal contact forces (post uses them when no
    /// field is written). Drops the cached columns; idempotent.
    void observe_root_stress();
    bool observes_root_stress() const { return !fillets_[0].empty(); }
    /// The observed fillets of gear i, and the row of its reaction moment (observe_root_stress).
    const std::vector<FilletObservation> &fillets(int i) const { return fillets_[i - 1]; }
    int reaction_row(int i) const { return reaction_row_[i - 1]; }

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

  private:
    /// Contact surfaces, tooth bookkeeping and solver on the bodies (timer section
    /// "contact surfaces").
    void set_up_contact(std::array<GearBody, 2> bodies);
    /// The contact solve of one position (scene and solve) in timer section "contact".
    /// `normal_force` [N] sizes the corner reach of the scene.
    ContactState timed_solve(double phi1, double normal_force, Control control, double value,
                             const ContactSolution *warm);
    /// The tip reliefs of pair_ as gap modifications (micro_geometry_as_gap), else none.
    void apply_micro_geometry();
    const geometry::MeshingPair *pair_;
    const geometry::GearPair *gear_pair_ = nullptr; ///< null for an internal pair
    std::shared_ptr<fem::ElasticBody> bodies_[2]; ///< the same body twice for identical gears
    std::unique_ptr<ContactSurface> surfaces_[2];
    std::unique_ptr<TwoBodyContact> solver_;
    std::vector<int> fine_[2];
    std::vector<FilletObservation> fillets_[2];
    int reaction_row_[2] = {-1, -1};
    std::vector<bool> slave_capable_[2]; ///< surface nodes on a drive flank, tip rounding or tip
    int tooth0_[2] = {0, 0};             ///< tooth of each gear at C when phi1 = 0
    double sense_[2] = {1, -1};          ///< sign of d(body angle)/d(phi1)
    double h_reach_ = 0;                 ///< contact element size of the coarser flank [m]
    ContactOptions options_;
    dealii::TimerOutput timer_;
  };

  /// Wall time [s] accumulated so far in section `name` of `timer` (0 if never entered).
  double section_seconds(const dealii::TimerOutput &timer, const std::string &name);

  /// Pinion roll angles [rad]: `n` equally spaced over `pitches` angular pitches starting at
  /// `start` (end excluded).
  std::vector<double> cycle_positions(const geometry::MeshingPair &pair, int n, double pitches,
                                      double start);
} // namespace gearfem::contact
