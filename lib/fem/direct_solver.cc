// Direct solvers: MUMPS through the PETSc C interface (factorise once, reuse for many
// right-hand sides), UMFPACK through deal.II.
#include "fem/direct_solver.h"

#include "base/errors.h"

#include <deal.II/lac/sparse_direct.h>

#include <petscksp.h>

#include <vector>

namespace gearfem::fem
{
  namespace
  {
    /// PETSc (and MPI, if nobody did) initialised on first use, finalised at exit.
    struct PetscGuard
    {
      bool we_initialized = false;
      PetscGuard()
      {
        PetscBool done = PETSC_FALSE;
        PetscInitialized(&done);
        if (!done)
          {
            if (PetscInitializeNoArguments() != 0)
              throw SolverError("PETSc could not be initialised");
            we_initialized = true;
          }
      }
      ~PetscGuard()
      {
        if (we_initialized)
          PetscFinalize();
      }
    };
    void ensure_petsc()
    {
      static PetscGuard guard;
    }
    void check(PetscErrorCode ierr, const char *what)
    {
      if (ierr != 0)
        throw SolverError(std::string("PETSc/MUMPS failed in ") + what + " (error " +
                          std::to_string(int(ierr)) + ")");
    }
  } // namespace

  SolverKind solver_kind_from_string(const std::string &s)
  {
    if (s == "automatic")
      return SolverKind::automatic;
    if (s == "mumps")
      return SolverKind::mumps;
    if (s == "umfpack")
      return SolverKind::umfpack;
    throw InputError("Finite elements/Linear solver", s, "{automatic, mumps, umfpack}");
  }

  const char *to_string(SolverKind k)
  {
    switch (k)
      {
        case SolverKind::mumps:
          return "mumps";
        case SolverKind::umfpack:
          return "umfpack";
        default:
          return "automatic";
      }
  }

  struct DirectSolver::Impl
  {
    dealii::SparseDirectUMFPACK umfpack;
    Mat A   = nullptr;
    KSP ksp = nullptr;
    Vec b = nullptr, x = nullptr;
    bool ready = false;
    ~Impl() { clear(); }
    void clear()
    {
      if (ksp)
        KSPDestroy(&ksp);
      if (A)
        MatDestroy(&A);
      if (b)
        VecDestroy(&b);
      if (x)
        VecDestroy(&x);
      ksp = nullptr, A = nullptr, b = nullptr, x = nullptr;
      ready = false;
    }
  };

  DirectSolver::DirectSolver()
    : impl_(std::make_unique<Impl>())
  {}
  DirectSolver::~DirectSolver() = default;

  bool DirectSolver::factorized() const { return impl_->ready; }

