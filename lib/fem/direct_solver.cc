// Direct solvers: MUMPS through the PETSc C interface (factorise once, reuse for many
// right-hand sides), UMFPACK through deal.II.
#include "fem/direct_solver.h"

#include <algorithm>
#include <cstdlib>

#include "base/errors.h"

#include <deal.II/lac/sparse_direct.h>

#include <petscksp.h>

#include <vector>

namespace gearfem::fem
{
  namespace
  {
    /// PETSc (and MPI, if nobody did) initialised on first use, finalised at exit (or by
    /// finalize_petsc(), before MPI_Finalize). Every PETSc object of gearfem lives on
    /// PETSC_COMM_SELF; when MPI is already running (gearfem batch), PETSc's world is
    /// MPI_COMM_SELF too, so that its initialisation is not collective: each rank runs the
    /// serial chain on its own.
    struct PetscGuard
    {
      bool we_initialized = false;
      PetscGuard()
      {
        PetscBool done = PETSC_FALSE;
        PetscInitialized(&done);
        if (!done)
          {
            int mpi_running = 0;
            MPI_Initialized(&mpi_running);
            if (mpi_running)
              PETSC_COMM_WORLD = MPI_COMM_SELF;
            else if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMIX_RANK"))
              // A process not started by mpirun is a singleton that never talks to another:
              // Open MPI's ob1 messaging instead of its default probe of UCX, which spends
              // 0.2 s of wall time (not CPU) in every MPI_Init. A value the user set stays.
              setenv("OMPI_MCA_pml", "ob1", 0);
            if (PetscInitializeNoArguments() != 0)
              throw SolverError("PETSc could not be initialised");
            we_initialized = true;
          }
        // MUMPS's ordering: approximate minimum degree (see factorize), unless PETSC_OPTIONS
        // names one. MUMPS reads it from the options database at its analysis (a
        // MatMumpsSetIcntl before the analysis does not hold in PETSc 3.18).
        PetscBool given = PETSC_FALSE;
        PetscOptionsHasName(nullptr, nullptr, "-mat_mumps_icntl_7", &given);
        if (!given)
          PetscOptionsSetValue(nullptr, "-mat_mumps_icntl_7", "0");
      }
      ~PetscGuard() { finalize(); }
      void finalize()
      {
        PetscBool up = PETSC_FALSE;
        PetscInitialized(&up);
        if (we_initialized && up)
          PetscFinalize();
        we_initialized = false;
      }
    };
    bool guard_created = false;
    PetscGuard &petsc_guard()
    {
      static PetscGuard guard;
      guard_created = true;
      return guard;
    }
    void ensure_petsc() { (void)petsc_guard(); }
    void check(PetscErrorCode ierr, const char *what)
    {
      if (ierr != 0)
        throw SolverError(std::string("PETSc/MUMPS failed in ") + what + " (error " +
                          std::to_string(int(ierr)) + ")");
    }
  } // namespace

  void initialize_petsc() { ensure_petsc(); }

