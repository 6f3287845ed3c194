#pragma once
// A gear body in three dimensions (dim = 3 lives only in this library target): the 2-D section's
// quadrilateral mesh (fem::ElasticBody's, unrefined) extruded along the face width into
// hexahedra, FE_Q(p)^3 on straight-sided cells, isotropic linear elasticity, MUMPS (fem/direct_solver.h). The face
// runs over z in [0, b] in layers of equal thickness. The lateral faces keep the section's
// boundary ids (flanks, fillets, bore, sector cuts: mesh/domain.h); the end faces get
// end_start() (z = 0) and end_finish() (z = b). SI units.
#include "fem/direct_solver.h"
#include "fem/elasticity.h"

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <set>

namespace gearfem::three_d
{
  using Point3  = dealii::Point<3>;
  using Tensor3 = dealii::Tensor<1, 3>;

  struct ExtrusionOptions
  {
    double face_width = 0;  ///< b [m]
    int layers        = 4;  ///< cells across the face
    unsigned degree   = 1;  ///< p of FE_Q(p)^3, {1, 2}
    /// Rotation of the section per unit z, counter-clockwise about the z axis [rad/m]: the
    /// vertices at z turn by twist (z - b/2), the middle of the face keeping the section (a
    /// helical gear; 0: spur). The cells stay straight-sided.
    double twist      = 0;
    /// InputError naming the entry for b <= 0, layers outside 1..400, p outside {1, 2}.
    void validate() const;
  };

  class SolidBody
  {
  public:
    /// `section`: an unrefined 2-D triangulation (deal.II extrudes coarse meshes only);
    /// `material`: E and nu (its plane model and thickness are not used).
    SolidBody(const dealii::Triangulation<2> &section, const fem::Elasticity &material, const ExtrusionOptions &options);
    ~SolidBody();

    /// Clamp boundary `id` (all three components). Before assemble_and_factorize().
    void constrain(dealii::types::boundary_id id);
    /// Assemble the stiffness and factorise it with the clamped DoFs eliminated; SolverError
    /// for a singular system.
    void assemble_and_factorize();
    /// Load vector [N] of the uniform traction t [Pa] on the faces with an id in `ids` whose
    /// centre passes `where` (all when null).
    dealii::Vector<double> traction_load(const Tensor3 &t, const std::set<dealii::types::boundary_id> &ids,
                                         const std::function<bool(const Point3 &)> &where = {}) const;
    /// Add the point force `force` [N] at x (a point of the body) to f.
    void add_point_force(const Point3 &x, const Tensor3 &force, dealii::Vector<double> &f) const;
    /// The normal stress d . sigma_h(x) . d at a point of the body (d a unit vector) as a
    /// linear functional of the displacement: (DoF, coefficient) pairs [Pa/m].
    std::vector<std::pair<unsigned, double>> stress_functional(const Point3 &x, const Tensor3 &d) const;
    /// u = K^-1 f with the clamped DoFs at zero.
    dealii::Vector<double> solve(const dealii::Vector<double> &f) const;
    /// The same for k load vectors at once (column-major n_dofs x k, overwritten by the
    /// displacements): one multi-right-hand-side solve.
    void solve_block(std::vector<double> &columns, unsigned k) const;
    /// u_h(x) [m] at a point of the body.
    Tensor3 displacement_at(const dealii::Vector<double> &u, const Point3 &x) const;
    /// The stress tensor sigma_h(x) [Pa] at a point of the body (from the displacement's
    /// gradient in the cell that holds x).
    dealii::SymmetricTensor<2, 3> stress_at(const dealii::Vector<double> &u, const Point3 &x) const;
    /// Sum of a nodal force vector [N].
    Tensor3 resultant(const dealii::Vector<double> &f) const;
    /// The body as VTU with the displacement u [m] and u times `scale` ("shown", for a warp
    /// by vector in the viewer), written atomically.
    void write_vtu(const dealii::Vector<double> &u, const std::filesystem::path &file, double scale = 1.0) const;

    dealii::types::boundary_id end_start() const { return end_start_; }
    dealii::types::boundary_id end_finish() const { return end_finish_; }
    unsigned int n_dofs() const { return dof_handler_.n_dofs(); }
    unsigned int n_cells() const { return tria_.n_active_cells(); }
    const dealii::Triangulation<3> &triangulation() const { return tria_; }

  private:
    fem::Elasticity material_;
    ExtrusionOptions options_;
    dealii::Triangulation<3> tria_;
    dealii::FESystem<3> fe_;
    dealii::DoFHandler<3> dof_handler_;
    dealii::SparsityPattern sparsity_;
    dealii::SparseMatrix<double> stiffness_;
    std::set<dealii::types::boundary_id> clamped_;
    std::vector<bool> constrained_;
    fem::DirectSolver solver_;
    dealii::types::boundary_id end_start_ = 0, end_finish_ = 0;
  };
} // namespace gearfem::three_d
