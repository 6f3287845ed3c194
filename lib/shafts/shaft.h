#pragma once
// Shafts and bearings as a static system (light layer: Eigen only, no deal.II).
//
// A shaft is a chain of stepped segments along its own axis z, each a hollow or solid circular
// section, discretised by two-node Timoshenko beam elements: per node the displacements
// (u_x, u_y, u_z) and rotations (theta_x, theta_y, theta_z), bending in the x-z and y-z planes
// with shear deformation (Cowper's shear coefficient of a circular tube), axial extension and
// St Venant torsion. The element's shape functions are those of the exact solution of a
// prismatic Timoshenko beam under end loads (Przemieniecki, Theory of matrix structural
// analysis, 1968, sec. 5.6: the shear parameter phi = 12 E I / (kappa G A L^2)), so that nodal
// loads on a stepped shaft give the exact beam solution at every node.
//
// Shafts sit in the system frame: shaft s's axis is the line (x_s, y_s) parallel to the system z,
// starting at z0_s (parallel shafts, as in a parallel-axis gearbox). Bearings join a shaft node
// to the rigid housing (or to a housing stiffness at the seat) by linear springs: radial (x and
// y), axial and tilting (about x and y); a spring of infinite stiffness is a rigid support
// (the degree of freedom is constrained, not penalised). Couplings join two shaft nodes.
// Units SI: m, N, N m, rad, Pa.
#include <Eigen/Dense>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace gearfem::shafts
{
  constexpr double rigid = std::numeric_limits<double>::infinity();

  /// One stepped segment: its length and its section (inner diameter 0: solid).
  struct Segment
  {
    double length = 0, outer_diameter = 0, inner_diameter = 0; ///< [m]
  };

  struct ShaftMaterial
  {
    double youngs_modulus = 206e9; ///< [Pa]
    double poisson_ratio  = 0.3;
  };

  /// Section properties of a circular tube [m^2, m^4]: area, second moment about a diameter,
  /// polar moment, and Cowper's shear coefficient (J. Appl. Mech. 33, 1966, table 1, hollow
  /// circle: 6 (1 + nu)(1 + m^2)^2 / ((7 + 6 nu)(1 + m^2)^2 + (20 + 12 nu) m^2), m = d_i / d_o).
  struct Section
  {
    double area = 0, second_moment = 0, polar_moment = 0, shear_coefficient = 0;
  };
  Section section(const Segment &s, double poisson_ratio);

  struct Shaft
  {
    std::string name;
    double x = 0, y = 0, z0 = 0; ///< axis position in the system frame and start [m]
    std::vector<Segment> segments;
    ShaftMaterial material;
    /// Extra node positions along the shaft [m from its start] (gears, bearings, loads);
    /// segment ends are always nodes. Each element is further split so that none is longer
    /// than max_element (0: no split).
    std::vector<double> stations;
    double max_element = 0;
    /// InputError naming the shaft for an empty or non-positive segment, an inner diameter
    /// not below the outer, or a station outside the shaft.
    void validate() const;
    double length() const;
  };

  /// The six degrees of freedom of a node, in this order.
  enum Dof
  {
    ux = 0, uy, uz, rx, ry, rz
  };

  /// A linear bearing between a shaft node (at axial position z [m from the shaft's start]) and
  /// the housing: springs [N/m, N m/rad], `rigid` constrains the DoF, 0 leaves it free.
  struct Bearing
  {
    std::string name;
    int shaft = 0;
    double z = 0;
    double radial = rigid, axial = 0, tilting = 0, torsional = 0;
    /// The housing at the seat as a 6x6 stiffness in series with the bearing's springs [SI];
    /// empty (the default): a rigid housing. Only finite springs may sit on a housing stiffness.
    Eigen::MatrixXd housing;
  };

  /// A coupling between two in-line shafts at one point (node z_a of shaft_a and z_b of shaft_b
  /// coincide in the system frame): springs per DoF (x, y, z, theta_x, theta_y, theta_z), finite.
  struct Coupling
  {
    int shaft_a = 0, shaft_b = 0;
    double z_a = 0, z_b = 0;
    std::array<double, 6> stiffness{};
  };

  /// A force and moment at an axial position of a shaft, in the system frame [N, N m]; placed
  /// on the shaft's node there (a station).
  struct PointLoad
  {
    int shaft = 0;
    double z = 0;
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  };

  struct System
  {
    std::vector<Shaft> shafts;
    std::vector<Bearing> bearings;
    std::vector<Coupling> couplings;
  };

  /// One node of the solution.
  struct NodeResult
  {
    int shaft = 0;
    double z = 0;                                  ///< from the shaft's start [m]
    Eigen::Matrix<double, 6, 1> u = decltype(u)::Zero(); ///< displacements [m], rotations [rad]
  };

  struct BearingReaction
  {
    std::string name;
    /// Force and moment the bearing exerts on the shaft [N, N m] (system frame, at its node).
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  };

  struct Solution
  {
    std::vector<NodeResult> nodes; ///< every node of every shaft, by shaft then z
    std::vector<BearingReaction> reactions;
    /// The node of shaft s at z (a station), or throws InputError.
    const NodeResult &at(int shaft, double z) const;
    /// Displacements and rotations of shaft s at z anywhere along it: the element's own
    /// Timoshenko interpolation between its nodes (exact for the bending line under nodal
    /// loads on a prismatic element).
    Eigen::Matrix<double, 6, 1> along(const System &system, int shaft, double z) const;
  };

  /// The static solution of `system` under `loads`. InputError (naming the part) for a bad shaft,
  /// a bearing or load off its shaft, or a system that is not supported (a singular stiffness:
  /// a rigid-body motion left free, e.g. an unrestrained torsion).
  Solution solve(const System &system, const std::vector<PointLoad> &loads);
  /// The same for several load cases on one factorisation (influence coefficients): the
  /// nodes of every case's loads are nodes of all of them.
  std::vector<Solution> solve_cases(const System &system, const std::vector<std::vector<PointLoad>> &cases);

  /// The 12x12 stiffness of one Timoshenko element of length L along z (node DoFs as Dof, node
  /// a then node b) [SI].
  Eigen::Matrix<double, 12, 12> element_stiffness(double L, const Section &s, const ShaftMaterial &m);
} // namespace gearfem::shafts
