// The coupled operator of the slices (helical/slicing_detail.h): block-diagonal plus the
// low-rank coupling across the face, solved by Sherman-Morrison-Woodbury on the active set.
#include "helical/slicing_detail.h"

namespace gearfem::helical
{
  SlicedOperator::SlicedOperator(const SlicedPair::System &s, const std::vector<SlicedPair::Sub> &sub)
    : s_(s)
  {
    owner_.resize(std::size_t(s.m));
    local_.resize(std::size_t(s.m));
    for (std::size_t j = 0; j < sub.size(); ++j)
      for (int r = 0; r < int(sub[j].keep.size()); ++r)
        owner_[std::size_t(sub[j].first + r)] = int(j), local_[std::size_t(sub[j].first + r)] = r;
  }

  double SlicedOperator::diagonal(Eigen::Index k) const
  {
    const auto i = std::size_t(k);
    double d     = s_.block[std::size_t(owner_[i])](local_[i], local_[i]);
    if (s_.coupled())
      d += s_.a[k] * s_.a[k] * s_.dC(s_.at[i], s_.at[i]);
    return d;
  }

  Eigen::VectorXd SlicedOperator::apply(const Eigen::VectorXd &x) const
  {
    Eigen::VectorXd y(s_.m);
    int first = 0;
    for (const auto &B : s_.block)
      {
        const auto n        = B.rows();
        y.segment(first, n) = B * x.segment(first, n);
        first += int(n);
      }
    if (s_.coupled())
      {
        Eigen::VectorXd t = Eigen::VectorXd::Zero(s_.dC.rows());
        for (int i = 0; i < s_.m; ++i)
          t[s_.at[std::size_t(i)]] += s_.a[i] * x[i];
        const Eigen::VectorXd v = s_.dC * t;
        for (int i = 0; i < s_.m; ++i)
          y[i] += s_.a[i] * v[s_.at[std::size_t(i)]];
      }
    return y;
  }

  bool SlicedOperator::factorise(const std::vector<int> &A)
  {
    A_ = A;
    active_.clear();
    for (int p = 0; p < int(A.size()); ++p)
      {
        const auto i = std::size_t(A[std::size_t(p)]);
        if (active_.empty() || active_.back().j != owner_[i])
          active_.push_back(Active{owner_[i], {}, {}, {}});
        active_.back().rows.push_back(local_[i]);
        active_.back().pos.push_back(p);
      }
    for (auto &a : active_)
      {
        const auto &B = s_.block[std::size_t(a.j)];
        const int n   = int(a.rows.size());
        Eigen::MatrixXd M(n, n);
        for (int r = 0; r < n; ++r)
          {
            for (int t = 0; t < n; ++t)
              M(r, t) = B(a.rows[std::size_t(r)], a.rows[std::size_t(t)]);
            M(r, r) += s_.D[A[std::size_t(a.pos[std::size_t(r)])]];
          }
        a.llt.compute(M);
        if (a.llt.info() != Eigen::Success)
          return false;
      }
    cols_.clear();
    if (!s_.coupled())
      return true;
    // The coupling indices of the active unknowns, S = U_A^T B_A^-1 U_A, F = I + S dC_aa.
    col_.assign(std::size_t(s_.dC.rows()), -1);
    for (const int i : A)
      if (col_[std::size_t(s_.at[std::size_t(i)])] < 0)
        col_[std::size_t(s_.at[std::size_t(i)])] = int(cols_.size()), cols_.push_back(s_.at[std::size_t(i)]);
    const int c = int(cols_.size()), n = int(A.size());
    Eigen::MatrixXd U = Eigen::MatrixXd::Zero(n, c);
    for (int p = 0; p < n; ++p)
      U(p, col_[std::size_t(s_.at[std::size_t(A[std::size_t(p)])])]) = s_.a[A[std::size_t(p)]];
    Eigen::MatrixXd Y(n, c);
    for (int k = 0; k < c; ++k)
      Y.col(k) = block_solve(U.col(k));
    const Eigen::MatrixXd S = U.transpose() * Y;
    dCa_.resize(c, c);
    for (int r = 0; r < c; ++r)
      for (int t = 0; t < c; ++t)
        dCa_(r, t) = s_.dC(cols_[std::size_t(r)], cols_[std::size_t(t)]);
    F_.compute(Eigen::MatrixXd::Identity(c, c) + S * dCa_);
    return true;
  }

  Eigen::VectorXd SlicedOperator::block_solve(const Eigen::VectorXd &y) const
  {
    Eigen::VectorXd x(y.size());
    for (const auto &a : active_)
      {
        const int n = int(a.pos.size());
        Eigen::VectorXd b(n);
        for (int r = 0; r < n; ++r)
          b[r] = y[a.pos[std::size_t(r)]];
        const Eigen::VectorXd z = a.llt.solve(b);
        for (int r = 0; r < n; ++r)
          x[a.pos[std::size_t(r)]] = z[r];
      }
    return x;
  }

  Eigen::VectorXd SlicedOperator::solve(const Eigen::VectorXd &y) const
  {
    Eigen::VectorXd x = block_solve(y);
    if (cols_.empty())
      return x;
    // (B + U dC U^T) x = y: x = B^-1 (y - U dC z), (I + S dC) z = U^T B^-1 y.
    const int n = int(A_.size());
    Eigen::VectorXd r = Eigen::VectorXd::Zero(Eigen::Index(cols_.size()));
    for (int p = 0; p < n; ++p)
      r[col_[std::size_t(s_.at[std::size_t(A_[std::size_t(p)])])]] += s_.a[A_[std::size_t(p)]] * x[p];
    const Eigen::VectorXd v = dCa_ * F_.solve(r);
    Eigen::VectorXd w(n);
    for (int p = 0; p < n; ++p)
      w[p] = s_.a[A_[std::size_t(p)]] * v[col_[std::size_t(s_.at[std::size_t(A_[std::size_t(p)])])]];
    return x - block_solve(w);
  }
} // namespace gearfem::helical
