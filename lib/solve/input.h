#pragma once
// The input of `gearfem solve` as one checked value: the `Solve` section (positions,
// torques, outputs) and GearContactInput, which gathers the geometry, material, mesh,
// finite-element and contact sections and builds the model. Engineering units at the
// interface (deg, N m), SI in the structs.
#include "analytical/friction.h"
#include "contact/gear_contact.h"
#include "contact/two_body.h"
#include "fem/elastic_body.h"
#include "geometry/pair.h"
#include "geometry/parameters.h"
#include "mesh/gear_mesh.h"
#include "solve/ring_input.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::solve
{
  /// The `Solve` section.
  struct SolveParameters
  {
    enum class Positions
    {
      cycle, ///< N equally spaced positions over `pitches` angular pitches from `start`
      named, ///< the named points of the line of action (A, B, C, D, E)
      list   ///< explicit roll angles
    };
    Positions positions = Positions::cycle;
    int n_positions     = 40;
    double pitches      = 1.0;
    /// Start of the cycle [rad]; NaN-free: `start_at_A` takes phi_A.
    double start       = 0.0;
    bool start_at_A    = true;
    std::vector<std::string> names = {"A", "B", "C", "D", "E"};
    std::vector<double> roll_angles; ///< [rad]
    std::vector<double> torques = {200.0}; ///< pinion torques [N m], each > 0
    enum class Vtu
    {
      none,
      named, ///< only the named points B, C, D (and every position of a `named` run)
      all
    };
    Vtu vtu = Vtu::named;
    double vtu_scale = 1.0; ///< displacement magnification in the VTU files
    bool plots       = true;
    /// `Error estimate`: after the sweep, estimate the discretisation error of STE, root
    /// stress and p_max at sample positions on a model with the fine mesh sizes halved
    /// (post/error_estimate.h).
    bool error_estimate = false;
    /// `Target`: the accuracy the run asks for (model_choice/target.h parses it; "none": the mesh
    /// as given), and `Cost cap` [s] of the automatic choice (0: none).
    std::string target = "none";
    double cost_cap    = 1800;
    /// `Target route`: auto (the condensed cycle where it pays, model_choice/route.h) or full FE.
    bool target_route_auto = true;
  };

  /// Everything `gearfem solve` reads, parsed and checked.
  struct GearContactInput
  {
    std::unique_ptr<geometry::GearPair> pair;
    /// `Contact/Micro-geometry = gap` with a tip relief: the gears without relief, which are
    /// meshed (null otherwise: `pair` is meshed).
    std::unique_ptr<geometry::GearPair> unmodified_pair;
    /// `Pair/Type = internal`: the pinion and its ring (then `pair` and `unmodified_pair` are
    /// null), the ring's unmodified twin when the pinion's tip relief is a gap, and the
    /// ring's mesh (mesh[1] holds the sizes it was made from).
    std::unique_ptr<geometry::InternalGearPair> internal_pair, unmodified_internal_pair;
    mesh::RingMeshParameters ring_mesh;
    mesh::GearMeshParameters mesh[2];
    fem::Elasticity material[2];
    fem::FeOptions fe;
    contact::ContactOptions contact;
    /// The friction law and its operating inputs (Contact section); contact.friction holds
    /// the coefficient at the first torque.
    analytical::friction::LawInputs friction;
    SolveParameters solve;
    /// The friction coefficient at each pinion torque [N m] (the law at the pitch point).
    std::vector<double> friction_coefficients(const std::vector<double> &torques) const;
    /// The positions of the `Solve` section: (name, roll angle [rad]).
    std::vector<std::pair<std::string, double>> positions() const;
    /// The pinion teeth the `Solve` positions and `extra` roll angles [rad] load (external
    /// pairs: geometry::loaded_teeth; gear tooth -k meshes with pinion tooth k).
    std::vector<int> loaded_teeth(const std::vector<double> &extra = {}) const;
    std::unique_ptr<contact::GearContactModel> model() const;
    /// The pair, external or internal.
    const geometry::MeshingPair &meshing() const;
    /// InputError naming `Pair/Type` when the pair is internal and `what` (a command or an
    /// option) covers external pairs only.
    void require_external(const std::string &what) const;
  };
  /// The key of the FE model an input builds: equal keys mean the same meshed geometry
  /// (the outline of each meshed gear, sampled at 1/50 module, its tooth count, face width
  /// and the centre distance), mesh, material, finite elements and contact options, so that
  /// one factorised model serves both (a batch shares it). Torques, positions, outputs and a
  /// tip relief applied as a gap (`Contact/Micro-geometry = gap`) do not enter it.
  /// `gap_route`: the key as if `Contact/Micro-geometry = gap` (the condensed cycle's key).
  std::string model_key(const GearContactInput &in, bool gap_route = false);

  /// Declare Rack, Gear 1/2, Pair, Material, Mesh, Finite elements, Contact and Solve.
  /// Warnings on an input that runs but may mislead (printed by the commands that solve it):
  /// a contact element size h_contact above the flank height r_SAP - r_Ff between a gear's
  /// start of active profile and its form circle lets the contact field of the tooth entering
  /// contact leak into its fillet, whose root stress is then a mesh artefact
  /// (validation/seed001_root_stress: 3.8 x the converged value at h_contact 0.4 mm on 23/69).
  std::vector<std::string> input_warnings(const GearContactInput &in);

  void declare_gear_contact_input(dealii::ParameterHandler &prm);
  GearContactInput parse_gear_contact_input(dealii::ParameterHandler &prm);
  /// The same with the parsed geometry sections mapped by `section` before the pair is built
  /// (a helical pair's normal section to its transverse section, helical/helix.h).
  GearContactInput parse_gear_contact_input(
    dealii::ParameterHandler &prm,
    const std::function<geometry::GeometryInput(const geometry::GeometryInput &)> &section);
  void declare_solve_parameters(dealii::ParameterHandler &prm);
  SolveParameters parse_solve_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::solve
