#pragma once
// The linear complementarity problem of contact on a fixed linearisation
// g = ghat + a q + W lambda (TwoBodyContact): primal-dual active set for Lagrange
// multipliers (D = 0; Hintermueller, Ito & Kunisch 2002, SIAM J. Optim. 13(3)) and the
// semismooth Newton of the nodal penalty (D = 1/eps), with the drive coordinate q as an
// extra unknown under load control. Dense: the operator lives on the contact nodes only.
#include "contact/two_body.h"

#include <Eigen/Dense>

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
  NcpResult solve_ncp(const Eigen::MatrixXd &W, const Eigen::VectorXd &D, const Eigen::VectorXd &a,
                      const Eigen::VectorXd &ghat, Control control, double value, double q0,
                      const Eigen::VectorXd &lambda0, int max_iterations,
                      const Eigen::VectorXd &af = Eigen::VectorXd());
  /// The same under load control for a symmetric positive definite W (no friction): the
  /// bordered active-set system is solved through the Cholesky factor of the active block
  /// (the Schur complement on q), a fraction of the cost of the general LU on large sets (the
  /// coupled slices of helical/slicing.h). Fails (ok false) where the active block is not
  /// positive definite.
  NcpResult solve_ncp_spd(const Eigen::MatrixXd &W, const Eigen::VectorXd &D, const Eigen::VectorXd &a,
                          const Eigen::VectorXd &ghat, double load, double q0, const Eigen::VectorXd &lambda0,
                          int max_iterations);
} // namespace gearfem::contact
