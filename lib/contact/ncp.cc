// Active-set and semismooth Newton solvers of the contact complementarity problem.
#include "contact/ncp.h"

#include <cmath>
#include <set>

namespace gearfem::contact
{
  /// min over lambda >= 0 (and q for load control) of the linear complementarity problem
  /// g = ghat + a q + W lambda, lambda >= 0, g + D lambda >= 0, lambda (g + D lambda) = 0,
  /// [-a^T lambda = T]. D = 0: Lagrange (PDAS); D = 1/eps: penalty (semismooth Newton).
  NcpResult solve_ncp(const Eigen::MatrixXd &W, const Eigen::VectorXd &D, const Eigen::VectorXd &a,
                      const Eigen::VectorXd &ghat, Control control, double value, double q0,
                      const Eigen::VectorXd &lambda0, int max_iterations, const Eigen::VectorXd &af_in,
                      const std::function<void(const std::vector<int> &)> *fill)
  {
    // The complementarity parameter of candidate k: 1/W_kk (any positive value where W_kk is
    // not filled: lambda_k = 0 there).
    const auto cpar = [&](int k) { return W(k, k) > 0 ? 1.0 / W(k, k) : 1.0; };
    const int m = int(W.rows());
    const Eigen::VectorXd &af = af_in.size() == m ? af_in : a;
    const bool symmetric      = af_in.size() != m;
    NcpResult r;
    r.q = control == Control::displacement ? value : q0;
    r.lambda = Eigen::VectorXd::Zero(m);
    r.gap    = ghat + a * r.q;
    std::vector<char> active(m, 0);
    bool any = false;
    for (int k = 0; k < m; ++k)
      if (lambda0.size() == m && lambda0[k] > 0)
        active[k] = 1, any = true;
    if (!any)
      {
        if (control == Control::load)
          {
            // The node that closes first as q grows.
            int best = -1;
            double qmin = 1e300;
            for (int k = 0; k < m; ++k)
              if (a[k] < 0 && ghat[k] / -a[k] < qmin)
                qmin = ghat[k] / -a[k], best = k;
            if (best >= 0)
              active[best] = 1;
          }
        else
          for (int k = 0; k < m; ++k)
            active[k] = r.gap[k] < 0;
      }
    std::set<std::vector<char>> seen;
    for (r.iterations = 1; r.iterations <= max_iterations; ++r.iterations)
      {
        std::vector<int> A;
        for (int k = 0; k < m; ++k)
          if (active[k])
            A.push_back(k);
        const int n = int(A.size());
        if (fill && n > 0)
          (*fill)(A);
        r.lambda.setZero();
        if (control == Control::load)
          {
            if (n == 0)
              {
                r.why = "no slave node can close its gap as the drive advances (no contact)";
                return r;
              }
            Eigen::MatrixXd K(n + 1, n + 1);
            Eigen::VectorXd rhs(n + 1);
            for (int i = 0; i < n; ++i)
              {
                for (int j = 0; j < n; ++j)
                  K(i, j) = W(A[i], A[j]);
                K(i, i) += D[A[i]];
                K(i, n) = a[A[i]];
                K(n, i) = af[A[i]];
                rhs[i] = -ghat[A[i]];
              }
            K(n, n) = 0;
            rhs[n]  = -value;
            const Eigen::VectorXd x = K.fullPivLu().solve(rhs);
            if (!x.allFinite() || !(K * x).isApprox(rhs, 1e-8))
              {
                r.why = "singular contact system on the active set (the active nodes cannot carry the load)";
                return r;
              }
            for (int i = 0; i < n; ++i)
              r.lambda[A[i]] = x[i];
            r.q = x[n];
          }
        else if (n > 0)
          {
            Eigen::MatrixXd K(n, n);
            Eigen::VectorXd rhs(n);
            for (int i = 0; i < n; ++i)
              {
                for (int j = 0; j < n; ++j)
                  K(i, j) = W(A[i], A[j]);
                K(i, i) += D[A[i]];
                rhs[i] = -ghat[A[i]] - a[A[i]] * r.q;
              }
            const Eigen::VectorXd x = symmetric ? Eigen::VectorXd(K.ldlt().solve(rhs))
                                                : Eigen::VectorXd(K.partialPivLu().solve(rhs));
            for (int i = 0; i < n; ++i)
              r.lambda[A[i]] = x[i];
          }
        // W lambda over the active columns only: lambda is zero elsewhere (n of m columns; the
        // full product was a quarter of a condensed re-solve).
        r.gap = ghat + a * r.q;
        for (const int k : A)
          r.gap.noalias() += W.col(k) * r.lambda[k];
        std::vector<char> next(m, 0);
        for (int k = 0; k < m; ++k)
          {
            const double c = cpar(k);
            next[k]        = r.lambda[k] - c * r.gap[k] > 0;
          }
        if (next == active)
          {
            r.ok     = true;
            r.active = active;
            double num = 0, den = 0;
            for (int k = 0; k < m; ++k)
              {
                const double c  = cpar(k);
                const double gk = r.gap[k] + D[k] * r.lambda[k];
                const double v  = std::min(r.lambda[k], c * gk);
                num += v * v;
                den += r.lambda[k] * r.lambda[k];
              }
            r.complementarity = den > 0 ? std::sqrt(num / den) : 0.0;
            if (n > 0)
              {
                Eigen::MatrixXd K(n, n);
                Eigen::VectorXd aa(n), afa(n);
                for (int i = 0; i < n; ++i)
                  {
                    for (int j = 0; j < n; ++j)
                      K(i, j) = W(A[i], A[j]);
                    K(i, i) += D[A[i]];
                    aa[i]  = a[A[i]];
                    afa[i] = af[A[i]];
                  }
                // dT/dq = af_A^T (W_AA + D)^-1 a_A
                r.tangent = symmetric ? aa.dot(K.ldlt().solve(aa)) : afa.dot(K.partialPivLu().solve(aa));
              }
            return r;
          }
        if (!seen.insert(active).second)
          {
            r.why = "the active set cycles";
            return r;
          }
        active = next;
      }
    r.why = "the active set did not settle in " + std::to_string(max_iterations) + " iterations";
    return r;
  }

