#pragma once
// Internals of helical/slicing.h shared by its translation units (slicing.cc solves,
// slicing_post.cc evaluates). Not part of the module's interface.
#include "contact/ncp.h"
#include "helical/slicing.h"

#include <Eigen/Dense>

#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace gearfem::helical
{
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
    /// Per sub-slice, its block of the operator: the stored W on its candidates / weight.
    std::vector<Eigen::MatrixXd> block;
    Eigen::VectorXd a, curvature, q_build, ghat, D, lambda0;
    std::vector<int> sub;   ///< sub-slice of each unknown
    std::vector<long> pair; ///< absolute tooth pair key of each unknown
    /// The coupling over (slice, tooth pair), index slice * n_pairs + pair_index: the correction
    /// (K + B)^-1 - K^-1 [rad/(N m)] (empty: uncoupled), and each slice's section stiffness
    /// over the pairs [N m/rad].
    std::map<long, int> pair_index;
    int n_pairs = 0;
    Eigen::MatrixXd dC;
    std::vector<int> at; ///< (slice, pair) index of each unknown in dC
    std::vector<Eigen::MatrixXd> K;
    /// The 3-D face: the contact's radius on gear 1 and gear 2 per (slice, pair index) [m].
    Eigen::MatrixXd radius[2];
    bool coupled() const { return dC.size() > 0; }
    int index(int slice, long key) const { return slice * n_pairs + pair_index.at(key); }
    /// The contact torque of each (slice, pair) [N m] under candidate forces lambda.
    Eigen::VectorXd pair_torques(const std::vector<SlicedPair::Sub> &sub, const Eigen::VectorXd &lambda) const
    {
      Eigen::VectorXd t = Eigen::VectorXd::Zero(Eigen::Index(K.size()) * n_pairs);
      for (int i = 0; i < m; ++i)
        t[index(sub[std::size_t(this->sub[std::size_t(i)])].slice, pair[std::size_t(i)])] -= a[i] * lambda[i];
      return t;
    }
    contact::NcpResult solution;
    double q = 0;
    Eigen::VectorXd arm;
    int iterations = 0;
  };


  /// A solved position (SlicedPair::Solved) before evaluate().
  struct SlicedPair::State
  {
    double phi1 = 0, torque = 0;
    std::vector<Sub> sub;
    System s;
    LeadModification lead;
    int iterations = 0;
    std::chrono::steady_clock::time_point start;
  };

  /// The coupled operator W = blockdiag(B_j) + U dC U^T (U(i, at_i) = a_i, the build arm) for
  /// contact::solve_ncp_spd: each active system is solved through the Cholesky factors of the
  /// sub-slices' active blocks and a dense system of the size of the coupling indices the
  /// active set touches (Sherman-Morrison-Woodbury), never forming W.
  class SlicedOperator : public contact::SpdOperator
  {
  public:
    SlicedOperator(const SlicedPair::System &s, const std::vector<SlicedPair::Sub> &sub);
    Eigen::Index size() const override { return s_.m; }
    double diagonal(Eigen::Index k) const override;
    Eigen::VectorXd apply(const Eigen::VectorXd &x) const override;
    bool factorise(const std::vector<int> &A) override;
    Eigen::VectorXd solve(const Eigen::VectorXd &y) const override;

  private:
    /// (B_AA + D_A)^-1 y blockwise.
    Eigen::VectorXd block_solve(const Eigen::VectorXd &y) const;
    const SlicedPair::System &s_;
    std::vector<int> owner_, local_; ///< sub-slice of each unknown and its row in the block
    struct Active
    {
      int j = 0;              ///< sub-slice
      std::vector<int> rows;  ///< rows of its block in the active set
      std::vector<int> pos;   ///< their positions in A
      Eigen::LLT<Eigen::MatrixXd> llt;
    };
    std::vector<Active> active_;
    std::vector<int> A_;
    std::vector<int> col_; ///< coupling index -> column of the active coupling, -1
    std::vector<int> cols_; ///< active coupling indices
    Eigen::MatrixXd dCa_;
    Eigen::PartialPivLU<Eigen::MatrixXd> F_;
  };
} // namespace gearfem::helical
