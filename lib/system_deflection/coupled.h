#pragma once
// The gear pair on its shafts and bearings: the helical slices (helical/slicing.h) coupled to a
// shafts::System through the mesh (shafts/mesh_coupling.h).
//
// At a position and torque, the slices' transverse forces F_k load both shafts along the line
// of action at their pitch points; the shafts' deflection gives the approach of the flanks
// delta_k = sum_j A_kj F_j at each slice (A: the influence coefficients of the shafts, bearings
// and housing, one factorisation and one load case per slice); its mismatch over the face,
//   g_k = max_j delta_j - delta_k  (>= 0, zero where the flanks are pushed together most),
// is a gap offset of the slices (LeadModification::profile, added to the lead modifications of
// the input), which moves the load. The fixed point F = F(g(F)) is found by Aitken-relaxed
// iteration on g until it moves by at most `tolerance`; the iterations and the last change
// are reported. The uniform part of delta (the shafts' give-way that turns the whole mesh) is
// reported apart and not added to the STE.
//
// The lead correction: the helix-slope and crowning correction that cancels the mismatch of
// the converged solution at a design torque (a least-squares quadratic over the face, averaged
// over the positions), as a lead profile; correction() gives it, and the coupled solve with it
// verifies the load distribution.
#include "helical/slicing.h"
#include "shafts/mesh_coupling.h"
#include "shafts/shaft.h"

#include <Eigen/Dense>

#include <vector>

namespace gearfem::system_deflection
{
  struct CoupledOptions
  {
    double tolerance = 1e-9; ///< largest change of the mismatch at the fixed point [m]
    int max_iterations = 50;
  };

  struct CoupledResult
  {
    helical::HelicalResult helical;  ///< the slices at the converged mismatch
    std::vector<double> z;           ///< slice centres [m], -b/2 .. b/2
    std::vector<double> approach;    ///< delta_k [m] (> 0: flanks pushed together)
    std::vector<double> mismatch;    ///< g_k [m], the gap offset the shafts add
    double mean_approach = 0;        ///< mean of delta over the face [m]
    /// The gear's axis relative to the pinion's at each slice [m] (shafts::mesh_axes_offset):
    /// along e (centre distance change) and along t (out of the plane of the axes).
    std::vector<double> axes_e, axes_t;
    int iterations = 0;
    double residual = 0;             ///< last change of g [m]
  };

  /// The lead correction [m] as slope and crowning along the face: c(z) = slope (z/b + 1/2) +
  /// crowning ((2z/b)^2 - 1) + offset, shifted to be >= 0 (the material a grinder removes).
  struct LeadCorrection
  {
    double slope = 0;    ///< f_Hbeta-like: the change over the face, > 0 removes material at +b/2
    double crowning = 0; ///< the parabola's rise from the middle to the ends (< 0: hollow)
    /// The correction at z [m] (z in [-b/2, b/2]), >= 0 over the face.
    double at(double z, double b) const;
  };

  /// One mesh of a train on the system's shafts: its sliced pair (which must outlive the train)
  /// and its layout (mesh.face_width the pair's).
  struct TrainMesh
  {
    const helical::SlicedPair *pair = nullptr;
    shafts::MeshLayout mesh;
  };

  /// Several meshes on one shafts::System (a gear train; one mesh is the pair of CoupledPair):
  /// the slices of every mesh load the shafts, and every mesh's mismatch comes from all of
  /// them (the influence coefficients over all slices, one factorisation). The fixed point is
  /// found on all meshes' mismatches together.
  class CoupledTrain
  {
  public:
    /// InputError for a mesh layout that does not fit the system or its pair.
    CoupledTrain(std::vector<TrainMesh> meshes, shafts::System system, CoupledOptions options = CoupledOptions());

    /// The coupled solution of every mesh at its roll angle phi1[m] and pinion torque[m] [N m]
    /// with its lead modification; `start`: each mesh's mismatch to start from (empty: none).
    /// The iterations and residual are the train's, in every result. SolverError when the fixed
    /// point does not settle.
    std::vector<CoupledResult> solve(const std::vector<double> &phi1, const std::vector<double> &torque,
                                     const std::vector<helical::LeadModification> &lead,
                                     const std::vector<std::vector<double>> &start = {}) const;