  namespace
  {
    /// W_AA + D_A of a dense W, factorised by Cholesky.
    class DenseSpd : public SpdOperator
    {
    public:
      DenseSpd(const Eigen::MatrixXd &W, const Eigen::VectorXd &D) : W_(W), D_(D) {}
      Eigen::Index size() const override { return W_.rows(); }
      double diagonal(Eigen::Index k) const override { return W_(k, k); }
      Eigen::VectorXd apply(const Eigen::VectorXd &x) const override { return W_ * x; }
      bool factorise(const std::vector<int> &A) override
      {
        const int n = int(A.size());
        Eigen::MatrixXd M(n, n);
        for (int i = 0; i < n; ++i)
          {
            for (int j = 0; j < n; ++j)
              M(i, j) = W_(A[std::size_t(i)], A[std::size_t(j)]);
            M(i, i) += D_[A[std::size_t(i)]];
          }
        llt_.compute(M);
        return llt_.info() == Eigen::Success;
      }
      Eigen::VectorXd solve(const Eigen::VectorXd &y) const override { return llt_.solve(y); }

    private:
      const Eigen::MatrixXd &W_;
      const Eigen::VectorXd &D_;
      Eigen::LLT<Eigen::MatrixXd> llt_;
    };
  } // namespace

  NcpResult solve_ncp_spd(SpdOperator &W, const Eigen::VectorXd &a, const Eigen::VectorXd &ghat, double load,
                          const Eigen::VectorXd &lambda0, int max_iterations)
  {
    const int m = int(W.size());
    NcpResult r;
    r.lambda = Eigen::VectorXd::Zero(m);
    std::vector<char> active(std::size_t(m), 0);
    bool any = false;
    for (int k = 0; k < m; ++k)
      if (lambda0.size() == m && lambda0[k] > 0)
        active[std::size_t(k)] = 1, any = true;
    if (!any)
      {
        // The node that closes first as q grows.
        int best = -1;
        double qmin = 1e300;
        for (int k = 0; k < m; ++k)
          if (a[k] < 0 && ghat[k] / -a[k] < qmin)
            qmin = ghat[k] / -a[k], best = k;
        if (best >= 0)
          active[std::size_t(best)] = 1;
      }
    std::set<std::vector<char>> seen;
    for (r.iterations = 1; r.iterations <= max_iterations; ++r.iterations)
      {
        std::vector<int> A;
        for (int k = 0; k < m; ++k)
          if (active[std::size_t(k)])
            A.push_back(k);
        const int n = int(A.size());
        if (n == 0)
          {
            r.why = "no slave node can close its gap as the drive advances (no contact)";
            return r;
          }
        if (!W.factorise(A))
          {
            r.why = "the contact operator is not positive definite on the active set";
            return r;
          }
        // lambda_A = -M^-1 (ghat + a q), a^T lambda = -T: q from the Schur complement.
        Eigen::VectorXd gA(n), aA(n);
        for (int i = 0; i < n; ++i)
          gA[i] = ghat[A[std::size_t(i)]], aA[i] = a[A[std::size_t(i)]];
        const Eigen::VectorXd x1 = W.solve(gA), x2 = W.solve(aA);
        const double den = aA.dot(x2);
        if (!(den > 0))
          {
            r.why = "the active nodes cannot carry the load";
            return r;
          }
        r.q = (load - aA.dot(x1)) / den;
        r.lambda.setZero();
        for (int i = 0; i < n; ++i)
          r.lambda[A[std::size_t(i)]] = -x1[i] - x2[i] * r.q;
        r.gap = ghat + a * r.q + W.apply(r.lambda);
        std::vector<char> next(std::size_t(m), 0);
        for (int k = 0; k < m; ++k)
          next[std::size_t(k)] = r.lambda[k] - r.gap[k] / W.diagonal(k) > 0;
        if (next == active)
          {
            r.ok      = true;
            r.active  = active;
            r.tangent = den; // dT/dq = a_A^T (W_AA + D_A)^-1 a_A
            double num = 0, dd = 0;
            for (int k = 0; k < m; ++k)
              {
                const double v = std::min(r.lambda[k], r.gap[k] / W.diagonal(k));
                num += v * v;
                dd += r.lambda[k] * r.lambda[k];
              }
            r.complementarity = dd > 0 ? std::sqrt(num / dd) : 0.0;
            return r;
          }
        if (!seen.insert(active).second)
          {
            r.why = "the active set cycles";
            return r;
          }
        active = next;
      }
    r.why = "the active set did not settle in " + std::to_string(max_iterations) + " iterations";
    return r;
  }

  NcpResult solve_ncp_spd(const Eigen::MatrixXd &W, const Eigen::VectorXd &D, const Eigen::VectorXd &a,
                          const Eigen::VectorXd &ghat, double load, const Eigen::VectorXd &lambda0,
                          int max_iterations)
  {
    DenseSpd op(W, D);
    return solve_ncp_spd(op, a, ghat, load, lambda0, max_iterations);
  }
} // namespace gearfem::contact
