#pragma once
// A helical pair as slices of its face width on the condensed cycle of its transverse section
// (condensed/cycle.h). Slice k, centred at axial position z_k, is the transverse section at
// roll angle phi1 + z_k tan(beta_b) / r_b1 (helix.h); it is the stored 2-D section of width
// b/N: its Delassus operator is N W, its pressures and stresses those of the 2-D section at
// N times its load. A slice whose roll angle falls between two stored positions is split
// into two sub-slices at those positions, their widths in proportion to the distance (the
// section's compliance interpolated linearly in the roll angle; exact on the grid).
//
// Coupling across the face: for each tooth pair, with K_k the stiffness of its section in slice
// k (the global part: the pair's minimum compliance over its stored candidates, which leaves
// out the local Hertzian flattening of the actual patch), the deflections of the pair along
// the face are w = (K + B)^-1 F instead of K^-1 F, B the coupling of neighbouring sections:
// - bending (default): the sections form a beam along the face on their own elastic
//   foundation (Hetenyi, Beams on elastic foundation, 1946), EI = k l^4 / 4 with free ends, so
//   that a point load spreads over an effective width 2 l (beta = 1/l) while a uniform load and
//   a rigid tilt of the tooth (a misalignment) cost nothing;
// - shear: a Pasternak layer between neighbours (as Ajmi & Velex 2005, Mech. Mach. Theory 40,
//   173-190), G = l^2 sqrt(K_k K_k+1) / dz^2, a point load spreading as exp(-|z|/l) / (2 l);
//   its free ends carry an edge force wherever the deflection has a slope.
// The correction (K + B)^-1 - K^-1, negative semi-definite, is added to the Delassus operator
// through the arms of the pair's candidates, so the coupled operator stays positive definite.
// The default l = m_n: Wellauer & Seireg's cantilever-plate kernel (J. Eng. Ind. 82, 1960)
// spreads a load at height x over an effective width 2 x, and a load at the pitch circle sits
// about one module above the critical root section. l = 0: uncoupled slices (Winkler).
//
// All slices share the rigid rotation of the pinion; the torque is carried by their sum; the
// contact problem of all slices together is solved by a primal-dual active set on the stored
// candidates near contact, the set grown where an excluded candidate would penetrate.
#include "condensed/cycle.h"
#include "condensed/resolve.h"
#include "helical/helix.h"
#include "post/position.h"
#include "solve/input.h"