  void finalize_petsc()
  {
    if (guard_created)
      petsc_guard().finalize();
  }

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
    // The stiffness is symmetric positive definite (symmetric element matrices, Dirichlet
    // rows and columns eliminated alike): MUMPS's LDL^T for SPD matrices (SYM = 1, no
    // pivoting) does half the work of its LU, with the approximate minimum degree ordering
    // (ICNTL(7) = 0, set with PETSc) instead of the automatic choice (PORD here). On a
    // 178 000-DoF pair (validation/model_choice, random 2 at m/30) the set-up of the two
    // bodies took 1.23 s instead of 1.76 s, every result equal to 1e-10 (docs/fem.md).
    check(MatSetOption(impl_->A, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption(MAT_SYMMETRIC)");
    check(MatSetOption(impl_->A, MAT_SPD, PETSC_TRUE), "MatSetOption(MAT_SPD)");
    check(PCSetType(pc, PCCHOLESKY), "PCSetType");
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

  std::vector<std::vector<double>> DirectSolver::inverse_entries(
    const std::vector<unsigned int> &cols, const std::vector<std::vector<unsigned int>> &rows) const
  {
    if (!impl_->ready)
      throw SolverError("DirectSolver::inverse_entries called before factorize");
    if (rows.size() != cols.size())
      throw SolverError("DirectSolver::inverse_entries: one row list per column expected");
    std::vector<std::vector<double>> out(cols.size());
    for (std::size_t j = 0; j < cols.size(); ++j)
      out[j].assign(rows[j].size(), 0.0);
    if (cols.empty())
      return out;
    if (kind_ == SolverKind::umfpack)
      {
        const std::size_t n = impl_->umfpack.m();
        std::vector<double> X(n * cols.size(), 0.0);
        for (std::size_t j = 0; j < cols.size(); ++j)
          X[j * n + cols[j]] = 1.0;
        solve_block(X, static_cast<unsigned int>(cols.size()));
        for (std::size_t j = 0; j < cols.size(); ++j)
          for (std::size_t i = 0; i < rows[j].size(); ++i)
            out[j][i] = X[j * n + rows[j][i]];
        return out;
      }
    // spRHST(j, i) receives (A^T)^{-1}(j, i) = (A^{-1})(i, j). Its pattern is given as CSR
    // arrays (MatCreateSeqAIJWithArrays): inserting and assembling a matrix of n rows took a
    // third of a small request.
    PetscInt n = 0;
    check(MatGetSize(impl_->A, &n, nullptr), "MatGetSize");
    std::vector<int> column_of(std::size_t(n), -1);
    for (std::size_t j = 0; j < cols.size(); ++j)
      {
        if (column_of[cols[j]] >= 0)
          throw SolverError("DirectSolver::inverse_entries: column " + std::to_string(cols[j]) + " requested twice");
        column_of[cols[j]] = int(j);
      }
    std::vector<PetscInt> ia(std::size_t(n) + 1, 0), ja;
    std::vector<std::vector<std::size_t>> order(cols.size()); // entry of each sorted row position
    for (PetscInt r = 0; r < n; ++r)
      {
        const int j = column_of[std::size_t(r)];
        if (j >= 0)
          {
            auto &o = order[std::size_t(j)];
            o.resize(rows[j].size());
            for (std::size_t i = 0; i < o.size(); ++i)
              o[i] = i;
            std::sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return rows[j][a] < rows[j][b]; });
            for (std::size_t i = 0; i < o.size(); ++i)
              {
                if (i > 0 && rows[j][o[i]] == rows[j][o[i - 1]])
                  throw SolverError("DirectSolver::inverse_entries: row " + std::to_string(rows[j][o[i]]) +
                                    " requested twice in one column (each row is filled once)");
                ja.push_back(PetscInt(rows[j][o[i]]));
              }
            if (o.empty())
              ja.push_back(r); // a column of no rows still needs an entry
          }
        ia[std::size_t(r) + 1] = PetscInt(ja.size());
      }
    std::vector<PetscScalar> a(ja.size(), 0.0);
    Mat S = nullptr;
    check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, n, n, ia.data(), ja.data(), a.data(), &S),
          "MatCreateSeqAIJWithArrays");
    PC pc;
    Mat F;
    check(KSPGetPC(impl_->ksp, &pc), "KSPGetPC");
    check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
    check(MatMumpsGetInverseTranspose(F, S), "MatMumpsGetInverseTranspose");
    // PETSc 3.18 leaves MUMPS in selected-entries mode (ICNTL(30) = 1, INFOG(1) = -47 on
    // the next ordinary solve): restore dense right-hand sides and full solutions.
    check(MatMumpsSetIcntl(F, 30, 0), "MatMumpsSetIcntl(30)");
    check(MatMumpsSetIcntl(F, 20, 0), "MatMumpsSetIcntl(20)");
    const PetscScalar *values = nullptr;
    check(MatSeqAIJGetArrayRead(S, &values), "MatSeqAIJGetArrayRead");
    for (std::size_t j = 0; j < cols.size(); ++j)
      {
        const PetscInt first = ia[cols[j]];
        for (std::size_t i = 0; i < order[j].size(); ++i)
          out[j][order[j][i]] = values[std::size_t(first) + i];
      }
    check(MatSeqAIJRestoreArrayRead(S, &values), "MatSeqAIJRestoreArrayRead");
    MatDestroy(&S);
    return out;
  }
} // namespace gearfem::fem
