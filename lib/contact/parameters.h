#pragma once
// ParameterHandler binding of the `Contact` and `Solve` sections (engineering units at the
// interface: mm, deg, N m, urad; SI in the structs).
#include "contact/gear_contact.h"
#include "contact/two_body.h"
#include "fem/elastic_body.h"
#include "geometry/pair.h"
#include "mesh/gear_mesh.h"

#include <memory>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::contact
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
  };

  /// Everything `gearfem solve` reads, parsed and checked.
  struct GearContactInput
  {
    std::unique_ptr<geometry::GearPair> pair;
    /// `Contact/Micro-geometry = gap` with a tip relief: the gears without relief, which are
    /// meshed (null otherwise: `pair` is meshed).
    std::unique_ptr<geometry::GearPair> unmodified_pair;
    mesh::GearMeshParameters mesh[2];
    fem::Elasticity material[2];
    fem::FeOptions fe;
    ContactOptions contact;
    SolveParameters solve;
    /// The positions of the `Solve` section: (name, roll angle [rad]).
    std::vector<std::pair<std::string, double>> positions() const;
    std::unique_ptr<GearContactModel> model() const;
  };
  /// Declare Rack, Gear 1/2, Pair, Material, Mesh, Finite elements, Contact and Solve.
  void declare_gear_contact_input(dealii::ParameterHandler &prm);
  GearContactInput parse_gear_contact_input(dealii::ParameterHandler &prm);

  void declare_contact_parameters(dealii::ParameterHandler &prm);
  /// Read and validate `Contact` (InputError). `E1`, `E2` resolve `Slave body = auto` (the
  /// softer body; the pinion when equal).
  ContactOptions parse_contact_parameters(dealii::ParameterHandler &prm, double E1, double E2);
  void declare_solve_parameters(dealii::ParameterHandler &prm);
  SolveParameters parse_solve_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::contact
