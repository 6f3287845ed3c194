#pragma once
// The condensed contact problem of one configuration: what TwoBodyContact::condense keeps of
// a converged solve so that the same configuration can be re-solved at another load or
// with another gap modification without the bodies, the search or a factorisation.
//
// On the stored candidate slave nodes k (all those within the search distance at the
// converged state of the build solve) the gap is
//   g_k(q, lambda) = ghat_k + o_k + a_k q + c_k (q - q_b)^2 / 2 + (W lambda)_k,
// with W the exact Delassus operator (Schur complement of the two factorised bodies on the
// contact unknowns, contact/two_body.h), a the arm dg/dq and ghat the gap of the unmodified
// geometry, all linearised at the build state (q_b, u_b); c_k = d^2 g_k / dq^2 at fixed
// elastic state (central difference of the exact rigid placement, so that a rotation far from
// q_b keeps the curvature of the flanks), and o_k the normal gap modification of the variant
// at the candidate's own sample points (ModificationSample: where and with which weight the
// full solver adds a body's modification to that gap). What is not kept: the slide of the
// master projection with the load (second order in the elastic displacement; measured in
// validation/condensed) and candidates outside the stored set (a re-solve whose contact reaches
// the edge of the stored set fails with SolverError, CondensedPosition::edge).
#include "contact/ncp.h"
#include "contact/two_body.h"

#include <Eigen/Dense>

#include <functional>
#include <string>

#include <utility>
#include <vector>

namespace gearfem::contact
{
  /// Where the gap modification of a body enters a candidate's gap: o_k = sum over its
  /// samples of weight * f_body(x) (f: material removed [m] at body-frame point x).
  struct ModificationSample
  {
    int body = 1;
    Vec2 x = Vec2::Zero(); ///< body frame [m]
    double weight = 0;     ///< [-], the samples of a candidate sum to 2 (slave + master side)
  };

  /// One stored candidate: the ContactPoint data of the build state (pair frame at q_b) and
  /// whether it borders slave nodes that were not stored.
  struct CondensedCandidate
  {
    ContactPoint point; ///< force, gap and pressure of the build solve
    /// A slave neighbour of this node along the surface was not a candidate (it lay farther
    /// than the search distance from the mating body at the build state): if this node
    /// approaches the mating body by half the search distance more than at the build, that
    /// neighbour may come into contact, and the stored set no longer covers the contact.
    bool edge = false;
    /// The gap is smooth in q: the central difference of the curvature agrees with the arm
    /// (the slope changes by less than 10 % over the difference step). Not smooth (the
    /// closest point jumps between pieces, at a corner or far from contact): its curvature is
    /// stored as 0, and a re-solve at another load in which it carries load fails.
    bool smooth = true;
  };

  struct CondensedPosition
  {
    double q_build = 0;      ///< drive coordinate of the build solve [rad or m]
    double load_build = 0;   ///< its generalised force [N m or N]
    /// The loads [N m or N] over which this configuration's scene (which body is the slave
    /// of each tooth pair, contact/gear_contact.h) is the one the full solver takes.
    double load_lo = 0, load_hi = 0;
    double search_distance = 0; ///< ContactOptions::search_distance of the build [m]
    geometry::Placement placement[2]; ///< rigid placements at q = 0 (Scene::placement)
    std::vector<CondensedCandidate> cand;
    Eigen::MatrixXd W;       ///< Delassus operator [m/N], symmetric
    Eigen::VectorXd a;       ///< arm at q_b [m/rad]
    Eigen::VectorXd ghat;    ///< gap of the unmodified geometry at q = 0, lambda = 0 [m]
    Eigen::VectorXd curvature; ///< d^2 g / dq^2 [m/rad^2]
    Eigen::VectorXd D;       ///< penalty compliance [m/N] (0: Lagrange)
    std::vector<std::vector<ModificationSample>> modification; ///< per candidate
    /// Per body, per candidate: the nodal force directions (index into the body's universe,
    /// TwoBodyContact::universe, and value): f_b = sum_k B_b[k] lambda_k [N].
    std::vector<std::vector<std::pair<int, double>>> B[2];
    /// Per candidate k: (candidate j, coefficient [1/m^2]): recovered pressure
    /// p_k = sum_j coefficient lambda_j [Pa] (ContactSurface::recover_pressure, which is linear).
    std::vector<std::vector<std::pair<int, double>>> pressure;
    std::size_t size() const { return cand.size(); }
  };