#include <Eigen/Dense>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace gearfem::helical
{
  /// The stored positions: G positions equally spaced over one pitch of gear 1 from phi0.
  struct Grid
  {
    double phi0 = 0, step = 0; ///< [rad]
    int size = 0;
    std::vector<std::pair<std::string, double>> positions() const;
  };

  struct SliceResult
  {
    double z = 0;              ///< slice centre [m]
    double phi1 = 0;           ///< roll angle of its section [rad]
    double force = 0;          ///< transverse normal force of the slice, its torque / r_b1 [N]
    double load_per_width = 0; ///< force / slice width [N/m]
    double p_max = 0;          ///< peak flank pressure [Pa] (0 unloaded)
    /// Peak fillet sigma_1 of the section at the slice's load per unit width [Pa].
    double root_stress_pinion = 0, root_stress_gear = 0;
    double lead_gap = 0;       ///< gap offset of the lead modifications [m]
  };

  /// One tooth pair's load along its contact line: per slice, its transverse normal force
  /// per unit face width [N/m] (0 where it does not touch). Teeth in the labels of the
  /// section at z = 0 of the first stored position.
  struct ContactLine
  {
    int pinion_tooth = 0, gear_tooth = 0;
    std::vector<double> load_per_width;
  };

  struct HelicalResult
  {
    double phi1 = 0;         ///< roll angle of the middle section [rad]
    double torque = 0;       ///< pinion torque T1 [N m]
    double rotation = 0;     ///< [rad]
    double ste = 0;          ///< rotation r_b1 [m]
    double normal_force = 0; ///< T1 / r_b1, transverse [N]
    double k_mesh = 0;       ///< secant normal_force / ste [N/m]
    double k_tangent = 0;    ///< dF/d(STE) at the converged active set [N/m]
    double k_h_beta = 0;     ///< face load factor: max over slices of w / (F / b)
    double p_max = 0, root_stress_pinion = 0, root_stress_gear = 0; ///< maxima over the slices [Pa]
    int n_pairs = 0;         ///< tooth pairs carrying load somewhere on the face
    std::vector<SliceResult> slices;
    std::vector<ContactLine> lines;
    int candidates = 0;      ///< unknowns of the coupled complementarity problem
    int iterations = 0;      ///< active-set iterations, all passes
    double seconds = 0;      ///< wall time [s]
  };

  struct SlicingOptions
  {
    Helix helix;
    int slices = 21;
    Coupling coupling = Coupling::bending;
    double coupling_length = 0; ///< l [m], >= 0
    FaceModel model = FaceModel::slices; ///< solid: `face` is set by the route (system_deflection::run_job)
    SolidFace solid;
    LeadModification lead;
    double alpha_wt = 0;        ///< working transverse pressure angle [rad] (lead_gap)
    Grid grid;
    post::PostOptions post;
    /// The face of one tooth pair in 3-D in place of the beam (helical/slicing.h, the 3-D FE
    /// model, three_d/face_compliance.h): given the contact's radius on gear 1 and on gear 2
    /// in each slice [m], the correction to the independent sections over the slices [m/N]
    /// (transverse strip forces, work-conjugate deflections; symmetric). Empty: the beam.
    std::function<Eigen::MatrixXd(const std::vector<double> &r1, const std::vector<double> &r2)> face;
    /// With `face`: gear g's (1, 2) fillet in 3-D, the load each slice's section would carry
    /// to reach it [N], from the slices' transverse forces [N] and contact radii on gear g [m].
    std::function<std::vector<double>(int g, const std::vector<double> &force, const std::vector<double> &r)> face_root;
    double face_seconds = 0; ///< to build `face` (both 3-D bodies and their tables) [s]
    unsigned face_dofs  = 0; ///< DoFs of the two 3-D bodies
  };

  class SlicedOperator;

  class SlicedPair
  {
    friend class SlicedOperator;

  public:
    /// `section`: the transverse section whose `Solve` positions are grid.positions() (the
    /// cycle's). Both must outlive this object.
    SlicedPair(const condensed::CondensedCycle &cycle, const solve::GearContactInput &section, SlicingOptions options);
    /// The pair at roll angle phi1 of its middle section under pinion torque T1 > 0 [N m].
    /// SolverError outside the cycle's torque range, and when the complementarity problem
    /// fails or leaves the stored candidates. A slice whose own load per unit width lies
    /// outside the range takes the nearest stored scene.
    HelicalResult solve(double phi1, double torque) const;
    /// The same with the lead modification `lead` in place of the options' (the shaft coupling
    /// iterates on it without rebuilding the pair).
    HelicalResult solve(double phi1, double torque, const LeadModification &lead) const;

  private:
    struct State;

  public:
    /// A position solved but not yet post-processed: the slices' forces, and the state that
    /// evaluate() turns into the full result. solve() is evaluate(solve_forces()); the shaft
    /// coupling iterates on the forces and post-processes its converged position only.
    struct Solved
    {
      std::vector<double> force; ///< transverse normal force of each slice [N]
      std::shared_ptr<const State> state;
    };
    /// `warm`: a solution of the same position and torque under a nearby lead (the coupling's
    /// previous iterate), whose scenes, candidate sets and forces start this one.
    Solved solve_forces(double phi1, double torque, const LeadModification &lead, const Solved *warm = nullptr) const;
    /// The full result (pressures, root stresses, contact lines) of a solved position.
    HelicalResult evaluate(const Solved &solved) const;
    const SlicingOptions &options() const { return o_; }

  private:
    struct Sub;
    struct System;
    /// The contact torque a sub-slice carries in the coupled problem's solution [N m].
    double sub_torque(const Sub &u, const System &s) const;
    std::vector<Sub> subs(double phi1) const;
    /// The stored section's stiffness at the level of the given tooth pairs (stored labels):
    /// P W^-1 P^T over their stored candidates [N m/rad] (cached).
    Eigen::MatrixXd section_stiffness(const contact::CondensedPosition &p,
                                      const std::vector<std::pair<int, int>> &pairs) const;
    void couple(System &s, const std::vector<Sub> &sub) const;
    /// The coupling of the 3-D face (options().face) in place of the beam.
    void face_correction(System &s, const std::vector<Sub> &sub) const;
    void index_unknowns(System &s, const std::vector<Sub> &sub) const;
    // The phases of solve(): the absolute tooth-pair key; a sub-slice's stored configuration,
    // offsets and initial candidates at a load; the coupled problem (returns the start
    // rotation); the Newton loop on the rotation (returns active-set iterations); a new scene
    // per sub-slice at its own load, and candidates that would penetrate (each true when the
    // problem changed); the coverage of the contact by the stored candidates.
    long pair_key(int t1, int t2, long wrap) const;
    void prepare(Sub &u, double load, const LeadModification &lead) const;
    /// Relief and lead gap offsets of a sub-slice's stored candidates [m].
    Eigen::VectorXd offsets(const Sub &u, const LeadModification &lead) const;
    double assemble(System &s, std::vector<Sub> &sub, double torque) const;
    int rotate(System &s, const std::vector<Sub> &sub, double torque, double q) const;
    bool rescene(std::vector<Sub> &sub, const System &s, const LeadModification &lead) const;
    bool grow(std::vector<Sub> &sub, const System &s) const;
    void check_coverage(const std::vector<Sub> &sub, const System &s) const;
    HelicalResult evaluate(double phi1, double torque, const std::vector<Sub> &sub, const System &s,
                           const LeadModification &lead) const;
    /// The root stress of each slice from its section load (helical/slicing_post.cc): `tau`
    /// the contact torque and `sig` the fillet stresses (pinion, gear) per tooth pair and slice.
    void root_stresses(HelicalResult &h, const std::map<long, Eigen::VectorXd> &tau,
                       const std::map<long, Eigen::VectorXd> sig[2], const std::vector<Sub> &sub,
                       const System &s) const;
    const condensed::CondensedCycle &cycle_;
    const solve::GearContactInput &in_;
    SlicingOptions o_;
    condensed::Resolver resolver_;
    double rb1_ = 0;
    int z_[2] = {0, 0};
    mutable std::map<std::pair<const void *, std::vector<std::pair<int, int>>>, Eigen::MatrixXd> section_;
  };
} // namespace gearfem::helical
