#pragma once
// A sparse direct solver that factorises once and solves for many right-hand sides:
// MUMPS through PETSc (KSPPREONLY + PCCHOLESKY, MatSolverType mumps: LDL^T of a symmetric
// positive definite matrix, AMD ordering) by default, UMFPACK for small problems.
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace gearfem::fem
{
  enum class SolverKind
  {
    automatic, ///< UMFPACK below `umfpack_max_dofs`, MUMPS above
    mumps,
    umfpack
  };
  /// Initialise PETSc now (it is otherwise initialised on the first MUMPS factorisation).
  /// A multi-threaded caller (the batch manager thread) calls this before it starts its
  /// threads, so that PETSc's start-up is not concurrent with them.
  void initialize_petsc();
  /// Finalise PETSc if gearfem initialised it (idempotent). A program that finalises MPI
  /// itself calls this first; otherwise PETSc is finalised at exit.
  void finalize_petsc();

  /// "automatic", "mumps", "umfpack" -> SolverKind; throws InputError otherwise.
  SolverKind solver_kind_from_string(const std::string &s);
  const char *to_string(SolverKind k);

  class DirectSolver
  {
  public:
    DirectSolver();
    ~DirectSolver();
    /// Factorise A (symmetric positive definite: MUMPS uses its SPD LDL^T and only the upper
    /// triangle; UMFPACK takes any square matrix). For `automatic`, picks UMFPACK when A.m() <= umfpack_max_dofs.
    /// Throws SolverError if the factorisation fails (singular matrix).
    void factorize(const dealii::SparseMatrix<double> &A, SolverKind kind,
                   unsigned int umfpack_max_dofs = 20000);
    /// x = A^{-1} b with the stored factors.
    void solve(const dealii::Vector<double> &b, dealii::Vector<double> &x) const;
    /// X = A^{-1} B for k right-hand sides at once, column-major n x k in `columns`
    /// (overwritten by the solutions). MUMPS solves the block in one call (KSPMatSolve),
    /// UMFPACK column by column.
    void solve_block(std::vector<double> &columns, unsigned int k) const;
    /// Selected entries of A^{-1}: for each j, E[j][i] = (A^{-1})(rows[j][i], cols[j]) (each
    /// column its own rows, none twice). MUMPS computes them with its sparse right-hand
    /// sides and selected-entries solve (ICNTL(30), through MatMumpsGetInverseTranspose),
    /// which prunes the elimination tree to the paths of the requested rows and columns:
    /// much cheaper than full solves when the rows are a small part of the body (the contact
    /// surface); its cost grows with the number of entries. UMFPACK falls back to full
    /// solves.
    std::vector<std::vector<double>> inverse_entries(const std::vector<unsigned int> &cols,
                                                     const std::vector<std::vector<unsigned int>> &rows) const;
    /// The solver actually used (mumps or umfpack).
    SolverKind kind() const { return kind_; }
    bool factorized() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    SolverKind kind_ = SolverKind::automatic;
  };
} // namespace gearfem::fem
