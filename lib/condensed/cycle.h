#pragma once
// The condensed mesh cycle: the FE contact problem of every position of a cycle, solved once
// at a build torque and condensed to the contact unknowns (contact/condensed.h), with the
// root-stress influence coefficients of each body. A later run re-solves any torque and any
// gap-route micro-geometry on it without meshing, factorising or searching: about a
// millisecond per position (condensed/resolve.h). The file layout is in
// docs/output-format.md ("condensed.h5"). SI units.
#include "contact/condensed.h"
#include "contact/gear_contact.h"
#include "solve/input.h"

#include <Eigen/Dense>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace gearfem::condensed
{
  inline constexpr const char *file_format         = "gearfem-condensed-cycle";
  inline constexpr const char *file_format_version = "1";
  inline constexpr const char *file_name           = "condensed.h5";

  /// The drive (tension-side) fillet of one fine tooth: the samples of
  /// fem::ElasticBody::boundary_stress, whose peak sigma_1 is the root stress of post.
  struct FilletSamples
  {
    int tooth = 0;              ///< tooth index in [0, z)
    int first_row = 0;          ///< first row of the body's stress influence (3 per sample)
    std::vector<double> x, y;   ///< sample points, body frame [m]
    std::vector<double> arc;    ///< arc length along the fillet [m]
    std::size_t size() const { return x.size(); }
  };

  /// One body of the cycle: what a re-solve needs besides the positions.
  struct CycleBody
  {
    int teeth = 0;
    /// Universe DoFs (contact/two_body.h): support point [m] and component (0 x, 1 y), for
    /// the moments of the nodal forces.
    std::vector<double> x, y;
    std::vector<int> component;
    /// Fillet stress per unit force at the universe DoFs [Pa/N]: rows 3 i + (xx, yy, xy) of
    /// the fillet samples, only the columns `stress_columns` (those the cycle loads).
    Eigen::MatrixXd stress;
    std::vector<int> stress_columns;
    std::vector<FilletSamples> fillets;
  };

  struct CondensedCycle
  {
    std::string key;        ///< condensed_key of the input it was built from
    std::string geometry_hash, input_name, method;
    /// The .prm text of the input it was built from (attribute `input_text`; empty where the
    /// file does not carry it): what a later re-solve varies (the Python module's load_cycle).
    std::string input_text;
    double build_torque = 0; ///< [N m]
    /// Pinion torques [N m] a re-solve may take: the scenes of this range are stored.
    double torque_lo = 0, torque_hi = 0;
    std::vector<std::pair<std::string, double>> positions; ///< (name, phi1 [rad])
    /// Per position, one condensed configuration per scene of [torque_lo, torque_hi]
    /// (CondensedPosition::load_lo .. load_hi, ascending): the full solver makes the owner of
    /// a tip corner within reach of the Hertz patch the slave of that tooth pair, so which
    /// body is the slave can change with the load. Each scene is solved and condensed at the
    /// build torque clamped into its range.
    std::vector<std::vector<contact::CondensedPosition>> cycle;
    /// The configuration of position k at pinion torque T [N m]; SolverError outside
    /// [torque_lo, torque_hi].
    const contact::CondensedPosition &at(std::size_t k, double torque) const;
    CycleBody body[2];
    /// Set-up and build wall times [s] (mesh + assemble + factorise, then the sweep).
    double setup_seconds = 0, build_seconds = 0;
    int dofs = 0;
    /// Read for a torque window only (read_cycle's `torques`): the scenes outside it are not
    /// in `cycle`, [torque_lo, torque_hi] is narrowed to the window, and write_cycle refuses it.
    bool partial = false;
  };

  /// The key of the FE model behind a condensed cycle: solve::model_key of the input's
  /// meshed (unmodified) geometry with micro-geometry on the gap route, so that a variant
  /// that differs in torques, positions, outputs or tip relief has the same key.
  std::string condensed_key(const solve::GearContactInput &in);

  /// Refuses (InputError naming the entry) an input the condensed route cannot serve: a tip
  /// relief meshed as geometry (`Contact/Micro-geometry = geometry`), and friction (the
  /// stored operator is the frictionless one).
  void check_condensable(const solve::GearContactInput &in);

  /// What a condensed cycle is for: it decides the torque range the cycle stores around the
  /// torques it serves (cycle_range).
  enum class CycleUse
  {
    /// Re-solved only at the torques it serves (Solve/Target's torque sweeps, a batch's designs,
    /// the tip-relief optimiser, the condensed benchmark): built at their geometric middle,
    /// which halves the largest load ratio to the build, for exactly their range.
    given_torques,
    /// Kept for variants of the design (`gearfem condense`, the hunting cycle, the Monte Carlo
    /// study): deviations and reliefs move a tooth pair's load away from the nominal one, so
    /// the range is widened to a quarter of the smallest and twice the largest torque; built at
    /// the largest, where the rating loads are.
    variants,
    /// The transverse section of a helical pair (helical/run.h): crowning, misalignment and end
    /// relief load a slice up to about twice and down to half of its even share, so the range of
    /// `variants` is widened by two again (an eighth of the smallest, four times the largest
    /// torque); built at the largest.
    slices
  };

  /// A cycle's build torque and stored torque range [N m] (0 < lo <= build <= hi).
  struct CycleRange
  {
    double build = 0, lo = 0, hi = 0;
  };

  /// The one torque-range rule of a condensed cycle: for `torques` (> 0, not empty) served for
  /// `use` (CycleUse says each use's build torque and margin). `build` > 0 replaces the rule's
  /// build torque (`Condense/Build torque`); the range then holds it. InputError naming
  /// Solve/Torques for no torques.
  CycleRange cycle_range(const std::vector<double> &torques, CycleUse use, double build = 0);

  /// The one scene-split rule of a condensed cycle (CycleOptions::scene_ratio) for `use`:
  /// `requested` >= 0 (`Condense/Scene torque ratio` set) is taken as it is; < 0 (`auto`) gives
  /// 4 (no re-solve more than a factor 2 from its build) for every use but `slices`, and no
  /// split (one build per slave configuration) for the transverse section of helical slices.
  /// There the build is at the largest served torque and the slices re-solve it from an eighth
  /// to 4 times that: on the Parker section (validation/helical) the slice results move by at
  /// most 2e-4 against the split cycle, far below the slicing's own error (about 1 % between 21
  /// and 51 slices), for a third of the build (one solve and one condensation per position).
  double scene_ratio(CycleUse use, double requested);

  struct CycleOptions
  {
    /// Largest torque ratio one scene spans (`Condense/Scene torque ratio`); 0: no split.
    double scene_ratio = 4.0;
    std::ostream *out = nullptr; ///< progress with i/N and ETA; null: silent
    /// Candidate band (0: every candidate within Contact/Search distance). For a cycle re-solved
    /// at its own torques only (CycleUse::given_torques with the modifications of its input,
    /// e.g. Solve/Target's torque sweeps): each scene keeps the candidates whose gap at its
    /// build is within band_factor times the approach (STE) at the top of its load range,
    /// extrapolated linearly from its build, and at least a twentieth of the search distance.
    /// The re-solve's edge check (half the band) refuses any load beyond it.
    double band_factor = 0;
  };

  /// The condensed cycle of `in` on `model` (built from `in`): the FE run over the positions of
  /// `in` at range.build and every position condensed, for re-solves from range.lo to range.hi.
  /// Throws SolverError when a position does not converge; InputError (naming the entry) for
  /// an input the condensed route cannot serve (check_condensable) or a bad range.
  ///
  /// The condensation is exact at the load it was solved at; away from it the geometry of
  /// the candidates (their projections, the tip-corner rounding) is carried by the gap's
  /// curvature in q only, and the error grows with the load ratio (FZG type C, reference
  /// mesh: 0.8 % STE at a third of the build torque near a transition). Every scene that
  /// spans more than options.scene_ratio (> 1) is therefore split at
  /// build * ratio^(j + 1/2), each part solved at the build torque if it holds it,
  /// else at its geometric middle, so that a re-solve is never more than sqrt(ratio) from
  /// the load its scene was solved at.
  CondensedCycle cycle_for(contact::GearContactModel &model, const solve::GearContactInput &in,
                           const CycleRange &range, const CycleOptions &options = {});

  /// The same on given positions (name, roll angle [rad]) of `model`, without an input: the
  /// cycle's key, geometry hash and method are left empty (for a caller that owns the model,
  /// e.g. the tip-relief optimiser).
  CondensedCycle cycle_for(contact::GearContactModel &model,
                           const std::vector<std::pair<std::string, double>> &positions, const CycleRange &range,
                           const CycleOptions &options = {});

  /// Write `c` to `file` atomically (docs/output-format.md).
  void write_cycle(const CondensedCycle &c, const std::filesystem::path &file);
  /// Read a condensed cycle. InputError naming the file and item for a missing, foreign,
  /// corrupt or newer file.
  CondensedCycle read_cycle(const std::filesystem::path &file);
  /// Read only what a run at `torques` [N m] (not empty) needs: per position, the scenes whose
  /// load range meets [min, max] of them (a re-solve at one torque reads one scene of each
  /// position; the demo's file of three scenes reads a third). The cycle's range is narrowed to
  /// that window, so a torque outside it is refused as outside the stored range; torques outside
  /// the file's own range are left for the run to refuse (CondensedCycle::at).
  CondensedCycle read_cycle(const std::filesystem::path &file, const std::vector<double> &torques);
} // namespace gearfem::condensed
