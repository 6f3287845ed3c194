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
  };

  /// The key of the FE model behind a condensed cycle: solve::model_key of the input's
  /// meshed (unmodified) geometry with micro-geometry on the gap route, so that a variant
  /// that differs in torques, positions, outputs or tip relief has the same key.
  std::string condensed_key(const solve::GearContactInput &in);

  /// Refuses (InputError naming the entry) an input the condensed route cannot serve: a tip
  /// relief meshed as geometry (`Contact/Micro-geometry = geometry`), and friction (the
  /// stored operator is the frictionless one).
  void check_condensable(const solve::GearContactInput &in);

  /// Run the FE over the positions of `in` at `build_torque` [N m] (> 0) on `model` (built
  /// from `in`) and condense every position, for re-solves between `torque_lo` and
  /// `torque_hi` [N m] (0 < lo <= build <= hi). Progress with i/N and ETA on `out` (may be
  /// null). Throws SolverError when a position does not converge.
  ///
  /// The condensation is exact at the load it was solved at; away from it the geometry of
  /// the candidates (their projections, the tip-corner rounding) is carried by the gap's
  /// curvature in q only, and the error grows with the load ratio (FZG type C, reference
  /// mesh: 0.8 % STE at a third of the build torque near a transition). Every scene that
  /// spans more than `scene_ratio` (> 1; default_scene_ratio) is therefore split at
  /// build_torque * ratio^(j + 1/2), each part solved at the build torque if it holds it,
  /// else at its geometric middle, so that a re-solve is never more than sqrt(ratio) from
  /// the load its scene was solved at. 0: no split (one load per slave configuration).
  CondensedCycle build_cycle(contact::GearContactModel &model, const solve::GearContactInput &in,
                             double build_torque, double torque_lo, double torque_hi, std::ostream *out = nullptr,
                             double scene_ratio = 4.0);

  /// The same on given positions (name, roll angle [rad]) of `model`, without an input: the
  /// cycle's key, geometry hash and method are left empty (for a caller that owns the model,
  /// e.g. the tip-relief optimiser).
  CondensedCycle build_cycle(contact::GearContactModel &model, const std::vector<std::pair<std::string, double>> &positions,
                             double build_torque, double torque_lo, double torque_hi, std::ostream *out = nullptr,
                             double scene_ratio = 4.0);

  /// Write `c` to `file` atomically (docs/output-format.md).
  void write_cycle(const CondensedCycle &c, const std::filesystem::path &file);
  /// Read a condensed cycle. InputError naming the file and item for a missing, foreign,
  /// corrupt or newer file.
  CondensedCycle read_cycle(const std::filesystem::path &file);
} // namespace gearfem::condensed
