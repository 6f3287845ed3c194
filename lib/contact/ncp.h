#pragma once
// The linear complementarity problem of contact on a fixed linearisation
// g = ghat + a q + W lambda (TwoBodyContact): primal-dual active set for Lagrange
// multipliers (D = 0; Hintermueller, Ito & Kunisch 2002, SIAM J. Optim. 13(3)) and the
// semismooth Newton of the nodal penalty (D = 1/eps), with the drive coordinate q as an
// extra unknown under load control. Dense: the operator lives on the contact nodes only.
#include "contact/two_body.h"

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

namespace gearfem::contact
{
  /// Result of the complementarity solve on a fixed linearisation.
  struct NcpResult
  {
    bool ok = false;
    std::string why;
    Eigen::VectorXd lambda, gap;
    double q = 0, tangent = 0, complementarity = 0;
    int iterations = 0;
    std::vector<char> active;
  };

  /// min over lambda >= 0 (and q for load control) of the linear complementarity problem
  /// g = ghat + a q + W lambda, lambda >= 0, g + D lambda >= 0, lambda (g + D lambda) = 0,
  /// [-af^T lambda = T]. D = 0: Lagrange (PDAS); D = 1/eps: penalty (semismooth Newton).
  /// `af`: the load arm when it differs from the gap's a (friction; empty: a). W may be
  /// non-symmetric (friction): the active-set systems are solved by LU then.
  /// `fill` (may be null): W is filled on demand. It is called with each active set before
  /// the set's system is formed and must fill W's columns (and rows) of those candidates in
  /// the matrix `W` refers to; only they are read, and the diagonal of the others only for
  /// its sign (an unfilled zero counts as positive: lambda is zero there, so the gap's sign
  /// alone decides whether the candidate enters the active set).
  NcpResult solve_ncp(const Eigen::MatrixXd &W, const Eigen::VectorXd &D, const Eigen::VectorXd &a,
                      const Eigen::VectorXd &ghat, Control control, double value, double q0,
                      const Eigen::VectorXd &lambda0, int max_iterations,
                      const Eigen::VectorXd &af = Eigen::VectorXd(),
                      const std::function<void(const std::vector<int> &)> *fill = nullptr);
  /// A symmetric positive definite contact operator W (with its penalty compliance D on the
  /// diagonal of the active systems) given by what the active-set loop needs of it, so that a
  /// caller with structure (block-diagonal plus low rank: the coupled slices of
  /// helical/slicing.h) solves its active systems without forming W.
  class SpdOperator
  {
  public:
    virtual ~SpdOperator() = default;
    virtual Eigen::Index size() const = 0;
    virtual double diagonal(Eigen::Index k) const = 0;                       ///< W_kk
    virtual Eigen::VectorXd apply(const Eigen::VectorXd &x) const = 0;       ///< W x
    /// Factorise W_AA + D_A of the active set A (ascending); false: not positive definite.
    virtual bool factorise(const std::vector<int> &A) = 0;
    /// (W_AA + D_A)^-1 y of the last factorised set (y in the order of A).
    virtual Eigen::VectorXd solve(const Eigen::VectorXd &y) const = 0;
  };

  /// The linear complementarity problem under load control for a symmetric positive definite
  /// W without friction: the primal-dual active set of solve_ncp with each bordered system
  /// solved through (W_AA + D_A)^-1 (q from the Schur complement); the tangent is that Schur
  /// complement. Fails (ok false) where the active block is not positive definite.
  NcpResult solve_ncp_spd(SpdOperator &W, const Eigen::VectorXd &a, const Eigen::VectorXd &ghat, double load,
                          const Eigen::VectorXd &lambda0, int max_iterations);
  /// The same for a dense W and penalty compliance D (Cholesky of the active block).
  NcpResult solve_ncp_spd(const Eigen::MatrixXd &W, const Eigen::VectorXd &D, const Eigen::VectorXd &a,
                          const Eigen::VectorXd &ghat, double load, const Eigen::VectorXd &lambda0,
                          int max_iterations);
} // namespace gearfem::contact