    /// The shafts' full solution (deflection lines, bearing reactions) under the meshes' results.
    shafts::Solution shafts_under(const std::vector<CoupledResult> &r) const;

    std::size_t size() const { return meshes_.size(); }
    const TrainMesh &mesh(std::size_t m) const { return meshes_[m]; }
    /// Slice centres of mesh m [m], -b/2 .. b/2.
    const std::vector<double> &slice_centres(std::size_t m) const { return z_[m]; }
    /// Influence coefficients A [m/N] of all slices' forces on their approach (mesh-major).
    const Eigen::MatrixXd &influence() const { return A_; }
    const shafts::System &system() const { return system_; }

  private:
    std::vector<shafts::PointLoad> loads(const std::vector<std::vector<double>> &force) const;
    std::vector<TrainMesh> meshes_;
    shafts::System system_;
    CoupledOptions options_;
    std::vector<std::vector<double>> z_, dz_;
    std::vector<int> first_; ///< first row of each mesh in A_
    Eigen::MatrixXd A_;
    Eigen::MatrixXd Ae_, At_; ///< influence on the axes' offset along e and t [m/N]
  };

  /// One pair on its two shafts: the train of one mesh, with the lead correction.
  class CoupledPair
  {
  public:
    /// `pair`'s slices on `system` through `mesh` (mesh.face_width must be the pair's). The pair
    /// must outlive this object. InputError for a mesh layout that does not fit the system or
    /// the pair.
    CoupledPair(const helical::SlicedPair &pair, shafts::System system, shafts::MeshLayout mesh,
                CoupledOptions options = CoupledOptions());

    /// The coupled solution at roll angle phi1 and torque T1 [N m] with the lead modification
    /// `lead` (the input's, plus a correction). `start`: a mismatch to start from (the previous
    /// position's; empty: none). SolverError when the fixed point does not settle.
    CoupledResult solve(double phi1, double torque, const helical::LeadModification &lead,
                        const std::vector<double> &start = {}) const;

    /// The shafts' full solution (deflection lines, bearing reactions) under a coupled result.
    shafts::Solution shafts_under(const CoupledResult &r) const { return train_.shafts_under({r}); }

    /// The correction that cancels the mean mismatch of `results` (one torque, the positions of
    /// a cycle), fitted by slope and crowning (least squares over the slice centres).
    LeadCorrection correction(const std::vector<CoupledResult> &results) const;

    /// `lead` with `c` added as a profile at the slice centres.
    helical::LeadModification corrected(helical::LeadModification lead, const LeadCorrection &c) const;

    /// Influence coefficients A [m/N] of the slices' forces on their approach.
    const Eigen::MatrixXd &influence() const { return train_.influence(); }
    const shafts::System &system() const { return train_.system(); }
    const shafts::MeshLayout &mesh() const { return train_.mesh(0).mesh; }

  private:
    CoupledTrain train_;
  };

  /// The lead correction c fitted to a mean mismatch g at slice centres z over a face b:
  /// slope and crowning of the least-squares quadratic.
  LeadCorrection fit_correction(const std::vector<double> &z, const std::vector<double> &g, double b);
  /// `lead` with `extra` [m] added to its profile at the slice centres z.
  helical::LeadModification with_profile(helical::LeadModification lead, const std::vector<double> &z,
                                         const std::vector<double> &extra, double b);

  /// A lead correction designed at one torque over positions of the cycle.
  struct DesignedCorrection
  {
    LeadCorrection correction;
    std::vector<CoupledResult> results; ///< the coupled solutions with the correction, per position
    int iterations = 0;                 ///< corrections tried
    double change = 0;                  ///< the last change of slope or crowning [m]
  };

  /// The lead correction that makes the load uniform at `torque` over the positions `phi1`:
  /// the correction cancels the shafts' mismatch under the load it leaves, which depends on the
  /// correction, so it is repeated until slope and crowning move by at most `tolerance` [m]
  /// (SolverError after 20).
  DesignedCorrection design_correction(const CoupledPair &pair, const std::vector<double> &phi1, double torque,
                                       const helical::LeadModification &lead, double tolerance = 1e-9);
} // namespace gearfem::system_deflection