  /// The solution of a condensed re-solve: the contact points (pair frame at the solved q),
  /// and the nodal forces on each body's universe.
  struct CondensedSolution
  {
    ContactSolution solution;          ///< forces[] empty: see universe_forces
    std::vector<std::pair<int, double>> universe_forces[2]; ///< (universe index, value) [N]
  };

  /// Move stored point `p` (pair frame at the build state) with body 1 turned by dq [rad] about
  /// its centre o1: the slave node when body 1 carries it, else the master point and normal.
  void turn_body1(ContactPoint &p, const Vec2 &o1, double dq);

  /// The curvature Newton of a condensed re-solve, shared by the 2-D position and the coupled
  /// helical slices (helical/slicing.h): candidate k's rigid gap at drive rotation q is
  /// ghat_k + a_k (q + s_k) + curvature_k (q + s_k - q_k)^2 / 2 (q_k its build rotation, s_k
  /// its drive advance; `advance` empty: none), linearised about the current q, and the
  /// complementarity problem `step(arm, linearised ghat, q, lambda0)` solved at each update
  /// until the active set repeats and q moves by at most `tolerance` relative (one update
  /// with `fixed_q`, rotation control). `what` prefixes the SolverError of a failed step or of
  /// a rotation that does not settle in 30 updates.
  struct CurvatureNewton
  {
    NcpResult ncp;       ///< the last complementarity solve
    Eigen::VectorXd arm; ///< its arms
    double q = 0;        ///< the settled rotation
    int iterations = 0;  ///< active-set iterations of all updates
  };
  CurvatureNewton curvature_newton(
    const Eigen::VectorXd &a, const Eigen::VectorXd &curvature, const Eigen::VectorXd &ghat,
    const Eigen::VectorXd &q_build, const Eigen::VectorXd &advance, double q, Eigen::VectorXd lambda0, bool fixed_q,
    double tolerance, const std::string &what,
    const std::function<NcpResult(const Eigen::VectorXd &, const Eigen::VectorXd &, double, const Eigen::VectorXd &)>
      &step);

  /// Solve position `c` at generalised force `load` (torque control, > 0) with the gap
  /// modifications `offset` (one per candidate, o_k [m]; empty: none). Newton on q over the
  /// curvature term, the complementarity problem of contact/ncp.h at each step; converges
  /// to `tolerance` in q. Throws SolverError when it does not converge, when nothing carries
  /// the load, and when an edge candidate has approached the mating body by more than half
  /// the search distance beyond its build state (the stored candidates may not cover the
  /// contact: rebuild the cycle at this load or with a larger search distance).
  CondensedSolution solve_condensed(const CondensedPosition &c, const Eigen::VectorXd &offset, double load,
                                    double tolerance = 1e-10, int max_active_set_iterations = 60);
  /// The same with an advance s_k [rad] of the drive coordinate per candidate (empty: none):
  /// candidate k's rigid gap is taken at q + s_k, arm and second-order term included. A tooth
  /// turned rigidly about its axis (a pitch deviation, a flank offset of an involute) is such an
  /// advance of the candidates of its tooth pair, exactly.
  CondensedSolution solve_condensed(const CondensedPosition &c, const Eigen::VectorXd &offset,
                                    const Eigen::VectorXd &advance, double load, double tolerance = 1e-10,
                                    int max_active_set_iterations = 60);
  /// The same under rotation control: the drive coordinate q is given (>= 0); the load is
  /// the result. One complementarity solve (the curvature term is exact at a given q).
  CondensedSolution solve_condensed_rotation(const CondensedPosition &c, const Eigen::VectorXd &offset, double q,
                                             int max_active_set_iterations = 60);
} // namespace gearfem::contact
