#pragma once
// The options of the two-body contact solver (the `Contact` section in SI): method, penalty
// factor, search distance, tolerances and iteration caps, slave selection, gap rule and the
// micro-geometry route. Read by contact/parameters.h, used by TwoBodyContact and the gear
// pair model.
#include <string>

namespace gearfem::contact
{
  enum class Method
  {
    penalty,
    lagrange
  };
  Method method_from_string(const std::string &s); ///< "penalty" | "lagrange", else InputError
  const char *to_string(Method m);

  /// How the gap of a slave node is measured.
  enum class GapRule
  {
    /// Node-to-segment: the gap at the slave node itself (collocation).
    node,
    /// Segment-to-segment (mortar-type): the gap weighted over the slave faces around the
    /// node, g_j = int phi_j g ds / int phi_j ds, with phi_j the piecewise-linear hat of the
    /// node on the polyline of face nodes (positive weights: the quadratic shape functions
    /// have negative lobes that bias vertex and mid-side gaps apart), Gauss points projected
    /// onto the exact master. Slave kinks (a sharp tip corner) and nodes whose faces reach a master corner
    /// keep the nodal gap: a corner is a point contact.
    integrated
  };
  GapRule gap_rule_from_string(const std::string &s); ///< "node" | "integrated", else InputError
  const char *to_string(GapRule g);

  struct ContactOptions
  {
    Method method = Method::lagrange;
    /// Penalty stiffness factor kappa: pressure = kappa E / h (-g), E the smaller Young's
    /// modulus, h the local slave face length. > 0.
    double penalty_factor = 100.0;
    /// Slave nodes farther than this from the master (either side) are not candidates [m].
    double search_distance = 0.3e-3;
    /// Each geometry iteration solves only the nodes whose gap is within a band above the
    /// smallest (TwoBodyContact::candidate_band) and those that carry or share a face with a
    /// force; false: every node within the search distance. The converged solution is the
    /// same either way; not a Contact entry.
    bool candidate_band = true;
    /// Relative tolerance of the drive coordinate, forces and torque.
    double tolerance = 1e-9;
    int max_active_set_iterations = 60;
    int max_geometry_iterations   = 25;
    /// Load-step cuts (halvings) tried after a non-converged solve.
    int max_load_cuts = 4;
    /// Body that carries the slave nodes (1 or 2); the other is the master. With
    /// `per_zone_slaves` (GearContactModel), only where no tip corner is within reach.
    int slave = 1;
    /// GearContactModel: the owner of a tip corner within reach of a tooth pair's contact
    /// is the slave of that pair (so that a corner is always a node checked against a
    /// smooth master flank); `slave` elsewhere. false: every node of `slave` (single pass).
    bool per_zone_slaves = true;
    /// Nodal or integrated (segment-to-segment) gaps.
    GapRule gap = GapRule::integrated;
    /// GearContactModel: profile modifications (tip relief) meshed as geometry (false), or
    /// applied as an initial normal separation on the unmodified mesh (true; designs that
    /// differ only in micro-geometry then share one mesh and factorisation).
    bool micro_geometry_as_gap = false;
    /// Coulomb friction coefficient mu in [0, 1] (docs/friction.md). At each contact point the
    /// tangential force is mu lambda against the rigid-body sliding velocity of the slave
    /// relative to the master (TwoBodyContact::set_kinematics); 0: frictionless.
    double friction = 0.0;
    /// Regularisation of the sliding direction: where |v_s| is below this fraction of the
    /// kinematics' reference speed (the pitch-line speed of a gear pair), the tangential
    /// force is mu lambda v_s / v_tol instead of mu lambda sign(v_s). In (0, 0.1].
    double friction_tolerance = 1e-4;
    /// Throws InputError naming the `Contact` entry.
    void validate() const;
  };
} // namespace gearfem::contact