  void DirectSolver::factorize(const dealii::SparseMatrix<double> &M, SolverKind kind,
                               unsigned int umfpack_max_dofs)
  {
    impl_->clear();
    if (kind == SolverKind::automatic)
      kind = M.m() <= umfpack_max_dofs ? SolverKind::umfpack : SolverKind::mumps;
    kind_ = kind;
    if (kind == SolverKind::umfpack)
      {
        try
          {
            impl_->umfpack.initialize(M);
          }
        catch (const std::exception &e)
          {
            throw SolverError(std::string("UMFPACK factorisation failed: ") + e.what());
          }
        impl_->ready = true;
        return;
      }

    ensure_petsc();
    const PetscInt n = PetscInt(M.m());
    std::vector<PetscInt> nnz(n);
    for (PetscInt i = 0; i < n; ++i)
      nnz[i] = PetscInt(M.get_row_length(i));
    check(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, nnz.data(), &impl_->A), "MatCreateSeqAIJ");
    std::vector<PetscInt> cols;
    std::vector<PetscScalar> vals;
    for (PetscInt i = 0; i < n; ++i)
      {
        cols.clear();
        vals.clear();
        for (auto it = M.begin(i); it != M.end(i); ++it)
          {
            cols.push_back(PetscInt(it->column()));
            vals.push_back(it->value());
          }
        check(MatSetValues(impl_->A, 1, &i, PetscInt(cols.size()), cols.data(), vals.data(),
                           INSERT_VALUES),
              "MatSetValues");
      }
    check(MatAssemblyBegin(impl_->A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    check(MatAssemblyEnd(impl_->A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    check(KSPCreate(PETSC_COMM_SELF, &impl_->ksp), "KSPCreate");
    check(KSPSetOperators(impl_->ksp, impl_->A, impl_->A), "KSPSetOperators");
    check(KSPSetType(impl_->ksp, KSPPREONLY), "KSPSetType");
    PC pc;
    check(KSPGetPC(impl_->ksp, &pc), "KSPGetPC");
    check(PCSetType(pc, PCLU), "PCSetType");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
    check(KSPSetUp(impl_->ksp), "KSPSetUp (MUMPS factorisation)");
    check(MatCreateVecs(impl_->A, &impl_->x, &impl_->b), "MatCreateVecs");
    impl_->ready = true;
  }

  void DirectSolver::solve(const dealii::Vector<double> &rhs, dealii::Vector<double> &sol) const
  {
    if (!impl_->ready)
      throw SolverError("DirectSolver::solve called before factorize");
    if (kind_ == SolverKind::umfpack)
      {
        sol = rhs;
        impl_->umfpack.solve(sol);
        return;
      }
    PetscScalar *p;
    check(VecGetArray(impl_->b, &p), "VecGetArray");
    std::copy(rhs.begin(), rhs.end(), p);
    check(VecRestoreArray(impl_->b, &p), "VecRestoreArray");
    check(KSPSolve(impl_->ksp, impl_->b, impl_->x), "KSPSolve");
    KSPConvergedReason reason;
    KSPGetConvergedReason(impl_->ksp, &reason);
    if (reason < 0)
      throw SolverError("MUMPS solve failed (KSP reason " + std::to_string(int(reason)) + ")");
    const PetscScalar *q;
    check(VecGetArrayRead(impl_->x, &q), "VecGetArrayRead");
    sol.reinit(rhs.size());
    std::copy(q, q + rhs.size(), sol.begin());
    check(VecRestoreArrayRead(impl_->x, &q), "VecRestoreArrayRead");
  }

  void DirectSolver::solve_block(std::vector<double> &X, unsigned int k) const
  {
    if (!impl_->ready)
      throw SolverError("DirectSolver::solve_block called before factorize");
    if (k == 0)
      return;
    const std::size_t n = X.size() / k;
    if (n * k != X.size())
      throw SolverError("DirectSolver::solve_block: block size is not a multiple of k");
    if (kind_ == SolverKind::umfpack)
      {
        dealii::Vector<double> c(n);
        for (unsigned int j = 0; j < k; ++j)
          {
            std::copy(X.begin() + j * n, X.begin() + (j + 1) * n, c.begin());
            impl_->umfpack.solve(c);
            std::copy(c.begin(), c.end(), X.begin() + j * n);
          }
        return;
      }
    Mat B = nullptr, Y = nullptr;
    check(MatCreateSeqDense(PETSC_COMM_SELF, PetscInt(n), PetscInt(k), X.data(), &B), "MatCreateSeqDense");
    check(MatCreateSeqDense(PETSC_COMM_SELF, PetscInt(n), PetscInt(k), nullptr, &Y), "MatCreateSeqDense");
    check(KSPMatSolve(impl_->ksp, B, Y), "KSPMatSolve (MUMPS)");
    const PetscScalar *y;
    check(MatDenseGetArrayRead(Y, &y), "MatDenseGetArrayRead");
    std::copy(y, y + n * k, X.begin());
    check(MatDenseRestoreArrayRead(Y, &y), "MatDenseRestoreArrayRead");
    MatDestroy(&B);
    MatDestroy(&Y);
  }
} // namespace gearfem::fem
