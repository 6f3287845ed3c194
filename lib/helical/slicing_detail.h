#pragma once
// Internals of helical/slicing.h shared by its translation units (slicing.cc solves,
// slicing_post.cc evaluates). Not part of the module's interface.
#include "helical/slicing.h"

#include <Eigen/Dense>

#include <map>
#include <string>
#include <vector>

namespace gearfem::helical
{
  /// The solution of the coupled complementarity problem on a fixed linearisation.
  struct Pdas
  {
    bool ok = false;
    std::string why;
    Eigen::VectorXd lambda, gap;
    double q = 0, tangent = 0;
    std::vector<char> active;
    int iterations = 0;
  };


  /// A slice, or the part of one, on one stored position.
  struct SlicedPair::Sub
  {
    int slice = 0;
    std::size_t g = 0;   ///< grid position
    long wrap = 0;       ///< pitches of gear 1 between the stored position and this section
    double weight = 0;   ///< width / b
    const contact::CondensedPosition *p = nullptr;
    Eigen::VectorXd offset; ///< relief + lead gap offsets at every stored candidate [m]
    std::vector<int> keep;  ///< stored candidates in the coupled problem
    int first = 0;          ///< index of keep[0] in the coupled problem
  };

  /// The coupled complementarity problem of all sub-slices.
  struct SlicedPair::System
  {
    int m = 0;
    Eigen::MatrixXd W;
    Eigen::VectorXd a, curvature, q_build, ghat, D, lambda0;
    std::vector<int> sub;   ///< sub-slice of each unknown
    std::vector<long> pair; ///< absolute tooth pair key of each unknown
    /// Per tooth pair: the coupling correction over the slices (N x N; empty uncoupled).
    std::map<long, Eigen::MatrixXd> dC;
    std::map<long, Eigen::VectorXd> K; ///< per tooth pair: section stiffness of each slice [N m/rad]
    Pdas solution;
    double q = 0;
    Eigen::VectorXd arm;
    int iterations = 0;
  };

} // namespace gearfem::helical
